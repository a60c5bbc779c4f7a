use super::*;

/// IC(0) of a tridiagonal matrix has no dropped fill: it is the exact
/// Cholesky factor, and one application solves the system.
#[test]
fn ic0_is_exact_without_fill() {
    let n = 6;
    let mut t = Vec::new();
    for i in 0..n {
        t.push((i, i, 2.0 + i as f64 * 0.1));
        if i + 1 < n {
            t.extend([(i, i + 1, -1.0), (i + 1, i, -1.0)]);
        }
    }
    let a = Csr::from_triplets(n, &t);
    let pre = Ic0::new(&a);
    let b: Vec<f64> = (0..n).map(|i| 1.0 + i as f64).collect();
    let mut x = vec![0.0; n];
    pre.apply(&b, &mut x);
    let mut ax = vec![0.0; n];
    a.apply(&x, &mut ax);
    for (u, v) in ax.iter().zip(&b) {
        assert!((u - v).abs() < 1e-12, "{ax:?} vs {b:?}");
    }
}

/// A positive definite 4-cycle whose incomplete factorisation breaks
/// down (the dropped fill of eliminating node 0 was needed): the
/// shifted factorisation still preconditions CG to the answer.
#[test]
fn ic0_breakdown_is_shifted_and_cg_converges() {
    let (a, b, c, d) = (-0.6, -0.6, 0.7, -0.4);
    let mut t: Vec<(usize, usize, f64)> = (0..4).map(|i| (i, i, 1.0)).collect();
    for (i, j, v) in [(0, 1, a), (0, 3, b), (1, 2, c), (2, 3, d)] {
        t.extend([(i, j, v), (j, i, v)]);
    }
    let (ptr, col, base) = Ic0::lower(&Csr::from_triplets(4, &t));
    let none = Ic0::factor(&ptr, &col, &base, 0.0).is_none();
    assert!(none, "the unshifted IC(0) should break down on this matrix");
    let a = Csr::from_triplets(4, &t);
    let pre = Ic0::new(&a);
    let rhs = [1.0, -2.0, 0.5, 3.0];
    let x = pcg(&a, &pre, &rhs).unwrap();
    let mut ax = vec![0.0; 4];
    a.apply(&x, &mut ax);
    for (u, v) in ax.iter().zip(&rhs) {
        assert!((u - v).abs() < 1e-10, "{ax:?} vs {rhs:?}");
    }
}
