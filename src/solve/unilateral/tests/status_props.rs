//! Property test: the status iteration against brute-force enumeration of
//! all 2^m statuses on random small problems, semi-definite K included
//! (unilateral-cases.md, "Property-based test").

use super::kit::*;
use crate::solve::unilateral::status::{Rule, StatusOptions};
use crate::solve::SolveError;
use faer::Mat;

/// Smallest/largest eigenvalue ratio of a symmetric PSD matrix.
fn min_ratio(a: &Mat<f64>) -> f64 {
    let ev = a.self_adjoint_eigenvalues(faer::Side::Lower).unwrap_or_default();
    let max = ev.iter().fold(0.0_f64, |x, v| x.max(v.abs()));
    let min = ev.iter().fold(f64::INFINITY, |x, v| x.min(*v));
    if max > 0.0 {
        min / max
    } else {
        0.0
    }
}

/// K = BBᵀ of rank n − r; C sparse, full row rank, ker K ∩ ker C = {0}.
pub(super) fn random_problem(rng: &mut Rng) -> Dense {
    loop {
        let n = 1 + rng.below(8);
        // Half the cases with m = n: the most statuses to choose from.
        let m = if rng.below(2) == 0 { n } else { 1 + rng.below(n) };
        let r = rng.below(3).min(n);
        let b = Mat::<f64>::from_fn(n, n - r, |_, _| rng.sym());
        let k = &b * b.transpose();
        let mut p = Dense::new(k, (0..n).map(|_| 2.0 * rng.sym()).collect());
        for _ in 0..m {
            let nnz = 1 + rng.below(3.min(n));
            let mut row: Vec<(usize, f64)> = Vec::new();
            while row.len() < nnz {
                let j = rng.below(n);
                if row.iter().all(|e| e.0 != j) {
                    let c = if rng.below(2) == 0 { 1.0 } else { 0.5 + 1.5 * rng.sym().abs() };
                    row.push((j, if rng.below(2) == 0 { c } else { -c }));
                }
            }
            let s = if rng.below(2) == 0 { MINI } else { MAXI };
            p = p.cond(&row, s, 0.5 * rng.sym());
        }
        let c = Mat::<f64>::from_fn(m, n, |i, j| p.rows[i].iter().filter(|e| e.0 == j).map(|e| e.1).sum());
        let gram = &c * c.transpose();
        let h = &p.k + c.transpose() * &c;
        // Keep K's non-zero eigenvalues away from 0: a nearly rigid mode
        // pushed by an O(1) load makes u inaccurate for any method, which
        // is not what this test is about.
        let mut ev = p.k.self_adjoint_eigenvalues(faer::Side::Lower).unwrap_or_default();
        ev.sort_by(f64::total_cmp);
        let soft = ev.get(r).is_some_and(|&e| e < 1e-2);
        if !soft && min_ratio(&gram) > 1e-6 && min_ratio(&h) > 1e-6 {
            return p;
        }
    }
}

const CASES: usize = 1500;

struct Stats {
    solved: usize,
    infeasible: usize,
    max_solves: usize,
    total_solves: usize,
    /// Cases that needed the least-index fallback, and rigid-mode swaps.
    safe: usize,
    swaps: usize,
}

fn check_rule(rule: Rule, cases: usize, seed: u64) -> Stats {
    let mut rng = Rng(seed);
    let opts = StatusOptions { rule, ..Default::default() };
    let mut st = Stats { solved: 0, infeasible: 0, max_solves: 0, total_solves: 0, safe: 0, swaps: 0 };
    for case in 0..cases {
        let p = random_problem(&mut rng);
        let (got, recs) = solve_recording(&p, &opts);
        let solves = recs.len();
        st.safe += usize::from(rule != Rule::SingleChange && recs.iter().any(|r| r.mode == "safe"));
        st.swaps += recs.iter().filter(|r| r.activated.len() == 1 && r.released.len() == 1).count();
        let old = solve_ancien(&p, &opts);
        st.max_solves = st.max_solves.max(solves);
        st.total_solves += solves;
        match brute_force(&p) {
            Some((u, _)) => {
                let a = got.unwrap_or_else(|e| panic!("case {case}: brute force solves it, solver says {e:?}\n{p:?}"));
                let scale = u.iter().fold(1.0_f64, |x, v| x.max(v.abs()));
                for (g, w) in a.u.iter().zip(&u) {
                    assert!((g - w).abs() <= 1e-8 * scale, "case {case}: u {:?} vs {u:?}\n{p:?}", a.u);
                }
                assert!(kkt_ok(&p, &a.u, &a.lambda, 1e-8), "case {case}: not KKT\n{p:?}");
                let o = old.unwrap_or_else(|e| panic!("case {case}: old method says {e:?}\n{p:?}"));
                for (g, w) in o.u.iter().zip(&u) {
                    assert!((g - w).abs() <= 1e-8 * scale, "case {case}: old u {:?} vs {u:?}", o.u);
                }
                st.solved += 1;
            }
            None => {
                assert!(
                    matches!(got, Err(SolveError::Infeasible { .. }) | Err(SolveError::Conflicting { .. })),
                    "case {case}: brute force finds no solution, solver gives {got:?}\n{p:?}"
                );
                assert!(
                    matches!(old, Err(SolveError::Infeasible { .. }) | Err(SolveError::Conflicting { .. })),
                    "case {case}: old method gives {old:?}"
                );
                st.infeasible += 1;
            }
        }
    }
    st
}

