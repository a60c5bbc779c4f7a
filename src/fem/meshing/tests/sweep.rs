use super::helpers::*;
use crate::fem::mesh::{ElemType, Nodes};
use crate::fem::meshing::*;

#[test]
fn tran_of_a_line_in_3_layers() {
    let mut n = Nodes::default();
    let (a, b) = (pt(&mut n, 0.0, 0.0), pt(&mut n, 2.0, 0.0));
    let l = droi(&mut n, a, b, &Spacing::count(2), ElemType::Seg2).unwrap();
    let s = tran(&mut n, &l, &Spacing::count(3), [0.0, 1.5, 0.0]).unwrap();
    assert_eq!(s.parts[0].ty, ElemType::Qua4);
    assert_eq!(nbel(&s), 6);
    assert_eq!(nbno(&s), 12);
    let ar = areas(&n, &s);
    assert!(ar.iter().all(|&x| close(x, 0.5)), "{ar:?}");
    // Layer-major order: element 2 is the second element of the first layer.
    let e2 = s.parts[0].elem(1);
    assert_eq!(&e2[..2], &l.parts[0].conn[2..4]);
    assert!(close(n.get(e2[2])[1], 0.5));
    // COTE of a TRAN surface: generator, end path, copy reversed, start path reversed.
    let c1 = cote(&s, 1).unwrap();
    assert_eq!(c1, l);
    let c2 = cote(&s, 2).unwrap();
    assert_eq!(poin_init(&c2).unwrap(), b);
    assert!(close(lengths(&n, &c2).iter().sum::<f64>(), 1.5));
    let c4 = cote(&s, 4).unwrap();
    assert_eq!(poin_final(&c4).unwrap(), a);
}

#[test]
fn tran_layers_follow_dini_dfin() {
    let mut n = Nodes::default();
    let (a, b) = (pt(&mut n, 0.0, 0.0), pt(&mut n, 1.0, 0.0));
    let l = droi(&mut n, a, b, &Spacing::count(1), ElemType::Seg2).unwrap();
    let s = tran(&mut n, &l, &Spacing::count(3).densities(0.1, 0.5), [0.0, 0.0, 2.0]).unwrap();
    let side = cote(&s, 2).unwrap();
    let h = lengths(&n, &side);
    assert!(h[0] < h[1] && h[1] < h[2]);
    assert!(close(h.iter().sum::<f64>(), 2.0));
}

#[test]
fn rota_of_a_line_90_degrees_is_a_quarter_annulus() {
    let mut n = Nodes::default();
    let o = pt(&mut n, 0.0, 0.0);
    let (a, b) = (pt(&mut n, 1.0, 0.0), pt(&mut n, 3.0, 0.0));
    let l = droi(&mut n, a, b, &Spacing::count(2), ElemType::Seg2).unwrap();
    let centre = n.get(o);
    let s = rota(&mut n, &l, &Spacing::count(4), 90.0, centre, None).unwrap();
    assert_eq!(nbel(&s), 8);
    assert_eq!(nbno(&s), 15);
    for m in s.node_list() {
        let x = n.get(m);
        let r = x[0].hypot(x[1]);
        assert!([1.0, 2.0, 3.0].iter().any(|&q| close(r, q)), "radius {r}");
        assert!(x[0] >= -1e-12 && x[1] >= -1e-12);
    }
    let ar: f64 = areas(&n, &s).iter().sum();
    assert!(ar > 0.0, "counter-clockwise");
    // Straight-sided quads inscribed in the annulus: 4 chords per ring.
    let chord = |r: f64| 4.0 * 0.5 * r * r * std::f64::consts::FRAC_PI_8.sin();
    assert!(close(ar, chord(3.0) - chord(1.0)), "{ar}");
    let far = cote(&s, 2).unwrap();
    assert!(lengths(&n, &far).iter().all(|&h| close(h, 2.0 * 3.0 * (std::f64::consts::PI / 16.0).sin())));
}

#[test]
fn rota_full_turn_closes_and_axis_nodes_are_not_copied() {
    let mut n = Nodes::default();
    let (a, b) = (pt(&mut n, 0.0, 0.0), pt(&mut n, 1.0, 0.0));
    let l = droi(&mut n, a, b, &Spacing::count(1), ElemType::Seg2).unwrap();
    let s = rota(&mut n, &l, &Spacing::count(4), 360.0, [0.0; 3], None).unwrap();
    assert_eq!(nbno(&s), 5, "centre + 4 rim nodes");
    let last = s.parts[0].elem(3);
    assert_eq!(last[2], b, "the last layer is the first");
}

