//! Complex modes of `M ẍ + C ẋ + K x = 0` (VIBC): the solutions
//! `x = φ e^{λt}` of `(λ² M + λ C + K) φ = 0`, for small dense matrices.
//!
//! The quadratic problem becomes the linear pencil of twice the size
//! `[0 I; -K -C] z = λ [I 0; 0 M] z`, `z = (φ, λφ)`, solved by the QZ
//! algorithm (faer's generalised eigensolver): a singular mass gives
//! infinite eigenvalues (β = 0) instead of a failure, and K, C need not be
//! symmetric (follower forces, gyroscopic terms).

use faer::Mat;

/// One eigenpair: `lambda = (re, im)`, or None when it is infinite; the
/// mode shape, scaled so that its component of largest modulus is 1.
#[derive(Debug, Clone)]
pub struct ComplexMode {
    pub lambda: Option<(f64, f64)>,
    pub shape: Vec<(f64, f64)>,
}

/// All the 2n modes of the n×n row-major matrices, the finite ones by
/// increasing modulus (of a conjugate pair, the one with Im λ ≥ 0 first),
/// then the infinite ones.
pub fn quadratic_modes(n: usize, m: &[f64], c: Option<&[f64]>, k: &[f64]) -> Result<Vec<ComplexMode>, String> {
    if m.len() != n * n || k.len() != n * n || c.is_some_and(|c| c.len() != n * n) {
        return Err("the matrices do not have the size of the unknowns".into());
    }
    if m.iter().chain(k).chain(c.unwrap_or(&[])).any(|v| !v.is_finite()) {
        return Err("a matrix holds a non-finite value".into());
    }
    let nn = 2 * n;
    // faer's QZ fails on a 2×2 pencil: smaller pencils are padded with
    // decoupled rows of infinite eigenvalue (a = 1, b = 0), dropped below.
    let size = nn.max(4);
    let mut a = Mat::<f64>::zeros(size, size);
    let mut b = Mat::<f64>::zeros(size, size);
    for i in nn..size {
        a[(i, i)] = 1.0;
    }
    for i in 0..n {
        a[(i, n + i)] = 1.0;
        b[(i, i)] = 1.0;
        for j in 0..n {
            a[(n + i, j)] = -k[i * n + j];
            a[(n + i, n + j)] = -c.map_or(0.0, |c| c[i * n + j]);
            b[(n + i, n + j)] = m[i * n + j];
        }
    }
    let evd = a.generalized_eigen(&b).map_err(|e| format!("the QZ algorithm did not converge ({e:?})"))?;
    let (sa, sb, u) = (evd.S_a().column_vector(), evd.S_b().column_vector(), evd.U());
    let scale = a.norm_max().max(b.norm_max()).max(f64::MIN_POSITIVE);
    let mut modes = Vec::with_capacity(size);
    for j in 0..size {
        let (al, be) = (sa[j], sb[j]);
        let bm = be.norm();
        let lambda = if bm <= 1e-13 * al.norm().max(scale * f64::EPSILON) {
            None
        } else {
            let d = be.re * be.re + be.im * be.im;
            Some(((al.re * be.re + al.im * be.im) / d, (al.im * be.re - al.re * be.im) / d))
        };
        let mut shape: Vec<(f64, f64)> = (0..n).map(|i| (u[(i, j)].re, u[(i, j)].im)).collect();
        normalise(&mut shape);
        modes.push(ComplexMode { lambda, shape });
    }
    modes.sort_by(|x, y| match (x.lambda, y.lambda) {
        (Some(p), Some(q)) => {
            let (mp, mq) = (p.0.hypot(p.1), q.0.hypot(q.1));
            // Conjugates have the same modulus up to rounding.
            if (mp - mq).abs() <= 1e-10 * mp.max(mq) {
                q.1.partial_cmp(&p.1).unwrap_or(std::cmp::Ordering::Equal)
            } else {
                mp.partial_cmp(&mq).unwrap_or(std::cmp::Ordering::Equal)
            }
        }
        (Some(_), None) => std::cmp::Ordering::Less,
        (None, Some(_)) => std::cmp::Ordering::Greater,
        (None, None) => std::cmp::Ordering::Equal,
    });
    // The padding's modes are infinite, hence last (and alike).
    modes.truncate(nn);
    Ok(modes)
}

/// Divide by the component of largest modulus (the shape becomes real
/// there and 1).
fn normalise(v: &mut [(f64, f64)]) {
    let Some(&(pr, pi)) = v.iter().max_by(|a, b| a.0.hypot(a.1).total_cmp(&b.0.hypot(b.1))) else { return };
    let d = pr * pr + pi * pi;
    if d == 0.0 || !d.is_finite() {
        return;
    }
    for x in v.iter_mut() {
        *x = ((x.0 * pr + x.1 * pi) / d, (x.1 * pr - x.0 * pi) / d);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn undamped_oscillator_has_imaginary_pair() {
        let modes = quadratic_modes(1, &[2.0], None, &[8.0]).unwrap();
        let l0 = modes[0].lambda.unwrap();
        let l1 = modes[1].lambda.unwrap();
        assert!(l0.0.abs() < 1e-12 && (l0.1 - 2.0).abs() < 1e-12, "{l0:?}");
        assert!(l1.0.abs() < 1e-12 && (l1.1 + 2.0).abs() < 1e-12, "{l1:?}");
    }

    #[test]
    fn damped_oscillator_decays() {
        // m = 1, c = 2 ζ ω, k = ω²: λ = -ζω ± iω√(1-ζ²).
        let (w, z) = (3.0f64, 0.1f64);
        let modes = quadratic_modes(1, &[1.0], Some(&[2.0 * z * w]), &[w * w]).unwrap();
        let l = modes[0].lambda.unwrap();
        assert!((l.0 + z * w).abs() < 1e-12 && (l.1 - w * (1.0 - z * z).sqrt()).abs() < 1e-12, "{l:?}");
    }

    #[test]
    fn singular_mass_gives_an_infinite_mode() {
        let modes = quadratic_modes(2, &[1.0, 0.0, 0.0, 0.0], None, &[2.0, 0.0, 0.0, 1.0]).unwrap();
        assert_eq!(modes.iter().filter(|m| m.lambda.is_none()).count(), 2);
    }
}
