//! Weighted least squares for AJU1 and AJU2, the steps of the AJUSTE
//! procedure (a fit y ≈ g + Σ q_i f_i, linear in the q and possibly
//! nonlinear in further parameters that the procedure searches).

use faer::linalg::solvers::Solve;
use faer::Mat;

/// The coefficients q minimising Σ_n (w_n (g_n + Σ_i q_i f_i,n − y_n))²
/// and that minimum. `f` holds one list of values per coefficient. The
/// normal equations are solved by LU with partial pivoting (faer); a
/// singular system (functions not independent at the points) is an error.
pub fn linear(f: &[Vec<f64>], g: &[f64], y: &[f64], w: &[f64]) -> Result<(Vec<f64>, f64), String> {
    let (l, n) = (f.len(), y.len());
    let w2: Vec<f64> = w.iter().map(|w| w * w).collect();
    let q = if l == 0 {
        vec![]
    } else {
        let s = Mat::<f64>::from_fn(l, l, |i, j| (0..n).map(|k| w2[k] * f[i][k] * f[j][k]).sum());
        let t = Mat::<f64>::from_fn(l, 1, |i, _| (0..n).map(|k| w2[k] * (y[k] - g[k]) * f[i][k]).sum());
        let q = s.partial_piv_lu().solve(&t);
        let q: Vec<f64> = (0..l).map(|i| q[(i, 0)]).collect();
        if q.iter().any(|v| !v.is_finite()) {
            return Err("the functions are not independent at these points: the coefficients are not determined".into());
        }
        q
    };
    let phi = (0..n).map(|k| (w[k] * (model(f, g, &q, k) - y[k])).powi(2)).sum();
    Ok((q, phi))
}

/// g_k + Σ_i q_i f_i,k.
fn model(f: &[Vec<f64>], g: &[f64], q: &[f64], k: usize) -> f64 {
    g[k] + q.iter().zip(f).map(|(q, f)| q * f[k]).sum::<f64>()
}

/// The gradient direction for the nonlinear parameters p_j:
/// d_j = Σ_n w_n² (y_n − g_n − Σ_i q_i f_i,n) (∂g/∂p_j + Σ_i q_i ∂f_i/∂p_j)
/// (`dg[j]`, `df[j][i]`), and Σ_j d_j².
pub fn gradient(
    f: &[Vec<f64>],
    g: &[f64],
    q: &[f64],
    dg: &[Vec<f64>],
    df: &[Vec<Vec<f64>>],
    y: &[f64],
    w: &[f64],
) -> (Vec<f64>, f64) {
    let mut d = vec![0.0; dg.len()];
    for k in 0..y.len() {
        let z = (y[k] - model(f, g, q, k)) * w[k] * w[k];
        for (j, dj) in d.iter_mut().enumerate() {
            let b = dg[j][k] + df[j].iter().zip(q).map(|(dfi, q)| q * dfi[k]).sum::<f64>();
            *dj += z * b;
        }
    }
    let a = d.iter().map(|x| x * x).sum();
    (d, a)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_line_through_three_points() {
        // y = 1 + 2x at x = 0, 1, 2: exact, zero residual.
        let f = vec![vec![1.0; 3], vec![0.0, 1.0, 2.0]];
        let (q, phi) = linear(&f, &[0.0; 3], &[1.0, 3.0, 5.0], &[1.0; 3]).unwrap();
        assert!((q[0] - 1.0).abs() < 1e-12 && (q[1] - 2.0).abs() < 1e-12 && phi < 1e-20);
    }
}
