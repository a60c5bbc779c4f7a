//! The exact cases of unilateral-cases.md (a–l), through the condensed
//! status iteration and through the old method.

use super::kit::*;
use crate::solve::unilateral::condensed::operator::run;
use crate::solve::unilateral::status::{Rule, StatusOptions};
use crate::solve::SolveError;
use faer::Mat;

fn close(got: &[f64], want: &[f64], tol: f64, what: &str) {
    assert_eq!(got.len(), want.len(), "{what}: lengths");
    for (k, (g, w)) in got.iter().zip(want).enumerate() {
        assert!((g - w).abs() <= tol * w.abs().max(1.0), "{what}[{k}]: got {g}, want {w} (all: {got:?})");
    }
}

pub(super) fn opts() -> StatusOptions {
    StatusOptions::default()
}

pub(super) fn warm(start: Vec<bool>) -> StatusOptions {
    StatusOptions { start: Some(start), ..Default::default() }
}

/// Solves by both methods, checks they agree and satisfy KKT, and returns
/// the condensed answer.
fn both(p: &Dense, o: &StatusOptions, tol: f64) -> Answer {
    let a = solve(p, o).expect("condensed status iteration");
    let b = solve_ancien(p, o).expect("old method");
    close(&b.u, &a.u, tol, "old method u");
    close(&b.lambda, &a.lambda, tol, "old method λ");
    assert!(kkt_ok(p, &a.u, &a.lambda, 1e-9), "KKT: {a:?}");
    a
}

#[test]
fn a_spring_against_a_stop() {
    // (g, u, λ, ours)
    for (g, u, l, ours) in [(1.0, 0.5, 0.0, 2), (0.2, 0.2, 3.0, 1), (0.5, 0.5, 0.0, 1)] {
        let p = spring(10.0, 5.0).cond(&[(0, 1.0)], MAXI, g);
        let a = both(&p, &opts(), 1e-10);
        close(&a.u, &[u], 1e-10, "u");
        close(&a.lambda, &[l], 1e-10, "λ");
        close(&p.reactions(&a.lambda), &[-l], 1e-10, "REAC");
        assert!(a.iterations <= ours + 1, "g = {g}: {} solves", a.iterations);
    }
    // a1 from all inactive: 1 solve.
    let p = spring(10.0, 5.0).cond(&[(0, 1.0)], MAXI, 1.0);
    assert_eq!(solve(&p, &warm(vec![false])).unwrap().iterations, 1);
    // a4, the MINI mirror.
    let p = spring(10.0, -5.0).cond(&[(0, 1.0)], MINI, -0.2);
    let a = both(&p, &opts(), 1e-10);
    close(&a.u, &[-0.2], 1e-10, "u");
    close(&a.lambda, &[-3.0], 1e-10, "λ");
    close(&p.reactions(&a.lambda), &[3.0], 1e-10, "REAC");
    assert!(a.iterations <= 2);
}

pub(super) fn chain(load: f64) -> Dense {
    let k = Mat::from_fn(3, 3, |i, j| [[2.0, -1.0, 0.0], [-1.0, 2.0, -1.0], [0.0, -1.0, 1.0]][i][j]);
    let mut p = Dense::new(k, vec![0.0, 0.0, load]);
    for (i, g) in [2.0, 1.5, 2.4].into_iter().enumerate() {
        p = p.cond(&[(i, 1.0)], MAXI, g);
    }
    p
}

#[test]
fn b_chain_with_three_stops() {
    let cases = [
        (0.4, [0.4, 0.8, 1.2], [0.0, 0.0, 0.0], 3),
        (1.0, [0.75, 1.5, 2.4], [0.0, 0.15, 0.1], 2),
        (3.0, [0.75, 1.5, 2.4], [0.0, 0.15, 2.1], 2),
    ];
    for (load, u, l, ours) in cases {
        let p = chain(load);
        let a = both(&p, &opts(), 1e-10);
        close(&a.u, &u, 1e-10, "u");
        close(&a.lambda, &l, 1e-10, "λ");
        close(&p.reactions(&a.lambda), &l.map(|v| -v), 1e-10, "REAC");
        assert!(a.iterations <= ours + 1, "P = {load}: {} solves", a.iterations);
    }
    // Warm starts (j): 2/5 → 1 → 3 → 2/5 reusing the previous status.
    let mut status = vec![false; 3];
    for (load, ours) in [(1.0, 2), (3.0, 1), (0.4, 3)] {
        let a = solve(&chain(load), &warm(status.clone())).unwrap();
        let cold = solve(&chain(load), &opts()).unwrap();
        close(&a.u, &cold.u, 1e-10, "warm u");
        close(&a.lambda, &cold.lambda, 1e-10, "warm λ");
        assert!(a.iterations <= ours + 1, "warm P = {load}: {} solves", a.iterations);
        status = a.active;
    }
}

