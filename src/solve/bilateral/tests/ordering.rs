use super::*;
use crate::solve::problem::{Condition, Kind, Matrix};

fn chain(n: usize) -> Problem {
    let mut e = Vec::new();
    for i in 0..n - 1 {
        e.extend([(i, i, 1.0), (i + 1, i + 1, 1.0), (i, i + 1, -1.0)]);
    }
    Problem {
        k: Matrix { n, entries: e, symmetric: true },
        conditions: vec![
            Condition { terms: vec![(0, 1.0)], kind: Kind::Equal, dual: None },
            Condition { terms: vec![(2, 1.0), (5, -1.0), (3, 2.0)], kind: Kind::Equal, dual: None },
            Condition { terms: vec![(4, 1.0)], kind: Kind::Mini, dual: None },
        ],
    }
}

#[test]
fn lambda1_before_and_lambda2_after_their_unknowns() {
    let p = chain(8);
    let (n, m) = (8, 3);
    let primal = primal_amd(&p, &[], None).unwrap();
    let fwd = doubled_order_interleaved(&p, &primal, &[]);
    assert_eq!(fwd.len(), n + 2 * m);
    let inv = inverse(&fwd);
    for (ci, c) in p.conditions.iter().enumerate() {
        for &(j, _) in &c.terms {
            assert!(inv[n + ci] < inv[j]);
            assert!(inv[n + m + ci] > inv[j]);
        }
        // Immediately before the first unknown / after the last.
        let first = c.terms.iter().map(|&(j, _)| inv[j]).min().unwrap();
        let last = c.terms.iter().map(|&(j, _)| inv[j]).max().unwrap();
        assert!(inv[n + ci] < first && first - inv[n + ci] <= m);
        assert!(inv[n + m + ci] > last && inv[n + m + ci] - last <= m);
    }
}

#[test]
fn lambda1_first_keeps_primal_chains_contiguous() {
    let p = chain(8);
    let (n, m) = (8, 3);
    let primal = primal_amd(&p, &[], None).unwrap();
    let fwd = doubled_order(&p, &primal, &[]);
    assert_eq!(&fwd[..m], &[n, n + 1, n + 2]);
    let inv = inverse(&fwd);
    for (ci, c) in p.conditions.iter().enumerate() {
        for &(j, _) in &c.terms {
            assert!(inv[n + ci] < inv[j] && inv[n + m + ci] > inv[j]);
        }
    }
    // The primal unknowns keep their AMD order, one after the other
    // except for the λ2 that close rows.
    let prim: Vec<usize> = fwd.iter().copied().filter(|&o| o < n).collect();
    assert_eq!(prim, primal);
}

/// Upper CSC pattern of a symmetric entry list.
fn upper(n: usize, e: &[(usize, usize, f64)]) -> (Vec<usize>, Vec<usize>) {
    let mut cols: Vec<Vec<usize>> = vec![Vec::new(); n];
    for &(i, j, _) in e {
        cols[i.max(j)].push(i.min(j));
    }
    let (mut cp, mut ri) = (vec![0], Vec::new());
    for mut c in cols {
        c.sort_unstable();
        c.dedup();
        ri.extend(c);
        cp.push(ri.len());
    }
    (cp, ri)
}

#[test]
fn factor_flops_counts_the_fill_of_the_order() {
    // A chain factorises without fill: column counts 2, …, 2, 1.
    let p = chain(10);
    let (cp, ri) = upper(10, &p.k.entries);
    let natural: Vec<usize> = (0..10).collect();
    assert_eq!(factor_flops(10, &cp, &ri, &natural), 9.0 * 4.0 + 1.0);
    // An arrow with its hub first fills completely: counts 10, 9, …, 1.
    let star: Vec<(usize, usize, f64)> = (1..10).flat_map(|j| [(0, j, 1.0), (j, j, 1.0)]).collect();
    let (cp, ri) = upper(10, &star);
    let full: f64 = (1..=10).map(|c| (c * c) as f64).sum();
    assert_eq!(factor_flops(10, &cp, &ri, &natural), full);
    // Hub last: no fill.
    let hub_last: Vec<usize> = (1..10).chain([0]).collect();
    assert_eq!(factor_flops(10, &cp, &ri, &hub_last), 9.0 * 4.0 + 1.0);
}

#[test]
fn nested_dissection_orders_a_3d_grid_with_less_fill_than_amd() {
    let nx = 12;
    let id = |x: usize, y: usize, z: usize| x + nx * (y + nx * z);
    let mut e = Vec::new();
    for z in 0..nx {
        for y in 0..nx {
            for x in 0..nx {
                e.push((id(x, y, z), id(x, y, z), 6.0));
                if x + 1 < nx {
                    e.push((id(x, y, z), id(x + 1, y, z), -1.0));
                }
                if y + 1 < nx {
                    e.push((id(x, y, z), id(x, y + 1, z), -1.0));
                }
                if z + 1 < nx {
                    e.push((id(x, y, z), id(x, y, z + 1), -1.0));
                }
            }
        }
    }
    let n = nx * nx * nx;
    let p = Problem { k: Matrix { n, entries: e.clone(), symmetric: true }, conditions: vec![] };
    let (cp, ri) = upper(n, &e);
    let nd = primal_order(&p, &[], Some((&cp, &ri)), Algo::Nd).unwrap();
    let mut seen = nd.clone();
    seen.sort_unstable();
    assert_eq!(seen, (0..n).collect::<Vec<_>>());
    let amd = primal_order(&p, &[], Some((&cp, &ri)), Algo::Amd).unwrap();
    let (f_nd, f_amd) = (factor_flops(n, &cp, &ri, &nd), factor_flops(n, &cp, &ri, &amd));
    assert!(f_nd < f_amd, "nd {f_nd} amd {f_amd}");
    // primal_best relies on AMD's own count being the etree count.
    let (again, estimate) = primal_order_counted(&p, &[], Some((&cp, &ri)), Algo::Amd).unwrap();
    assert_eq!(again, amd);
    let estimate = estimate.unwrap();
    assert!((estimate - f_amd).abs() <= 1e-9 * f_amd, "AMD {estimate} etree {f_amd}");
}

#[test]
fn unilateral_lambda2_go_last() {
    let p = chain(8);
    let primal = primal_amd(&p, &[], None).unwrap();
    let fwd = doubled_order(&p, &primal, &[2]);
    assert_eq!(*fwd.last().unwrap(), 8 + 3 + 2);
    let kept = primal_amd(&p, &[6, 1], None).unwrap();
    assert_eq!(&kept[6..], &[6, 1]);
}
