//! 'ENSE': the free mode of a chain held at one unknown, the load solved.

use super::*;
use crate::solve::bilateral::tests::kit::{assert_close, chain, cond};

#[test]
fn a_free_chain_is_held_once_and_solved() {
    // Nothing holds the chain: one rigid mode. A self-equilibrated load
    // (+1 at the tip, −1 at the root) stretches it.
    let p = Problem { k: chain(4), conditions: vec![] };
    let held = hold_rigid_modes(&p, &DirectOptions::default()).unwrap();
    assert_eq!(held.held.len(), 1);
    let load = Load { f: vec![-1.0, 0.0, 0.0, 1.0], d: vec![] };
    let s = &held.solve(&[load]).unwrap()[0];
    let j = held.held[0];
    assert_close(s.u[j], 0.0, 1.0);
    // The elongation is that of springs 1, 1.5, 2 in series under 1.
    assert_close(s.u[3] - s.u[0], 1.0 + 1.0 / 1.5 + 0.5, 1.0);
    // A held system with an imposed condition keeps it.
    let p = Problem { k: chain(3), conditions: vec![cond(&[(1, 1.0)], Kind::Equal)] };
    let held = hold_rigid_modes(&p, &DirectOptions::default()).unwrap();
    assert!(held.held.is_empty());
}
