use super::helpers::*;
use crate::fem::mesh::{ElemType, Nodes};
use crate::fem::meshing::*;

#[test]
fn droi_4_gives_quarter_steps_and_4_seg2() {
    let mut n = Nodes::default();
    let (a, b) = (pt(&mut n, 0.0, 0.0), pt(&mut n, 1.0, 0.0));
    let l = droi(&mut n, a, b, &Spacing::count(4), ElemType::Qua4).unwrap();
    assert_eq!(l.parts.len(), 1);
    assert_eq!(l.parts[0].ty, ElemType::Seg2);
    assert_eq!(l.parts[0].conn, vec![0, 2, 2, 3, 3, 4, 4, 1]);
    for (k, x) in [0.25, 0.5, 0.75].iter().enumerate() {
        assert!(close(n.get(2 + k)[0], *x) && n.get(2 + k)[1] == 0.0);
    }
    assert_eq!(nbel(&l), 4);
    assert_eq!(nbno(&l), 5);
    assert_eq!(poin_init(&l).unwrap(), a);
    assert_eq!(poin_final(&l).unwrap(), b);
    assert_eq!(poin_nth(&l, 2).unwrap(), 2);
    assert_eq!(poin_nth(&l, 5).unwrap(), b);
}

#[test]
fn droi_seg3_interleaves_middle_nodes() {
    let mut n = Nodes::default();
    let (a, b) = (pt(&mut n, 0.0, 0.0), pt(&mut n, 0.0, 2.0));
    let l = droi(&mut n, a, b, &Spacing::count(2), ElemType::Qua8).unwrap();
    assert_eq!(l.parts[0].ty, ElemType::Seg3);
    assert_eq!(l.parts[0].conn, vec![0, 2, 3, 3, 4, 1]);
    let ys: Vec<f64> = (2..5).map(|k| n.get(k)[1]).collect();
    assert_eq!(ys, vec![0.5, 1.0, 1.5]);
    assert_eq!(line_chain("T", &l).unwrap(), vec![0, 2, 3, 4, 1]);
}

#[test]
fn dini_dfin_grading_sums_to_length_and_grows_geometrically() {
    let mut n = Nodes::default();
    let (a, b) = (pt(&mut n, 0.0, 0.0), pt(&mut n, 3.0, 4.0));
    let l = droi(&mut n, a, b, &Spacing::count(5).densities(0.1, 2.0), ElemType::Seg2).unwrap();
    let h = lengths(&n, &l);
    assert_eq!(h.len(), 5);
    assert!(close(h.iter().sum::<f64>(), 5.0));
    let q = 20f64.powf(0.2);
    for w in h.windows(2) {
        assert!(close(w[1] / w[0], q));
    }
    // Without a count: n = L ln(d2/d1) / (d2 - d1) rounded.
    let l2 = droi(&mut n, a, b, &Spacing::default().densities(0.1, 2.0), ElemType::Seg2).unwrap();
    let expect = (5.0 * 20f64.ln() / 1.9).round() as usize;
    assert_eq!(nbel(&l2), expect);
    assert!(close(lengths(&n, &l2).iter().sum::<f64>(), 5.0));
}

#[test]
fn node_densities_give_the_count_and_negative_n_grades() {
    let mut n = Nodes::default();
    let a = n.push([0.0; 3], 0.25);
    let b = n.push([1.0, 0.0, 0.0], 0.25);
    let l = droi(&mut n, a, b, &Spacing::default(), ElemType::Seg2).unwrap();
    assert_eq!(nbel(&l), 4);
    let c = n.push([2.0, 0.0, 0.0], 1.0);
    let g = droi(&mut n, b, c, &Spacing::count(-3), ElemType::Seg2).unwrap();
    let h = lengths(&n, &g);
    assert_eq!(h.len(), 3);
    assert!(h[0] < h[1] && h[1] < h[2]);
    assert!(close(h.iter().sum::<f64>(), 1.0));
    // A positive count alone ignores node densities.
    let u = droi(&mut n, b, c, &Spacing::count(2), ElemType::Seg2).unwrap();
    assert_eq!(lengths(&n, &u), vec![0.5, 0.5]);
}

#[test]
fn droi_errors_are_clear() {
    let mut n = Nodes::default();
    let (a, b) = (pt(&mut n, 0.0, 0.0), pt(&mut n, 1.0, 0.0));
    let e = droi(&mut n, a, b, &Spacing::default(), ElemType::Seg2).unwrap_err();
    assert!(e.to_string().starts_with("DROI: no element count"), "{e}");
    let e = droi(&mut n, a, a, &Spacing::count(2), ElemType::Seg2).unwrap_err();
    assert!(e.to_string().contains("same point"));
    let e = droi(&mut n, a, 99, &Spacing::count(2), ElemType::Seg2).unwrap_err();
    assert!(e.to_string().contains("node 99 does not exist"));
    let e = droi(&mut n, a, b, &Spacing::count(2).densities(-1.0, 1.0), ElemType::Seg2).unwrap_err();
    assert!(e.to_string().contains("'DINI' must be positive"));
}

#[test]
fn droi_extend_prolongs_a_line() {
    let mut n = Nodes::default();
    let (a, b, c) = (pt(&mut n, 0.0, 0.0), pt(&mut n, 1.0, 0.0), pt(&mut n, 1.0, 1.0));
    let l = droi(&mut n, a, b, &Spacing::count(2), ElemType::Seg2).unwrap();
    let l2 = droi_extend(&mut n, &l, c, &Spacing::count(2), ElemType::Seg2).unwrap();
    assert_eq!(nbel(&l2), 4);
    assert_eq!(poin_final(&l2).unwrap(), c);
    assert_eq!(line_chain("T", &l2).unwrap().len(), 5);
}

#[test]
fn cerc_quarter_arc_stays_on_the_circle() {
    let mut n = Nodes::default();
    let (a, o, b) = (pt(&mut n, 2.0, 0.0), pt(&mut n, 0.0, 0.0), pt(&mut n, 0.0, 2.0));
    let l = cerc(&mut n, a, o, b, &Spacing::count(6), ElemType::Seg3).unwrap();
    let chain = line_chain("T", &l).unwrap();
    assert_eq!(chain.len(), 13);
    for (k, &m) in chain.iter().enumerate() {
        let x = n.get(m);
        assert!(close(x[0].hypot(x[1]), 2.0));
        let ang = x[1].atan2(x[0]);
        assert!(close(ang, std::f64::consts::FRAC_PI_2 * k as f64 / 12.0));
    }
    // Half circle in 2D goes counter-clockwise.
    let c = pt(&mut n, -2.0, 0.0);
    let h = cerc(&mut n, a, o, c, &Spacing::count(2), ElemType::Seg2).unwrap();
    let mid = n.get(h.parts[0].conn[1]);
    assert!(close(mid[0], 0.0) && close(mid[1], 2.0));
    let e = cerc(&mut n, a, o, a, &Spacing::count(2), ElemType::Seg2).unwrap_err();
    assert!(e.to_string().starts_with("CERC:"));
}

#[test]
fn absurd_counts_are_refused() {
    let mut n = Nodes::default();
    let (a, b) = (pt(&mut n, 0.0, 0.0), pt(&mut n, 1.0, 0.0));
    let e = droi(&mut n, a, b, &Spacing::count(1 << 40), ElemType::Seg2).unwrap_err();
    assert!(e.to_string().contains("allowed"), "{e}");
    let e = droi(&mut n, a, b, &Spacing::default().densities(1e-12, 1e-12), ElemType::Seg2).unwrap_err();
    assert!(e.to_string().contains("more than"), "{e}");
}
