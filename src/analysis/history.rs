//! Loads as functions of time: a time function (the EVOLUTIO of a
//! CHARGEMENT) and a load history, the sum of fixed loads each scaled by its
//! time function.
//!
//! For an elastic structure every load of a step is such a sum, so the step
//! driver never re-reads a field: it combines a few vectors per step.

use crate::solve::Load;

/// A piecewise-linear function of time: abscissae increasing, one ordinate
/// each. Outside the abscissae it is not defined (an error, as `IPOL`
/// does: a silent extrapolation of a load is a wrong answer).
#[derive(Debug, Clone, PartialEq)]
pub struct TimeFunction {
    x: Vec<f64>,
    y: Vec<f64>,
}

/// Why a time function could not be built or evaluated.
#[derive(Debug, Clone, PartialEq)]
pub enum TimeError {
    /// No point, lengths that differ, or a non-finite value.
    Invalid(String),
    /// Abscissae that decrease.
    NotIncreasing { at: usize },
    /// A time outside [first, last].
    Outside { t: f64, first: f64, last: f64 },
}

impl std::fmt::Display for TimeError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            TimeError::Invalid(s) => write!(f, "{s}"),
            TimeError::NotIncreasing { at } => {
                write!(f, "the times of the time function decrease at point {}", at + 1)
            }
            TimeError::Outside { t, first, last } => {
                write!(f, "time {t} is outside the time function, defined from {first} to {last}")
            }
        }
    }
}

impl TimeFunction {
    pub fn new(x: Vec<f64>, y: Vec<f64>) -> Result<Self, TimeError> {
        if x.is_empty() || x.len() != y.len() {
            return Err(TimeError::Invalid(format!(
                "a time function needs as many values as times, and at least one ({} times, {} values)",
                x.len(),
                y.len()
            )));
        }
        if !x.iter().chain(&y).all(|v| v.is_finite()) {
            return Err(TimeError::Invalid("a time function holds a non-finite value".into()));
        }
        if let Some(at) = (1..x.len()).find(|&i| x[i] < x[i - 1]) {
            return Err(TimeError::NotIncreasing { at });
        }
        Ok(TimeFunction { x, y })
    }

    /// A function equal to `v` at every time.
    pub fn constant(v: f64) -> Self {
        TimeFunction { x: vec![f64::NEG_INFINITY, f64::INFINITY], y: vec![v, v] }
    }

    pub fn times(&self) -> &[f64] {
        &self.x
    }

    /// The values at [`times`](Self::times).
    pub fn values(&self) -> &[f64] {
        &self.y
    }

    /// The value at `t`, linear between points. At a repeated abscissa (a
    /// jump) the last value given there wins.
    pub fn at(&self, t: f64) -> Result<f64, TimeError> {
        let (x, y) = (&self.x, &self.y);
        let (first, last) = (x[0], x[x.len() - 1]);
        // Times are compared with a relative tolerance: a step list built by
        // PROG 0. PAS 0.1 1. ends at 0.9999999999999999.
        let tol = 1e-12 * first.abs().max(last.abs()).max(1.0);
        if first.is_infinite() {
            return Ok(y[0]);
        }
        if t < first - tol || t > last + tol || !t.is_finite() {
            return Err(TimeError::Outside { t, first, last });
        }
        let t = t.clamp(first, last);
        // The last point at or before t.
        let k = x.partition_point(|&xi| xi <= t).max(1) - 1;
        if k + 1 >= x.len() || x[k] == t {
            return Ok(y[k]);
        }
        let w = (t - x[k]) / (x[k + 1] - x[k]);
        Ok(y[k] + w * (y[k + 1] - y[k]))
    }
}

/// One fixed load and the time function it follows.
#[derive(Debug, Clone)]
pub struct Term {
    pub load: Load,
    pub time: TimeFunction,
}

