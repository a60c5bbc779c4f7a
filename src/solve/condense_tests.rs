//! The interrupted factorisation against dense formulas and direct solves.

use super::*;
use crate::solve::direct::{self, DirectOptions};
use crate::solve::problem::{Condition, Kind, Matrix};
use faer::linalg::solvers::Solve;

/// A free chain of springs (K singular), stiffnesses varying along it.
fn chain(n: usize) -> Matrix {
    let mut entries = Vec::new();
    for i in 0..n - 1 {
        let k = 1.0 + 0.5 * i as f64;
        entries.extend([(i, i, k), (i, i + 1, -k), (i + 1, i, -k), (i + 1, i + 1, k)]);
    }
    Matrix { n, entries, symmetric: true }
}

fn cond(terms: &[(usize, f64)], kind: Kind) -> Condition {
    Condition { terms: terms.to_vec(), kind, dual: None }
}

fn dense(p: &Problem) -> Mat<f64> {
    let n = p.k.n;
    let mut k = Mat::<f64>::zeros(n, n);
    for &(i, j, v) in &p.k.entries {
        k[(i, j)] += v;
    }
    k
}

fn assert_close(a: f64, b: f64, scale: f64) {
    assert!((a - b).abs() <= 1e-10 * scale, "{a} vs {b}");
}

/// Unilateral only, with a MINI/MAXI pair on one dof (G singular) and a
/// two-term row: G, h and XᵀF against the dense formulas of §3.2.
#[test]
fn trailing_supernode_gives_g_h_and_xtf() {
    let n = 6;
    let p = Problem {
        k: chain(n),
        conditions: vec![
            cond(&[(0, 1.0)], Kind::Mini),
            cond(&[(5, 1.0)], Kind::Maxi),
            cond(&[(2, 1.0), (3, -2.0)], Kind::Mini),
            cond(&[(4, 1.0)], Kind::Mini),
            cond(&[(4, 1.0)], Kind::Maxi),
        ],
    };
    let load = Load { f: vec![0.3, -1.0, 0.0, 2.0, 0.5, -0.7], d: vec![-0.1, 0.2, 0.05, -0.3, 0.4] };
    let c = Condenser::new(&p).unwrap();
    let cd = c.condensed(&load).unwrap();
    let m = p.conditions.len();
    let mut cm = Mat::<f64>::zeros(m, n);
    for (i, cnd) in p.conditions.iter().enumerate() {
        for &(j, v) in &cnd.terms {
            cm[(i, j)] += v;
        }
    }
    // H = K + CᵀWC, W = ΣA⁻¹Σ.
    let w: Vec<f64> = (0..m).map(|i| cd.sigma[i].powi(2) / cd.alpha[i]).collect();
    let mut h = dense(&p);
    for i in 0..m {
        for a in 0..n {
            for b in 0..n {
                h[(a, b)] += w[i] * cm[(i, a)] * cm[(i, b)];
            }
        }
    }
    let lu = h.partial_piv_lu();
    let sc = Mat::from_fn(n, m, |j, i| cm[(i, j)] * cd.sigma[i]); // CᵀΣ
    let x = lu.solve(&sc);
    let g = sc.transpose() * &x;
    let gmax = (0..m).fold(0.0f64, |a, i| a.max(g[(i, i)].abs()));
    for i in 0..m {
        for j in 0..m {
            assert_close(cd.g[(i, j)], g[(i, j)], gmax);
        }
    }
    // Column 0 gets the limits added below; column 1 stays F alone.
    let mut rhs = Mat::from_fn(n, 2, |j, _| load.f[j]);
    for i in 0..m {
        for j in 0..n {
            rhs[(j, 0)] += cm[(i, j)] * w[i] * load.d[i];
        }
    }
    let uf = lu.solve(&rhs);
    let y = sc.transpose() * &uf;
    for i in 0..m {
        let href = 0.5 * (y[(i, 0)] - cd.sigma[i] * load.d[i]);
        assert_close(cd.h[i], href, 1.0 + href.abs());
        assert_close(cd.xtf[i], y[(i, 1)], 1.0 + y[(i, 1)].abs());
    }
    assert_eq!(cd.sense, vec![1.0, -1.0, 1.0, 1.0, -1.0]);
    assert_eq!(cd.d, load.d);
    assert_eq!(cd.rows[2], vec![(2, 1.0), (3, -2.0)]);
}

fn mixed() -> (Problem, Load) {
    let n = 7;
    let p = Problem {
        k: chain(n),
        conditions: vec![
            cond(&[(3, 1.0)], Kind::Equal),
            cond(&[(0, 1.0)], Kind::Mini),
            cond(&[(6, 2.0), (5, -1.0)], Kind::Maxi),
            cond(&[(1, 1.0), (2, 1.0)], Kind::Equal),
            cond(&[(4, 1.0)], Kind::Mini),
        ],
    };
    let load = Load { f: vec![0.1, -0.4, 0.0, 1.0, 0.5, -2.0, 0.7], d: vec![0.2, -0.1, 0.3, 0.05, -0.2] };
    (p, load)
}

