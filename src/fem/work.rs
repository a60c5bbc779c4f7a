//! WORK: the trace of the product of a stress tensor σ with a displacement
//! gradient G at each stress point of a massive element, Tr(σ·G) =
//! Σ_ij σ_ij G_ji. This is the work density the G-theta fracture
//! integrals (G_THETA) assemble; INTG of it gives their terms.
//!
//! Axes: x y z, or r z θ in AXIS (where the gradient names are UR,R UR,Z
//! UR,T UZ,R … UT,T and the stresses SMRR SMZZ SMTT SMRZ).

use super::element::{FemError, Mode};

/// Stress component of the tensor entry (i, j) (symmetric), by axis index.
fn stress_name(mode: Mode, i: usize, j: usize) -> &'static str {
    let (a, b) = if i <= j { (i, j) } else { (j, i) };
    match (mode, a, b) {
        (Mode::Axis, 0, 0) => "SMRR",
        (Mode::Axis, 1, 1) => "SMZZ",
        (Mode::Axis, 2, 2) => "SMTT",
        (Mode::Axis, 0, 1) => "SMRZ",
        // The r-θ and z-θ shears do not exist for axisymmetric loading.
        (Mode::Axis, _, _) => "",
        (_, 0, 0) => "SMXX",
        (_, 1, 1) => "SMYY",
        (_, 2, 2) => "SMZZ",
        (_, 0, 1) => "SMXY",
        (_, 0, 2) => "SMXZ",
        _ => "SMYZ",
    }
}

/// Name of the gradient term ∂u_i/∂x_j as GRAD writes it.
fn gradient_name(mode: Mode, i: usize, j: usize) -> &'static str {
    const XYZ: [[&str; 3]; 3] = [["UX,X", "UX,Y", "UX,Z"], ["UY,X", "UY,Y", "UY,Z"], ["UZ,X", "UZ,Y", "UZ,Z"]];
    const RZT: [[&str; 3]; 3] = [["UR,R", "UR,Z", "UR,T"], ["UZ,R", "UZ,Z", "UZ,T"], ["UT,R", "UT,Z", "UT,T"]];
    if mode == Mode::Axis {
        RZT[i][j]
    } else {
        XYZ[i][j]
    }
}

