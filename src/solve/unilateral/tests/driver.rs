//! Spring-against-stop cases of unilateral-cases.md (a) and (b).

use crate::solve::problem::{Condition, Kind, Matrix};
use crate::solve::problem::{Load, Problem, Solution};
use crate::solve::unilateral::*;

fn spring(kind: Kind) -> Problem {
    Problem {
        k: Matrix { n: 1, entries: vec![(0, 0, 10.0)], symmetric: true },
        conditions: vec![Condition { terms: vec![(0, 1.0)], kind, dual: None }],
    }
}

fn run(p: &Problem, f: Vec<f64>, d: Vec<f64>, cache: &mut UnilCache) -> (Solution, UnilReport) {
    solve_unilateral(p, &Load { f, d }, &UnilOptions::default(), cache, &mut |_| {}).unwrap()
}

fn close(a: f64, b: f64) {
    assert!((a - b).abs() <= 1e-10 * (1.0 + b.abs()), "{a} vs {b}");
}

#[test]
fn spring_against_a_stop() {
    // (a): k = 10, F = 5, MAXI u ≤ g: u = min(F/k, g), λ = max(0, F − k g).
    for (g, u, lam) in [(1.0, 0.5, 0.0), (0.2, 0.2, 3.0), (0.5, 0.5, 0.0)] {
        let (s, _) = run(&spring(Kind::Maxi), vec![5.0], vec![g], &mut UnilCache::default());
        close(s.u[0], u);
        close(s.lambda[0], lam);
    }
    // (a4): MINI u ≥ −0.2 under F = −5: active, λ = −3.
    let (s, r) = run(&spring(Kind::Mini), vec![-5.0], vec![-0.2], &mut UnilCache::default());
    close(s.u[0], -0.2);
    close(s.lambda[0], -3.0);
    assert!(s.active[0]);
    assert_eq!(r.iterations, 1);
}

#[test]
fn chain_with_three_stops_and_warm_start() {
    // (b): K = [[2,−1,0],[−1,2,−1],[0,−1,1]], MAXI stops g = (2, 3/2, 12/5).
    let mut entries = vec![];
    for i in 0..3 {
        entries.push((i, i, if i < 2 { 2.0 } else { 1.0 }));
        if i < 2 {
            entries.extend([(i, i + 1, -1.0), (i + 1, i, -1.0)]);
        }
    }
    let p = Problem {
        k: Matrix { n: 3, entries, symmetric: true },
        conditions: (0..3).map(|i| Condition { terms: vec![(i, 1.0)], kind: Kind::Maxi, dual: None }).collect(),
    };
    let g = vec![2.0, 1.5, 2.4];
    let mut cache = UnilCache::default();
    let cases = [
        (0.4, [0.4, 0.8, 1.2], [0.0, 0.0, 0.0]),
        (1.0, [0.75, 1.5, 2.4], [0.0, 0.15, 0.1]),
        (3.0, [0.75, 1.5, 2.4], [0.0, 0.15, 2.1]),
    ];
    for (load, u, lam) in cases {
        let (s, _) = run(&p, vec![0.0, 0.0, load], g.clone(), &mut cache);
        for i in 0..3 {
            close(s.u[i], u[i]);
            close(s.lambda[i], lam[i]);
        }
    }
    // Warm start from {2, 3}: P = 3 again settles at once.
    let (_, r) = run(&p, vec![0.0, 0.0, 3.0], g.clone(), &mut cache);
    assert_eq!(r.iterations, 1);
}

#[test]
fn bilateral_and_unilateral_together() {
    // Spring chain 0–1–2 (k = 1) with UX blocked at 0 (bilateral) and a
    // MAXI stop u2 ≤ 1 under F = 1 at 2: free answer u2 = 2, so the stop
    // takes λ = 0.5 and u = (0, 0.5, 1).
    let mut entries = vec![];
    for i in 0..2 {
        entries.extend([(i, i, 1.0), (i + 1, i + 1, 1.0), (i, i + 1, -1.0)]);
    }
    let p = Problem {
        k: Matrix { n: 3, entries, symmetric: true },
        conditions: vec![
            Condition { terms: vec![(0, 1.0)], kind: Kind::Equal, dual: None },
            Condition { terms: vec![(2, 1.0)], kind: Kind::Maxi, dual: None },
        ],
    };
    let mut seen = 0;
    let (s, r) = solve_unilateral(
        &p,
        &Load { f: vec![0.0, 0.0, 1.0], d: vec![0.0, 1.0] },
        &UnilOptions::default(),
        &mut UnilCache::default(),
        &mut |_| seen += 1,
    )
    .unwrap();
    close(s.u[1], 0.5);
    close(s.u[2], 1.0);
    close(s.lambda[0], 0.5);
    close(s.lambda[1], 0.5);
    assert_eq!(r.m, 1);
    assert_eq!(seen, r.iterations);
}

#[test]
fn automatic_choice() {
    assert_eq!(choose(Method::Auto, 1000, 300), Method::Condense);
    assert_eq!(choose(Method::Auto, 100_000, 3_000), Method::Condense);
    assert_eq!(choose(Method::Auto, 100_000, 30_000), Method::Creux);
    assert_eq!(choose(Method::Auto, 10_000_000, 20_000), Method::Creux);
    assert_eq!(choose(Method::Iter, 100, 50), Method::Iter);
}

#[test]
fn bad_indices_are_errors_for_every_method() {
    let mut p = spring(Kind::Mini);
    p.conditions[0].terms[0].0 = 7;
    let l = Load { f: vec![1.0], d: vec![0.0] };
    for method in [Method::Condense, Method::Ancien, Method::Creux, Method::Iter] {
        let o = UnilOptions { method, ..Default::default() };
        let r = solve_unilateral(&p, &l, &o, &mut UnilCache::default(), &mut |_| {});
        assert!(r.is_err(), "{method:?}");
    }
}
