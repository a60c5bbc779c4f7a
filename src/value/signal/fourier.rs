//! Discrete Fourier transforms of sampled signals, scaled as the
//! continuous transform: for samples x_j at step dt, the value at the
//! frequency k / (n dt) is dt · Σ x_j e^(-2iπ jk/n), so that the inverse,
//! df · Σ X_k e^(2iπ jk/n) over the whole (Hermitian) spectrum, gives the
//! samples back. rustfft does the transforms.

use rustfft::num_complex::Complex64;
use rustfft::FftPlanner;

/// The one-sided spectrum of a real signal at harmonics `first..=last`
/// (0-based, `last <= n / 2`) of an `n`-point transform; `x` is cut or
/// padded with zeros to `n` points.
pub struct Spectrum {
    pub freq: Vec<f64>,
    pub re: Vec<f64>,
    pub im: Vec<f64>,
}

pub fn forward(x: &[f64], dt: f64, n: usize, first: usize, last: usize) -> Spectrum {
    let mut buf: Vec<Complex64> = (0..n).map(|j| Complex64::new(x.get(j).copied().unwrap_or(0.0), 0.0)).collect();
    FftPlanner::new().plan_fft_forward(n).process(&mut buf);
    let df = 1.0 / (dt * n as f64);
    let mut s = Spectrum { freq: vec![], re: vec![], im: vec![] };
    for (k, z) in buf.iter().enumerate().take(last + 1).skip(first) {
        s.freq.push(k as f64 * df);
        s.re.push(dt * z.re);
        // The constant and the middle harmonic of a real signal are real.
        s.im.push(if k == 0 || 2 * k == n { 0.0 } else { dt * z.im });
    }
    s
}

/// The real signal whose one-sided spectrum at harmonics 0, 1, … m is
/// (`re`, `im`) at frequency step `df`: 2(m) samples at step
/// 1 / (2 m df). The imaginary parts of the constant and of the last
/// harmonic are ignored (they are zero for a real signal).
pub fn inverse(re: &[f64], im: &[f64], df: f64) -> (Vec<f64>, Vec<f64>) {
    let m = re.len() - 1;
    let n = 2 * m;
    let mut buf = vec![Complex64::new(0.0, 0.0); n];
    buf[0] = Complex64::new(re[0], 0.0);
    for k in 1..m {
        buf[k] = Complex64::new(re[k], im[k]);
        buf[n - k] = Complex64::new(re[k], -im[k]);
    }
    buf[m] = Complex64::new(re[m], 0.0);
    FftPlanner::new().plan_fft_inverse(n).process(&mut buf);
    let dt = 1.0 / (df * n as f64);
    let t = (0..n).map(|j| j as f64 * dt).collect();
    let y = buf.iter().map(|z| df * z.re).collect();
    (t, y)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inverse_gives_the_signal_back() {
        let x: Vec<f64> = (0..16).map(|j| (j as f64 * 0.7).sin() + 0.1 * j as f64).collect();
        let s = forward(&x, 0.5, 16, 0, 8);
        assert!((s.re[0] - 0.5 * x.iter().sum::<f64>()).abs() < 1e-12);
        let (t, y) = inverse(&s.re, &s.im, s.freq[1]);
        assert!((t[1] - 0.5).abs() < 1e-12);
        for (a, b) in x.iter().zip(&y) {
            assert!((a - b).abs() < 1e-12);
        }
    }
}
