//! Unilateral conditions on a non-symmetric operator (`MANU RIGI … QUEL`).
//!
//! Neither the condensation (an LDLᵀ) nor its quasi-definite structure
//! exists here, so this is what Cast3M itself does for a non-symmetric
//! matrix (unilateral.md §3.6): each status iteration solves the whole
//! system, the active unilateral conditions acting as equalities, through
//! the sparse LU of [`crate::solve::bilateral::direct`]. The decisions are the same as the
//! symmetric loop's — release every wrong-sign condition first, else
//! activate the violated ones within 70 % of the worst; a repeated status
//! set switches to one change per iteration (least index) — but without a
//! symmetric positive definite operator nothing guarantees convergence:
//! when a status set repeats in that mode too, the error says so.

use super::backend::{Job, Outcome, StatusError, Trace};
use super::status::{IterRecord, Rule, UNCONVERGED};
use crate::solve::bilateral::direct::{self, DirectOptions};
use crate::solve::error::SolveError;
use crate::solve::problem::{Condition, Kind, Load, Problem, Solution};
use std::collections::HashSet;

/// Cast3M's relative tolerance on gaps and multipliers (EXCITER).
const EPS: f64 = 1e-10;
/// Activation threshold of the damped rule, relative to the worst violation.
const ACTIVATE: f64 = 0.7;

pub(super) fn solve(job: &Job, trace: &mut Trace) -> Outcome {
    let Job { p, load, uni, sopts } = *job;
    let Trace { on_iter, phases } = trace;
    let t0 = std::time::Instant::now();
    let m = uni.len();
    let mut active = match &sopts.start {
        Some(s) if s.len() == m => s.clone(),
        _ => vec![true; m],
    };
    let cap = sopts.max_iter.unwrap_or((20 * m).max(100));
    let mut single = sopts.rule == Rule::SingleChange;
    let mut history: HashSet<Vec<bool>> = HashSet::new();
    for it in 1..=cap {
        let sol = solve_status(p, load, uni, &active).map_err(StatusError::Global)?;
        // Signed violations: s (d − c u) > 0 is a penetration of an inactive
        // condition; s λ > 0 a wrong-sign reaction of an active one.
        let scale_u =
            uni.iter().map(|&i| load.d[i].abs().max(row_dot(&p.conditions[i], &sol.u).abs())).fold(0.0f64, f64::max);
        let scale_l = sol.lambda.iter().fold(0.0f64, |a, l| a.max(l.abs()));
        let mut penetration = vec![0.0; m];
        let mut wrong = vec![0.0; m];
        for (q, &i) in uni.iter().enumerate() {
            let s = p.conditions[i].kind.sense();
            if active[q] {
                wrong[q] = s * sol.lambda[i];
            } else {
                penetration[q] = s * (load.d[i] - row_dot(&p.conditions[i], &sol.u));
            }
        }
        let worst_pen = penetration.iter().cloned().fold(0.0f64, f64::max);
        let worst_wrong = wrong.iter().cloned().fold(0.0f64, f64::max);
        let tol_u = EPS * scale_u.max(f64::MIN_POSITIVE);
        let tol_l = EPS * scale_l.max(f64::MIN_POSITIVE);
        let release: Vec<usize> = (0..m).filter(|&q| active[q] && wrong[q] > tol_l).collect();
        let violated: Vec<usize> = (0..m).filter(|&q| !active[q] && penetration[q] > tol_u).collect();
        let mut record = IterRecord {
            iteration: it,
            activated: vec![],
            released: vec![],
            worst_violation: worst_pen,
            worst_wrong_sign: worst_wrong,
            active_count: active.iter().filter(|a| **a).count(),
            mode: if single { "safe" } else { "fast" },
        };
        if release.is_empty() && violated.is_empty() {
            on_iter(&record);
            phases.push(("lu status loop", t0.elapsed().as_secs_f64()));
            return Ok((sol, active));
        }
        let repeated = !history.insert(active.clone());
        if sopts.keep_last && (it == cap || (repeated && single)) {
            // 'SOUC': this solve is the last iterate.
            record.mode = UNCONVERGED;
            record.activated = violated;
            record.released = release;
            on_iter(&record);
            phases.push(("lu status loop", t0.elapsed().as_secs_f64()));
            return Ok((sol, active));
        }
        if repeated {
            if single {
                on_iter(&record);
                let mut changing = release.clone();
                changing.extend(&violated);
                return Err(StatusError::Local(SolveError::NoConvergence { iterations: it, conditions: changing }));
            }
            // A cycle: one change per iteration from now on.
            single = true;
            history.clear();
            history.insert(active.clone());
        }
        if single {
            let q = *release.iter().chain(violated.iter()).min().expect("something changes");
            active[q] = !active[q];
            if active[q] {
                record.activated.push(q);
            } else {
                record.released.push(q);
            }
        } else if !release.is_empty() {
            for &q in &release {
                active[q] = false;
            }
            record.released = release;
        } else {
            for &q in violated.iter().filter(|&&q| penetration[q] >= ACTIVATE * worst_pen) {
                active[q] = true;
                record.activated.push(q);
            }
        }
        on_iter(&record);
    }
    Err(StatusError::Local(SolveError::NoConvergence { iterations: cap, conditions: vec![] }))
}

fn row_dot(c: &Condition, u: &[f64]) -> f64 {
    c.terms.iter().map(|&(j, a)| a * u[j]).sum()
}

/// One linear solve: bilateral conditions and the active unilateral ones
/// as equalities, the inactive ones left out (multiplier 0).
fn solve_status(p: &Problem, load: &Load, uni: &[usize], active: &[bool]) -> Result<Solution, SolveError> {
    let mut keep: Vec<usize> = Vec::with_capacity(p.conditions.len());
    let mut is_uni_inactive = vec![false; p.conditions.len()];
    for (q, &i) in uni.iter().enumerate() {
        is_uni_inactive[i] = !active[q];
    }
    for (i, flag) in is_uni_inactive.iter().enumerate() {
        if !flag {
            keep.push(i);
        }
    }
    let sub = Problem {
        k: p.k.clone(),
        conditions: keep.iter().map(|&i| Condition { kind: Kind::Equal, ..p.conditions[i].clone() }).collect(),
    };
    let sub_load = Load { f: load.f.clone(), d: keep.iter().map(|&i| load.d[i]).collect() };
    let s = direct::solve(&sub, &[sub_load], &DirectOptions::default())?.remove(0);
    let mut lambda = vec![0.0; p.conditions.len()];
    let mut act = vec![false; p.conditions.len()];
    for (k, &i) in keep.iter().enumerate() {
        lambda[i] = s.lambda[k];
        act[i] = true;
    }
    Ok(Solution { u: s.u, lambda, active: act })
}
