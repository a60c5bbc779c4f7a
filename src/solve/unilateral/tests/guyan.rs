use super::*;
use crate::solve::unilateral::tests::kit::{beam, solve, Dense, MINI};

/// Guyan condensation onto `keep` (§5 step 1): K_c = K_PP − K_PR K_RR⁻¹ K_RP.
fn guyan(k: &Mat<f64>, f: &[f64], keep: &[usize]) -> (Mat<f64>, Vec<f64>) {
    let n = f.len();
    let rest: Vec<usize> = (0..n).filter(|j| !keep.contains(j)).collect();
    let krr = Mat::<f64>::from_fn(rest.len(), rest.len(), |a, b| k[(rest[a], rest[b])]);
    let fac = DenseLdlt::factor(krr.as_ref());
    let solve_r = |col: &dyn Fn(usize) -> f64| {
        let mut y: Vec<f64> = (0..rest.len()).map(col).collect();
        fac.solve_in_place(&mut y);
        y
    };
    let kc = Mat::<f64>::from_fn(keep.len(), keep.len(), |a, b| {
        let y = solve_r(&|r| k[(rest[r], keep[b])]);
        k[(keep[a], keep[b])] - (0..rest.len()).map(|r| k[(keep[a], rest[r])] * y[r]).sum::<f64>()
    });
    let y = solve_r(&|r| f[rest[r]]);
    let fc = keep.iter().map(|&p| f[p] - (0..rest.len()).map(|r| k[(p, rest[r])] * y[r]).sum::<f64>()).collect();
    (kc, fc)
}

/// Cases (c) and (d) with the stiffness condensed onto the supported
/// dofs only, as Cast3M's SUPER does: same answers as the full solve.
#[test]
fn old_method_on_guyan_condensed_beams() {
    let cases: [(&[f64], usize, &[usize]); 2] =
        [(&[0.0, 0.5, 1.0, 2.0], 2, &[0, 4, 6]), (&[0.0, 1.0, 4.0], 2, &[0, 4])];
    for (x, loaded, supports) in cases {
        let n = 2 * x.len();
        let mut f = vec![0.0; n];
        f[loaded] = -1.0;
        let mut p = Dense::new(beam(x, 1.0), f.clone());
        for &s in supports {
            p = p.cond(&[(s, 1.0)], MINI, 0.0);
        }
        let full = solve(&p, &StatusOptions::default()).unwrap();
        let (kc, fc) = guyan(&p.k, &f, supports);
        let rows: Vec<Vec<(usize, f64)>> = (0..supports.len()).map(|q| vec![(q, 1.0)]).collect();
        let sense = vec![1.0; supports.len()];
        let d = vec![0.0; supports.len()];
        // k_i from the full stiffness (§2.2), as the caller would.
        let k_ref: Vec<f64> = supports.iter().map(|&s| (0..n).fold(0.0_f64, |a, l| a.max(p.k[(s, l)].abs()))).collect();
        let pb = ReducedProblem {
            kc: &kc,
            fc: &fc,
            rows: &rows,
            sense: &sense,
            d: &d,
            k_ref: Some(&k_ref),
            eq_rows: &[],
            eq_d: &[],
        };
        let old = run(&pb, &StatusOptions::default(), &mut |_| {}).unwrap();
        for (q, &s) in supports.iter().enumerate() {
            assert!(
                (old.u[q] - full.u[s]).abs() < 1e-10,
                "u at dof {s}: {:?} vs {:?} {:?}",
                old.u,
                full.u,
                old.records
            );
            assert!((old.lambda[q] - full.lambda[q]).abs() < 1e-10, "λ {q}");
        }
        assert_eq!(old.active, full.active);
    }
}

#[test]
fn singular_warm_start_falls_back_to_cold() {
    // Case (d) started from all inactive: the beam would be free.
    let mut f = vec![0.0; 6];
    f[2] = -1.0;
    let p = Dense::new(beam(&[0.0, 1.0, 4.0], 1.0), f).cond(&[(0, 1.0)], MINI, 0.0).cond(&[(4, 1.0)], MINI, 0.0);
    let o = StatusOptions { start: Some(vec![false, false]), ..Default::default() };
    let a = solve(&p, &o).unwrap();
    assert!((a.lambda[0] + 0.75).abs() < 1e-10 && (a.lambda[1] + 0.25).abs() < 1e-10);
    assert_eq!(a.iterations, 1);
    let b = crate::solve::unilateral::tests::kit::solve_ancien(&p, &o).unwrap();
    assert!((b.lambda[0] + 0.75).abs() < 1e-10);
}

#[test]
fn no_condition_is_a_plain_solve() {
    let k = Mat::<f64>::from_fn(1, 1, |_, _| 4.0);
    let pb = ReducedProblem { kc: &k, fc: &[2.0], rows: &[], sense: &[], d: &[], k_ref: None, eq_rows: &[], eq_d: &[] };
    let r = run(&pb, &StatusOptions::default(), &mut |_| {}).unwrap();
    assert_eq!(r.u, vec![0.5]);
    let pb = ReducedProblem { fc: &[2.0, 1.0], ..pb };
    let bad = run(&pb, &StatusOptions::default(), &mut |_| {});
    assert!(matches!(bad, Err(SolveError::Other(_))));
}