#[test]
fn b_intermediate_values_all_active() {
    // P = 1, all active: λ = (−5/2, 7/5, 1/10), so only stop 1 is released.
    let p = chain(1.0);
    let b = build(&p);
    let mut recs = Vec::new();
    let r = run(&b.c, &opts(), &mut |r| recs.push(r.clone())).unwrap();
    assert_eq!(recs[0].released, vec![0]);
    assert!(recs[0].activated.is_empty());
    assert_eq!(recs.len(), 2);
    assert_eq!(r.active, vec![false, true, true]);
}

/// Case (c): two spans of length 1, nodes x = 0, 1/2, 1, 2; (v, θ) dofs.
pub(super) fn two_spans(p: f64) -> Dense {
    let mut f = vec![0.0; 8];
    f[2] = -p;
    Dense::new(beam(&[0.0, 0.5, 1.0, 2.0], 1.0), f).cond(&[(0, 1.0)], MINI, 0.0).cond(&[(4, 1.0)], MINI, 0.0).cond(
        &[(6, 1.0)],
        MINI,
        0.0,
    )
}

#[test]
fn c_continuous_beam_with_uplift() {
    let p = two_spans(1.0);
    let a = both(&p, &opts(), 1e-8);
    let want = [0.0, -0.0625, -1.0 / 48.0, 0.0, 0.0, 0.0625, 0.0625, 0.0625];
    close(&a.u, &want, 1e-8, "u");
    close(&a.lambda, &[-0.5, -0.5, 0.0], 1e-8, "λ");
    assert_eq!(a.active, vec![true, true, false]);
    assert!(a.iterations <= 3, "{} solves", a.iterations);
    // The first solve (all active) has the three-moment reactions.
    let b = build(&p);
    let r = run(&b.c, &StatusOptions { max_iter: Some(1), ..opts() }, &mut |_| {});
    assert!(matches!(r, Err(SolveError::NoConvergence { iterations: 1, .. })));
}

#[test]
fn c2_uplift_everywhere_is_infeasible() {
    let p = two_spans(-1.0);
    let (r, solves) = solve_counting(&p, &opts());
    assert!(matches!(r, Err(SolveError::Infeasible { .. })), "{r:?}");
    assert!(solves <= 3 + 2, "{solves} solves");
    assert!(matches!(solve_ancien(&p, &opts()), Err(SolveError::Infeasible { .. })));
}

/// Case (d): nodes x = 0, 1, 4, supports A and B only.
fn held_by_supports(p: f64) -> Dense {
    let mut f = vec![0.0; 6];
    f[2] = -p;
    Dense::new(beam(&[0.0, 1.0, 4.0], 1.0), f).cond(&[(0, 1.0)], MINI, 0.0).cond(&[(4, 1.0)], MINI, 0.0)
}

#[test]
fn d_body_held_only_by_unilateral_supports() {
    let p = held_by_supports(1.0);
    let a = both(&p, &opts(), 1e-8);
    close(&a.u, &[0.0, -0.875, -0.75, -0.5, 0.0, 0.625], 1e-8, "u");
    close(&a.lambda, &[-0.75, -0.25], 1e-8, "λ");
    close(&p.reactions(&a.lambda), &[0.75, 0.0, 0.0, 0.0, 0.25, 0.0], 1e-8, "REAC");
    assert_eq!(a.iterations, 1);
}

fn assert_infeasible(p: &Dense, max_solves: usize) -> f64 {
    let (r, solves) = solve_counting(p, &opts());
    let Err(SolveError::Infeasible { work, .. }) = r else { panic!("expected Infeasible, got {r:?}") };
    assert!(work > 0.0, "work {work}");
    assert!(solves <= max_solves, "{solves} solves");
    match solve_ancien(p, &opts()) {
        Err(SolveError::Infeasible { work: w2, .. }) => close(&[w2], &[work], 1e-8, "old method work"),
        other => panic!("old method: expected Infeasible, got {other:?}"),
    }
    work
}

