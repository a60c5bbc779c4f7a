//! The generalised symmetric eigenproblem K x = λ M x under equality
//! conditions C x = 0 (VIBR: vibration with M a mass, buckling with M a
//! geometric stiffness), solved densely.
//!
//! The conditions are removed by a basis Z of their null space (the
//! unknowns that no single-unknown condition fixes, or the right singular
//! vectors of C when a condition links several unknowns): x = Z y,
//! Z'KZ y = λ Z'MZ y. Then a shift σ makes B = Z'(K − σM)Z positive
//! definite (σ = 0 when K is; a negative one for a free structure, whose K
//! is only semi-definite while M is positive), and with B = V D Vᵀ,
//! S = B^-1/2 = V D^-1/2 Vᵀ, the ordinary symmetric problem
//! S (Z'MZ) S w = ν w gives λ = σ + 1/ν and x = Z S w. This works for an
//! indefinite or singular M (buckling: ν = 0 are the directions M does not
//! see, at infinite λ, dropped).
//!
//! Dense, so meant for the model sizes of the test decks (a few thousand
//! unknowns): [`MAX_DENSE`] bounds it.

use faer::{Mat, Side};

/// The largest reduced system solved (beyond it the dense eigensolver
/// would take minutes and gigabytes).
pub const MAX_DENSE: usize = 4000;

/// One eigenpair: λ and x over all the unknowns.
#[derive(Debug, Clone)]
pub struct Pair {
    pub lambda: f64,
    pub x: Vec<f64>,
}

#[derive(Debug, Clone, PartialEq)]
pub enum EigenError {
    TooLarge {
        n: usize,
    },
    /// No shift made K − σM positive definite.
    NoShift,
    Failed,
}

impl std::fmt::Display for EigenError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            EigenError::TooLarge { n } => {
                write!(f, "{} free unknowns: the dense eigensolver takes at most {}", n, MAX_DENSE)
            }
            EigenError::NoShift => write!(
                f,
                "no combination K − σM is positive definite: the stiffness leaves motions free that the mass does not see"
            ),
            EigenError::Failed => write!(f, "the eigensolver did not converge"),
        }
    }
}

/// All finite eigenpairs of K x = λ M x under `conditions` (rows of terms,
/// each `Σ c·x = 0`), λ ascending. `k` and `m` are (row, col, value)
/// entries over unknowns `0..n`, duplicates summed, symmetric (both
/// triangles given, or either: the matrices are symmetrised).
pub fn solve(
    n: usize,
    k: &[(usize, usize, f64)],
    m: &[(usize, usize, f64)],
    conditions: &[Vec<(usize, f64)>],
) -> Result<Vec<Pair>, EigenError> {
    let z = null_space(n, conditions)?;
    let r = z.cols();
    if r > MAX_DENSE {
        return Err(EigenError::TooLarge { n: r });
    }
    if r == 0 {
        return Ok(Vec::new());
    }
    let kr = reduce(n, k, &z);
    let mr = reduce(n, m, &z);
    let scale_k = (0..r).map(|i| kr[(i, i)].abs()).fold(0.0, f64::max);
    let scale_m = (0..r).map(|i| mr[(i, i)].abs()).fold(0.0, f64::max);
    let ratio = if scale_m > 0.0 { scale_k / scale_m } else { 1.0 };
    for sigma in [0.0, -1e-3 * ratio, -1e-1 * ratio, -ratio, -10.0 * ratio] {
        let b = Mat::from_fn(r, r, |i, j| kr[(i, j)] - sigma * mr[(i, j)]);
        let Some(s) = inverse_sqrt(&b) else { continue };
        let c = &s * &mr * &s;
        let c = Mat::from_fn(r, r, |i, j| 0.5 * (c[(i, j)] + c[(j, i)]));
        let evd = c.self_adjoint_eigen(Side::Lower).map_err(|_| EigenError::Failed)?;
        let nu = evd.S().column_vector();
        let w = evd.U();
        let numax = (0..r).map(|i| nu[i].abs()).fold(0.0, f64::max);
        let mut out = Vec::new();
        for i in 0..r {
            if nu[i].abs() <= 1e-12 * numax || numax == 0.0 {
                continue;
            }
            let sw: Vec<f64> = (0..r).map(|a| (0..r).map(|b| s[(a, b)] * w[(b, i)]).sum()).collect();
            let x = z.expand(n, &sw);
            out.push(Pair { lambda: sigma + 1.0 / nu[i], x });
        }
        out.sort_by(|a, b| a.lambda.total_cmp(&b.lambda));
        return Ok(out);
    }
    Err(EigenError::NoShift)
}

/// B^-1/2 of a symmetric matrix, None unless it is positive definite.
fn inverse_sqrt(b: &Mat<f64>) -> Option<Mat<f64>> {
    let r = b.nrows();
    let evd = b.self_adjoint_eigen(Side::Lower).ok()?;
    let d = evd.S().column_vector();
    let v = evd.U();
    let dmax = (0..r).map(|i| d[i].abs()).fold(0.0, f64::max);
    // NaN counts as not positive.
    if (0..r).any(|i| d[i].is_nan() || d[i] <= 1e-11 * dmax) {
        return None;
    }
    let vs = Mat::from_fn(r, r, |i, j| v[(i, j)] / d[j].sqrt());
    Some(&vs * v.transpose())
}

