//! Covariance of a stationary random field between points, and its
//! Cholesky factor (DCOV): a field `F = L G` with `G` white noise of unit
//! variance has covariance `L L^T = C`.

/// The law of correlation against the (scaled) distance.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Law {
    /// `s^2 exp(-d)`.
    Exponential,
    /// `s^2 exp(-d^2)`.
    Gaussian,
}

/// How distances are measured: isotropic (`d = r / lambda` for the
/// exponential law, `d^2 = r^2 / lambda` for the Gaussian one, as
/// dcov.notice writes them) or along the axes of `frame` with a
/// correlation length each.
pub enum Metric {
    Isotropic(f64),
    Axes { frame: Vec<[f64; 3]>, lengths: Vec<f64> },
}

/// The covariance matrix (row-major n x n) between the points.
pub fn matrix(points: &[[f64; 3]], law: Law, sigma: f64, metric: &Metric) -> Vec<f64> {
    let n = points.len();
    let mut c = vec![0.0; n * n];
    for i in 0..n {
        for j in 0..n {
            let d = [points[i][0] - points[j][0], points[i][1] - points[j][1], points[i][2] - points[j][2]];
            // The squared scaled distance.
            let q = match metric {
                Metric::Isotropic(l) => {
                    let r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
                    match law {
                        Law::Exponential => r2 / (l * l),
                        Law::Gaussian => r2 / l,
                    }
                }
                Metric::Axes { frame, lengths } => frame
                    .iter()
                    .zip(lengths)
                    .map(|(e, l)| {
                        let p = (e[0] * d[0] + e[1] * d[1] + e[2] * d[2]) / l;
                        p * p
                    })
                    .sum(),
            };
            let arg = match law {
                Law::Exponential => q.sqrt(),
                Law::Gaussian => q,
            };
            c[i * n + j] = sigma * sigma * (-arg).exp();
        }
    }
    c
}

/// The lower Cholesky factor of a symmetric positive-definite matrix
/// (row-major, upper part zero). The matrices are dense and small (one
/// row per point of a mesh), so the plain column algorithm is enough.
pub fn cholesky(a: &[f64], n: usize) -> Result<Vec<f64>, String> {
    let mut l = vec![0.0; n * n];
    for j in 0..n {
        let mut d = a[j * n + j];
        for k in 0..j {
            d -= l[j * n + k] * l[j * n + k];
        }
        if d.is_nan() || d <= 0.0 {
            return Err(format!(
                "the covariance matrix is not positive definite (pivot {} of {}): points too close for the correlation length?",
                j + 1,
                n
            ));
        }
        let d = d.sqrt();
        l[j * n + j] = d;
        for i in j + 1..n {
            let mut s = a[i * n + j];
            for k in 0..j {
                s -= l[i * n + k] * l[j * n + k];
            }
            l[i * n + j] = s / d;
        }
    }
    Ok(l)
}
