//! Property test of the sparse path: every UNIL method through
//! `solve_unilateral` against brute-force enumeration of all statuses on
//! random small problems, semi-definite K included (the sparse mirror of
//! `status_props`).

use super::kit::*;
use super::methods::sparse;
use super::status_props::random_problem;
use crate::solve::unilateral::{solve_unilateral, Method, UnilCache, UnilOptions};
use crate::solve::SolveError;

#[test]
fn every_method_matches_brute_force() {
    let mut rng = Rng(0x0B5E_55ED_F00D);
    let methods = [Method::Condense, Method::Ancien, Method::Creux, Method::Iter];
    let (mut solved, mut infeasible) = (0, 0);
    for case in 0..400 {
        let d = random_problem(&mut rng);
        let (p, l) = sparse(&d);
        let reference = brute_force(&d);
        for method in methods {
            let o = UnilOptions { method, ..Default::default() };
            let got = solve_unilateral(&p, &l, &o, &mut UnilCache::default(), &mut |_| {}).map(|r| r.0);
            match &reference {
                Some((u, _)) => {
                    let s = got.unwrap_or_else(|e| panic!("case {case} {method:?}: brute force solves it, got {e:?}"));
                    let scale = u.iter().fold(1.0_f64, |x, v| x.max(v.abs()));
                    for (g, w) in s.u.iter().zip(u) {
                        assert!((g - w).abs() <= 1e-8 * scale, "case {case} {method:?}: u {:?} vs {u:?}", s.u);
                    }
                    assert!(kkt_ok(&d, &s.u, &s.lambda, 1e-8), "case {case} {method:?}: not KKT");
                }
                None => assert!(
                    matches!(got, Err(SolveError::Infeasible { .. }) | Err(SolveError::Conflicting { .. })),
                    "case {case} {method:?}: brute force finds no solution, got {got:?}"
                ),
            }
        }
        if reference.is_some() {
            solved += 1;
        } else {
            infeasible += 1;
        }
    }
    assert!(solved > 150 && infeasible > 30, "{solved} solved, {infeasible} infeasible");
}
