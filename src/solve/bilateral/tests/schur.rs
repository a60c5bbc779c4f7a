//! The static condensation onto kept unknowns against direct solves and
//! the Guyan matrix.

use super::*;
use crate::solve::bilateral::direct::{self, DirectOptions};
use crate::solve::bilateral::tests::kit::{assert_close, chain, cond};
use crate::solve::problem::Kind;
use faer::linalg::solvers::Solve;

#[test]
fn static_condensation_onto_kept_unknowns() {
    let n = 6;
    let p = Problem { k: chain(n), conditions: vec![cond(&[(0, 1.0)], Kind::Equal), cond(&[(5, 1.0)], Kind::Equal)] };
    let load = Load { f: vec![0.0, 1.0, -0.5, 0.0, 2.0, 0.3], d: vec![0.1, -0.2] };
    let s = schur_onto(&p, &[2, 5]).unwrap();
    // The tail: kept unknowns plus the multipliers of the BLOQ on 5.
    let tail = s.unknowns().to_vec();
    assert!(tail.contains(&2) && tail.contains(&5));
    let kc = s.matrix();
    let fc = s.load(&load);
    let nt = tail.len();
    let x = kc.partial_piv_lu().solve(Mat::from_fn(nt, 1, |q, _| fc[q]));
    let xs: Vec<f64> = (0..nt).map(|q| x[(q, 0)]).collect();
    let sol = s.expand(&load, &xs);
    let r = direct::solve(&p, &[load], &DirectOptions::default()).unwrap();
    for j in 0..n {
        assert_close(sol.u[j], r[0].u[j], 1.0 + r[0].u[j].abs());
    }
    for i in 0..2 {
        assert_close(sol.lambda[i], r[0].lambda[i], 1.0 + r[0].lambda[i].abs());
    }
}

#[test]
fn pure_stiffness_condensation_is_the_guyan_matrix() {
    // Dof 0 blocked (not kept): K_c is K without dof 0, condensed on {1, 3}.
    let p = Problem { k: chain(4), conditions: vec![cond(&[(0, 1.0)], Kind::Equal)] };
    let s = schur_onto(&p, &[1, 3]).unwrap();
    assert_eq!(s.unknowns(), &[1, 3]);
    // Springs 1.5 (1–2) and 2 (2–3) in series between 1 and 3: 6/7; plus
    // spring 1 from the blocked dof 0 on unknown 1.
    let ks = 1.5 * 2.0 / 3.5;
    let kc = s.matrix();
    assert_close(kc[(0, 0)], 1.0 + ks, 1.0);
    assert_close(kc[(0, 1)], -ks, 1.0);
    assert_close(kc[(1, 1)], ks, 1.0);
}
