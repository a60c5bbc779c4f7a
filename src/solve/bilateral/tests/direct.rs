//! Hand-computed cases for the bilateral RESO.

use super::*;
use crate::solve::problem::{Condition, Matrix};

/// Two bars in series: k1 = 1 between unknowns 0–1, k2 = 0.5 between 1–2.
fn bars(scale: f64) -> Matrix {
    let mut entries = Vec::new();
    for (a, b, k) in [(0, 1, 1.0 * scale), (1, 2, 0.5 * scale)] {
        entries.extend([(a, a, k), (a, b, -k), (b, a, -k), (b, b, k)]);
    }
    Matrix { n: 3, entries, symmetric: true }
}

fn eq(terms: &[(usize, f64)]) -> Condition {
    Condition { terms: terms.to_vec(), kind: Kind::Equal, dual: None }
}

fn close(a: &[f64], b: &[f64]) {
    assert_eq!(a.len(), b.len());
    for (x, y) in a.iter().zip(b) {
        assert!((x - y).abs() <= 1e-12 * (1.0 + y.abs()), "{a:?} vs {b:?}");
    }
}

fn blocked_bars() -> Problem {
    Problem { k: bars(1.0), conditions: vec![eq(&[(0, 1.0)])] }
}

fn load(f: [f64; 3], d: &[f64]) -> Load {
    Load { f: f.to_vec(), d: d.to_vec() }
}

#[test]
fn two_bars_in_series() {
    let s = solve(&blocked_bars(), &[load([0.0, 0.0, 2.0], &[0.0])], &Default::default()).unwrap();
    close(&s[0].u, &[0.0, 2.0, 6.0]);
    // K u + Cᵀλ = F at unknown 0: −2 + λ = 0.
    close(&s[0].lambda, &[2.0]);
    assert_eq!(s[0].active, vec![true]);
}

#[test]
fn imposed_displacements() {
    let p = Problem { k: bars(1.0), conditions: vec![eq(&[(0, 1.0)]), eq(&[(2, 1.0)])] };
    let s = solve(&p, &[load([0.0; 3], &[0.5, 1.5])], &Default::default()).unwrap();
    close(&s[0].u, &[0.5, 5.0 / 6.0, 1.5]);
    // Force in bar 1 = 1/3: reactions −(−1/3) at 0 and −(1/3) at 2.
    close(&s[0].lambda, &[1.0 / 3.0, -1.0 / 3.0]);
}

#[test]
fn two_term_relation() {
    // u2 − u1 = 1 with u0 blocked: bar 2 stretched by 1, bar 1 unloaded.
    let p = Problem { k: bars(1.0), conditions: vec![eq(&[(0, 1.0)]), eq(&[(2, 1.0), (1, -1.0)])] };
    let s = solve(&p, &[load([0.0; 3], &[0.0, 1.0])], &Default::default()).unwrap();
    close(&s[0].u, &[0.0, 0.0, 1.0]);
    close(&s[0].lambda, &[0.0, -0.5]);
}

#[test]
fn several_right_hand_sides_and_refactor() {
    let mut p = blocked_bars();
    let mut f = Factorization::new(&p, &Default::default()).unwrap();
    let loads = [load([0.0, 0.0, 2.0], &[0.0]), load([0.0, 3.0, 0.0], &[1.0])];
    let s = f.solve(&loads).unwrap();
    close(&s[0].u, &[0.0, 2.0, 6.0]);
    close(&s[1].u, &[1.0, 4.0, 4.0]);
    close(&s[1].lambda, &[3.0]);
    p.k = bars(2.0);
    assert!(f.same_pattern(&p));
    f.refactor(&p).unwrap();
    let s = f.solve(&loads[..1]).unwrap();
    close(&s[0].u, &[0.0, 1.0, 3.0]);
    close(&s[0].lambda, &[2.0]);
}

