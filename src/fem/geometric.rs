//! KSIGMA: the geometric (initial stress) stiffness of line elements
//! carrying a normal force.
//!
//! A line element under the normal force N stores the second-order energy
//! ½ ∫ N |d'|² dσ, where d' is the derivative along the element of its
//! transverse displacement (the rotation of its axis). The matrix is
//! therefore K_g = ∫ N B(σ)ᵀ B(σ) dσ with B the 3×ndof map from the
//! element's dofs to d'. The axial part of the displacement is left out:
//! with it, every stretching mode would "buckle" at λ = EA/N, spurious
//! roots below the bending ones. The transverse part is linear for a bar
//! and the cubic Hermite of the bending elements for beams and COQ2, whose
//! nodal slope is θ × t (a rotation θ turns the tangent t by θ × t), so no
//! local frame is needed and the same formula serves 2D and 3D. Only the normal force enters: shear forces and
//! moments add higher-order terms that matter little for buckling and are
//! left out.
//!
//! With N > 0 (tension) K_g stiffens; `K + λ K_g(σ)` loses its positive
//! definiteness at the buckling multiplier λ of a compressive σ.
//!
//! Where N comes from: EFFX at the two ends of bars and beams (interpolated
//! linearly), N11 at COQ2's three Gauss points (times the width DIM3 in
//! PLAN CONT, as COQ2's own matrices).

use super::element::{node_dofs, ElemMatrix, FemError, Formulation, GaussField, Mode};
use super::material::Material;
use super::quadrature::seg;

/// The geometric stiffness of one element under the stresses `sig` (at the
/// element's output points).
pub fn stiffness(
    f: Formulation,
    mode: Mode,
    x: &[[f64; 3]],
    m: &Material,
    sig: &GaussField,
) -> Result<ElemMatrix, FemError> {
    let elem = f.name();
    let (force_comp, cubic) = match f {
        Formulation::Barr => ("EFFX", false),
        Formulation::Pout | Formulation::Timo => ("EFFX", true),
        Formulation::Coq2 if mode != Mode::Axis => ("N11", true),
        _ => return Err(FemError::NotFor { what: "KSIGMA", form: elem }),
    };
    if x.len() != 2 {
        return Err(FemError::WrongNodeCount { elem: "SEG2", expected: 2, got: x.len() });
    }
    let names = node_dofs(f, mode)?;
    let mut d = [x[1][0] - x[0][0], x[1][1] - x[0][1], x[1][2] - x[0][2]];
    if mode != Mode::Trid {
        d[2] = 0.0;
    }
    let l = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    if l <= 0.0 || !l.is_finite() {
        return Err(FemError::Degenerate { elem, why: "zero length".into() });
    }
    let t = [d[0] / l, d[1] / l, d[2] / l];
    let get = |k: usize| sig.get(force_comp, k).ok_or(FemError::MissingComponent { comp: force_comp, elem });
    // N at ξ ∈ [−1, 1].
    let rule = seg(3);
    let n_at: Vec<f64> = if f == Formulation::Coq2 {
        if sig.values.len() != rule.len() {
            return Err(FemError::WrongPointCount { elem, expected: rule.len(), got: sig.values.len() });
        }
        let width = if mode == Mode::PlanCont { m.dim3.unwrap_or(1.0) } else { 1.0 };
        (0..rule.len()).map(|k| get(k).map(|v| v * width)).collect::<Result<_, _>>()?
    } else {
        if sig.values.len() != 2 {
            return Err(FemError::WrongPointCount { elem, expected: 2, got: sig.values.len() });
        }
        let (n1, n2) = (get(0)?, get(1)?);
        rule.iter().map(|(p, _)| 0.5 * (1.0 - p[0]) * n1 + 0.5 * (1.0 + p[0]) * n2).collect()
    };
    let nd = names.len();
    let ndof = 2 * nd;
    let mut k = vec![0.0; ndof * ndof];
    for ((p, wq), n) in rule.iter().zip(&n_at) {
        let b = derivative_rows(names, &t, l, p[0], cubic);
        let w = wq * l / 2.0 * n;
        for i in 0..ndof {
            for j in 0..ndof {
                k[i * ndof + j] += w * (0..3).map(|c| b[c][i] * b[c][j]).sum::<f64>();
            }
        }
    }
    if k.iter().any(|v| !v.is_finite()) {
        return Err(FemError::Degenerate { elem, why: "non-finite normal force".into() });
    }
    let dofs = (0..2).flat_map(|a| names.iter().map(move |&c| (a, c))).collect();
    Ok(ElemMatrix { dofs, k })
}

