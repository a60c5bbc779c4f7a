//! A property as a piecewise-linear function of one parameter (a curve
//! given point by point), evaluated as Cast3M's VARI does: linear between
//! the points, and prolonged by the first and the last segment outside
//! them (not clamped: a Young's modulus linear in the temperature stays
//! linear past the last point given).

use std::fmt;

#[derive(Debug, Clone, PartialEq)]
pub enum CurveError {
    /// No point at all.
    Empty,
    /// The abscissae neither strictly increase nor strictly decrease.
    NotMonotonic,
    /// Lengths of the abscissae and ordinates differ.
    Lengths(usize, usize),
    /// A parameter or result that is not a finite number.
    NotFinite(f64),
}

impl fmt::Display for CurveError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CurveError::Empty => write!(f, "the curve has no point"),
            CurveError::NotMonotonic => {
                write!(f, "the curve's abscissae must be strictly increasing or strictly decreasing")
            }
            CurveError::Lengths(x, y) => write!(f, "the curve has {} abscissae but {} ordinates", x, y),
            CurveError::NotFinite(v) => write!(f, "the curve gives {} there, not a finite number", v),
        }
    }
}

/// Check that (xs, ys) can be evaluated: same length, at least one point,
/// strictly monotonic abscissae.
pub fn check(xs: &[f64], ys: &[f64]) -> Result<(), CurveError> {
    if xs.len() != ys.len() {
        return Err(CurveError::Lengths(xs.len(), ys.len()));
    }
    if xs.is_empty() {
        return Err(CurveError::Empty);
    }
    let up = xs.windows(2).all(|w| w[1] > w[0]);
    let down = xs.windows(2).all(|w| w[1] < w[0]);
    if !(up || down) {
        return Err(CurveError::NotMonotonic);
    }
    Ok(())
}

/// y(x) on the polyline (xs, ys), prolonged linearly at both ends; a curve
/// of a single point is a constant.
pub fn eval(xs: &[f64], ys: &[f64], x: f64) -> Result<f64, CurveError> {
    check(xs, ys)?;
    if !x.is_finite() {
        return Err(CurveError::NotFinite(x));
    }
    let n = xs.len();
    if n == 1 {
        return Ok(ys[0]);
    }
    let up = xs[n - 1] > xs[0];
    // The first segment whose right end lies past x (the last one past
    // the end): the same segment choice as a left-to-right scan.
    let past = |xi: f64| if up { xi > x } else { xi < x };
    let j = (1..n).find(|&i| past(xs[i])).unwrap_or(n - 1);
    let (x0, x1, y0, y1) = (xs[j - 1], xs[j], ys[j - 1], ys[j]);
    let y = y0 + (y1 - y0) / (x1 - x0) * (x - x0);
    if y.is_finite() {
        Ok(y)
    } else {
        Err(CurveError::NotFinite(y))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interpolates_and_prolongs_the_end_segments() {
        let (x, y) = ([0.0, 100.0, 200.0], [2.0e11, 1.9e11, 1.7e11]);
        assert_eq!(eval(&x, &y, 50.0).unwrap(), 1.95e11);
        assert_eq!(eval(&x, &y, 150.0).unwrap(), 1.8e11);
        // Past the last point: the slope of the last segment (-2e8 per unit).
        assert_eq!(eval(&x, &y, 300.0).unwrap(), 1.5e11);
        // Before the first: the slope of the first (-1e8 per unit).
        assert_eq!(eval(&x, &y, -100.0).unwrap(), 2.1e11);
        assert_eq!(eval(&x, &y, 100.0).unwrap(), 1.9e11);
    }

    #[test]
    fn decreasing_abscissae_and_single_points() {
        let (x, y) = ([10.0, 0.0], [1.0, 3.0]);
        assert_eq!(eval(&x, &y, 5.0).unwrap(), 2.0);
        assert_eq!(eval(&x, &y, 20.0).unwrap(), -1.0);
        assert_eq!(eval(&[1.0], &[7.0], 99.0).unwrap(), 7.0);
    }

    #[test]
    fn refuses_bad_curves_and_parameters() {
        assert_eq!(eval(&[0.0, 0.0], &[1.0, 2.0], 0.0), Err(CurveError::NotMonotonic));
        assert_eq!(eval(&[], &[], 0.0), Err(CurveError::Empty));
        assert_eq!(eval(&[0.0], &[1.0, 2.0], 0.0), Err(CurveError::Lengths(1, 2)));
        assert!(matches!(eval(&[0.0, 1.0], &[1.0, 2.0], f64::NAN), Err(CurveError::NotFinite(_))));
    }
}