#[test]
fn damped_rule_matches_brute_force() {
    let st = check_rule(Rule::Damped, CASES, 0x9E37_79B9_7F4A_7C15);
    // Both outcomes must really be exercised.
    assert!(st.solved > 500 && st.infeasible > 100, "{} solved, {} infeasible", st.solved, st.infeasible);
    assert!(st.max_solves <= 40, "max {} solves", st.max_solves);
    eprintln!(
        "damped: {} solved, {} infeasible, {:.2} solves on average, at most {}; {} needed the fallback, {} swaps",
        st.solved,
        st.infeasible,
        st.total_solves as f64 / CASES as f64,
        st.max_solves,
        st.safe,
        st.swaps
    );
}

#[test]
fn pdas_and_single_change_match_brute_force() {
    for (rule, seed) in [(Rule::Pdas, 17), (Rule::SingleChange, 4242)] {
        let st = check_rule(rule, 500, seed);
        assert!(st.solved > 100, "{rule:?}: {} solved", st.solved);
        eprintln!(
            "{rule:?}: {} solved, {} infeasible, {:.2} solves on average, at most {}; {} needed the fallback",
            st.solved,
            st.infeasible,
            st.total_solves as f64 / 500.0,
            st.max_solves,
            st.safe
        );
    }
}

/// Larger problems (n ≤ 25, m < n): no brute force, but every answer must
/// satisfy KKT, every infeasibility must come with positive load work, and
/// nothing else may go wrong.
#[test]
fn larger_problems_converge_or_prove_infeasibility() {
    let mut rng = Rng(0xDEAD_BEEF_1234_5678);
    let (mut solved, mut infeasible, mut max_solves, mut total) = (0, 0, 0, 0);
    let cases = 300;
    for case in 0..cases {
        let n = 9 + rng.below(17);
        let m = 1 + rng.below(n - 1);
        let r = rng.below(3);
        let b = Mat::<f64>::from_fn(n, n - r, |_, _| rng.sym());
        let mut p = Dense::new(&b * b.transpose(), (0..n).map(|_| 2.0 * rng.sym()).collect());
        for i in 0..m {
            // Rows on distinct leading dofs keep C of full row rank.
            let mut row = vec![(i, 1.0 + rng.sym().abs())];
            if rng.below(2) == 0 {
                row.push((m + rng.below(n - m), rng.sym()));
            }
            let s = if rng.below(2) == 0 { MINI } else { MAXI };
            p = p.cond(&row, s, 0.5 * rng.sym());
        }
        let c = Mat::<f64>::from_fn(m, n, |i, j| p.rows[i].iter().filter(|e| e.0 == j).map(|e| e.1).sum());
        if min_ratio(&(&p.k + c.transpose() * &c)) < 1e-8 {
            continue;
        }
        let (got, solves) = solve_counting(&p, &StatusOptions::default());
        max_solves = max_solves.max(solves);
        total += solves;
        match got {
            Ok(a) => {
                assert!(kkt_ok(&p, &a.u, &a.lambda, 1e-7), "case {case}: not KKT");
                solved += 1;
            }
            Err(SolveError::Infeasible { work, .. }) => {
                assert!(work > 0.0, "case {case}: work {work}");
                assert!(r > 0, "case {case}: infeasible with K positive definite");
                infeasible += 1;
            }
            Err(e) => panic!("case {case}: {e:?}"),
        }
    }
    eprintln!(
        "larger: {solved} solved, {infeasible} infeasible, {:.2} solves on average, at most {max_solves}",
        total as f64 / (solved + infeasible) as f64
    );
    assert!(solved > 100 && max_solves <= 60);
}
