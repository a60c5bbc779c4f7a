//! The UNIL driver: RESO with unilateral conditions.
//!
//! Default method (CONDENSE, unilateral.md §3): one interrupted LDLᵀ gives
//! the condensed operator on the second multipliers of the unilateral
//! conditions; the status iteration runs on that dense m×m problem; one
//! partial substitution recovers u and the multipliers.
//!
//! The [`UnilCache`] lives with the RIGIDITE object on the language side:
//! it keeps the condenser (symbolic analysis always reusable for the same
//! structure, numeric factor reused when the values are identical too) and
//! the last converged statuses, the warm start of the next RESO.

use std::time::Instant;

use super::condense::Condenser;
use super::error::SolveError;
use super::problem::{Load, Problem, Solution};
use super::status;
pub use status::{IterRecord, Rule};

/// How the unilateral problem is solved.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Method {
    /// Currently CONDENSE.
    #[default]
    Auto,
    /// Interrupted factorisation onto the unilateral λ2 (§3).
    Condense,
    /// Cast3M's old method (SUPER onto the primal unknowns): not wired yet.
    Ancien,
    /// G formed by one iterative solve per condition: not implemented.
    Iter,
    /// Status iteration on the full sparse doubled system: not implemented.
    Creux,
}

#[derive(Debug, Clone, PartialEq)]
pub struct UnilOptions {
    pub method: Method,
    pub max_iter: Option<usize>,
    /// Initial statuses ('INIB'), one per unilateral condition in the order
    /// of `Problem::conditions`; overrides the cached warm start.
    pub initial: Option<Vec<bool>>,
    pub rule: Rule,
}

impl Default for UnilOptions {
    fn default() -> Self {
        UnilOptions { method: Method::Auto, max_iter: None, initial: None, rule: Rule::Damped }
    }
}

/// State kept between RESO calls on the same operator.
#[derive(Debug, Default)]
pub struct UnilCache {
    condenser: Option<Condenser>,
    values: u64,
    /// Final statuses of the last converged solve (unilateral order).
    pub status: Option<Vec<bool>>,
}

#[derive(Debug, Clone)]
pub struct UnilReport {
    pub method: &'static str,
    /// Number of unilateral conditions.
    pub m: usize,
    pub iterations: usize,
    /// Status records, with global condition numbers.
    pub records: Vec<IterRecord>,
    pub active_count: usize,
    pub phase_seconds: Vec<(&'static str, f64)>,
}

/// Solves `p` for `load`, unilateral conditions included.
pub fn solve_unilateral(
    p: &Problem,
    load: &Load,
    opts: &UnilOptions,
    cache: &mut UnilCache,
    on_iter: &mut dyn FnMut(&IterRecord),
) -> Result<(Solution, UnilReport), SolveError> {
    match opts.method {
        Method::Auto | Method::Condense => {}
        Method::Ancien | Method::Iter | Method::Creux => {
            return Err(SolveError::Other(format!("unilateral method {:?} is not available yet", opts.method)))
        }
    }
    let mut phases = Vec::new();
    let t0 = Instant::now();
    let values = values_hash(p);
    let reuse = cache.condenser.as_ref().is_some_and(|c| c.same_pattern(p));
    if !reuse {
        cache.condenser = None;
        cache.status = None;
        cache.condenser = Some(Condenser::new(p)?);
    } else if cache.values != values {
        let c = cache.condenser.as_mut().expect("checked above");
        if let Err(e) = c.refactor(p) {
            cache.condenser = None;
            return Err(e);
        }
    }
    cache.values = values;
    let cond = cache.condenser.as_ref().expect("built above");
    let uni = cond.unilateral().to_vec();
    let condensed = cond.condensed(load)?;
    phases.push(("condense", t0.elapsed().as_secs_f64()));

    let t1 = Instant::now();
    let start = match &opts.initial {
        Some(s) if s.len() != uni.len() => {
            return Err(SolveError::Other(format!(
                "{} initial statuses for {} unilateral conditions",
                s.len(),
                uni.len()
            )))
        }
        Some(s) => Some(s.clone()),
        None => cache.status.clone(),
    };
    let sopts = status::StatusOptions { max_iter: opts.max_iter, start, rule: opts.rule };
    let global = |v: &[usize]| v.iter().map(|&q| uni[q]).collect::<Vec<_>>();
    let mut records = Vec::new();
    let mut forward = |r: &IterRecord| {
        let g = IterRecord {
            iteration: r.iteration,
            activated: global(&r.activated),
            released: global(&r.released),
            worst_violation: r.worst_violation,
            worst_wrong_sign: r.worst_wrong_sign,
            active_count: r.active_count,
            mode: r.mode,
        };
        on_iter(&g);
        records.push(g);
    };
    let res = status::run(&condensed, &sopts, &mut forward).map_err(|e| to_global(e, &uni))?;
    phases.push(("status", t1.elapsed().as_secs_f64()));

    let t2 = Instant::now();
    let sol = cond.recover(load, &res.x, &res.active)?;
    phases.push(("recover", t2.elapsed().as_secs_f64()));
    cache.status = Some(res.active.clone());
    let report = UnilReport {
        method: "condense",
        m: uni.len(),
        iterations: records.len(),
        active_count: res.active.iter().filter(|a| **a).count(),
        records,
        phase_seconds: phases,
    };
    Ok((sol, report))
}

/// Condition positions among the unilateral ones → global numbers.
fn to_global(e: SolveError, uni: &[usize]) -> SolveError {
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
fn values_hash(p: &Problem) -> u64 {
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

#[cfg(test)]
#[path = "unilateral_tests.rs"]
mod tests;
