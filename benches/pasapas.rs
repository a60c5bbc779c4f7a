//! A 100-step elastic contact analysis (PASAPAS's step driver) against one
//! factorisation F and one solve S of the same operator, measured in the
//! same run: `cargo bench --bench pasapas`.
//!
//! The 2D bench grid of `unilateral` (a 512×512 membrane, 5-point
//! Laplacian, n = 262,144) rests on 500 MINI supports along its bottom edge
//! (cos-shaped gaps) under a downward load whose moment rocks with time,
//! f(t) = f₀ (1 + 1.5 sin(2πt) (2x/L − 1)): the contact zone moves from one
//! side to the other, conditions open and close along the 100 steps
//! t = 0.01 … 1.
//!
//! Target (issue 15): the whole run at most F + 100 × 1.5 S; the bench
//! prints `budget_ratio` = total / (F + 150 S), which must be ≤ 1, and where
//! the time goes (the one-off condensation and forward substitution of the
//! history's loads, then per step their combination, the status iteration
//! and the back substitution).
//! `GIBI_BENCH_N` sets the grid, `GIBI_BENCH_STEPS` the number of steps.

mod common;

use std::time::Instant;

use gibi::analysis::history::{LoadHistory, Term, TimeFunction};
use gibi::analysis::stepper::Stepper;
use gibi::solve::{Condition, Kind, Load, Problem};

fn main() {
    let nx = std::env::var("GIBI_BENCH_N").ok().and_then(|s| s.parse().ok()).unwrap_or(512);
    let steps: usize = std::env::var("GIBI_BENCH_STEPS").ok().and_then(|s| s.parse().ok()).unwrap_or(100);
    let k = common::laplacian(nx);
    let n = k.n;
    let m = 500.min(nx);
    let nodes: Vec<usize> = (0..m).map(|q| q * nx / m).collect();
    let conditions: Vec<Condition> =
        nodes.iter().map(|&j| Condition { terms: vec![(j, 1.0)], kind: Kind::Mini, dual: None }).collect();
    let p = Problem { k: k.clone(), conditions };
    // Loads: a uniform downward part, and a rocking moment of zero
    // resultant that follows sin(2πt).
    let f0 = -1.0 / nx as f64;
    let gap = 150.0;
    let mut history = LoadHistory::new(n, m);
    history.base.f = vec![f0; n];
    for (q, d) in history.base.d.iter_mut().enumerate() {
        *d = -gap * (1.0 - (std::f64::consts::TAU * q as f64 / m as f64).cos());
    }
    let rock: Vec<f64> = (0..n).map(|j| f0 * 1.5 * (2.0 * (j % nx) as f64 / (nx - 1) as f64 - 1.0)).collect();
    let ts: Vec<f64> = (0..=200).map(|i| i as f64 / 200.0).collect();
    let sin: Vec<f64> = ts.iter().map(|t| (std::f64::consts::TAU * t).sin()).collect();
    history
        .terms
        .push(Term { load: Load { f: rock, d: vec![0.0; m] }, time: TimeFunction::new(ts, sin).expect("valid") });

    let (f_ref, s_ref, s_seq) = common::reference_f_s(&p.k, &nodes);
    let t0 = Instant::now();
    let mut stepper = Stepper::new(p).expect("condenses");
    let setup = t0.elapsed().as_secs_f64();
    let mut phases: Vec<(&'static str, f64)> = Vec::new();
    let (mut solves, mut changes, mut loads_s) = (0, 0, 0.0);
    let mut actives = Vec::new();
    for i in 1..=steps {
        let t = i as f64 / steps as f64;
        let tl = Instant::now();
        let c = history.coefficients(t).expect("in range");
        loads_s += tl.elapsed().as_secs_f64();
        let out = stepper.solve_history(&history, &c, None, &mut |_| {}).expect("solves");
        solves += out.iterations;
        changes += out.changed;
        actives.push(out.active);
        for (name, s) in out.phases {
            match phases.iter_mut().find(|(p, _)| *p == name) {
                Some(e) => e.1 += s,
                None => phases.push((name, s)),
            }
        }
    }
    let total = t0.elapsed().as_secs_f64();
    let budget = f_ref + 1.5 * steps as f64 * s_ref;
    println!(
        "case=pasapas_contact n={n} m={m} steps={steps} F_s={f_ref:.3} S_s={s_ref:.4} total_s={total:.3} budget_s={budget:.3} budget_ratio={:.3}",
        total / budget
    );
    let per = |s: f64| s / steps as f64 / s_ref;
    let detail: Vec<String> = phases.iter().map(|(k, v)| format!("{k}:{:.2}S", per(*v))).collect();
    println!(
        "#   setup (condensed operator, once): {setup:.3} s = {:.2} F; per step: {:.2} S in all ({}, loads:{:.2}S)",
        setup / f_ref,
        per(total - setup),
        detail.join(", "),
        per(loads_s)
    );
    println!(
        "#   S_seq_s={s_seq:.4} (the same solve without threads): per step {:.2} S_seq",
        (total - setup) / steps as f64 / s_seq
    );
    println!(
        "#   status solves {solves} ({:.2} per step), status changes {changes}, active from {} to {}",
        solves as f64 / steps as f64,
        actives.iter().min().unwrap_or(&0),
        actives.iter().max().unwrap_or(&0)
    );
}
