//! Roots of a real polynomial (RACPOL), as the eigenvalues of its
//! companion matrix.
//!
//! faer's dense non-symmetric eigenvalue solver (already a dependency for
//! the factorisations) does the work: a QR iteration on the companion
//! matrix is the standard, backward-stable way to get every root at once,
//! complex ones included, without the deflation troubles of Newton or
//! Bairstow iterations. Each root is then polished by a few Newton steps
//! on the original coefficients.

use faer::Mat;

/// A root: real and imaginary parts.
pub type Root = (f64, f64);

/// Every root of `c[0] + c[1] x + … + c[n] x^n`, sorted by real part then
/// imaginary part. Zero leading coefficients are dropped; `None` when the
/// polynomial is a constant (no roots to speak of, or every number) or
/// the eigenvalue iteration fails.
pub fn roots(c: &[f64]) -> Option<Vec<Root>> {
    let n = c.iter().rposition(|&x| x != 0.0)?;
    if n == 0 {
        return None;
    }
    // Roots at zero: low-order zero coefficients.
    let z = c.iter().position(|&x| x != 0.0)?;
    let mut out: Vec<Root> = vec![(0.0, 0.0); z];
    let p = &c[z..=n];
    let m = p.len() - 1;
    if m == 1 {
        out.push((-p[0] / p[1], 0.0));
    } else if m > 1 {
        // Companion matrix of the monic polynomial: ones below the
        // diagonal, -p[i]/p[m] in the last column.
        let lead = p[m];
        let a = Mat::<f64>::from_fn(m, m, |i, j| {
            if j == m - 1 {
                -p[i] / lead
            } else if i == j + 1 {
                1.0
            } else {
                0.0
            }
        });
        for ev in a.eigenvalues().ok()? {
            out.push(polish(p, (ev.re, ev.im)));
        }
    }
    out.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.total_cmp(&b.1)));
    Some(out)
}

/// The roots whose imaginary part is negligible, as real numbers sorted
/// in increasing order.
pub fn real_roots(c: &[f64]) -> Option<Vec<f64>> {
    let all = roots(c)?;
    Some(all.into_iter().filter(|&(re, im)| im.abs() <= 1e-8 * re.abs().max(1.0)).map(|(re, _)| re).collect())
}

/// A few Newton steps on the complex root `z`; the step is kept only
/// while it lowers |p(z)|.
fn polish(p: &[f64], mut z: Root) -> Root {
    let mut best = norm(eval(p, z).0);
    for _ in 0..4 {
        let (v, d) = eval(p, z);
        let dd = d.0 * d.0 + d.1 * d.1;
        if dd == 0.0 || best == 0.0 {
            break;
        }
        // z - v/d
        let q = ((v.0 * d.0 + v.1 * d.1) / dd, (v.1 * d.0 - v.0 * d.1) / dd);
        let t = (z.0 - q.0, z.1 - q.1);
        let r = norm(eval(p, t).0);
        // A NaN residual also stops the polishing.
        if r.is_nan() || r >= best {
            break;
        }
        best = r;
        z = t;
    }
    if z.1.abs() <= 1e-12 * z.0.abs() {
        z.1 = 0.0;
    }
    z
}

fn norm(v: Root) -> f64 {
    v.0.hypot(v.1)
}

/// p(z) and p'(z) by Horner's scheme.
fn eval(p: &[f64], z: Root) -> (Root, Root) {
    let mut v = (0.0, 0.0);
    let mut d = (0.0, 0.0);
    for &a in p.iter().rev() {
        d = (d.0 * z.0 - d.1 * z.1 + v.0, d.0 * z.1 + d.1 * z.0 + v.1);
        v = (v.0 * z.0 - v.1 * z.1 + a, v.0 * z.1 + v.1 * z.0);
    }
    (v, d)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quadratic_and_cubic() {
        // (x-1)(x-2) = 2 - 3x + x^2
        let r = real_roots(&[2.0, -3.0, 1.0]).unwrap();
        assert!((r[0] - 1.0).abs() < 1e-12 && (r[1] - 2.0).abs() < 1e-12);
        // x^2 + 1: two complex roots, no real one
        assert!(real_roots(&[1.0, 0.0, 1.0]).unwrap().is_empty());
        let c = roots(&[1.0, 0.0, 1.0]).unwrap();
        assert!((c[0].1 + 1.0).abs() < 1e-12 && (c[1].1 - 1.0).abs() < 1e-12);
        // x (x+3)(x-0.5) = -1.5x + 2.5x^2 + x^3
        let r = real_roots(&[0.0, -1.5, 2.5, 1.0]).unwrap();
        assert_eq!(r.len(), 3);
        assert!((r[0] + 3.0).abs() < 1e-12 && r[1] == 0.0 && (r[2] - 0.5).abs() < 1e-12);
        assert!(roots(&[3.0]).is_none());
    }
}
