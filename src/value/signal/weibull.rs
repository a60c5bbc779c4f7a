//! Weibull parameters of a sample of failure stresses (WEIP).

/// Maximum-likelihood Weibull modulus `m` and characteristic stress
/// `s` of a sample: `P(failure at sigma) = 1 - exp(-(sigma/s)^m)`.
/// The likelihood equation in `m` alone, `sum(x^m ln x)/sum(x^m) - 1/m
/// - mean(ln x) = 0`, increases with `m`: bisection finds its root.
pub fn fit(sample: &[f64]) -> Result<(f64, f64), String> {
    if sample.len() < 2 {
        return Err(format!("a Weibull fit needs at least 2 values, found {}", sample.len()));
    }
    if let Some(bad) = sample.iter().find(|&&x| !(x > 0.0 && x.is_finite())) {
        return Err(format!("the failure stresses must be positive, found {}", bad));
    }
    let top = sample.iter().cloned().fold(0.0, f64::max);
    // Scaled by the largest value so x^m stays finite for large m.
    let u: Vec<f64> = sample.iter().map(|x| x / top).collect();
    let mean_ln = u.iter().map(|x| x.ln()).sum::<f64>() / u.len() as f64;
    if mean_ln.abs() < 1e-15 {
        return Err("the failure stresses are all equal: no Weibull modulus".into());
    }
    let g = |m: f64| {
        let (mut a, mut b) = (0.0, 0.0);
        for &x in &u {
            let p = x.powf(m);
            a += p * x.ln();
            b += p;
        }
        a / b - 1.0 / m - mean_ln
    };
    let (mut lo, mut hi) = (1e-3, 1.0);
    while g(hi) < 0.0 {
        hi *= 2.0;
        if hi > 1e6 {
            return Err("no Weibull modulus fits the values".into());
        }
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if g(mid) < 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let m = 0.5 * (lo + hi);
    let s = top * (u.iter().map(|x| x.powf(m)).sum::<f64>() / u.len() as f64).powf(1.0 / m);
    Ok((m, s))
}

/// The effective volume of a four-point bending bar (loads `d2` apart,
/// supports `d1` apart, cross-section `area`) for a Weibull modulus `m`:
/// the bar's stressed volume weighted by `(sigma/sigma_max)^m`, tension side only.
pub fn four_point_volume(m: f64, d1: f64, d2: f64, area: f64) -> f64 {
    area * d1 * (m * d2 / d1 + 1.0) / (2.0 * (m + 1.0) * (m + 1.0))
}
