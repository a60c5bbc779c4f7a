//! Levenberg-Marquardt fit of a model's parameters to points (LEVM), and
//! one Gauss-Newton step for a model linearised about its parameters
//! (MOCA). Plain numbers in and out: the model is a callback, so that the
//! operator can run a Gibiane procedure for it.

use super::fit;

/// One Gauss-Newton step: the parameters p + δ where δ minimises
/// Σ_n (w_n (y_n − f_n − Σ_i δ_i d_i,n))², the model f being linear in the
/// parameters with derivatives `d` (one list per parameter).
pub fn gauss_newton_step(p: &[f64], y: &[f64], f: &[f64], d: &[Vec<f64>], w: &[f64]) -> Result<Vec<f64>, String> {
    let (delta, _) = fit::linear(d, f, y, w)?;
    Ok(p.iter().zip(&delta).map(|(p, d)| p + d).collect())
}

/// The model's values at the points and their derivatives, `jac[n][i]` =
/// ∂f_n/∂p_i, for parameters p.
pub type Eval = (Vec<f64>, Vec<Vec<f64>>);

/// χ² = Σ ((y_n − f_n)/σ_n)².
fn chi2(y: &[f64], f: &[f64], sigma: &[f64]) -> f64 {
    y.iter().zip(f).zip(sigma).map(|((y, f), s)| ((y - f) / s).powi(2)).sum()
}

/// The parameters minimising χ² from `p0`, and that χ². The damping λ
/// starts at 1e-3 of the diagonal, is divided by 10 after a step that
/// lowers χ² and multiplied by 10 after one that does not; the search
/// stops when an accepted step lowers χ² by less than 1e-12 of it (or
/// below 1e-30 of Σ (y/σ)², an exact fit), when λ exceeds 1e16 (no
/// descent left) or after `max_iter` steps.
pub fn levenberg_marquardt<E>(
    p0: &[f64],
    y: &[f64],
    sigma: &[f64],
    max_iter: usize,
    mut model: impl FnMut(&[f64]) -> Result<Eval, E>,
) -> Result<Result<(Vec<f64>, f64), String>, E> {
    let m = p0.len();
    let scale: f64 = y.iter().zip(sigma).map(|(y, s)| (y / s).powi(2)).sum();
    let mut p = p0.to_vec();
    let (mut f, mut jac) = model(&p)?;
    let mut c = chi2(y, &f, sigma);
    let mut lambda = 1e-3;
    for _ in 0..max_iter {
        if c <= 1e-30 * scale {
            break;
        }
        let mut alpha = faer::Mat::<f64>::zeros(m, m);
        let mut beta = faer::Mat::<f64>::zeros(m, 1);
        for n in 0..y.len() {
            let w = 1.0 / (sigma[n] * sigma[n]);
            for k in 0..m {
                beta[(k, 0)] += w * (y[n] - f[n]) * jac[n][k];
                for l in 0..m {
                    alpha[(k, l)] += w * jac[n][k] * jac[n][l];
                }
            }
        }
        for k in 0..m {
            let d = alpha[(k, k)];
            alpha[(k, k)] = if d > 0.0 { d * (1.0 + lambda) } else { lambda };
        }
        use faer::linalg::solvers::Solve;
        let delta = alpha.partial_piv_lu().solve(&beta);
        let trial: Vec<f64> = (0..m).map(|k| p[k] + delta[(k, 0)]).collect();
        if trial.iter().any(|v| !v.is_finite()) {
            lambda *= 10.0;
        } else {
            let (ft, jt) = model(&trial)?;
            let ct = chi2(y, &ft, sigma);
            if ct.is_finite() && ct < c {
                let gain = c - ct;
                (p, f, jac, c) = (trial, ft, jt, ct);
                lambda /= 10.0;
                if gain <= 1e-12 * c {
                    break;
                }
                continue;
            }
            lambda *= 10.0;
        }
        if lambda > 1e16 {
            break;
        }
    }
    if !c.is_finite() {
        return Ok(Err("the criterion is not finite at the parameters found".into()));
    }
    Ok(Ok((p, c)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fits_an_exponential_exactly() {
        let x: Vec<f64> = (0..8).map(|i| i as f64 * 0.5).collect();
        let y: Vec<f64> = x.iter().map(|x| 3.0 * (-0.7 * x).exp()).collect();
        let s = vec![1.0; x.len()];
        let r = levenberg_marquardt::<()>(&[1.0, -0.1], &y, &s, 500, |p| {
            let f = x.iter().map(|x| p[0] * (p[1] * x).exp()).collect();
            let j = x.iter().map(|x| vec![(p[1] * x).exp(), p[0] * x * (p[1] * x).exp()]).collect();
            Ok((f, j))
        });
        let (p, c) = r.unwrap().unwrap();
        assert!((p[0] - 3.0).abs() < 1e-8 && (p[1] + 0.7).abs() < 1e-8, "{p:?}");
        assert!(c < 1e-16);
    }

    #[test]
    fn one_step_solves_a_linear_model() {
        // f = a + b x at (a, b) = (0, 0); data y = 1 + 2x.
        let y = [1.0, 3.0, 5.0];
        let p = gauss_newton_step(&[0.0, 0.0], &y, &[0.0; 3], &[vec![1.0; 3], vec![0.0, 1.0, 2.0]], &[1.0; 3]).unwrap();
        assert!((p[0] - 1.0).abs() < 1e-12 && (p[1] - 2.0).abs() < 1e-12);
    }
}
