//! Incompressible (mixed displacement/pressure) massive elements: ICT3,
//! ICQ4, ICT6, ICQ8 in the 2D modes, ICT4, ICC8, ICP6 in TRID.
//!
//! The stress splits into a deviatoric part 2μ·dev(ε) and a mean stress
//! p, interpolated on its own inside each element and tied to the strains
//! weakly: ∫ q (tr ε − p/κ) = 0 for every pressure mode q (κ the bulk
//! modulus). The pressure is discontinuous between elements, so it is
//! condensed out element by element: the element keeps only the
//! displacement unknowns of its mesh (UX UY, UR UZ, UX UY UZ) and the
//! matrix is
//!
//!   K = ∫ Bᵀ D_dev B + Gᵀ M⁻¹ G,   G = ∫ N_pᵀ (mᵀB),   M = ∫ N_pᵀ N_p / κ,
//!
//! with m the trace vector. As ν → 1/2, κ grows but only the pressure
//! modes are constrained, not every Gauss point's volume: the element does
//! not lock the way the displacement element does.
//!
//! Pressure modes: constant (one per element) except on ICQ8, where
//! it is linear (1, x, y in physical coordinates about the centroid).
//! These are the stable pairs: a linear pressure locks QUA4 and is not
//! stable on TRI6, while P2/P0 is; QUA8 has enough displacement unknowns
//! for three pressure modes, which follow linear pressure fields exactly.
//! ICT3 (and ICT4) with one pressure still constrain too much on fine
//! meshes: they are the least accurate of the family.
//!
//! Plane stress has no incompressibility constraint (ε_zz takes up the
//! volume change), so PLAN CONT uses the displacement element.

use super::element::{ElemMatrix, FemError, Formulation, GaussField, Mode};
use super::material::Material;
use super::mesh::ElemType;
use super::solid::{self, bmat, dof_list, points, Point};
use faer::linalg::solvers::Solve;

/// Number of strain components whose sum is the trace (the first three).
const TRACE: usize = 3;

/// Pressure modes at a point: 1, or on QUA8 (1, x, y) about the centroid
/// scaled by the element size.
fn pressure_modes(ty: ElemType, mode: Mode, x: &[[f64; 3]], p: &Point) -> Vec<f64> {
    if ty != ElemType::Qua8 {
        return vec![1.0];
    }
    let dim = if mode == Mode::Trid { 3 } else { 2 };
    let n = x.len() as f64;
    let mut c = [0.0; 3];
    for xi in x {
        for k in 0..dim {
            c[k] += xi[k] / n;
        }
    }
    let size = x
        .iter()
        .map(|xi| (0..dim).map(|k| (xi[k] - c[k]).powi(2)).sum::<f64>().sqrt())
        .fold(0.0, f64::max)
        .max(f64::MIN_POSITIVE);
    let mut pos = [0.0; 3];
    for (ni, xi) in p.n.iter().zip(x) {
        for k in 0..dim {
            pos[k] += ni * xi[k];
        }
    }
    let mut q = vec![1.0];
    q.extend((0..dim).map(|k| (pos[k] - c[k]) / size));
    q
}

/// Shear modulus and bulk modulus of the 3D law.
fn moduli(m: &Material, elem: &'static str) -> Result<(f64, f64), FemError> {
    let e = m.young(elem)?;
    let nu = m.poisson(elem)?;
    if nu >= 0.5 {
        return Err(FemError::InvalidProperty {
            prop: "NU",
            value: nu,
            elem,
            why: "must stay below 0.5: the pressure is condensed per element, which needs a finite bulk modulus",
        });
    }
    Ok((e / (2.0 * (1.0 + nu)), e / (3.0 * (1.0 - 2.0 * nu))))
}

/// 2μ·dev(ε) for a strain vector of the mode (engineering shears last).
fn deviatoric(mu: f64, eps: &[f64]) -> Vec<f64> {
    let tr: f64 = eps[..TRACE].iter().sum();
    eps.iter().enumerate().map(|(i, e)| if i < TRACE { 2.0 * mu * (e - tr / 3.0) } else { mu * e }).collect()
}

/// The element's integration points with their B matrices and pressure
/// modes, and the condensation operator C = M⁻¹ G (pressure coefficients
/// from element displacements).
struct Mixed {
    pts: Vec<(Point, Vec<Vec<f64>>, Vec<f64>)>,
    g: Vec<Vec<f64>>,
    c: Vec<Vec<f64>>,
}

fn mixed(ty: ElemType, mode: Mode, x: &[[f64; 3]], kappa: f64, t: f64) -> Result<Mixed, FemError> {
    let rule = solid::rule(Formulation::Solid, ty);
    let pts: Vec<_> = points(ty, mode, x, &rule, t)?
        .into_iter()
        .map(|p| {
            let b = bmat(mode, &p);
            let q = pressure_modes(ty, mode, x, &p);
            (p, b, q)
        })
        .collect();
    let np = pts[0].2.len();
    let nd = pts[0].1[0].len();
    let mut g = vec![vec![0.0; nd]; np];
    let mut m = vec![vec![0.0; np]; np];
    for (p, b, q) in &pts {
        for a in 0..np {
            for (j, gv) in g[a].iter_mut().enumerate() {
                *gv += q[a] * (0..TRACE).map(|i| b[i][j]).sum::<f64>() * p.w;
            }
            for c in 0..np {
                m[a][c] += q[a] * q[c] * p.w / kappa;
            }
        }
    }
    let c = solve(m, &g).ok_or_else(|| FemError::Degenerate {
        elem: ty.name(),
        why: "the pressure modes are not independent on this element".into(),
    })?;
    Ok(Mixed { pts, g, c })
}

