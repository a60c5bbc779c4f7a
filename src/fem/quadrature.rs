//! Quadrature rules on the reference elements of [`super::shape`].
//!
//! Points are given in reference coordinates `[ξ, η, ζ]` (unused ones 0)
//! with weights that sum to the reference measure (2 for a segment, 1/2 for
//! the triangle, 4 for the square, 1/6 for the tetrahedron, 1 for the prism,
//! 8 for the cube).
//!
//! Ordering, which is visible to users through `EXTR chml comp iz ie ig`:
//! for the 2-point-per-direction rules on QUA4 and CUB8 Gauss point *k* is
//! the one nearest node *k* (counter-clockwise, bottom face then top face),
//! so that a field extracted at point k "belongs" to node k as in Cast3M
//! listings; the 3×3 rule on QUA8 is in tensor order (ξ fastest); triangle
//! rules put point k nearest corner k.

/// A quadrature point: reference coordinates and weight.
pub type QPoint = ([f64; 3], f64);

/// Gauss–Legendre points and weights on [-1, 1].
pub fn gauss_1d(n: usize) -> Vec<(f64, f64)> {
    match n {
        1 => vec![(0.0, 2.0)],
        2 => {
            let a = 1.0 / 3f64.sqrt();
            vec![(-a, 1.0), (a, 1.0)]
        }
        _ => {
            let a = (0.6f64).sqrt();
            vec![(-a, 5.0 / 9.0), (0.0, 8.0 / 9.0), (a, 5.0 / 9.0)]
        }
    }
}

/// n-point rule on the segment.
pub fn seg(n: usize) -> Vec<QPoint> {
    gauss_1d(n).into_iter().map(|(x, w)| ([x, 0.0, 0.0], w)).collect()
}

/// n×n rule on the square; n = 2 is counter-clockwise from (-,-).
pub fn quad(n: usize) -> Vec<QPoint> {
    if n == 2 {
        let a = 1.0 / 3f64.sqrt();
        return [(-a, -a), (a, -a), (a, a), (-a, a)].into_iter().map(|(x, y)| ([x, y, 0.0], 1.0)).collect();
    }
    let g = gauss_1d(n);
    let mut out = Vec::new();
    for &(y, wy) in &g {
        for &(x, wx) in &g {
            out.push(([x, y, 0.0], wx * wy));
        }
    }
    out
}

/// n×n×n rule on the cube; n = 2 follows the CUB8 node order.
pub fn hexa(n: usize) -> Vec<QPoint> {
    if n == 2 {
        let mut out = Vec::new();
        let a = 1.0 / 3f64.sqrt();
        for z in [-a, a] {
            for ([x, y, _], w) in quad(2) {
                out.push(([x, y, z], w));
            }
        }
        return out;
    }
    let g = gauss_1d(n);
    let mut out = Vec::new();
    for &(z, wz) in &g {
        for &(y, wy) in &g {
            for &(x, wx) in &g {
                out.push(([x, y, z], wx * wy * wz));
            }
        }
    }
    out
}

/// Triangle rules exact to degree 1 (1 point), 2 (3 points) or 5 (7 points).
pub fn tri(n: usize) -> Vec<QPoint> {
    match n {
        1 => vec![([1.0 / 3.0, 1.0 / 3.0, 0.0], 0.5)],
        3 => {
            // Interior points, each nearest one corner (corner order 1,2,3).
            let (a, b) = (2.0 / 3.0, 1.0 / 6.0);
            vec![([b, b, 0.0], 1.0 / 6.0), ([a, b, 0.0], 1.0 / 6.0), ([b, a, 0.0], 1.0 / 6.0)]
        }
        _ => {
            // Radon's degree-5 rule.
            let s = 15f64.sqrt();
            let (a1, b1, w1) = ((6.0 - s) / 21.0, (9.0 + 2.0 * s) / 21.0, (155.0 - s) / 2400.0);
            let (a2, b2, w2) = ((6.0 + s) / 21.0, (9.0 - 2.0 * s) / 21.0, (155.0 + s) / 2400.0);
            vec![
                ([1.0 / 3.0, 1.0 / 3.0, 0.0], 9.0 / 80.0),
                ([a1, a1, 0.0], w1),
                ([b1, a1, 0.0], w1),
                ([a1, b1, 0.0], w1),
                ([a2, a2, 0.0], w2),
                ([b2, a2, 0.0], w2),
                ([a2, b2, 0.0], w2),
            ]
        }
    }
}

