//! The UNIL driver: RESO with unilateral conditions.
//!
//! Default method (CONDENSE, unilateral.md §3): one interrupted LDLᵀ gives
//! the condensed operator on the second multipliers of the unilateral
//! conditions; the status iteration runs on that dense m×m problem; one
//! partial substitution recovers u and the multipliers. The other methods
//! ([`Method`]) return the same [`Solution`] and make the same status
//! decisions (the loop of [`status`] over their own linear algebra); the
//! automatic choice is documented on [`Method::Auto`].
//!
//! The [`UnilCache`] lives with the RIGIDITE object on the language side:
//! it keeps the condenser or CREUX's sparse operator (symbolic analysis
//! always reusable for the same structure, numeric factor reused when the
//! values are identical too) and the last converged statuses, the warm
//! start of the next RESO (reset when the structure changes).

use std::time::Instant;

use super::condense::Condenser;
use super::error::SolveError;
use super::problem::{Load, Problem, Solution};
use super::status;
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
}

impl Default for UnilOptions {
    fn default() -> Self {
        UnilOptions { method: Method::Auto, max_iter: None, initial: None, rule: Rule::Auto, keep_last: false }
    }
}

/// State kept between RESO calls on the same operator.
#[derive(Debug, Default)]
pub struct UnilCache {
    condenser: Option<Condenser>,
    values: u64,
    /// Structure the warm start belongs to.
    structure: Option<u64>,
    /// CREUX: the sparse operator with its symbolic analysis.
    pub(super) creux: Option<super::creux::Creux>,
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
    let structure = super::lagrange::structure_hash(p);
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
    let sopts =
        status::StatusOptions { max_iter: opts.max_iter, start, rule, keep_last: opts.keep_last, adhesion: None };
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
    let res = match method {
        _ if nonsym => super::nonsym::solve(p, load, &uni, &sopts, &mut forward, &mut phases),
        Method::Auto | Method::Condense => condense(p, load, &sopts, cache, &mut forward, &mut phases),
        Method::Ancien => super::uni_ancien::solve(p, load, &uni, &sopts, &mut forward, &mut phases),
        Method::Creux => super::creux::solve(p, load, &uni, &sopts, cache, &mut forward, &mut phases),
        Method::Iter => super::iter::solve(p, load, &uni, &sopts, &mut forward, &mut phases),
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
fn choose(asked: Method, n: usize, m: usize) -> Method {
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

/// An error in global condition numbers, or one from the status loop in
/// positions among the unilateral conditions.
#[derive(Debug)]
pub(super) enum StatusError {
    Global(SolveError),
    Local(SolveError),
}

/// CONDENSE: interrupted factorisation, dense status loop, recovery.
fn condense(
    p: &Problem,
    load: &Load,
    sopts: &status::StatusOptions,
    cache: &mut UnilCache,
    on_iter: &mut dyn FnMut(&IterRecord),
    phases: &mut Vec<(&'static str, f64)>,
) -> Result<(Solution, Vec<bool>), StatusError> {
    let g = StatusError::Global;
    let t0 = Instant::now();
    let values = values_hash(p);
    let reuse = cache.condenser.as_ref().is_some_and(|c| c.same_pattern(p));
    if !reuse {
        cache.condenser = None;
        cache.condenser = Some(Condenser::new(p).map_err(g)?);
    } else if cache.values != values {
        let c = cache.condenser.as_mut().expect("checked above");
        if let Err(e) = c.refactor(p) {
            cache.condenser = None;
            return Err(g(e));
        }
    }
    cache.values = values;
    let cond = cache.condenser.as_ref().expect("built above");
    let condensed = cond.condensed(load).map_err(g)?;
    phases.push(("condense", t0.elapsed().as_secs_f64()));

    let t1 = Instant::now();
    let res = status::run(&condensed, sopts, on_iter).map_err(StatusError::Local)?;
    phases.push(("status", t1.elapsed().as_secs_f64()));

    let t2 = Instant::now();
    let sol = cond.recover(load, &res.x, &res.active).map_err(g)?;
    phases.push(("recover", t2.elapsed().as_secs_f64()));
    Ok((sol, res.active))
}

/// Condition positions among the unilateral ones → global numbers (or any
/// position map `uni`).
pub(super) fn to_global(e: SolveError, uni: &[usize]) -> SolveError {
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
pub(super) fn values_hash(p: &Problem) -> u64 {
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
