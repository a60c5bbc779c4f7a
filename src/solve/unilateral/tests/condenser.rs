//! The condenser against dense formulas, direct solves, and its own two
//! paths (border and whole matrix).

use super::*;
use crate::solve::bilateral::direct::{self, DirectOptions};
use crate::solve::bilateral::tests::kit::{assert_close, chain, cond, dense};
use crate::solve::problem::{Kind, Matrix};
use faer::linalg::solvers::Solve;

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
    let mut t = (*cd.g).clone();
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
        let cd = Condenser::new_whole(&p).unwrap().condensed(&load(m)).unwrap();
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

/// A 5-point Laplacian on an nx×nx grid (free: singular).
fn grid(nx: usize) -> Matrix {
    let mut entries = Vec::new();
    let id = |i: usize, j: usize| i * nx + j;
    for i in 0..nx {
        for j in 0..nx {
            for (a, b) in [(i + 1, j), (i, j + 1)] {
                if a < nx && b < nx {
                    let (p, q) = (id(i, j), id(a, b));
                    entries.extend([(p, p, 1.0), (p, q, -1.0), (q, p, -1.0), (q, q, 1.0)]);
                }
            }
        }
    }
    Matrix { n: nx * nx, entries, symmetric: true }
}

/// The border path (A₁₁ factorised alone, S formed from W = L⁻¹B) gives
/// the numbers of the whole-matrix path: G, h, XᵀF and the recovered
/// solution, with multi-term rows, bilateral conditions among the
/// unilateral ones and contact zones far apart on a mesh large enough to
/// have many supernodes.
#[test]
fn border_path_matches_the_whole_matrix_path() {
    let nx = 24;
    let mut rng = crate::solve::unilateral::tests::kit::Rng(0x9e37_79b9);
    let mut rnd = move |k: usize| rng.below(k);
    let mut conditions = Vec::new();
    for q in 0..60 {
        let j = rnd(nx * nx);
        let kind = if q % 3 == 0 { Kind::Maxi } else { Kind::Mini };
        let mut terms = vec![(j, 1.0 + (q % 5) as f64 * 0.25)];
        if q % 4 == 1 {
            terms.push(((j + 1 + rnd(nx)) % (nx * nx), -0.5));
        }
        conditions.push(cond(&terms, kind));
        if q % 15 == 7 {
            conditions.push(cond(&[(rnd(nx * nx), 1.0), (rnd(nx * nx), 2.0)], Kind::Equal));
        }
    }
    let p = Problem { k: grid(nx), conditions };
    let m = p.conditions.len();
    let n = p.k.n;
    let load = Load {
        f: (0..n).map(|j| ((j * 7919) % 13) as f64 / 13.0 - 0.4).collect(),
        d: (0..m).map(|i| ((i * 31) % 7) as f64 * 0.01 - 0.02).collect(),
    };
    let (a, b) = (Condenser::new(&p).unwrap(), Condenser::new_whole(&p).unwrap());
    assert!(matches!(a.core, Core::Bordered(_)) && matches!(b.core, Core::Whole(_)));
    let (ca, cb) = (a.condensed(&load).unwrap(), b.condensed(&load).unwrap());
    let mu = ca.h.len();
    let gmax = (0..mu).fold(0.0f64, |s, i| s.max(cb.g[(i, i)].abs()));
    for i in 0..mu {
        for j in 0..mu {
            assert_close(ca.g[(i, j)], cb.g[(i, j)], gmax);
        }
    }
    let hmax = cb.h.iter().chain(&cb.xtf).fold(1.0f64, |s, v| s.max(v.abs()));
    for q in 0..mu {
        assert_close(ca.h[q], cb.h[q], hmax);
        assert_close(ca.xtf[q], cb.xtf[q], hmax);
    }
    // Some statuses, some values of the condensed unknowns.
    let x: Vec<f64> = (0..mu).map(|q| if q % 3 == 1 { 0.0 } else { 0.1 * q as f64 - 2.0 }).collect();
    let active: Vec<bool> = (0..mu).map(|q| q % 3 != 1).collect();
    let (sa, sb) = (a.recover(&load, &x, &active).unwrap(), b.recover(&load, &x, &active).unwrap());
    let umax = sb.u.iter().chain(&sb.lambda).fold(1.0f64, |s, v| s.max(v.abs()));
    for (u, v) in sa.u.iter().zip(&sb.u).chain(sa.lambda.iter().zip(&sb.lambda)) {
        assert!((u - v).abs() <= 1e-8 * umax, "{u} vs {v}");
    }
}