/// Tr(σ·G) at each point: `sig` and `grad` are `values[point][component]`
/// under the names `sig_comps` and `grad_comps`. Stress components the
/// field lacks are zero (the out-of-plane shears of the plane modes); all
/// nine gradient terms are required, as GRAD gives them.
pub fn stress_gradient_trace(
    mode: Mode,
    elem: &'static str,
    sig_comps: &[String],
    sig: &[Vec<f64>],
    grad_comps: &[String],
    grad: &[Vec<f64>],
) -> Result<Vec<f64>, FemError> {
    if sig.len() != grad.len() {
        return Err(FemError::WrongPointCount { elem, expected: sig.len(), got: grad.len() });
    }
    let first = stress_name(mode, 0, 0);
    if !sig_comps.iter().any(|c| c == first) {
        return Err(FemError::MissingComponent { comp: first, elem });
    }
    // (stress column or None, gradient column) for each of the nine terms.
    let mut terms = Vec::with_capacity(9);
    for i in 0..3 {
        for j in 0..3 {
            let s = stress_name(mode, i, j);
            let s = sig_comps.iter().position(|c| c == s);
            let g = gradient_name(mode, j, i);
            let g = grad_comps.iter().position(|c| c == g).ok_or(FemError::MissingComponent { comp: g, elem })?;
            terms.push((s, g));
        }
    }
    sig.iter()
        .zip(grad)
        .map(|(s, g)| {
            let mut sum = 0.0;
            for (si, gi) in &terms {
                let (Some(si), Some(gv)) = (si, g.get(*gi)) else { continue };
                let sv = s.get(*si).copied().unwrap_or(0.0);
                sum += sv * gv;
            }
            if sum.is_finite() {
                Ok(sum)
            } else {
                Err(FemError::Degenerate { elem, why: "the stress-gradient product is not finite".into() })
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(v: &[&str]) -> Vec<String> {
        v.iter().map(|s| s.to_string()).collect()
    }

    #[test]
    fn plane_trace_pairs_shear_with_both_cross_terms() {
        let sc = names(&["SMXX", "SMYY", "SMZZ", "SMXY"]);
        let gc = names(&["UX,X", "UX,Y", "UX,Z", "UY,X", "UY,Y", "UY,Z", "UZ,X", "UZ,Y", "UZ,Z"]);
        let s = vec![vec![1.0, 2.0, 3.0, 4.0]];
        let g = vec![vec![10.0, 20.0, 0.0, 30.0, 40.0, 0.0, 0.0, 0.0, 5.0]];
        let w = stress_gradient_trace(Mode::PlanDefo, "QUA4", &sc, &s, &gc, &g).unwrap();
        // 1·10 + 2·40 + 3·5 + 4·(20 + 30)
        assert_eq!(w, vec![10.0 + 80.0 + 15.0 + 200.0]);
    }

    #[test]
    fn missing_gradient_term_is_an_error() {
        let sc = names(&["SMRR", "SMZZ", "SMTT", "SMRZ"]);
        let gc = names(&["UR,R"]);
        let err = stress_gradient_trace(Mode::Axis, "QUA4", &sc, &[vec![0.0; 4]], &gc, &[vec![0.0]]).unwrap_err();
        assert!(err.to_string().contains("UZ,R"), "{err}");
    }
}

/// The gradient names of `comps` (UX,X … or UR,R … in AXIS) as a mode, or
/// None when `comps` is not a gradient field.
pub fn gradient_mode(comps: &[String]) -> Option<Mode> {
    if comps.iter().any(|c| c == "UR,R") {
        Some(Mode::Axis)
    } else if comps.iter().any(|c| c == "UX,X") {
        Some(Mode::Trid)
    } else {
        None
    }
}

/// The matrix product A·B of two gradient tensors at each point,
/// (A·B)_ij = Σ_k A_ik B_kj, written under the nine names of GRAD.
pub fn gradient_product(
    mode: Mode,
    elem: &'static str,
    a_comps: &[String],
    a: &[Vec<f64>],
    b_comps: &[String],
    b: &[Vec<f64>],
) -> Result<(Vec<&'static str>, Vec<Vec<f64>>), FemError> {
    if a.len() != b.len() {
        return Err(FemError::WrongPointCount { elem, expected: a.len(), got: b.len() });
    }
    let cols = |comps: &[String]| -> Result<Vec<usize>, FemError> {
        (0..9)
            .map(|k| {
                let n = gradient_name(mode, k / 3, k % 3);
                comps.iter().position(|c| c == n).ok_or(FemError::MissingComponent { comp: n, elem })
            })
            .collect()
    };
    let (ca, cb) = (cols(a_comps)?, cols(b_comps)?);
    let names = (0..9).map(|k| gradient_name(mode, k / 3, k % 3)).collect();
    let values = a
        .iter()
        .zip(b)
        .map(|(pa, pb)| {
            let at = |i: usize, j: usize| pa.get(ca[3 * i + j]).copied().unwrap_or(0.0);
            let bt = |i: usize, j: usize| pb.get(cb[3 * i + j]).copied().unwrap_or(0.0);
            (0..9).map(|k| (0..3).map(|m| at(k / 3, m) * bt(m, k % 3)).sum()).collect()
        })
        .collect();
    Ok((names, values))
}

#[cfg(test)]
mod product_tests {
    use super::*;

    #[test]
    fn product_is_the_matrix_product() {
        let gc: Vec<String> = gradient_name_list(Mode::Trid);
        let a = vec![vec![1.0, 2.0, 0.0, 3.0, 4.0, 0.0, 0.0, 0.0, 1.0]];
        let b = vec![vec![0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 2.0]];
        let (_, p) = gradient_product(Mode::Trid, "QUA4", &gc, &a, &gc, &b).unwrap();
        assert_eq!(p, vec![vec![2.0, 1.0, 0.0, 4.0, 3.0, 0.0, 0.0, 0.0, 2.0]]);
    }

    fn gradient_name_list(mode: Mode) -> Vec<String> {
        (0..9).map(|k| gradient_name(mode, k / 3, k % 3).to_string()).collect()
    }
}
