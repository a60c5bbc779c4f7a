//! What every backend of the status loop shares with the driver: its
//! error type, the renumbering of conditions, and the fingerprint of a
//! problem's values.

use super::status::{IterRecord, StatusOptions};
use crate::solve::error::SolveError;
use crate::solve::problem::{Load, Problem};

/// What the driver hands every backend: the problem, the load, the
/// unilateral conditions (global numbers, in the order of the status
/// vectors) and the options of the status loop.
#[derive(Clone, Copy)]
pub(crate) struct Job<'a> {
    pub p: &'a Problem,
    pub load: &'a Load,
    pub uni: &'a [usize],
    pub sopts: &'a StatusOptions,
}

/// Where a backend reports: each solve of the status loop (positions among
/// `Job::uni`), and the time of each of its phases.
pub(crate) struct Trace<'a> {
    pub on_iter: &'a mut dyn FnMut(&IterRecord),
    pub phases: &'a mut Vec<(&'static str, f64)>,
}

/// An error in global condition numbers, or one from the status loop in
/// positions among the unilateral conditions.
#[derive(Debug)]
pub(crate) enum StatusError {
    Global(SolveError),
    Local(SolveError),
}

/// What a backend returns: the solution and the final statuses of the
/// unilateral conditions (in their order).
pub(crate) type Outcome = Result<(crate::solve::Solution, Vec<bool>), StatusError>;

/// Condition positions among the unilateral ones → global numbers (or any
/// position map `uni`).
pub(crate) fn to_global(e: SolveError, uni: &[usize]) -> SolveError {
    let g = |v: Vec<usize>| v.into_iter().map(|q| uni.get(q).copied().unwrap_or(q)).collect();
    match e {
        SolveError::DependentConditions { conditions } => SolveError::DependentConditions { conditions: g(conditions) },
        SolveError::Conflicting { conditions } => SolveError::Conflicting { conditions: g(conditions) },
        SolveError::Infeasible { conditions, work } => SolveError::Infeasible { conditions: g(conditions), work },
        SolveError::NoConvergence { iterations, conditions } => {
            SolveError::NoConvergence { iterations, conditions: g(conditions) }
        }
        e => e,
    }
}

/// Fingerprint of the numbers of `p` (K values and condition coefficients),
/// to reuse the numeric factor when nothing changed.
pub(crate) fn values_hash(p: &Problem) -> u64 {
    let mut h: u64 = 0x9e37_79b9_7f4a_7c15;
    let mut mix = |x: f64| {
        h ^= x.to_bits();
        h = h.wrapping_mul(0x0000_0100_0000_01b3).rotate_left(23);
    };
    for &(_, _, v) in &p.k.entries {
        mix(v);
    }
    for c in &p.conditions {
        for &(_, v) in &c.terms {
            mix(v);
        }
    }
    h
}
