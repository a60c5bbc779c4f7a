//! Small sparse problems the bilateral and unilateral tests share.

use crate::solve::problem::{Condition, Kind, Matrix, Problem};
use faer::Mat;

/// A free chain of springs (K singular), stiffnesses varying along it.
pub(crate) fn chain(n: usize) -> Matrix {
    let mut entries = Vec::new();
    for i in 0..n - 1 {
        let k = 1.0 + 0.5 * i as f64;
        entries.extend([(i, i, k), (i, i + 1, -k), (i + 1, i, -k), (i + 1, i + 1, k)]);
    }
    Matrix { n, entries, symmetric: true }
}

pub(crate) fn cond(terms: &[(usize, f64)], kind: Kind) -> Condition {
    Condition { terms: terms.to_vec(), kind, dual: None }
}

pub(crate) fn dense(p: &Problem) -> Mat<f64> {
    let n = p.k.n;
    let mut k = Mat::<f64>::zeros(n, n);
    for &(i, j, v) in &p.k.entries {
        k[(i, j)] += v;
    }
    k
}

pub(crate) fn assert_close(a: f64, b: f64, scale: f64) {
    assert!((a - b).abs() <= 1e-10 * scale, "{a} vs {b}");
}
