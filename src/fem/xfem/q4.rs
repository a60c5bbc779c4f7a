//! XQ4R: the QUA4 of the plane modes enriched by the crack (see the module
//! above). Element dofs are node-major: UX UY, then the node's enriched
//! unknowns ([`super::kind_dofs`]). An element without enriched node is the
//! classical QUA4 with its 2×2 Gauss rule; an enriched one is integrated
//! by sub-cells ([`super::subcell`]). Strains and stresses are given at the
//! 2×2 Gauss points of every element, so the fields of an X-FEM zone have
//! the layout of a QUA4 zone.

use super::functions::{tip, Fun};
use super::{kind_dofs, subcell, NodeKind};
use crate::fem::element::{ElemMatrix, FemError, Formulation, GaussField, Mode};
use crate::fem::material::{elasticity, Material};
use crate::fem::mesh::ElemType;
use crate::fem::shape::eval;
use crate::fem::solid::{self, Point};

/// One enriched element: its corners, the level sets there and the
/// enrichment of each corner.
pub struct XElem<'a> {
    pub x: &'a [[f64; 3]],
    pub psi: &'a [f64],
    pub phi: &'a [f64],
    pub kinds: &'a [Option<NodeKind>],
}

/// What [`field`] gives at the points.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Field {
    Strain,
    Stress,
    Gradient,
}

const NAME: &str = "XQ4R";

fn check(mode: Mode, e: &XElem) -> Result<(), FemError> {
    if !matches!(mode, Mode::PlanCont | Mode::PlanDefo) {
        return Err(FemError::Unsupported { form: NAME, elem: "QUA4", mode: mode.name() });
    }
    for n in [e.x.len(), e.psi.len(), e.phi.len(), e.kinds.len()] {
        if n != 4 {
            return Err(FemError::WrongNodeCount { elem: NAME, expected: 4, got: n });
        }
    }
    Ok(())
}

/// The element's dofs.
pub fn dofs(kinds: &[Option<NodeKind>]) -> Vec<(usize, &'static str)> {
    let mut out = Vec::new();
    for (i, k) in kinds.iter().enumerate() {
        out.push((i, "UX"));
        out.push((i, "UY"));
        if let Some(k) = k {
            out.extend(kind_dofs(*k, 2).iter().map(|d| (i, *d)));
        }
    }
    out
}

/// Every dof's displacement field at a point: (component, value, gradient).
fn basis(e: &XElem, p: &Point, side: f64) -> Vec<(usize, f64, [f64; 3])> {
    let lv = |v: &[f64]| -> (f64, [f64; 3]) {
        let mut g = [0.0; 3];
        for (d, vi) in p.dndx.iter().zip(v) {
            for c in 0..3 {
                g[c] += d[c] * vi;
            }
        }
        (p.n.iter().zip(v).map(|(a, b)| a * b).sum(), g)
    };
    let tips: Option<[Fun; 4]> = e.kinds.contains(&Some(NodeKind::Tip)).then(|| {
        let ((s, gs), (f, gf)) = (lv(e.psi), lv(e.phi));
        tip(s, f, gs, gf, side)
    });
    let mut out = Vec::with_capacity(40);
    for i in 0..4 {
        let (n, d) = (p.n[i], p.dndx[i]);
        let mut push = |v: f64, g: [f64; 3]| {
            out.push((0, v, g));
            out.push((1, v, g));
        };
        push(n, d);
        match e.kinds[i] {
            Some(NodeKind::Jump) => push(n * side, [d[0] * side, d[1] * side, 0.0]),
            Some(NodeKind::Tip) => {
                for f in tips.iter().flatten() {
                    push(n * f.v, [d[0] * f.v + n * f.g[0], d[1] * f.v + n * f.g[1], 0.0]);
                }
            }
            None => {}
        }
    }
    out
}

/// Strain rows [xx, yy, zz, xy] over the dofs.
fn bmat(basis: &[(usize, f64, [f64; 3])]) -> [Vec<f64>; 4] {
    let nd = basis.len();
    let mut b = [vec![0.0; nd], vec![0.0; nd], vec![0.0; nd], vec![0.0; nd]];
    for (j, (c, _, g)) in basis.iter().enumerate() {
        if *c == 0 {
            b[0][j] = g[0];
            b[3][j] = g[1];
        } else {
            b[1][j] = g[1];
            b[3][j] = g[0];
        }
    }
    b
}

