//! BARR: two-node truss element, axial stiffness EA/L in any orientation.
//! Dofs UX UY in the plane modes, UX UY UZ in TRID (AXIS is not a bar
//! mode in Cast3M). Output (EFFX, EPSS) is given at both ends, equal.

use super::element::{ElemMatrix, FemError, GaussField, Mode};
use super::material::Material;

pub fn dofs(mode: Mode) -> Result<&'static [&'static str], FemError> {
    match mode {
        Mode::PlanCont | Mode::PlanDefo => Ok(&["UX", "UY"]),
        Mode::Trid => Ok(&["UX", "UY", "UZ"]),
        Mode::Axis | Mode::Fourier(_) => Err(FemError::Unsupported { form: "BARR", elem: "SEG2", mode: mode.name() }),
    }
}

/// Unit axis and length.
fn axis(mode: Mode, x: &[[f64; 3]]) -> Result<(usize, [f64; 3], f64), FemError> {
    let nc = dofs(mode)?.len();
    if x.len() != 2 {
        return Err(FemError::WrongNodeCount { elem: "SEG2", expected: 2, got: x.len() });
    }
    let mut d = [0.0; 3];
    for (c, dc) in d.iter_mut().enumerate().take(nc) {
        *dc = x[1][c] - x[0][c];
    }
    let l = d.iter().map(|v| v * v).sum::<f64>().sqrt();
    let scale = x.iter().flatten().fold(0.0f64, |a, v| a.max(v.abs()));
    if l <= 1e-12 * scale.max(f64::MIN_POSITIVE) || !l.is_finite() {
        return Err(FemError::Degenerate { elem: "BARR", why: "zero-length element (both ends coincide)".into() });
    }
    Ok((nc, [d[0] / l, d[1] / l, d[2] / l], l))
}

fn dof_list(names: &'static [&'static str]) -> Vec<(usize, &'static str)> {
    (0..2).flat_map(|i| names.iter().map(move |&d| (i, d))).collect()
}

pub fn stiffness(mode: Mode, x: &[[f64; 3]], m: &Material) -> Result<ElemMatrix, FemError> {
    let (nc, e, l) = axis(mode, x)?;
    let ea = m.young("BARR")? * m.positive(m.sect, "SECT", "BARR")?;
    let n = 2 * nc;
    let mut k = vec![0.0; n * n];
    for a in 0..2 {
        for b in 0..2 {
            let s = if a == b { ea / l } else { -ea / l };
            for i in 0..nc {
                for j in 0..nc {
                    k[(a * nc + i) * n + b * nc + j] = s * e[i] * e[j];
                }
            }
        }
    }
    Ok(ElemMatrix { dofs: dof_list(dofs(mode)?), k })
}

/// Consistent ρAL/6·[2 1; 1 2] per direction (the bar moves as a rigid
/// body transversally too), or lumped ρAL/2.
pub fn mass(mode: Mode, x: &[[f64; 3]], m: &Material, lumped: bool) -> Result<ElemMatrix, FemError> {
    let (nc, _, l) = axis(mode, x)?;
    let mt = m.density("BARR")? * m.positive(m.sect, "SECT", "BARR")? * l;
    let (d, o) = if lumped { (mt / 2.0, 0.0) } else { (mt / 3.0, mt / 6.0) };
    let n = 2 * nc;
    let mut k = vec![0.0; n * n];
    for a in 0..2 {
        for b in 0..2 {
            for i in 0..nc {
                k[(a * nc + i) * n + b * nc + i] = if a == b { d } else { o };
            }
        }
    }
    Ok(ElemMatrix { dofs: dof_list(dofs(mode)?), k })
}

/// Axial strain at both ends.
fn epss(mode: Mode, x: &[[f64; 3]], u: &[f64]) -> Result<f64, FemError> {
    let (nc, e, l) = axis(mode, x)?;
    if u.len() != 2 * nc {
        return Err(FemError::WrongDofCount { elem: "BARR", expected: 2 * nc, got: u.len() });
    }
    Ok((0..nc).map(|i| (u[nc + i] - u[i]) * e[i]).sum::<f64>() / l)
}

pub fn strain(mode: Mode, x: &[[f64; 3]], u: &[f64]) -> Result<GaussField, FemError> {
    let eps = epss(mode, x, u)?;
    Ok(GaussField { comps: vec!["EPSS"], values: vec![vec![eps]; 2] })
}

pub fn stress(mode: Mode, x: &[[f64; 3]], m: &Material, u: &[f64]) -> Result<GaussField, FemError> {
    let ea = m.young("BARR")? * m.positive(m.sect, "SECT", "BARR")?;
    let n = ea * epss(mode, x, u)?;
    Ok(GaussField { comps: vec!["EFFX"], values: vec![vec![n]; 2] })
}

/// Nodal forces of the normal force EFFX: `-N e` and `+N e`, N being the
/// mean of the two points' values. The strain-displacement row of a bar
/// is constant along it, so ∫Bᵀσ weighs both points alike (L/2 each): a
/// field set at one point only (MANU 'CHAM') loads both ends equally, in
/// equilibrium, as Cast3M's BSIG does.
pub fn internal_forces(mode: Mode, x: &[[f64; 3]], sig: &GaussField) -> Result<Vec<f64>, FemError> {
    let (nc, e, _) = axis(mode, x)?;
    if sig.values.len() != 2 {
        return Err(FemError::WrongPointCount { elem: "BARR", expected: 2, got: sig.values.len() });
    }
    let n = |k: usize| sig.get("EFFX", k).ok_or(FemError::MissingComponent { comp: "EFFX", elem: "BARR" });
    let mean = 0.5 * (n(0)? + n(1)?);
    Ok((0..nc).map(|i| -mean * e[i]).chain((0..nc).map(|i| mean * e[i])).collect())
}
