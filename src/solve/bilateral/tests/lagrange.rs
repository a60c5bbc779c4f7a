use super::*;
use crate::solve::problem::{Condition, Kind, Matrix};

fn bar() -> Problem {
    Problem {
        k: Matrix { n: 2, entries: vec![(0, 0, 4.0), (0, 1, -4.0), (1, 0, -4.0), (1, 1, 4.0)], symmetric: true },
        conditions: vec![Condition { terms: vec![(0, 2.0)], kind: Kind::Equal, dual: None }],
    }
}

#[test]
fn scaling_follows_cast3m() {
    let d = Doubled::new(&bar(), &[]).unwrap();
    // k = 4, ĉ = 2, κ = 6, σ = 3, α = 12.
    assert_eq!(d.scaling.sigma, vec![3.0]);
    assert_eq!(d.scaling.alpha, vec![12.0]);
    let (l1, l2) = (2, 3);
    assert_eq!(d.values[d.find(l1, l1).unwrap()], -12.0);
    assert_eq!(d.values[d.find(l2, l2).unwrap()], -12.0);
    assert_eq!(d.values[d.find(l1, l2).unwrap()], 12.0);
    assert_eq!(d.values[d.find(0, l1).unwrap()], 6.0);
    assert_eq!(d.values[d.find(l2, 0).unwrap()], 6.0);
    // K read once, from the upper triangle.
    assert_eq!(d.values[d.find(0, 1).unwrap()], -4.0);
}

/// A relation between a stiff and a soft unknown is scaled on the soft
/// side (k = the smallest row maximum among its unknowns).
#[test]
fn relation_scaled_on_its_softest_unknown() {
    let p = Problem {
        k: Matrix { n: 2, entries: vec![(0, 0, 1.0e9), (1, 1, 2.0)], symmetric: true },
        conditions: vec![Condition { terms: vec![(0, 1.0), (1, -1.0)], kind: Kind::Mini, dual: None }],
    };
    let d = Doubled::new(&p, &[]).unwrap();
    // k = 2, ĉ = 1, κ = 3.
    assert_eq!(d.scaling.sigma, vec![3.0]);
    assert_eq!(d.scaling.alpha, vec![6.0]);
}

#[test]
fn refill_tracks_new_values() {
    let mut p = bar();
    let mut d = Doubled::new(&p, &[]).unwrap();
    for e in &mut p.k.entries {
        e.2 *= 2.0;
    }
    assert!(d.same_pattern(&p));
    d.fill(&p, 0.0).unwrap();
    assert_eq!(d.values[d.find(1, 1).unwrap()], 8.0);
    assert_eq!(d.scaling.alpha, vec![24.0]);
    p.conditions[0].terms[0].0 = 1;
    assert!(!d.same_pattern(&p));
}