#[test]
fn rota_in_3d_about_an_axis() {
    let mut n = Nodes::default();
    let a = n.push([1.0, 0.0, 0.0], 0.0);
    let b = n.push([1.0, 0.0, 1.0], 0.0);
    let l = droi(&mut n, a, b, &Spacing::count(1), ElemType::Seg2).unwrap();
    let s = rota(&mut n, &l, &Spacing::count(1), 90.0, [0.0; 3], Some([0.0, 0.0, 5.0])).unwrap();
    let e = s.parts[0].elem(0);
    let x = n.get(e[2]);
    assert!(close(x[0], 0.0) && close(x[1], 1.0) && close(x[2], 1.0));
}

#[test]
fn tran_of_surfaces_makes_positive_volumes() {
    let mut n = Nodes::default();
    let p: Vec<usize> =
        [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]].iter().map(|x| pt(&mut n, x[0], x[1])).collect();
    let q = manu(&n, ElemType::Qua4, &[p[0], p[1], p[2], p[3]]).unwrap();
    let t = manu(&n, ElemType::Tri3, &[p[0], p[1], p[2]]).unwrap();
    for v in [[0.0, 0.0, 2.0], [0.0, 0.0, -2.0]] {
        let c = tran(&mut n, &q, &Spacing::count(2), v).unwrap();
        assert_eq!(c.parts[0].ty, ElemType::Cub8);
        for e in c.parts[0].elems() {
            assert!(close(volume(&n, ElemType::Cub8, e), 1.0));
        }
        let pr = tran(&mut n, &t, &Spacing::count(1), v).unwrap();
        assert!(close(volume(&n, ElemType::Pri6, pr.parts[0].elem(0)), 1.0));
    }
}

#[test]
fn tran_seg3_gives_qua8_with_middle_layer() {
    let mut n = Nodes::default();
    let (a, b) = (pt(&mut n, 0.0, 0.0), pt(&mut n, 1.0, 0.0));
    let l = droi(&mut n, a, b, &Spacing::count(1), ElemType::Seg3).unwrap();
    let s = tran(&mut n, &l, &Spacing::count(1), [0.0, 1.0, 0.0]).unwrap();
    assert_eq!(s.parts[0].ty, ElemType::Qua8);
    assert_eq!(nbno(&s), 8);
    assert!(close(areas(&n, &s)[0], 1.0));
    let e = s.parts[0].elem(0);
    assert!(close(n.get(e[3])[1], 0.5) && close(n.get(e[7])[1], 0.5));
    assert!(close(n.get(e[5])[0], 0.5) && close(n.get(e[5])[1], 1.0));
}

#[test]
fn volu_between_two_surfaces() {
    let mut n = Nodes::default();
    let p: Vec<usize> =
        [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]].iter().map(|x| pt(&mut n, x[0], x[1])).collect();
    let q = manu(&n, ElemType::Qua4, &[p[0], p[1], p[2], p[3]]).unwrap();
    let top = translate_copy(&mut n, &q, [0.0, 0.0, 3.0]).unwrap();
    let v = volu(&mut n, &q, &top, &Spacing::count(3)).unwrap();
    assert_eq!(nbel(&v), 3);
    assert_eq!(nbno(&v), 16);
    let total: f64 = v.parts[0].elems().map(|e| volume(&n, ElemType::Cub8, e)).sum();
    assert!(close(total, 3.0));
    assert_eq!(&v.parts[0].elem(2)[4..], top.parts[0].elem(0));
}

#[test]
fn cote_of_a_qua8_tran_surface_and_sweep_errors() {
    let mut n = Nodes::default();
    let (a, b) = (pt(&mut n, 0.0, 0.0), pt(&mut n, 1.0, 0.0));
    let l = droi(&mut n, a, b, &Spacing::count(2), ElemType::Seg3).unwrap();
    let s = tran(&mut n, &l, &Spacing::count(2), [0.0, 1.0, 0.0]).unwrap();
    assert_eq!(cote(&s, 1).unwrap(), l);
    let c3 = cote(&s, 3).unwrap();
    assert_eq!(c3.parts[0].ty, ElemType::Seg3);
    assert!(close(n.get(poin_init(&c3).unwrap())[0], 1.0));
    // Quadratic surfaces sweep into quadratic volumes: the base, the
    // mid-height nodes above its corners, the top.
    let v = tran(&mut n, &s, &Spacing::count(1), [0.0, 0.0, 1.0]).unwrap();
    assert_eq!(v.parts[0].ty, ElemType::Cu20);
    let e0 = v.parts[0].elem(0);
    assert!(close(n.get(e0[8])[2], 0.5) && close(n.get(e0[12])[2], 1.0));
    let e = rota(&mut n, &l, &Spacing::count(1), 400.0, [0.0; 3], None).unwrap_err();
    assert!(e.to_string().starts_with("ROTA: the angle"));
    let other = droi(&mut n, a, b, &Spacing::count(3), ElemType::Seg2).unwrap();
    assert!(volu(&mut n, &l, &other, &Spacing::count(1)).is_err());
}
