//! The pool's policy: the same object reuses, another object of the same
//! pattern refactorises, anything else factorises; answers stay right.

use super::*;
use crate::solve::bilateral::tests::kit::{assert_close, chain, cond};
use crate::solve::problem::{Kind, Load};

fn held_chain(scale: f64) -> Problem {
    let mut k = chain(4);
    for e in k.entries.iter_mut() {
        e.2 *= scale;
    }
    Problem { k, conditions: vec![cond(&[(0, 1.0)], Kind::Equal)] }
}

/// The tip displacement of the held chain under a unit tip force: the
/// springs 1, 1.5, 2 (times `scale`) in series.
fn tip(scale: f64) -> f64 {
    (1.0 + 1.0 / 1.5 + 1.0 / 2.0) / scale
}

#[test]
fn reuse_refactor_and_new_factorisation() {
    let mut pool = FactorPool::default();
    let load = Load { f: vec![0.0, 0.0, 0.0, 1.0], d: vec![0.0] };
    let opts = DirectOptions::default();
    let (p1, p2) = (held_chain(1.0), held_chain(3.0));
    let (mut key1, mut key2) = (None, None);
    let run = |pool: &mut FactorPool, owner, key: &mut Option<u64>, p: &Problem| {
        let (f, phase) = pool.factor(owner, key, p, &opts).unwrap();
        (f.solve(std::slice::from_ref(&load)).unwrap()[0].u[3], phase)
    };
    let (u, phase) = run(&mut pool, 1, &mut key1, &p1);
    assert_eq!(phase, Phase::Factorised);
    assert_close(u, tip(1.0), 1.0);
    assert_eq!(run(&mut pool, 1, &mut key1, &p1).1, Phase::Reused);
    // Another object of the same pattern: numeric refactorisation, and
    // its own values are solved.
    let (u, phase) = run(&mut pool, 2, &mut key2, &p2);
    assert_eq!(phase, Phase::Refactored);
    assert_close(u, tip(3.0), 1.0);
    // The first object's values are gone from the pool: refactorised again.
    let (u, phase) = run(&mut pool, 1, &mut key1, &p1);
    assert_eq!(phase, Phase::Refactored);
    assert_close(u, tip(1.0), 1.0);
    // A different structure: a new factorisation.
    let mut key3 = None;
    let p3 = Problem { k: chain(5), conditions: vec![cond(&[(4, 1.0)], Kind::Equal)] };
    let (f, phase) = pool.factor(3, &mut key3, &p3, &opts).unwrap();
    assert_eq!(phase, Phase::Factorised);
    assert!(f.same_pattern(&p3));
}
