//! The unilateral half of the solver: RESO with MINI/MAXI conditions.
//!
//! This file is the driver ([`solve_unilateral`]): it checks the input,
//! picks a method ([`Method`], the automatic choice documented on
//! [`Method::Auto`]), sets the warm start from the [`UnilCache`], and
//! renumbers what the method reports. Every method runs the one status
//! loop of [`status`] over its own linear algebra, so they return the same
//! [`Solution`] from the same decisions:
//!
//! * [`condensed`]: CONDENSE, the default (unilateral.md §3): one
//!   interrupted LDLᵀ onto the second multipliers of the unilateral
//!   conditions, the loop on that dense m×m operator, one partial
//!   substitution back;
//! * [`guyan`]: ANCIEN, Cast3M's old method (§5): Guyan condensation onto
//!   the contact unknowns, the small doubled system refactored per status;
//! * [`sparse`]: CREUX, the loop on the whole sparse system (obstacle
//!   problems, conditions on most unknowns);
//! * [`iterative`]: ITER, the condensed operator formed by preconditioned
//!   CG, no factorisation (§6);
//! * [`nonsymmetric`]: full LU solves per status, for a non-symmetric
//!   operator, whatever the method asked.
//!
//! [`backend`] holds what the methods share with the driver, [`cache`]
//! what is kept between solves, [`dense_ldlt`] the dense factor the
//! condensed and old methods update.

pub mod backend;
pub mod cache;
pub mod condensed;
pub mod dense_ldlt;
pub mod guyan;
pub mod iterative;
pub mod nonsymmetric;
pub mod sparse;
pub mod status;

use crate::solve::error::SolveError;
use crate::solve::problem::{Load, Problem, Solution};
use backend::{to_global, Job, StatusError, Trace};
pub use cache::UnilCache;
pub use condensed::Condensed;
pub use status::{IterRecord, Rule};

/// How the unilateral problem is solved.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Method {
    /// CONDENSE, except CREUX when the conditions touch more than a
    /// quarter of the unknowns (m > n/4, with m > 2000) or when the dense m×m operator
    /// would exceed about 1 GB (8m² bytes, m ≳ 11,000). ITER is never
    /// chosen automatically: the language asks for it ('OPTI RESO ITER').
    #[default]
    Auto,
    /// Interrupted factorisation onto the unilateral λ2 (§3).
    Condense,
    /// Cast3M's old method: Guyan condensation onto the primal unknowns of
    /// the unilateral rows, small doubled system refactored per status (§5).
    Ancien,
    /// G formed by one preconditioned-CG solve per condition (§6).
    Iter,
    /// Status iteration on the full sparse system, symbolic analysis
    /// reused, one numeric factorisation per status (obstacle problems).
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
    /// Return the last iterate when the status iteration does not converge
    /// (RESO 'SOUC'); [`UnilReport::converged`] then says so.
    pub keep_last: bool,
    /// Stops the status iteration between two solves (see
    /// [`status::StatusOptions::cancel`]).
    pub cancel: Option<status::Cancel>,
}

impl Default for UnilOptions {
    fn default() -> Self {
        UnilOptions {
            method: Method::Auto,
            max_iter: None,
            initial: None,
            rule: Rule::Auto,
            keep_last: false,
            cancel: None,
        }
    }
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
    /// False when the iteration stopped without converging and the last
    /// iterate was kept ([`UnilOptions::keep_last`]); the last record then
    /// lists the conditions that still wanted to change.
    pub converged: bool,
}