/// The 3 rows of d'(ξ) (global components) over the element dofs.
fn derivative_rows(names: &[&str], t: &[f64; 3], l: f64, xi: f64, cubic: bool) -> [Vec<f64>; 3] {
    let nd = names.len();
    let mut b = [vec![0.0; 2 * nd], vec![0.0; 2 * nd], vec![0.0; 2 * nd]];
    let dn = [-1.0 / l, 1.0 / l];
    // Derivatives of the Hermite functions (the slope ones in length units).
    let (_, dh, _) = super::coq2::hermite(l, xi);
    for a in 0..2 {
        for (ci, name) in names.iter().enumerate() {
            let col = a * nd + ci;
            match translation(name) {
                Some(c) => {
                    // The transverse part P⊥ e_c.
                    let wt = if cubic { dh[2 * a] } else { dn[a] };
                    for r in 0..3 {
                        b[r][col] += wt * (f64::from(u8::from(r == c)) - t[r] * t[c]);
                    }
                }
                None => {
                    if let (Some(c), true) = (rotation(name), cubic) {
                        // Slope θ × t for a unit rotation about axis c.
                        let mut e = [0.0; 3];
                        e[c] = 1.0;
                        let s = [e[1] * t[2] - e[2] * t[1], e[2] * t[0] - e[0] * t[2], e[0] * t[1] - e[1] * t[0]];
                        for r in 0..3 {
                            b[r][col] += dh[2 * a + 1] * s[r];
                        }
                    }
                }
            }
        }
    }
    b
}

fn translation(name: &str) -> Option<usize> {
    match name {
        "UX" => Some(0),
        "UY" => Some(1),
        "UZ" => Some(2),
        _ => None,
    }
}

fn rotation(name: &str) -> Option<usize> {
    match name {
        "RX" => Some(0),
        "RY" => Some(1),
        "RZ" => Some(2),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A pinned–pinned beam of one element under N: the classical
    /// consistent geometric matrix N/(30L)·[36 3L; 3L 4L²] on (w, θ).
    #[test]
    fn beam_matches_the_classical_matrix() {
        let m = Material::default();
        let sig = GaussField { comps: vec!["EFFX", "EFFY", "MOMZ"], values: vec![vec![-3.0, 0.0, 0.0]; 2] };
        let x = [[0.0, 0.0, 0.0], [2.0, 0.0, 0.0]];
        let k = stiffness(Formulation::Pout, Mode::PlanCont, &x, &m, &sig).unwrap();
        let (n, l) = (-3.0, 2.0);
        // Row UY1 (index 1): UY1, RZ1, UY2, RZ2.
        let row = |i: usize, j: usize| k.k[i * 6 + j];
        assert!((row(1, 1) - n * 36.0 / (30.0 * l)).abs() < 1e-12);
        assert!((row(1, 2) - n * 3.0 * l / (30.0 * l)).abs() < 1e-12);
        assert!((row(2, 2) - n * 4.0 * l * l / (30.0 * l)).abs() < 1e-12);
        assert!((row(2, 5) + n * l * l / (30.0 * l)).abs() < 1e-12);
        assert_eq!(row(0, 0), 0.0);
    }
}
