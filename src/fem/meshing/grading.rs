//! How DROI, CERC and TRAN divide a length: equal elements, or elements
//! graded by densities (`'DINI'`/`'DFIN'` or the densities stored with the
//! end points).
//!
//! # The grading rule
//!
//! A density is a target element size. Along a line of length `L` from a
//! point of density `d1` to a point of density `d2` we take the target size
//! to vary linearly, `d(s) = d1 + (d2 - d1) s / L`, and place the nodes at
//! equal increments of `∫ ds / d(s)` (the "number of elements so far").
//! This gives, with `r = d2 / d1` and `n` elements, node `k` at
//!
//! ```text
//!     s_k / L = (r^(k/n) - 1) / (r - 1)        (s_k / L = k / n when r = 1)
//! ```
//!
//! so element sizes form a geometric progression of ratio `r^(1/n)`, the
//! first and last sizes stand in the ratio `≈ d1 / d2`, and the sizes add
//! up to `L` exactly. When the count is not given it is the integral itself,
//! rounded to the nearest integer and at least 1:
//! `n = L ln(d2 / d1) / (d2 - d1)` (`n = L / d1` when `d1 = d2`).
//!
//! Which inputs grade (Cast3M's DROI rules): a positive `n` alone gives `n`
//! equal elements; a positive `n` with `'DINI'` or `'DFIN'` gives `n`
//! elements graded between those densities; a negative `n` gives `|n|`
//! elements graded by the densities (node densities unless overridden, equal
//! elements if no density is positive); no `n` derives the count from the
//! densities, which must then be positive.

use super::{fail, MeshError};

/// How to divide a length: Cast3M's optional count and `'DINI'`/`'DFIN'`.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Spacing {
    /// `Some(n > 0)`: n elements (equal unless a density keyword is given);
    /// `Some(n < 0)`: |n| elements graded by densities; `None` or
    /// `Some(0)`: the count comes from the densities.
    pub n: Option<i64>,
    /// `'DINI'`: density (target element size) at the start.
    pub dini: Option<f64>,
    /// `'DFIN'`: density (target element size) at the end.
    pub dfin: Option<f64>,
}

impl Spacing {
    /// `n` equal elements.
    pub fn count(n: i64) -> Self {
        Spacing { n: Some(n), dini: None, dfin: None }
    }

    /// Add `'DINI' d1 'DFIN' d2`.
    pub fn densities(self, d1: f64, d2: f64) -> Self {
        Spacing { dini: Some(d1), dfin: Some(d2), ..self }
    }
}

/// The node positions of a divided length as fractions `0 = t_0 < ... <
/// t_n = 1`. `length` is the true length (used only to derive a count);
/// `node_d1`/`node_d2` are the densities stored with the end points, used
/// when `'DINI'`/`'DFIN'` are absent.
pub fn fractions(
    op: &'static str,
    spacing: &Spacing,
    length: f64,
    node_d1: f64,
    node_d2: f64,
) -> Result<Vec<f64>, MeshError> {
    for (kw, d) in [("DINI", spacing.dini), ("DFIN", spacing.dfin)] {
        if let Some(d) = d {
            if !(d > 0.0 && d.is_finite()) {
                return fail(op, format!("the density after '{kw}' must be positive (got {d})"));
            }
        }
    }
    if !length.is_finite() {
        return fail(op, "the length to divide overflows (the end points are too far apart)");
    }
    if length <= 0.0 {
        // One element joins the two points as they are: nothing to place
        // (a Voronoi vertex met twice gives such an edge, merged by ELIM).
        if spacing.n == Some(1) {
            return Ok(uniform(1));
        }
        return fail(op, "the length to divide is zero (the end points coincide)");
    }
    if let Some(n) = spacing.n {
        if n.unsigned_abs() as usize > MAX_COUNT {
            return fail(op, format!("{n} elements is more than the {MAX_COUNT} allowed"));
        }
    }
    let (d1, d2) = end_densities(spacing, node_d1, node_d2);
    let explicit = spacing.dini.is_some() || spacing.dfin.is_some();
    match spacing.n {
        Some(n) if n > 0 && !explicit => Ok(uniform(n as usize)),
        Some(n) if n != 0 => match (d1, d2) {
            (Some(d1), Some(d2)) => Ok(graded(n.unsigned_abs() as usize, d1, d2)),
            _ => Ok(uniform(n.unsigned_abs() as usize)),
        },
        _ => match (d1, d2) {
            (Some(d1), Some(d2)) => match count_from_densities(length, d1, d2) {
                Some(n) => Ok(graded(n, d1, d2)),
                None => fail(
                    op,
                    format!(
                        "the densities ({d1}, {d2}) ask for more than {MAX_COUNT} elements \
                         over a length of {length}"
                    ),
                ),
            },
            _ => fail(
                op,
                "no element count given and the densities of the end points are not positive \
                 (give a count, 'DINI'/'DFIN', or set OPTI DENS before creating the points)",
            ),
        },
    }
}

/// The densities used at both ends: the keywords first, then the node
/// densities. If only one end has a positive density it is used for both
/// (a constant target size); `None` when neither has one.
fn end_densities(s: &Spacing, node_d1: f64, node_d2: f64) -> (Option<f64>, Option<f64>) {
    let pos = |d: f64| (d > 0.0 && d.is_finite()).then_some(d);
    let d1 = s.dini.or(pos(node_d1));
    let d2 = s.dfin.or(pos(node_d2));
    match (d1, d2) {
        (Some(a), None) => (Some(a), Some(a)),
        (None, Some(b)) => (Some(b), Some(b)),
        other => other,
    }
}

/// Equal division in `n` parts.
pub fn uniform(n: usize) -> Vec<f64> {
    let n = n.max(1);
    (0..=n).map(|k| k as f64 / n as f64).collect()
}

/// Nodes at equal increments of `∫ ds / d(s)` for a linear target size.
fn graded(n: usize, d1: f64, d2: f64) -> Vec<f64> {
    let n = n.max(1);
    let r = d2 / d1;
    if (r - 1.0).abs() < 1e-12 {
        return uniform(n);
    }
    let mut t: Vec<f64> = (0..=n).map(|k| (r.powf(k as f64 / n as f64) - 1.0) / (r - 1.0)).collect();
    // Pin the ends so the sizes add up to the length to the last bit.
    t[0] = 0.0;
    t[n] = 1.0;
    t
}

/// A count above this is surely a typo (or a density in the wrong unit);
/// refusing it keeps memory safe.
pub(crate) const MAX_COUNT: usize = 10_000_000;

/// `round(∫_0^L ds / d(s))`, at least 1; `None` above [`MAX_COUNT`].
fn count_from_densities(length: f64, d1: f64, d2: f64) -> Option<usize> {
    let x = if ((d2 - d1) / d1).abs() < 1e-12 { length / d1 } else { length * (d2 / d1).ln() / (d2 - d1) };
    if !x.is_finite() || x > MAX_COUNT as f64 {
        None
    } else {
        Some((x.round() as usize).max(1))
    }
}
