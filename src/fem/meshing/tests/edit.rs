use super::helpers::*;
use crate::fem::mesh::{ElemType, Mesh, Nodes};
use crate::fem::meshing::*;

#[test]
fn elim_merges_a_duplicated_line() {
    let mut n = Nodes::default();
    let (a, b) = (pt(&mut n, 0.0, 0.0), pt(&mut n, 1.0, 0.0));
    let (c, d) = (pt(&mut n, 0.0, 0.0), pt(&mut n, 1.0, 1e-7));
    let l1 = droi(&mut n, a, b, &Spacing::count(3), ElemType::Seg2).unwrap();
    let l2 = droi(&mut n, c, d, &Spacing::count(3), ElemType::Seg2).unwrap();
    let both = l1.union(&l2);
    assert_eq!(nbno(&both), 8);
    let (merged, map) = elim(&n, &both, 1e-5).unwrap();
    assert_eq!(merged, l1);
    assert_eq!(map.len(), 4);
    assert_eq!(map.get(c), a);
    assert_eq!(map.get(d), b);
    assert_eq!(map.apply(&l2), l1);
    let (same, none) = elim(&n, &both, 1e-9).unwrap();
    assert_eq!(none.len(), 1, "only the exact duplicate of the start point");
    assert_eq!(nbel(&same), 6);
    assert!(elim(&n, &both, -1.0).is_err());
}

#[test]
fn chan_qua8_shares_mid_nodes() {
    let mut n = Nodes::default();
    let p: Vec<usize> =
        [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]].iter().map(|x| pt(&mut n, x[0], x[1])).collect();
    let s: Vec<Mesh> =
        (0..4).map(|k| droi(&mut n, p[k], p[(k + 1) % 4], &Spacing::count(2), ElemType::Seg2).unwrap()).collect();
    let d = dall(&mut n, [&s[0], &s[1], &s[2], &s[3]], ElemType::Qua4).unwrap();
    let before = n.len();
    let q = change_to_quadratic(&mut n, &d.union(&s[0])).unwrap();
    assert_eq!(n.len(), before + 12, "12 distinct edges");
    let q8 = elem_type(&q, ElemType::Qua8);
    assert_eq!(nbno(&q8), 21);
    assert!(close(areas(&n, &q8).iter().sum::<f64>(), 1.0));
    // The bottom line shares the mid nodes of the quads.
    let seg3 = elem_type(&q, ElemType::Seg3);
    assert_eq!(seg3.parts[0].conn[1], q8.parts[0].conn[1]);
    assert_eq!(change_to_linear(&q), d.union(&s[0]));
    assert_eq!(change_to_poi1(&d).n_elements(), 9);
}

#[test]
fn inte_and_diff() {
    let mut n = Nodes::default();
    let p: Vec<usize> = (0..4).map(|k| pt(&mut n, k as f64, 0.0)).collect();
    let seg = |a: usize, b: usize| manu(&n, ElemType::Seg2, &[a, b]).unwrap();
    let g1 = seg(p[0], p[1]).union(&seg(p[1], p[2]));
    let g2 = seg(p[2], p[1]).union(&seg(p[2], p[3]));
    assert_eq!(inte(&g1, &g2), seg(p[1], p[2]));
    assert_eq!(diff(&g1, &g2), seg(p[0], p[1]).union(&seg(p[2], p[3])));
    assert_eq!(inte(&Mesh::points(&[1, 2]), &Mesh::points(&[2, 3])), Mesh::points(&[2]));
}

#[test]
fn translated_copy_has_new_nodes() {
    let mut n = Nodes::default();
    let (a, b) = (pt(&mut n, 0.0, 0.0), pt(&mut n, 1.0, 0.0));
    let l = droi(&mut n, a, b, &Spacing::count(2), ElemType::Seg2).unwrap();
    let c = translate_copy(&mut n, &l, [0.0, 2.0, 0.0]).unwrap();
    assert_eq!(c.parts[0].conn, vec![3, 4, 4, 5]);
    assert_eq!(n.get(4), [0.5, 2.0, 0.0]);
}

#[test]
fn inve_reverses_lines_and_surfaces() {
    let mut n = Nodes::default();
    let (a, b) = (pt(&mut n, 0.0, 0.0), pt(&mut n, 1.0, 0.0));
    let l = droi(&mut n, a, b, &Spacing::count(2), ElemType::Seg3).unwrap();
    let r = inve(&l).unwrap();
    let mut chain = line_chain("T", &l).unwrap();
    chain.reverse();
    assert_eq!(line_chain("T", &r).unwrap(), chain);
    let c = pt(&mut n, 0.0, 1.0);
    let t = manu(&n, ElemType::Tri3, &[a, b, c]).unwrap();
    assert!(areas(&n, &inve(&t).unwrap())[0] < 0.0);
}

#[test]
fn manu_checks_the_element() {
    let mut n = Nodes::default();
    let (a, b) = (pt(&mut n, 0.0, 0.0), pt(&mut n, 1.0, 0.0));
    assert_eq!(manu(&n, ElemType::Seg2, &[a, b]).unwrap().n_elements(), 1);
    assert_eq!(manu(&n, ElemType::Poi1, &[a, b]).unwrap(), Mesh::points(&[a, b]));
    let e = manu(&n, ElemType::Tri3, &[a, b]).unwrap_err();
    assert_eq!(e.to_string(), "MANU: a TRI3 element needs 3 points, got 2");
    assert!(manu(&n, ElemType::Seg2, &[a, a]).unwrap_err().to_string().contains("twice"));
    assert!(manu(&n, ElemType::Seg2, &[a, 7]).is_err());
}