/// M⁻¹ R (M is at most 3×3, symmetric positive definite for a valid
/// element): faer's LU, with a check that the result is finite and M not
/// singular relative to its diagonal.
fn solve(m: Vec<Vec<f64>>, r: &[Vec<f64>]) -> Option<Vec<Vec<f64>>> {
    let n = m.len();
    let nd = r.first()?.len();
    let mm = faer::Mat::from_fn(n, n, |i, j| m[i][j]);
    let lu = mm.partial_piv_lu();
    let det: f64 = (0..n).map(|i| lu.U()[(i, i)]).product();
    let diag: f64 = (0..n).map(|i| m[i][i].abs()).product();
    if det.abs() <= 1e-12 * diag {
        return None;
    }
    let x = lu.solve(faer::Mat::from_fn(n, nd, |i, j| r[i][j]));
    let out: Vec<Vec<f64>> = (0..n).map(|i| (0..nd).map(|j| x[(i, j)]).collect()).collect();
    out.iter().flatten().all(|v| v.is_finite()).then_some(out)
}

pub fn stiffness(ty: ElemType, mode: Mode, x: &[[f64; 3]], m: &Material) -> Result<ElemMatrix, FemError> {
    if mode == Mode::PlanCont {
        return solid::stiffness(Formulation::Solid, ty, mode, x, m);
    }
    let (mu, kappa) = moduli(m, ty.name())?;
    let t = m.thickness(mode, ty.name())?;
    let mx = mixed(ty, mode, x, kappa, t)?;
    let dofs = dof_list(ty, mode);
    let nd = dofs.len();
    let mut k = vec![0.0; nd * nd];
    for (p, b, _) in &mx.pts {
        for j in 0..nd {
            let col: Vec<f64> = b.iter().map(|row| row[j]).collect();
            let s = deviatoric(mu, &col);
            for i in 0..nd {
                k[i * nd + j] += b.iter().zip(&s).map(|(row, sv)| row[i] * sv).sum::<f64>() * p.w;
            }
        }
    }
    // Gᵀ M⁻¹ G = Gᵀ C.
    for i in 0..nd {
        for j in 0..nd {
            k[i * nd + j] += mx.g.iter().zip(&mx.c).map(|(gr, cr)| gr[i] * cr[j]).sum::<f64>();
        }
    }
    // Symmetrise the round-off of the two products.
    for i in 0..nd {
        for j in 0..i {
            let v = 0.5 * (k[i * nd + j] + k[j * nd + i]);
            k[i * nd + j] = v;
            k[j * nd + i] = v;
        }
    }
    Ok(ElemMatrix { dofs, k })
}

/// Stresses at the integration points: 2μ·dev(ε) plus the element's
/// pressure field (the condensed one, not κ·tr ε at the point).
pub fn stress(ty: ElemType, mode: Mode, x: &[[f64; 3]], m: &Material, u: &[f64]) -> Result<GaussField, FemError> {
    if mode == Mode::PlanCont {
        return solid::field(Formulation::Solid, ty, mode, x, m, u, true);
    }
    let nd = ty.nodes() * solid::dofs(mode).len();
    if u.len() != nd {
        return Err(FemError::WrongDofCount { elem: ty.name(), expected: nd, got: u.len() });
    }
    let (mu, kappa) = moduli(m, ty.name())?;
    let mx = mixed(ty, mode, x, kappa, 1.0)?;
    let pc: Vec<f64> = mx.c.iter().map(|row| row.iter().zip(u).map(|(a, b)| a * b).sum()).collect();
    let values = mx
        .pts
        .iter()
        .map(|(_, b, q)| {
            let eps: Vec<f64> = b.iter().map(|row| row.iter().zip(u).map(|(a, b)| a * b).sum()).collect();
            let p: f64 = q.iter().zip(&pc).map(|(a, b)| a * b).sum();
            let mut s = deviatoric(mu, &eps);
            s[..TRACE].iter_mut().for_each(|v| *v += p);
            s
        })
        .collect();
    Ok(GaussField { comps: solid::stress_comps(mode), values })
}

/// The incompressible element of each massive geometry: ICT3, ICQ4, ICT6,
/// ICQ8 in the plane, ICT4, ICC8, ICP6 in TRID.
pub const NAMES: &[(&str, ElemType)] = &[
    ("ICT3", ElemType::Tri3),
    ("ICQ4", ElemType::Qua4),
    ("ICT6", ElemType::Tri6),
    ("ICQ8", ElemType::Qua8),
    ("ICT4", ElemType::Tet4),
    ("ICC8", ElemType::Cub8),
    ("ICP6", ElemType::Pri6),
];

pub fn geometry_ok(ty: ElemType) -> bool {
    NAMES.iter().any(|(_, t)| *t == ty)
}
