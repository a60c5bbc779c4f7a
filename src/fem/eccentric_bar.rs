//! BAEX: a bar (BARR) whose axis is offset from its two nodes, in TRID.
//!
//! The bar's fibre runs parallel to the segment between the nodes, at the
//! offset e = EXCY·ey + EXCZ·ez, ey being the local y axis given by the
//! material (VX VY VZ, or VECT) made normal to the element and ez = ex × ey.
//! Each node carries UX UY UZ RX RY RZ and is tied to its fibre end by a
//! rigid arm: the fibre end moves by u + θ × e. The element is then the
//! plain bar on the fibre ends, transformed: K = Tᵀ K_bar T with
//! T = [I, −[e]×] per node. The fibre's axial strain EPSS and normal force
//! EFFX are the bar's; the nodes receive its forces and their moments
//! e × F, which is what makes the element useful (a stiffener off a
//! shell's mid-surface).

use super::bar;
use super::element::{ElemMatrix, FemError, GaussField, Mode};
use super::material::Material;
use super::vec3::{cross, dot, sub};

pub const DOFS: &[&str] = &["UX", "UY", "UZ", "RX", "RY", "RZ"];

pub fn dofs(mode: Mode) -> Result<&'static [&'static str], FemError> {
    match mode {
        Mode::Trid => Ok(DOFS),
        _ => Err(FemError::Unsupported { form: "BAEX", elem: "SEG2", mode: mode.name() }),
    }
}

/// The offset of the fibre from the nodes, in global axes.
fn offset(x: &[[f64; 3]], m: &Material) -> Result<[f64; 3], FemError> {
    if x.len() != 2 {
        return Err(FemError::WrongNodeCount { elem: "SEG2", expected: 2, got: x.len() });
    }
    let d = sub(x[1], x[0]);
    let l = dot(d, d).sqrt();
    if l == 0.0 || !l.is_finite() {
        return Err(FemError::Degenerate { elem: "BAEX", why: "zero-length element (both ends coincide)".into() });
    }
    let ex = [d[0] / l, d[1] / l, d[2] / l];
    let (ey_c, ez_c) = (m.excy.unwrap_or(0.0), m.excz.unwrap_or(0.0));
    if !ey_c.is_finite() || !ez_c.is_finite() {
        return Err(FemError::InvalidProperty {
            prop: "EXCY",
            value: ey_c + ez_c,
            elem: "BAEX",
            why: "must be finite",
        });
    }
    if ey_c == 0.0 && ez_c == 0.0 {
        return Ok([0.0; 3]);
    }
    let v = m.vect.ok_or(FemError::MissingProperty { prop: "VECT", elem: "BAEX" })?;
    let p = dot(v, ex);
    let y = [v[0] - p * ex[0], v[1] - p * ex[1], v[2] - p * ex[2]];
    let ny = dot(y, y).sqrt();
    if ny <= 1e-8 * dot(v, v).sqrt() || !ny.is_finite() {
        return Err(FemError::Degenerate {
            elem: "BAEX",
            why: "the local y vector (VX VY VZ) is parallel to the element axis".into(),
        });
    }
    let ey = [y[0] / ny, y[1] / ny, y[2] / ny];
    let ez = cross(ex, ey);
    Ok([0, 1, 2].map(|i| ey_c * ey[i] + ez_c * ez[i]))
}

/// Fibre ends and the 6×12 map from the node dofs to the fibre ends'
/// translations (row-major).
fn transform(x: &[[f64; 3]], m: &Material) -> Result<(Vec<[f64; 3]>, Vec<f64>), FemError> {
    let e = offset(x, m)?;
    let ends = x.iter().map(|p| [p[0] + e[0], p[1] + e[1], p[2] + e[2]]).collect();
    let mut t = vec![0.0; 6 * 12];
    for node in 0..2 {
        for i in 0..3 {
            let row = (3 * node + i) * 12 + 6 * node;
            t[row + i] = 1.0;
            // (θ × e)_i = Σ_j θ_j (e_j × … ): the i-th row of −[e]×.
            let unit = |j: usize| {
                let mut th = [0.0; 3];
                th[j] = 1.0;
                cross(th, e)[i]
            };
            for j in 0..3 {
                t[row + 3 + j] = unit(j);
            }
        }
    }
    Ok((ends, t))
}