#[test]
fn nothing_blocked_is_singular_and_names_the_mode() {
    let p = Problem { k: bars(1.0), conditions: vec![] };
    match Factorization::new(&p, &Default::default()) {
        Err(SolveError::Singular { mut dofs }) => {
            dofs.sort();
            assert_eq!(dofs, vec![0, 1, 2]);
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn half_blocked_rigid_mode_names_only_the_free_part() {
    // Bars 0–1 blocked at 0; a separate bar 2–3 floats.
    let mut k = bars(1.0);
    k.n = 4;
    k.entries.retain(|e| e.0 != 2 && e.1 != 2);
    k.entries.extend([(2, 2, 1.0), (2, 3, -1.0), (3, 2, -1.0), (3, 3, 1.0)]);
    let p = Problem { k, conditions: vec![eq(&[(0, 1.0)])] };
    match Factorization::new(&p, &Default::default()) {
        Err(SolveError::Singular { mut dofs }) => {
            dofs.sort();
            assert_eq!(dofs, vec![2, 3]);
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn doubly_blocked_and_untouched() {
    let p = Problem { k: bars(1.0), conditions: vec![eq(&[(0, 1.0)]), eq(&[(0, 2.0)])] };
    assert_eq!(
        Factorization::new(&p, &Default::default()).unwrap_err(),
        SolveError::DoublyConstrained { dof: 0, conditions: vec![0, 1] }
    );
    let mut k = bars(1.0);
    k.n = 4;
    let p = Problem { k, conditions: vec![eq(&[(0, 1.0)])] };
    assert_eq!(Factorization::new(&p, &Default::default()).unwrap_err(), SolveError::Untouched { dofs: vec![3] });
}

fn proportional_relations() -> Problem {
    Problem { k: bars(1.0), conditions: vec![eq(&[(0, 1.0)]), eq(&[(1, 1.0), (2, -1.0)]), eq(&[(2, 2.0), (1, -2.0)])] }
}

#[test]
fn consistent_proportional_relations_are_dropped() {
    // u1 − u2 = −1 and 2u2 − 2u1 = 2 say the same: one row carries the
    // reaction (−0.5 on unknown 2), the dropped one gets none.
    let s = solve(&proportional_relations(), &[load([0.0; 3], &[0.0, -1.0, 2.0])], &Default::default()).unwrap();
    close(&s[0].u, &[0.0, 0.0, 1.0]);
    let l = &s[0].lambda;
    assert!(l[1] == 0.0 || l[2] == 0.0, "{l:?}");
    close(&[-l[1] + 2.0 * l[2]], &[-0.5]);
}

#[test]
fn inconsistent_proportional_relations_are_refused() {
    let f = Factorization::new(&proportional_relations(), &Default::default()).unwrap();
    match f.solve(&[load([0.0; 3], &[0.0, -1.0, 0.0])]) {
        Err(SolveError::DependentConditions { conditions }) => {
            assert!(conditions.contains(&1) && conditions.contains(&2));
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn a_relation_implied_by_two_blocks() {
    // u0 = 0, u2 = 1 and u2 − u0 = 1: the third row follows from the others.
    let p = Problem { k: bars(1.0), conditions: vec![eq(&[(0, 1.0)]), eq(&[(2, 1.0)]), eq(&[(2, 1.0), (0, -1.0)])] };
    let s = solve(&p, &[load([0.0; 3], &[0.0, 1.0, 1.0])], &Default::default()).unwrap();
    close(&s[0].u, &[0.0, 1.0 / 3.0, 1.0]);
    assert!(solve(&p, &[load([0.0; 3], &[0.0, 1.0, 2.0])], &Default::default()).is_err());
}

#[test]
fn non_symmetric_stiffness_goes_through_lu() {
    let p = Problem {
        k: Matrix {
            n: 3,
            entries: vec![(0, 0, 1.0), (1, 0, -1.0), (1, 1, 2.0), (1, 2, -0.5), (2, 1, -1.0), (2, 2, 1.0)],
            symmetric: false,
        },
        conditions: vec![eq(&[(0, 1.0)])],
    };
    let s = solve(&p, &[load([0.0, 0.0, 1.0], &[1.0])], &Default::default()).unwrap();
    close(&s[0].u, &[1.0, 1.0, 2.0]);
    close(&s[0].lambda, &[-1.0]);
}

#[test]
fn stab_lets_an_unloaded_mechanism_through() {
    let p = Problem { k: bars(1.0), conditions: vec![] };
    let opts = DirectOptions { check_residual: true, stab: true };
    let s = solve(&p, &[load([0.0; 3], &[])], &opts).unwrap();
    close(&s[0].u, &[0.0; 3]);
}

#[test]
fn non_associated_relation() {
    // u0 blocked; u2 − u1 = 1 with the reaction on u2 alone (dual = e2),
    // so nothing but the bars acts on u1.
    let mut k = bars(1.0);
    k.symmetric = false;
    let mut rel = eq(&[(2, 1.0), (1, -1.0)]);
    rel.dual = Some(vec![(2, 1.0)]);
    let p = Problem { k, conditions: vec![eq(&[(0, 1.0)]), rel] };
    let s = solve(&p, &[load([0.0; 3], &[0.0, 1.0])], &Default::default()).unwrap();
    // Row 1: k1 (u1 − u0) + k2 (u1 − u2) = 0 with no reaction there:
    // u1 − (u2 − u1)/2 = 0 and u2 − u1 = 1 give u1 = 0.5, u2 = 1.5; then
    // at u2: 0.5 (u2 − u1) + λ = 0, λ = −0.5; at u0: −u1 + λ0 = 0.
    close(&s[0].u, &[0.0, 0.5, 1.5]);
    close(&s[0].lambda, &[0.5, -0.5]);
    // A non-associated condition on a matrix declared symmetric is refused.
    let mut q = p.clone();
    q.k.symmetric = true;
    assert!(matches!(solve(&q, &[load([0.0; 3], &[0.0, 1.0])], &Default::default()), Err(SolveError::Other(_))));
}