#[test]
fn e_infeasible_and_pushed_cases() {
    // e1: a free point pulled away from its support; F·r = 1 for the unit
    // translation.
    let work = assert_infeasible(&spring(0.0, 1.0).cond(&[(0, 1.0)], MINI, 0.0), 3);
    close(&[work], &[1.0], 1e-10, "e1 work");
    // e1': pushed onto it.
    let p = spring(0.0, -1.0).cond(&[(0, 1.0)], MINI, 0.0);
    let a = both(&p, &opts(), 1e-10);
    close(&a.u, &[0.0], 1e-10, "u");
    close(&a.lambda, &[-1.0], 1e-10, "λ");
    close(&p.reactions(&a.lambda), &[1.0], 1e-10, "REAC");
    assert_eq!(a.iterations, 1);
    // e2: the beam of (d) loaded upwards.
    assert_infeasible(&held_by_supports(-1.0), 4);
    // e3: tipping over the support at x = 3.
    let mut f = vec![0.0; 6];
    f[4] = -1.0;
    let p = Dense::new(beam(&[0.0, 3.0, 4.0], 1.0), f).cond(&[(0, 1.0)], MINI, 0.0).cond(&[(2, 1.0)], MINI, 0.0);
    assert_infeasible(&p, 4);
    // e4: u ≥ 1 and u ≤ 0: conflicting, before any solve.
    let p = spring(10.0, 0.0).cond(&[(0, 1.0)], MINI, 1.0).cond(&[(0, 1.0)], MAXI, 0.0);
    let (r, solves) = solve_counting(&p, &opts());
    assert_eq!(r.unwrap_err(), SolveError::Conflicting { conditions: vec![0, 1] });
    assert_eq!(solves, 0);
    assert!(matches!(solve_ancien(&p, &opts()), Err(SolveError::Conflicting { .. })));
}

pub(super) fn cycling() -> Dense {
    let k = Mat::from_fn(3, 3, |i, j| [[5.0, -7.0, -7.0], [-7.0, 14.0, 16.0], [-7.0, 16.0, 19.0]][i][j]);
    let mut p = Dense::new(k, vec![-3.0, 3.0, 1.0]);
    for i in 0..3 {
        p = p.cond(&[(i, 1.0)], MINI, 0.0);
    }
    p
}

#[test]
fn f_cycling_needs_the_single_change_fallback() {
    let p = cycling();
    let check = |a: &Answer| {
        close(&a.u, &[0.0, 3.0 / 14.0, 0.0], 1e-10, "u");
        close(&a.lambda, &[-1.5, 0.0, -17.0 / 7.0], 1e-10, "λ");
        close(&p.reactions(&a.lambda), &[1.5, 0.0, 17.0 / 7.0], 1e-10, "REAC");
    };
    // Damped: {1,2,3} → {1} → {} → {3} → {1,3}, 5 solves.
    let b = build(&p);
    let mut recs = Vec::new();
    run(&b.c, &opts(), &mut |r| recs.push(r.clone())).unwrap();
    let counts: Vec<usize> = recs.iter().map(|r| r.active_count).collect();
    assert_eq!(counts, vec![3, 1, 0, 1, 2]);
    let a = both(&p, &opts(), 1e-10);
    check(&a);
    assert_eq!(a.iterations, 5);
    // PDAS cycles; the repeated status is seen by solve 4 and the
    // least-index fallback finishes within 3 more.
    let pdas = StatusOptions { rule: Rule::Pdas, ..opts() };
    let mut recs = Vec::new();
    let r = run(&b.c, &pdas, &mut |r| recs.push(r.clone())).unwrap();
    let first_safe = recs.iter().position(|r| r.mode == "safe").expect("cycle detected");
    assert!(first_safe < 4, "detected at solve {}", first_safe + 1);
    assert!(recs.len() <= first_safe + 1 + 3);
    assert_eq!(r.active, vec![true, false, true]);
    check(&both(&p, &pdas, 1e-10));
    // Least index from the start: 2 solves.
    let single = StatusOptions { rule: Rule::SingleChange, ..opts() };
    let a = both(&p, &single, 1e-10);
    check(&a);
    assert_eq!(a.iterations, 2);
    // From all inactive, single change: 3 solves.
    let a = solve(&p, &StatusOptions { start: Some(vec![false; 3]), ..single }).unwrap();
    check(&a);
    assert!(a.iterations <= 4);
}

