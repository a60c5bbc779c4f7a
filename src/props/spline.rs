//! Cubic spline through sampled points (IPOL 'SPLI'): second derivatives
//! from the tridiagonal continuity system, with either the natural end
//! condition (zero second derivative) or a given first derivative at each
//! end. Outside the abscissae the spline is held at its end value, as the
//! linear interpolation of IPOL is.

/// The end condition at one side of the spline.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum End {
    /// Zero second derivative.
    Natural,
    /// The first derivative dy/dx given.
    Slope(f64),
}

/// A spline ready to evaluate: abscissae made increasing, and the second
/// derivative at every point.
#[derive(Debug, Clone)]
pub struct Spline {
    xs: Vec<f64>,
    ys: Vec<f64>,
    m: Vec<f64>,
}

impl Spline {
    /// Build through (xs, ys). The abscissae must be strictly monotonic
    /// and as many as the ordinates (the caller checks); decreasing ones
    /// are reversed. `left` holds at the smallest abscissa, `right` at
    /// the largest, whatever order they are written in.
    pub fn new(xs: &[f64], ys: &[f64], left: End, right: End) -> Spline {
        let n = xs.len();
        let (mut xs, mut ys) = (xs.to_vec(), ys.to_vec());
        if n > 1 && xs[n - 1] < xs[0] {
            xs.reverse();
            ys.reverse();
        }
        let m = if n < 2 { vec![0.0; n] } else { second_derivatives(&xs, &ys, left, right) };
        Spline { xs, ys, m }
    }

    /// The spline at `t`; the end values outside the abscissae.
    pub fn eval(&self, t: f64) -> f64 {
        let (xs, ys, m) = (&self.xs, &self.ys, &self.m);
        let n = xs.len();
        if n == 1 || t <= xs[0] {
            return ys[0];
        }
        if t >= xs[n - 1] {
            return ys[n - 1];
        }
        let j = xs.partition_point(|x| *x < t).clamp(1, n - 1);
        let (x0, x1) = (xs[j - 1], xs[j]);
        let h = x1 - x0;
        let (a, b) = (x1 - t, t - x0);
        m[j - 1] * a.powi(3) / (6.0 * h)
            + m[j] * b.powi(3) / (6.0 * h)
            + (ys[j - 1] / h - m[j - 1] * h / 6.0) * a
            + (ys[j] / h - m[j] * h / 6.0) * b
    }
}

/// Second derivatives at the points (increasing xs, at least two): the
/// tridiagonal system solved by elimination (Thomas), which needs no
/// pivoting since it is diagonally dominant.
fn second_derivatives(xs: &[f64], ys: &[f64], left: End, right: End) -> Vec<f64> {
    let n = xs.len();
    let h: Vec<f64> = xs.windows(2).map(|w| w[1] - w[0]).collect();
    let slope: Vec<f64> = (0..n - 1).map(|i| (ys[i + 1] - ys[i]) / h[i]).collect();
    // Row i: sub[i] m[i-1] + diag[i] m[i] + sup[i] m[i+1] = rhs[i].
    let (mut sub, mut diag, mut sup, mut rhs) = (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    for i in 1..n - 1 {
        sub[i] = h[i - 1];
        diag[i] = 2.0 * (h[i - 1] + h[i]);
        sup[i] = h[i];
        rhs[i] = 6.0 * (slope[i] - slope[i - 1]);
    }
    match left {
        End::Natural => diag[0] = 1.0,
        End::Slope(d) => {
            diag[0] = 2.0 * h[0];
            sup[0] = h[0];
            rhs[0] = 6.0 * (slope[0] - d);
        }
    }
    match right {
        End::Natural => diag[n - 1] = 1.0,
        End::Slope(d) => {
            sub[n - 1] = h[n - 2];
            diag[n - 1] = 2.0 * h[n - 2];
            rhs[n - 1] = 6.0 * (d - slope[n - 2]);
        }
    }
    for i in 1..n {
        let w = sub[i] / diag[i - 1];
        diag[i] -= w * sup[i - 1];
        rhs[i] -= w * rhs[i - 1];
    }
    let mut m = vec![0.0; n];
    m[n - 1] = rhs[n - 1] / diag[n - 1];
    for i in (0..n - 1).rev() {
        m[i] = (rhs[i] - sup[i] * m[i + 1]) / diag[i];
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn natural_spline_of_a_line_is_the_line() {
        let s = Spline::new(&[0.0, 1.0, 3.0], &[1.0, 3.0, 7.0], End::Natural, End::Natural);
        for t in [0.0, 0.5, 2.0, 3.0] {
            assert!((s.eval(t) - (1.0 + 2.0 * t)).abs() < 1e-12);
        }
        assert_eq!(s.eval(-1.0), 1.0);
        assert_eq!(s.eval(5.0), 7.0);
    }

    #[test]
    fn clamped_spline_reproduces_a_cubic() {
        // y = x^3 on [0, 2]: slopes 0 and 12 at the ends; a clamped spline
        // is exact for any cubic.
        let xs = [0.0, 0.5, 1.0, 2.0];
        let ys: Vec<f64> = xs.iter().map(|x: &f64| x.powi(3)).collect();
        let s = Spline::new(&xs, &ys, End::Slope(0.0), End::Slope(12.0));
        for t in [0.25, 0.75, 1.5, 1.9] {
            assert!((s.eval(t) - t * t * t).abs() < 1e-12, "{}", t);
        }
        // Decreasing abscissae: the same spline.
        let (mut rx, mut ry) = (xs.to_vec(), ys.clone());
        rx.reverse();
        ry.reverse();
        let r = Spline::new(&rx, &ry, End::Slope(0.0), End::Slope(12.0));
        assert!((r.eval(1.5) - 3.375).abs() < 1e-12);
    }
}
