use super::*;
use crate::solve::unilateral::status::StatusOptions;
use crate::solve::unilateral::tests::kit::{build, spring, Dense, Rng, MAXI, MINI};

/// A positive definite problem: every status is regular.
fn random_pd(rng: &mut Rng, n: usize, m: usize) -> Dense {
    let b = Mat::<f64>::from_fn(n, n, |_, _| rng.sym());
    let mut k = &b * b.transpose();
    for i in 0..n {
        k[(i, i)] += 0.5;
    }
    let mut p = Dense::new(k, (0..n).map(|_| rng.sym()).collect());
    for i in 0..m {
        let s = if rng.below(2) == 0 { MINI } else { MAXI };
        p = p.cond(&[(i, 1.0), ((i + 1) % n, rng.sym())], s, rng.sym());
    }
    p
}

#[test]
fn update_path_matches_fresh_factorisation() {
    let mut rng = Rng(99);
    let p = random_pd(&mut rng, 20, 15);
    let b = build(&p);
    let mut op = TOperator::new(&b.c).unwrap();
    let mut active = vec![true; 15];
    op.set_status(&active).unwrap();
    let mut max_updates = 0;
    for step in 0..60 {
        for _ in 0..1 + rng.below(3) {
            let i = rng.below(15);
            active[i] = !active[i];
        }
        op.set_status(&active).unwrap();
        let updates = op.factor.as_ref().unwrap().updates();
        max_updates = max_updates.max(updates);
        assert!(updates <= MAX_UPDATES);
        let x = op.solve().unwrap();
        let mut fresh = TOperator::new(&b.c).unwrap();
        fresh.set_status(&active).unwrap();
        assert_eq!(fresh.factor.as_ref().unwrap().updates(), 0);
        let y = fresh.solve().unwrap();
        let scale = y.iter().fold(1.0_f64, |a, v| a.max(v.abs()));
        for (u, v) in x.iter().zip(&y) {
            assert!((u - v).abs() <= 1e-10 * scale, "step {step}: {u} vs {v}");
        }
        // The determinant lemma agrees with a fresh factorisation.
        if let Some(i) = (0..15).find(|&i| active[i]) {
            let (singular, _) = op.release(i).unwrap();
            assert!(!singular);
        }
    }
    assert!(max_updates > 5, "the update path was not used");
}

#[test]
fn unloaded_rigid_mode_keeps_the_condition_active() {
    // Hand-made data as round-off could leave it: releasing the only
    // condition is singular (T' = G − α = 0), its sign is wrong by a
    // hair, and the load does no work along the freed mode.
    let p = spring(0.0, 0.0).cond(&[(0, 1.0)], MINI, 0.0);
    let mut b = build(&p);
    b.c.h[0] = 1e-3 * b.c.g[(0, 0)];
    let r = run(&b.c, &StatusOptions::default(), &mut |_| {}).unwrap();
    assert_eq!(r.active, vec![true]);
    assert_eq!(r.records.len(), 1);
}