/// Tᵀ A T for the 6×6 bar matrix A.
fn congruence(a: &[f64], t: &[f64]) -> Vec<f64> {
    let mut out = vec![0.0; 144];
    for p in 0..12 {
        for q in 0..12 {
            let mut s = 0.0;
            for i in 0..6 {
                for j in 0..6 {
                    s += t[i * 12 + p] * a[i * 6 + j] * t[j * 12 + q];
                }
            }
            out[p * 12 + q] = s;
        }
    }
    out
}

fn dof_list() -> Vec<(usize, &'static str)> {
    (0..2).flat_map(|i| DOFS.iter().map(move |&d| (i, d))).collect()
}

pub fn stiffness(mode: Mode, x: &[[f64; 3]], m: &Material) -> Result<ElemMatrix, FemError> {
    dofs(mode)?;
    let (ends, t) = transform(x, m)?;
    let k = bar::stiffness(mode, &ends, m)?;
    Ok(ElemMatrix { dofs: dof_list(), k: congruence(&k.k, &t) })
}

/// The bar's mass carried by the fibre, seen from the nodes through the
/// rigid arms.
pub fn mass(mode: Mode, x: &[[f64; 3]], m: &Material, lumped: bool) -> Result<ElemMatrix, FemError> {
    dofs(mode)?;
    let (ends, t) = transform(x, m)?;
    let k = bar::mass(mode, &ends, m, lumped)?;
    Ok(ElemMatrix { dofs: dof_list(), k: congruence(&k.k, &t) })
}

/// The fibre ends' translations of the element dofs `u`.
fn fibre_dofs(x: &[[f64; 3]], m: &Material, u: &[f64]) -> Result<(Vec<[f64; 3]>, Vec<f64>), FemError> {
    if u.len() != 12 {
        return Err(FemError::WrongDofCount { elem: "BAEX", expected: 12, got: u.len() });
    }
    let (ends, t) = transform(x, m)?;
    let v = (0..6).map(|i| (0..12).map(|j| t[i * 12 + j] * u[j]).sum()).collect();
    Ok((ends, v))
}

pub fn strain(mode: Mode, x: &[[f64; 3]], m: &Material, u: &[f64]) -> Result<GaussField, FemError> {
    dofs(mode)?;
    let (ends, v) = fibre_dofs(x, m, u)?;
    bar::strain(mode, &ends, &v)
}

pub fn stress(mode: Mode, x: &[[f64; 3]], m: &Material, u: &[f64]) -> Result<GaussField, FemError> {
    dofs(mode)?;
    let (ends, v) = fibre_dofs(x, m, u)?;
    bar::stress(mode, &ends, m, &v)
}

/// Tᵀ of the bar's nodal forces: the forces and their moments about the
/// nodes.
pub fn internal_forces(mode: Mode, x: &[[f64; 3]], m: &Material, sig: &GaussField) -> Result<Vec<f64>, FemError> {
    dofs(mode)?;
    let (ends, t) = transform(x, m)?;
    let f = bar::internal_forces(mode, &ends, sig)?;
    Ok((0..12).map(|q| (0..6).map(|i| t[i * 12 + q] * f[i]).sum()).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn mat() -> Material {
        Material {
            youn: Some(2.0),
            nu: Some(0.3),
            sect: Some(3.0),
            excy: Some(0.1),
            excz: Some(0.4),
            vect: Some([1.0, 0.0, 0.0]),
            ..Default::default()
        }
    }

    /// A rotation about the node axis moves the fibre axially by θ × e:
    /// with ex = z, ey = x, ez = y, the fibre sits at (0.1, 0.4, 0) and a
    /// rotation RX = θ at the far end stretches it by 0.4 θ.
    #[test]
    fn rotation_stretches_the_offset_fibre() {
        let x = [[0.0; 3], [0.0, 0.0, 2.0]];
        let mut u = [0.0; 12];
        u[9] = 0.01;
        let s = stress(Mode::Trid, &x, &mat(), &u).unwrap();
        let n = 2.0 * 3.0 * 0.4 * 0.01 / 2.0;
        assert!((s.get("EFFX", 0).unwrap() - n).abs() < 1e-14);
        let k = stiffness(Mode::Trid, &x, &mat()).unwrap();
        let f: Vec<f64> = (0..12).map(|i| (0..12).map(|j| k.k[i * 12 + j] * u[j]).sum()).collect();
        // The first node receives −N along z at the fibre: moment e × F.
        assert!((f[2] + n).abs() < 1e-14);
        assert!((f[3] - (-n * 0.4)).abs() < 1e-14 && (f[4] - n * 0.1).abs() < 1e-14);
    }
}