#[test]
fn g_rela_between_two_bodies() {
    let k = Mat::from_fn(2, 2, |i, j| if i == j { [2.0, 3.0][i] } else { 0.0 });
    for (load, u, l, ours) in [(5.0, [1.6, 0.6], -1.8, 1), (1.5, [0.75, 0.0], 0.0, 2)] {
        let p = Dense::new(k.clone(), vec![load, 0.0]).cond(&[(1, 1.0), (0, -1.0)], MINI, -1.0);
        let a = both(&p, &opts(), 1e-10);
        close(&a.u, &u, 1e-10, "u");
        close(&a.lambda, &[l], 1e-10, "λ");
        close(&p.reactions(&a.lambda), &[l, -l], 1e-10, "REAC");
        assert!(a.iterations <= ours + 1);
    }
}

#[test]
fn h_duplicate_conditions() {
    let p = spring(10.0, -5.0).cond(&[(0, 1.0)], MINI, -0.2).cond(&[(0, 1.0)], MINI, -0.2);
    let a = both(&p, &opts(), 1e-10);
    close(&a.u, &[-0.2], 1e-10, "u");
    close(&[a.lambda.iter().sum()], &[-3.0], 1e-10, "Σλ");
    close(&p.reactions(&a.lambda), &[3.0], 1e-10, "REAC");
    // Also through a warm start asking for both.
    let a = solve(&p, &warm(vec![true, true])).unwrap();
    close(&[a.lambda.iter().sum()], &[-3.0], 1e-10, "Σλ");
}

#[test]
fn i_degenerate_contact_either_status() {
    for start in [vec![true], vec![false]] {
        let p = spring(10.0, 5.0).cond(&[(0, 1.0)], MAXI, 0.5);
        let a = solve(&p, &warm(start)).unwrap();
        close(&a.u, &[0.5], 1e-10, "u");
        close(&a.lambda, &[0.0], 1e-10, "λ");
        assert_eq!(a.iterations, 1);
    }
}

#[test]
fn k_weighted_rela_and_row_scaling() {
    let eye = Mat::<f64>::identity(3, 3);
    let want_u = [3.0 / 65.0, -6.0 / 325.0, 18.0 / 325.0];
    for scale in [1.0, 7.0, 0.01] {
        let row = [(0, 2.5 * scale), (1, -scale), (2, 3.0 * scale)];
        let p = Dense::new(eye.clone(), vec![0.0; 3]).cond(&row, MINI, 0.3 * scale);
        let a = both(&p, &opts(), 1e-10);
        close(&a.u, &want_u, 1e-10, "u");
        close(&a.lambda, &[-6.0 / 325.0 / scale], 1e-10, "λ");
        close(&p.reactions(&a.lambda), &want_u, 1e-10, "REAC");
        assert_eq!(a.iterations, 1);
    }
}

#[test]
fn l_gap_on_both_sides() {
    for mini_first in [true, false] {
        let build_p = |f: f64, dmin: f64, dmax: f64| {
            let p = spring(10.0, f);
            if mini_first {
                p.cond(&[(0, 1.0)], MINI, dmin).cond(&[(0, 1.0)], MAXI, dmax)
            } else {
                p.cond(&[(0, 1.0)], MAXI, dmax).cond(&[(0, 1.0)], MINI, dmin)
            }
        };
        let order = |l: [f64; 2]| if mini_first { l } else { [l[1], l[0]] };
        for (f, u, l) in [(5.0, 0.2, [0.0, 3.0]), (-5.0, -0.1, [-4.0, 0.0]), (1.0, 0.1, [0.0, 0.0])] {
            let p = build_p(f, -0.1, 0.2);
            let a = both(&p, &opts(), 1e-10);
            close(&a.u, &[u], 1e-10, "u");
            close(&a.lambda, &order(l), 1e-10, "λ");
            close(&p.reactions(&a.lambda), &[-(l[0] + l[1])], 1e-10, "REAC");
            assert!(a.iterations <= 3, "F = {f}: {} solves", a.iterations);
            assert!(!(a.active[0] && a.active[1]));
        }
        // l2: 0.3 ≤ u ≤ 0.2.
        let (r, solves) = solve_counting(&build_p(1.0, 0.3, 0.2), &opts());
        assert!(matches!(r, Err(SolveError::Conflicting { .. })));
        assert_eq!(solves, 0);
    }
}