/// Tetrahedron rules exact to degree 1 (1 point) or 2 (4 points).
pub fn tet(n: usize) -> Vec<QPoint> {
    if n == 1 {
        return vec![([0.25, 0.25, 0.25], 1.0 / 6.0)];
    }
    let a = 0.585_410_196_624_968_5;
    let b = 0.138_196_601_125_010_5;
    // Point k nearest vertex k (vertex 1 is the origin).
    vec![([b, b, b], 1.0 / 24.0), ([a, b, b], 1.0 / 24.0), ([b, a, b], 1.0 / 24.0), ([b, b, a], 1.0 / 24.0)]
}

/// Prism rule: triangle rule × Gauss rule along ζ (bottom layer first).
pub fn prism(ntri: usize, nz: usize) -> Vec<QPoint> {
    let mut out = Vec::new();
    for (z, wz) in gauss_1d(nz) {
        for ([x, y, _], w) in tri(ntri) {
            out.push(([x, y, z], w * wz));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn integrate(rule: &[QPoint], f: impl Fn([f64; 3]) -> f64) -> f64 {
        rule.iter().map(|&(p, w)| w * f(p)).sum()
    }

    #[test]
    fn triangle_rules_integrate_monomials_exactly() {
        // ∫_T ξ^a η^b = a! b! / (a+b+2)!
        let fact = |n: u32| (1..=n).map(f64::from).product::<f64>();
        for (n, deg) in [(1, 1), (3, 2), (7, 5)] {
            for a in 0..=deg {
                for b in 0..=(deg - a) {
                    let exact = fact(a) * fact(b) / fact(a + b + 2);
                    let got = integrate(&tri(n), |p| p[0].powi(a as i32) * p[1].powi(b as i32));
                    assert!((got - exact).abs() < 1e-14, "tri{n} x^{a} y^{b}: {got} vs {exact}");
                }
            }
        }
    }

    #[test]
    fn tet_rule_integrates_quadratics() {
        // ∫ ξ² = 2/5! = 1/60, ∫ ξη = 1/120
        let r = tet(4);
        assert!((integrate(&r, |p| p[0] * p[0]) - 1.0 / 60.0).abs() < 1e-14);
        assert!((integrate(&r, |p| p[0] * p[2]) - 1.0 / 120.0).abs() < 1e-14);
        assert!((integrate(&tet(1), |_| 1.0) - 1.0 / 6.0).abs() < 1e-15);
    }

    #[test]
    fn tensor_rules_have_the_right_measure_and_degree() {
        for n in 1..=3 {
            assert!((integrate(&quad(n), |_| 1.0) - 4.0).abs() < 1e-14);
            assert!((integrate(&hexa(n), |_| 1.0) - 8.0).abs() < 1e-14);
            let deg = 2 * n as i32 - 1;
            let exact = if deg % 2 == 0 { 2.0 / (deg as f64 + 1.0) } else { 0.0 };
            assert!((integrate(&seg(n), |p| p[0].powi(deg)) - exact).abs() < 1e-14);
            let e2 = if (deg - 1) % 2 == 0 { 2.0 / deg as f64 } else { 0.0 };
            assert!((integrate(&seg(n), |p| p[0].powi(deg - 1)) - e2).abs() < 1e-14);
        }
        assert!((integrate(&prism(3, 2), |p| p[2] * p[2]) - 1.0 / 3.0).abs() < 1e-14);
    }
}