fn phi_at(e: &XElem, p: &Point) -> f64 {
    p.n.iter().zip(e.phi).map(|(a, b)| a * b).sum()
}

fn side_of(f: f64) -> f64 {
    if f < 0.0 {
        -1.0
    } else {
        1.0
    }
}

/// The 2×2 Gauss points, each with its side of the crack.
fn gauss(mode: Mode, e: &XElem, t: f64) -> Result<Vec<(Point, f64)>, FemError> {
    let pts = solid::points(ElemType::Qua4, mode, e.x, &solid::rule(Formulation::Solid, ElemType::Qua4), t)?;
    Ok(pts.into_iter().map(|p| (side_of(phi_at(e, &p)), p)).map(|(s, p)| (p, s)).collect())
}

/// The integration points of the stiffness.
fn integration(mode: Mode, e: &XElem, t: f64) -> Result<Vec<(Point, f64)>, FemError> {
    if e.kinds.iter().all(|k| k.is_none()) {
        return gauss(mode, e, t);
    }
    let sp = if !e.kinds.contains(&Some(NodeKind::Tip)) {
        subcell::quad_rule(e.phi, 0)
    } else if let Some(t) = tip_point(e) {
        subcell::tip_rule(e.phi, t, 2)
    } else {
        // Tip functions away from the tip: smooth, but not polynomials.
        subcell::quad_rule(e.phi, 2)
    };
    let rule: Vec<_> = sp.iter().map(|(q, _)| *q).collect();
    let pts = solid::points(ElemType::Qua4, mode, e.x, &rule, t)?;
    Ok(pts.into_iter().zip(sp.iter().map(|(_, s)| *s)).collect())
}

/// The reference coordinates of the tip (PSI = PHI = 0) when the element
/// holds it, by Newton's method on the bilinear level sets.
fn tip_point(e: &XElem) -> Option<[f64; 2]> {
    let mut p = [0.0, 0.0];
    for _ in 0..50 {
        let s = eval(ElemType::Qua4, [p[0], p[1], 0.0]);
        let val = |v: &[f64]| s.n.iter().zip(v).map(|(a, b)| a * b).sum::<f64>();
        let der = |v: &[f64], k: usize| s.dn.iter().zip(v).map(|(d, b)| d[k] * b).sum::<f64>();
        let (f, g) = (val(e.psi), val(e.phi));
        let j = [[der(e.psi, 0), der(e.psi, 1)], [der(e.phi, 0), der(e.phi, 1)]];
        let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        let d = [(j[1][1] * f - j[0][1] * g) / det, (j[0][0] * g - j[1][0] * f) / det];
        p = [p[0] - d[0], p[1] - d[1]];
        if p.iter().any(|v| v.abs() > 10.0) {
            return None;
        }
        if d[0].abs() + d[1].abs() < 1e-13 {
            let inside = p.iter().all(|v| v.abs() <= 1.0 + 1e-9);
            return inside.then(|| [p[0].clamp(-1.0, 1.0), p[1].clamp(-1.0, 1.0)]);
        }
    }
    None
}

pub fn stiffness(mode: Mode, e: &XElem, m: &Material) -> Result<ElemMatrix, FemError> {
    check(mode, e)?;
    let d = elasticity(mode, m, NAME)?;
    let t = m.thickness(mode, NAME)?;
    let dofs = dofs(e.kinds);
    let nd = dofs.len();
    let mut k = vec![0.0; nd * nd];
    for (p, side) in integration(mode, e, t)? {
        let b = bmat(&basis(e, &p, side));
        let db: Vec<Vec<f64>> = d
            .iter()
            .map(|row| (0..nd).map(|j| row.iter().zip(&b).map(|(dv, br)| dv * br[j]).sum()).collect())
            .collect();
        for q in 0..4 {
            for r in 0..nd {
                let br = b[q][r] * p.w;
                if br != 0.0 {
                    for c in 0..nd {
                        k[r * nd + c] += br * db[q][c];
                    }
                }
            }
        }
    }
    Ok(ElemMatrix { dofs, k })
}