fn check_against_direct(active: &[bool]) {
    let (p, load) = mixed();
    let c = Condenser::new(&p).unwrap();
    let cd = c.condensed(&load).unwrap();
    let mu = cd.h.len();
    let mut t = cd.g.clone();
    for q in 0..mu {
        if !active[q] {
            t[(q, q)] -= cd.alpha[q];
        }
    }
    let hm = Mat::from_fn(mu, 1, |q, _| cd.h[q]);
    let x = t.partial_piv_lu().solve(&hm);
    let xs: Vec<f64> = (0..mu).map(|q| x[(q, 0)]).collect();
    let s = c.recover(&load, &xs, active).unwrap();
    // Reference: active unilateral conditions as equalities, others dropped.
    let mut q_of = vec![None; p.conditions.len()];
    for (q, &i) in c.unilateral().iter().enumerate() {
        q_of[i] = Some(q);
    }
    let keep: Vec<usize> = (0..p.conditions.len()).filter(|&i| q_of[i].is_none_or(|q| active[q])).collect();
    let pr = Problem {
        k: p.k.clone(),
        conditions: keep.iter().map(|&i| cond(&p.conditions[i].terms, Kind::Equal)).collect(),
    };
    let lr = Load { f: load.f.clone(), d: keep.iter().map(|&i| load.d[i]).collect() };
    let r = direct::solve(&pr, &[lr], &DirectOptions::default()).unwrap();
    for j in 0..p.k.n {
        assert_close(s.u[j], r[0].u[j], 1.0 + r[0].u[j].abs());
    }
    for (k, &i) in keep.iter().enumerate() {
        assert_close(s.lambda[i], r[0].lambda[k], 1.0 + r[0].lambda[k].abs());
    }
    for i in 0..p.conditions.len() {
        if !keep.contains(&i) {
            assert_eq!(s.lambda[i], 0.0);
            assert!(!s.active[i]);
        }
    }
}

#[test]
fn recovery_matches_direct_solve_all_active() {
    check_against_direct(&[true, true, true]);
}

#[test]
fn recovery_matches_direct_solve_with_a_released_condition() {
    check_against_direct(&[true, false, true]);
    check_against_direct(&[false, true, false]);
}

#[test]
fn refactor_reuses_the_analysis() {
    let (mut p, load) = mixed();
    let mut c = Condenser::new(&p).unwrap();
    for e in &mut p.k.entries {
        e.2 *= 3.0;
    }
    assert!(c.same_pattern(&p));
    c.refactor(&p).unwrap();
    let fresh = Condenser::new(&p).unwrap();
    let (a, b) = (c.condensed(&load).unwrap(), fresh.condensed(&load).unwrap());
    for i in 0..a.h.len() {
        assert_close(a.h[i], b.h[i], 1.0);
        for j in 0..a.h.len() {
            assert_close(a.g[(i, j)], b.g[(i, j)], 1.0);
        }
    }
}

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

/// G = ΣC H⁻¹ CᵀΣ by dense algebra (unilateral rows only, no bilateral).
fn reference_g(p: &Problem, cd: &Condensed) -> Mat<f64> {
    let n = p.k.n;
    let m = p.conditions.len();
    let cm = Mat::<f64>::from_fn(m, n, |i, j| p.conditions[i].terms.iter().filter(|t| t.0 == j).map(|t| t.1).sum());
    let mut h = dense(p);
    for i in 0..m {
        let w = cd.sigma[i].powi(2) / cd.alpha[i];
        for a in 0..n {
            for b in 0..n {
                h[(a, b)] += w * cm[(i, a)] * cm[(i, b)];
            }
        }
    }
    let sc = Mat::from_fn(n, m, |j, i| cm[(i, j)] * cd.sigma[i]);
    let x = h.partial_piv_lu().solve(&sc);
    sc.transpose() * &x
}

/// Independent rows: the tail is factorised unshifted and its factor is
/// G's own (L D Lᵀ = G). A row that is a sum of two others (dependent, not
/// proportional) makes that factor singular: the tail is factorised again
/// with the shift, and G is still right.
#[test]
fn unshifted_tail_gives_the_factor_of_g_or_falls_back() {
    let load = |m: usize| Load { f: vec![0.3, -1.0, 0.0, 2.0, 0.5, -0.7], d: vec![0.0; m] };
    let independent = Problem {
        k: chain(6),
        conditions: vec![
            cond(&[(0, 1.0)], Kind::Mini),
            cond(&[(2, 1.0), (3, -2.0)], Kind::Maxi),
            cond(&[(5, 1.0)], Kind::Mini),
        ],
    };
    let dependent = Problem {
        k: chain(6),
        conditions: vec![
            cond(&[(1, 1.0)], Kind::Mini),
            cond(&[(4, 1.0)], Kind::Mini),
            cond(&[(1, 1.0), (4, 1.0)], Kind::Maxi),
        ],
    };
    for (p, factored) in [(independent, true), (dependent, false)] {
        let m = p.conditions.len();
        let cd = Condenser::new(&p).unwrap().condensed(&load(m)).unwrap();
        let g = reference_g(&p, &cd);
        let gmax = (0..m).fold(0.0f64, |a, i| a.max(g[(i, i)].abs()));
        for i in 0..m {
            for j in 0..m {
                assert_close(cd.g[(i, j)], g[(i, j)], gmax);
            }
        }
        assert_eq!(cd.g_factor.is_some(), factored);
        if let Some(f) = &cd.g_factor {
            let l = Mat::<f64>::from_fn(m, m, |i, j| {
                if i == j {
                    1.0
                } else if i > j {
                    f[(i, j)]
                } else {
                    0.0
                }
            });
            let ld = Mat::<f64>::from_fn(m, m, |i, j| l[(i, j)] * f[(j, j)]);
            let back = &ld * l.transpose();
            for i in 0..m {
                for j in 0..m {
                    assert_close(back[(i, j)], g[(i, j)], gmax);
                }
            }
        }
    }
}