/// `L(t) = base + Σ fₖ(t) Lₖ`: forces on the unknowns and limits of the
/// conditions (imposed values, gaps) at every time.
///
/// A history has an identity ([`LoadHistory::id`]): the step solver keeps
/// the responses to its loads under it, so a history is built once and not
/// changed afterwards (new loads, new history).
#[derive(Debug, Clone)]
pub struct LoadHistory {
    /// What does not depend on time (the initial gaps of contact).
    pub base: Load,
    pub terms: Vec<Term>,
    id: u64,
}

static NEXT_ID: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(1);

impl LoadHistory {
    /// A history with no load: `n` unknowns, `m` conditions.
    pub fn new(n: usize, m: usize) -> Self {
        let id = NEXT_ID.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        LoadHistory { base: Load { f: vec![0.0; n], d: vec![0.0; m] }, terms: Vec::new(), id }
    }

    pub fn id(&self) -> u64 {
        self.id
    }

    /// The weight of each term at time `t`.
    pub fn coefficients(&self, t: f64) -> Result<Vec<f64>, TimeError> {
        self.terms.iter().map(|term| term.time.at(t)).collect()
    }

    /// `base + Σ cₖ Lₖ`.
    pub fn combine(&self, c: &[f64]) -> Load {
        let mut l = self.base.clone();
        for (term, &ck) in self.terms.iter().zip(c) {
            if ck != 0.0 {
                axpy(&mut l.f, ck, &term.load.f);
                axpy(&mut l.d, ck, &term.load.d);
            }
        }
        l
    }

    /// The limits of `base + Σ cₖ Lₖ` only.
    pub fn combine_limits(&self, c: &[f64]) -> Vec<f64> {
        let mut d = self.base.d.clone();
        for (term, &ck) in self.terms.iter().zip(c) {
            if ck != 0.0 {
                axpy(&mut d, ck, &term.load.d);
            }
        }
        d
    }

    /// The load at time `t`.
    pub fn at(&self, t: f64) -> Result<Load, TimeError> {
        Ok(self.combine(&self.coefficients(t)?))
    }
}

pub(crate) fn axpy(y: &mut [f64], a: f64, x: &[f64]) {
    for (yi, xi) in y.iter_mut().zip(x) {
        *yi += a * xi;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_between_points_and_jumps_take_the_last_value() {
        let f = TimeFunction::new(vec![0.0, 1.0, 1.0, 3.0], vec![0.0, 2.0, 5.0, 1.0]).unwrap();
        assert_eq!(f.at(0.5).unwrap(), 1.0);
        assert_eq!(f.at(1.0).unwrap(), 5.0);
        assert_eq!(f.at(2.0).unwrap(), 3.0);
        assert_eq!(f.at(3.0).unwrap(), 1.0);
        assert!(matches!(f.at(3.5), Err(TimeError::Outside { .. })));
        assert!(matches!(f.at(-0.1), Err(TimeError::Outside { .. })));
        // Round-off at the ends is not outside.
        assert_eq!(f.at(3.0 + 1e-15).unwrap(), 1.0);
    }

    #[test]
    fn bad_functions_are_refused() {
        assert!(TimeFunction::new(vec![], vec![]).is_err());
        assert!(TimeFunction::new(vec![0.0, 1.0], vec![0.0]).is_err());
        assert_eq!(TimeFunction::new(vec![0.0, 2.0, 1.0], vec![0.0; 3]), Err(TimeError::NotIncreasing { at: 2 }));
        assert!(TimeFunction::new(vec![0.0, f64::NAN], vec![0.0; 2]).is_err());
    }

    #[test]
    fn history_sums_scaled_loads() {
        let mut h = LoadHistory::new(2, 1);
        h.base.d[0] = -0.5;
        let ramp = TimeFunction::new(vec![0.0, 2.0], vec![0.0, 2.0]).unwrap();
        h.terms.push(Term { load: Load { f: vec![1.0, 3.0], d: vec![0.0] }, time: ramp });
        h.terms.push(Term { load: Load { f: vec![0.0, 0.0], d: vec![1.0] }, time: TimeFunction::constant(4.0) });
        let l = h.at(1.5).unwrap();
        assert_eq!(l.f, vec![1.5, 4.5]);
        assert_eq!(l.d, vec![3.5]);
    }
}
