//! Generalised plane strain (OPTI MODE PLAN GENE, MODE … 'DPGE' P): the
//! massive plane elements with an out-of-plane strain that is no longer 0
//! but an affine function of the section's point,
//!
//!   εzz(x, y) = UZ + RX·(y − yP) − RY·(x − xP),
//!
//! whose three unknowns UZ RX RY live on one extra point P shared by the
//! whole model (a long prism whose sections stay plane). Their duals are
//! the axial force FZ and the bending moments MX = ∫σzz (y − yP) and
//! MY = −∫σzz (x − xP): a force and moments on P load the prism as a
//! beam. Elements see their nodes then P, the element dofs being the
//! nodes' UX UY followed by P's UZ RX RY; the rest is the plane-strain
//! element (same points, same elasticity matrix with its zz row).

use super::element::{ElemMatrix, FemError, Formulation, GaussField, Mode};
use super::material::{elasticity, Material};
use super::mesh::ElemType;
use super::solid::{bmat, points, rule, strain_comps, stress_comps, Point};

pub const DOFS: &[&str] = &["UX", "UY"];
pub const POINT_DOFS: &[&str] = &["UZ", "RX", "RY"];
const MODE: Mode = Mode::PlanDefo;

pub fn dofs(mode: Mode) -> Result<&'static [&'static str], FemError> {
    match mode {
        Mode::PlanDefo => Ok(DOFS),
        _ => Err(FemError::Unsupported { form: "DPGE", elem: "plane", mode: mode.name() }),
    }
}

pub fn accepts(ty: ElemType, mode: Mode) -> bool {
    mode == MODE && ty.dim() == 2 && !rule(Formulation::Solid, ty).is_empty()
}

fn dof_list(ty: ElemType) -> Vec<(usize, &'static str)> {
    let nn = ty.nodes();
    (0..nn).flat_map(|i| DOFS.iter().map(move |&d| (i, d))).chain(POINT_DOFS.iter().map(|&d| (nn, d))).collect()
}

/// An integration point and its strain rows over the element dofs.
type PointRows = (Point, Vec<Vec<f64>>);

/// Integration points and the strain rows (EPXX EPYY EPZZ GAXY) over the
/// element dofs; `x` holds the nodes then P.
fn strain_rows(ty: ElemType, x: &[[f64; 3]]) -> Result<Vec<PointRows>, FemError> {
    let nn = ty.nodes();
    if x.len() != nn + 1 {
        return Err(FemError::WrongNodeCount { elem: ty.name(), expected: nn + 1, got: x.len() });
    }
    let p0 = x[nn];
    let pts = points(ty, MODE, &x[..nn], &rule(Formulation::Solid, ty), 1.0)?;
    Ok(pts
        .into_iter()
        .map(|p| {
            let (mut xp, mut yp) = (0.0, 0.0);
            for (n, c) in p.n.iter().zip(x) {
                xp += n * c[0];
                yp += n * c[1];
            }
            let rows = bmat(MODE, &p)
                .into_iter()
                .enumerate()
                .map(|(q, mut row)| {
                    row.extend(if q == 2 { [1.0, yp - p0[1], -(xp - p0[0])] } else { [0.0; 3] });
                    row
                })
                .collect();
            (p, rows)
        })
        .collect())
}

pub fn stiffness(ty: ElemType, x: &[[f64; 3]], m: &Material) -> Result<ElemMatrix, FemError> {
    let d = elasticity(MODE, m, ty.name())?;
    let dofs = dof_list(ty);
    let nd = dofs.len();
    let mut k = vec![0.0; nd * nd];
    for (p, b) in strain_rows(ty, x)? {
        let db: Vec<Vec<f64>> = d
            .iter()
            .map(|drow| (0..nd).map(|j| drow.iter().zip(&b).map(|(dv, br)| dv * br[j]).sum()).collect())
            .collect();
        for (brow, dbrow) in b.iter().zip(&db) {
            for i in 0..nd {
                if brow[i] != 0.0 {
                    for j in 0..nd {
                        k[i * nd + j] += brow[i] * dbrow[j] * p.w;
                    }
                }
            }
        }
    }
    Ok(ElemMatrix { dofs, k })
}

/// Strains (`stress = false`) or stresses at the integration points.
pub fn field(ty: ElemType, x: &[[f64; 3]], m: &Material, u: &[f64], stress: bool) -> Result<GaussField, FemError> {
    let nd = dof_list(ty).len();
    if u.len() != nd {
        return Err(FemError::WrongDofCount { elem: ty.name(), expected: nd, got: u.len() });
    }
    let d = if stress { Some(elasticity(MODE, m, ty.name())?) } else { None };
    let values = strain_rows(ty, x)?
        .into_iter()
        .map(|(_, b)| {
            let eps: Vec<f64> = b.iter().map(|row| row.iter().zip(u).map(|(a, v)| a * v).sum()).collect();
            match &d {
                Some(d) => d.iter().map(|row| row.iter().zip(&eps).map(|(a, e)| a * e).sum()).collect(),
                None => eps,
            }
        })
        .collect();
    let comps = if stress { stress_comps(MODE) } else { strain_comps(MODE) };
    Ok(GaussField { comps, values })
}

/// Nodal forces of a stress field (BSIG): Σ Bᵀ σ w, P's FZ MX MY last.
pub fn internal_forces(ty: ElemType, x: &[[f64; 3]], sig: &GaussField) -> Result<Vec<f64>, FemError> {
    let rows = strain_rows(ty, x)?;
    if sig.values.len() != rows.len() {
        return Err(FemError::WrongPointCount { elem: ty.name(), expected: rows.len(), got: sig.values.len() });
    }
    let comps = stress_comps(MODE);
    let mut out = vec![0.0; dof_list(ty).len()];
    for (k, (p, b)) in rows.iter().enumerate() {
        for (row, c) in b.iter().zip(&comps) {
            let s = sig.get(c, k).ok_or(FemError::MissingComponent { comp: c, elem: ty.name() })?;
            for (o, bv) in out.iter_mut().zip(row) {
                *o += bv * s * p.w;
            }
        }
    }
    Ok(out)
}