fn check_u(e: &XElem, u: &[f64]) -> Result<(), FemError> {
    let nd = dofs(e.kinds).len();
    if u.len() != nd {
        return Err(FemError::WrongDofCount { elem: NAME, expected: nd, got: u.len() });
    }
    Ok(())
}

/// Strains, stresses or displacement gradients at the 2×2 Gauss points.
pub fn field(mode: Mode, e: &XElem, m: &Material, u: &[f64], what: Field) -> Result<GaussField, FemError> {
    check(mode, e)?;
    check_u(e, u)?;
    let d = if what == Field::Stress { Some(elasticity(mode, m, NAME)?) } else { None };
    let mut values = Vec::with_capacity(4);
    for (p, side) in gauss(mode, e, 1.0)? {
        let bs = basis(e, &p, side);
        if what == Field::Gradient {
            let mut g = [[0.0; 2]; 2];
            for ((c, _, gr), ui) in bs.iter().zip(u) {
                g[*c][0] += gr[0] * ui;
                g[*c][1] += gr[1] * ui;
            }
            values.push(vec![g[0][0], g[0][1], 0.0, g[1][0], g[1][1], 0.0, 0.0, 0.0, 0.0]);
            continue;
        }
        let b = bmat(&bs);
        let mut eps: Vec<f64> = b.iter().map(|row| row.iter().zip(u).map(|(a, b)| a * b).sum()).collect();
        if mode == Mode::PlanCont && what == Field::Strain && m.nu.is_some() {
            let nu = m.poisson_plane_stress(NAME)?;
            eps[2] = -nu / (1.0 - nu) * (eps[0] + eps[1]);
        }
        values.push(match &d {
            Some(d) => d.iter().map(|row| row.iter().zip(&eps).map(|(a, b)| a * b).sum()).collect(),
            None => eps,
        });
    }
    let comps = match what {
        Field::Stress => solid::stress_comps(mode),
        Field::Strain => solid::strain_comps(mode),
        Field::Gradient => solid::gradient_comps(mode),
    };
    Ok(GaussField { comps, values })
}

/// Nodal forces Σ Bᵀ σ w of stresses given at the 2×2 Gauss points (BSIG).
pub fn internal_forces(mode: Mode, e: &XElem, m: &Material, sig: &GaussField) -> Result<Vec<f64>, FemError> {
    check(mode, e)?;
    let t = m.thickness(mode, NAME)?;
    let pts = gauss(mode, e, t)?;
    if sig.values.len() != pts.len() {
        return Err(FemError::WrongPointCount { elem: NAME, expected: pts.len(), got: sig.values.len() });
    }
    let comps = solid::stress_comps(mode);
    let idx: Vec<usize> = comps
        .iter()
        .map(|c| sig.comps.iter().position(|s| s == c).ok_or(FemError::MissingComponent { comp: c, elem: NAME }))
        .collect::<Result<_, _>>()?;
    let mut f = vec![0.0; dofs(e.kinds).len()];
    for ((p, side), s) in pts.iter().zip(&sig.values) {
        let b = bmat(&basis(e, p, *side));
        for (q, &i) in idx.iter().enumerate() {
            for (fj, bj) in f.iter_mut().zip(&b[q]) {
                *fj += bj * s[i] * p.w;
            }
        }
    }
    Ok(f)
}

/// The displacement at reference point `xi`, on side `side` of the crack
/// (by the sign of PHI there when None).
pub fn displacement(e: &XElem, xi: [f64; 3], u: &[f64], side: Option<f64>) -> Result<[f64; 2], FemError> {
    check(Mode::PlanDefo, e)?;
    check_u(e, u)?;
    let p = solid::points(ElemType::Qua4, Mode::PlanDefo, e.x, &[(xi, 1.0)], 1.0)?.remove(0);
    let side = side.unwrap_or_else(|| side_of(phi_at(e, &p)));
    let mut out = [0.0; 2];
    for ((c, v, _), ui) in basis(e, &p, side).iter().zip(u) {
        out[*c] += v * ui;
    }
    Ok(out)
}
