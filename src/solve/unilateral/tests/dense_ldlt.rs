use super::*;

/// Tiny deterministic generator (xorshift) for test matrices.
fn rng(seed: &mut u64) -> f64 {
    *seed ^= *seed << 13;
    *seed ^= *seed >> 7;
    *seed ^= *seed << 17;
    (*seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
}

/// A quasi-definite matrix: G = BBᵀ + I (SPD) minus α on `inactive`.
fn quasi(n: usize, seed: &mut u64, inactive: &[bool], alpha: f64) -> Mat<f64> {
    let b = Mat::<f64>::from_fn(n, n, |_, _| rng(seed));
    let mut g = &b * b.transpose();
    for k in 0..n {
        g[(k, k)] += 1.0;
        if inactive[k] {
            g[(k, k)] -= alpha;
        }
    }
    g
}

#[test]
fn solve_matches_matrix() {
    let mut seed = 7u64;
    let n = 9;
    let inactive: Vec<bool> = (0..n).map(|k| k % 3 == 1).collect();
    let alpha = 50.0;
    let a = quasi(n, &mut seed, &inactive, alpha);
    let f = DenseLdlt::factor(a.as_ref());
    let positive: Vec<bool> = inactive.iter().map(|&x| !x).collect();
    assert_eq!(f.first_bad_pivot(&positive, &vec![alpha; n], 1e-12), None);
    let b: Vec<f64> = (0..n).map(|k| k as f64 - 3.0).collect();
    let mut x = b.clone();
    f.solve_in_place(&mut x);
    for i in 0..n {
        let r: f64 = (0..n).map(|j| a[(i, j)] * x[j]).sum::<f64>() - b[i];
        assert!(r.abs() < 1e-10, "residual {r}");
    }
}

#[test]
fn updates_match_fresh_factorisation() {
    let mut seed = 12345u64;
    let n = 12;
    let alpha = 40.0;
    let mut inactive = vec![false; n];
    let mut a = quasi(n, &mut seed, &inactive, alpha);
    let mut f = DenseLdlt::factor(a.as_ref());
    // A sequence of releases and re-activations, as the status loop does.
    for step in 0..30 {
        let i = ((rng(&mut seed) + 1.0) * 0.5 * n as f64) as usize % n;
        let delta = if inactive[i] { alpha } else { -alpha };
        inactive[i] = !inactive[i];
        a[(i, i)] += delta;
        f.update_diag(i, delta);
        let fresh = DenseLdlt::factor(a.as_ref());
        for r in 0..n {
            for c in 0..=r {
                let (u, v) = (f.ld[(r, c)], fresh.ld[(r, c)]);
                assert!((u - v).abs() <= 1e-9 * (1.0 + v.abs()), "step {step} ({r},{c}): {u} vs {v}");
            }
        }
    }
    assert_eq!(f.updates(), 30);
}

#[test]
fn singular_matrix_is_flagged() {
    // [[1, 1], [1, 1]]: second pivot exactly 0.
    let a = Mat::<f64>::from_fn(2, 2, |_, _| 1.0);
    let f = DenseLdlt::factor(a.as_ref());
    assert_eq!(f.first_bad_pivot(&[true, true], &[1.0, 1.0], 1e-10), Some(1));
    // Wrong sign: [[1, 0], [0, 1]] with the second expected negative.
    let a = Mat::<f64>::identity(2, 2);
    let f = DenseLdlt::factor(a.as_ref());
    assert_eq!(f.first_bad_pivot(&[true, false], &[1.0, 1.0], 1e-10), Some(1));
}
