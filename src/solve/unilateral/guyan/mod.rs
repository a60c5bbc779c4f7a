//! The ANCIEN method of the UNIL driver (unilateral.md §5): Guyan
//! condensation onto the primal unknowns P of the unilateral rows, the
//! status iteration of the old method on the dense K_c, and one expansion.
//!
//! Bilateral conditions stay inside the condensed part (Cast3M's
//! `SUPER … 'NOMU'`), except those that share an unknown with the masters:
//! their multipliers would land among the masters, so they move to the
//! small system instead (always assembled), and their unknowns join P
//! (repeatedly, until no remaining bilateral row touches P).

pub mod reduced;

pub use reduced::{ReducedProblem, ReducedResult};

use super::backend::{Job, Outcome, StatusError, Trace};
use crate::solve::bilateral::schur::schur_onto;
use crate::solve::error::SolveError;
use crate::solve::problem::{Load, Problem, Solution};

/// Solves `p` by the old method. Records and status-loop errors use
/// positions among the unilateral conditions (`uni`); the caller maps them.
pub(super) fn solve(job: &Job, trace: &mut Trace) -> Outcome {
    let Job { p, load, uni, sopts } = *job;
    let Trace { on_iter, phases } = trace;
    let t0 = std::time::Instant::now();
    // Indices are used below before any factorisation checks them.
    crate::solve::bilateral::lagrange::validate(p).map_err(StatusError::Global)?;
    let n = p.k.n;
    let mut in_p = vec![false; n];
    for &i in uni {
        for &(j, _) in &p.conditions[i].terms {
            if j < n {
                in_p[j] = true;
            }
        }
    }
    let mut bil: Vec<usize> = (0..p.conditions.len()).filter(|&i| !p.conditions[i].kind.is_unilateral()).collect();
    let mut moved: Vec<usize> = Vec::new();
    loop {
        let touches = |b: &usize| p.conditions[*b].terms.iter().any(|&(j, _)| j < n && in_p[j]);
        let (now, rest): (Vec<usize>, Vec<usize>) = bil.iter().partition(|b| touches(b));
        if now.is_empty() {
            break;
        }
        for &b in &now {
            for &(j, _) in &p.conditions[b].terms {
                if j < n {
                    in_p[j] = true;
                }
            }
        }
        moved.extend(now);
        bil = rest;
    }
    moved.sort_unstable();
    let keep: Vec<usize> = (0..n).filter(|&j| in_p[j]).collect();
    let rest = Problem { k: p.k.clone(), conditions: bil.iter().map(|&b| p.conditions[b].clone()).collect() };
    let rest_load = Load { f: load.f.clone(), d: bil.iter().map(|&b| load.d[b]).collect() };
    let back = |e: SolveError| StatusError::Global(rest_to_global(e, &bil));
    let so = schur_onto(&rest, &keep).map_err(back)?;
    let tail = so.unknowns();
    if tail.len() != keep.len() || tail.iter().any(|&t| t >= n) {
        return Err(StatusError::Global(SolveError::Other("method ANCIEN: unexpected condensed unknowns".into())));
    }
    let mut local = vec![usize::MAX; n];
    for (q, &t) in tail.iter().enumerate() {
        local[t] = q;
    }
    let fc = so.load(&rest_load);
    let local_row = |i: usize| p.conditions[i].terms.iter().map(|&(j, v)| (local[j], v)).collect::<Vec<_>>();
    let rows: Vec<Vec<(usize, f64)>> = uni.iter().map(|&i| local_row(i)).collect();
    let eq_rows: Vec<Vec<(usize, f64)>> = moved.iter().map(|&i| local_row(i)).collect();
    let eq_d: Vec<f64> = moved.iter().map(|&i| load.d[i]).collect();
    let sense: Vec<f64> = uni.iter().map(|&i| p.conditions[i].kind.sense()).collect();
    let d: Vec<f64> = uni.iter().map(|&i| load.d[i]).collect();
    let all: Vec<usize> = uni.iter().chain(&moved).copied().collect();
    let k_ref = stiffness_ref(p, &all, &in_p);
    phases.push(("condense", t0.elapsed().as_secs_f64()));

    let t1 = std::time::Instant::now();
    let pb = ReducedProblem {
        kc: so.matrix(),
        fc: &fc,
        rows: &rows,
        sense: &sense,
        d: &d,
        k_ref: Some(&k_ref),
        eq_rows: &eq_rows,
        eq_d: &eq_d,
    };
    let res = reduced::run(&pb, sopts, on_iter).map_err(StatusError::Local)?;
    phases.push(("status", t1.elapsed().as_secs_f64()));

    let t2 = std::time::Instant::now();
    let expanded = so.expand(&rest_load, &res.u);
    let m = p.conditions.len();
    let mut lambda = vec![0.0; m];
    let mut active = vec![true; m];
    for (r, &b) in bil.iter().enumerate() {
        lambda[b] = expanded.lambda[r];
    }
    for (q, &b) in moved.iter().enumerate() {
        lambda[b] = res.eq_lambda[q];
    }
    for (q, &i) in uni.iter().enumerate() {
        lambda[i] = if res.active[q] { res.lambda[q] } else { 0.0 };
        active[i] = res.active[q];
    }
    phases.push(("recover", t2.elapsed().as_secs_f64()));
    Ok((Solution { u: expanded.u, lambda, active }, res.active))
}

/// k_i of the §2.2 scaling from the stiffness before condensation: the
/// largest |assembled K entry| in the rows of the condition's unknowns
/// (fallback: the largest entry overall, then 1). Only the rows of P are
/// assembled, which keeps this O(nnz(K)) with a small map.
fn stiffness_ref(p: &Problem, uni: &[usize], in_p: &[bool]) -> Vec<f64> {
    use std::collections::HashMap;
    let upper = p.k.entries.iter().any(|&(i, j, _)| i < j) || p.k.entries.is_empty();
    let mut sums: HashMap<(usize, usize), f64> = HashMap::new();
    let mut global = 0.0_f64;
    for &(i, j, v) in &p.k.entries {
        global = global.max(v.abs());
        // Read one triangle only, as the assembly does.
        if p.k.symmetric && (if upper { i > j } else { i < j }) {
            continue;
        }
        if in_p[i] || in_p[j] {
            *sums.entry((i.min(j), i.max(j))).or_insert(0.0) += v;
        }
    }
    let mut row_max = vec![0.0_f64; in_p.len()];
    for (&(i, j), &v) in &sums {
        row_max[i] = row_max[i].max(v.abs());
        row_max[j] = row_max[j].max(v.abs());
    }
    uni.iter()
        .map(|&c| {
            let k = p.conditions[c].terms.iter().fold(0.0_f64, |a, &(j, _)| a.max(row_max[j]));
            if k > 0.0 {
                k
            } else if global > 0.0 {
                global
            } else {
                1.0
            }
        })
        .collect()
}

/// Condition numbers of the bilateral-only problem → global numbers.
fn rest_to_global(e: SolveError, bil: &[usize]) -> SolveError {
    let g = |v: Vec<usize>| v.into_iter().map(|q| bil.get(q).copied().unwrap_or(q)).collect();
    match e {
        SolveError::DependentConditions { conditions } => SolveError::DependentConditions { conditions: g(conditions) },
        SolveError::DoublyConstrained { dof, conditions } => {
            SolveError::DoublyConstrained { dof, conditions: g(conditions) }
        }
        e => e,
    }
}