/// Solves `p` for `load`, unilateral conditions included.
pub fn solve_unilateral(
    p: &Problem,
    load: &Load,
    opts: &UnilOptions,
    cache: &mut UnilCache,
    on_iter: &mut dyn FnMut(&IterRecord),
) -> Result<(Solution, UnilReport), SolveError> {
    let (n, m) = (p.k.n, p.conditions.len());
    if load.f.len() != n || load.d.len() != m {
        return Err(SolveError::Other(format!(
            "load sizes ({}, {}) do not match ({n}, {m})",
            load.f.len(),
            load.d.len()
        )));
    }
    let uni: Vec<usize> = (0..m).filter(|&i| p.conditions[i].kind.is_unilateral()).collect();
    if uni.is_empty() {
        return Err(SolveError::Other("no unilateral condition".into()));
    }
    let method = choose(opts.method, n, uni.len());
    // The warm start belongs to one structure and one condition set.
    let structure = crate::solve::bilateral::lagrange::structure_hash(p);
    if cache.structure != Some(structure) {
        cache.status = None;
        cache.structure = Some(structure);
    }
    let start = match &opts.initial {
        Some(s) if s.len() != uni.len() => {
            return Err(SolveError::Other(format!(
                "{} initial statuses for {} unilateral conditions",
                s.len(),
                uni.len()
            )))
        }
        Some(s) => Some(s.clone()),
        // CREUX starts cold from the unconstrained solution: with conditions
        // on most unknowns, "all active" (Cast3M's cold start) pins the whole
        // body and unpins it ring by ring (obstacle bench, damped rule: 166
        // steps, against 32 from all inactive). A singular start (a body
        // held only by its supports) falls back to all active in `status`.
        None if method == Method::Creux => cache.status.clone().or_else(|| Some(vec![false; uni.len()])),
        None => cache.status.clone(),
    };
    let rule = match opts.rule {
        Rule::Auto if method == Method::Creux => Rule::Mixed,
        Rule::Auto => Rule::Damped,
        r => r,
    };
    let sopts = status::StatusOptions {
        max_iter: opts.max_iter,
        start,
        rule,
        keep_last: opts.keep_last,
        cancel: opts.cancel.clone(),
        adhesion: None,
    };
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
    let mut phases = Vec::new();
    // A non-symmetric operator has no LDLᵀ to condense or to update: every
    // method falls back to full LU solves per status (nonsym.rs).
    let nonsym = !p.k.symmetric;
    let job = Job { p, load, uni: &uni, sopts: &sopts };
    let trace = &mut Trace { on_iter: &mut forward, phases: &mut phases };
    let res = match method {
        _ if nonsym => nonsymmetric::solve(&job, trace),
        Method::Auto | Method::Condense => condensed::solve(&job, &mut cache.condensed, trace),
        Method::Ancien => guyan::solve(&job, trace),
        Method::Creux => sparse::solve(&job, &mut cache.sparse, trace),
        Method::Iter => iterative::solve(&job, trace),
    };
    let (sol, active) = match res {
        Ok(r) => r,
        Err(StatusError::Global(e)) => return Err(e),
        Err(StatusError::Local(e)) => return Err(to_global(e, &uni)),
    };
    let converged = records.last().is_none_or(|r| r.mode != status::UNCONVERGED);
    let report = UnilReport {
        converged,
        method: match method {
            _ if nonsym => "lu",
            Method::Auto | Method::Condense => "condense",
            Method::Ancien => "ancien",
            Method::Creux => "creux",
            Method::Iter => "iter",
        },
        m: uni.len(),
        iterations: records.len(),
        active_count: active.iter().filter(|a| **a).count(),
        records,
        phase_seconds: phases,
    };
    // An unconverged status is no warm start.
    cache.status = if report.converged { Some(active) } else { None };
    Ok((sol, report))
}

/// Below this many conditions the dense operator costs little (≤ 40 ms per
/// factorisation at m = 2000, solver-notes §3.4) whatever n.
const MIN_CREUX: usize = 2000;

/// The automatic choice (see [`Method::Auto`]).
pub(crate) fn choose(asked: Method, n: usize, m: usize) -> Method {
    match asked {
        Method::Auto => {
            // 8m² bytes of dense G above ~1 GB, or conditions on a large
            // fraction of the unknowns (obstacle problems): the dense
            // condensed operator would dominate, the sparse iteration not.
            let dense_bytes = 8.0 * (m as f64) * (m as f64);
            if (4 * m > n && m > MIN_CREUX) || dense_bytes > 1.0e9 {
                Method::Creux
            } else {
                Method::Condense
            }
        }
        other => other,
    }
}

#[cfg(test)]
mod tests;