/// A basis of the unknowns the conditions leave free: some of the unknowns
/// themselves (when every condition fixes one unknown), or dense columns.
enum Basis {
    Select(Vec<usize>),
    Dense(Mat<f64>),
}

impl Basis {
    fn cols(&self) -> usize {
        match self {
            Basis::Select(f) => f.len(),
            Basis::Dense(z) => z.ncols(),
        }
    }

    /// Z y over all the unknowns.
    fn expand(&self, n: usize, y: &[f64]) -> Vec<f64> {
        match self {
            Basis::Select(free) => {
                let mut x = vec![0.0; n];
                for (k, &j) in free.iter().enumerate() {
                    x[j] = y[k];
                }
                x
            }
            Basis::Dense(z) => (0..n).map(|a| (0..y.len()).map(|b| z[(a, b)] * y[b]).sum()).collect(),
        }
    }
}

/// Zᵀ A Z, symmetrised (a selection never forms the full matrix).
fn reduce(n: usize, a: &[(usize, usize, f64)], z: &Basis) -> Mat<f64> {
    match z {
        Basis::Select(free) => {
            let mut at = vec![usize::MAX; n];
            for (k, &j) in free.iter().enumerate() {
                at[j] = k;
            }
            let mut out = Mat::<f64>::zeros(free.len(), free.len());
            for &(i, j, v) in a {
                let (p, q) = (at[i], at[j]);
                if p != usize::MAX && q != usize::MAX {
                    out[(p, q)] += 0.5 * v;
                    out[(q, p)] += 0.5 * v;
                }
            }
            out
        }
        Basis::Dense(z) => {
            let mut full = Mat::<f64>::zeros(n, n);
            for &(i, j, v) in a {
                full[(i, j)] += 0.5 * v;
                full[(j, i)] += 0.5 * v;
            }
            z.transpose() * &full * z
        }
    }
}

/// An orthonormal basis of {x : every condition row · x = 0}.
fn null_space(n: usize, conditions: &[Vec<(usize, f64)>]) -> Result<Basis, EigenError> {
    let single = conditions.iter().all(|c| c.iter().filter(|(_, v)| *v != 0.0).count() <= 1);
    if single {
        let mut fixed = vec![false; n];
        for c in conditions {
            for (j, v) in c {
                if *v != 0.0 {
                    fixed[*j] = true;
                }
            }
        }
        let free: Vec<usize> = (0..n).filter(|j| !fixed[*j]).collect();
        if free.len() > MAX_DENSE {
            return Err(EigenError::TooLarge { n: free.len() });
        }
        return Ok(Basis::Select(free));
    }
    if n > MAX_DENSE {
        return Err(EigenError::TooLarge { n });
    }
    let m = conditions.len();
    let mut c = Mat::<f64>::zeros(m.max(1), n);
    for (r, row) in conditions.iter().enumerate() {
        for (j, v) in row {
            c[(r, *j)] += v;
        }
    }
    let svd = c.svd().map_err(|_| EigenError::Failed)?;
    let s = svd.S().column_vector();
    let smax = (0..s.nrows()).map(|i| s[i]).fold(0.0, f64::max);
    let rank = (0..s.nrows()).filter(|&i| s[i] > 1e-10 * smax).count();
    let v = svd.V();
    Ok(Basis::Dense(Mat::from_fn(n, n - rank, |i, j| v[(i, rank + j)])))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Two springs in series, fixed at one end: K = k[[2,-1],[-1,1]],
    /// M = I: λ = k(3 ∓ √5)/2.
    #[test]
    fn two_masses() {
        let k = vec![(0, 0, 2.0), (0, 1, -1.0), (1, 0, -1.0), (1, 1, 1.0)];
        let m = vec![(0, 0, 1.0), (1, 1, 1.0)];
        let p = solve(2, &k, &m, &[]).unwrap();
        assert!((p[0].lambda - (3.0 - 5f64.sqrt()) / 2.0).abs() < 1e-12);
        assert!((p[1].lambda - (3.0 + 5f64.sqrt()) / 2.0).abs() < 1e-12);
    }

    /// A free pair (K singular) and a condition tying both unknowns.
    #[test]
    fn free_and_tied() {
        let k = vec![(0, 0, 1.0), (0, 1, -1.0), (1, 0, -1.0), (1, 1, 1.0), (2, 2, 4.0)];
        let m = vec![(0, 0, 1.0), (1, 1, 1.0), (2, 2, 1.0)];
        let p = solve(3, &k, &m, &[]).unwrap();
        let l: Vec<f64> = p.iter().map(|p| p.lambda).collect();
        assert!(l[0].abs() < 1e-9 && (l[1] - 2.0).abs() < 1e-9 && (l[2] - 4.0).abs() < 1e-9, "{:?}", l);
        // x0 = x2: the modes of the (0,2) pair under the tie, plus x1.
        let p = solve(3, &k, &m, &[vec![(0, 1.0), (2, -1.0)]]).unwrap();
        assert_eq!(p.len(), 2);
        for q in &p {
            assert!((q.x[0] - q.x[2]).abs() < 1e-9);
        }
    }
}
