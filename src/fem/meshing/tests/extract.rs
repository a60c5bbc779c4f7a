use super::helpers::*;
use crate::fem::mesh::{ElemType, Mesh, Nodes};
use crate::fem::meshing::*;

fn square(n: &mut Nodes, m: i64, ty: ElemType) -> ([Mesh; 4], Mesh) {
    let p: Vec<usize> = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]].iter().map(|x| pt(n, x[0], x[1])).collect();
    let s: Vec<Mesh> = (0..4).map(|k| droi(n, p[k], p[(k + 1) % 4], &Spacing::count(m), ty).unwrap()).collect();
    let d = dall(n, [&s[0], &s[1], &s[2], &s[3]], ty).unwrap();
    ([s[0].clone(), s[1].clone(), s[2].clone(), s[3].clone()], d)
}

#[test]
fn cont_of_a_dall_square() {
    let mut n = Nodes::default();
    let (s, d) = square(&mut n, 2, ElemType::Qua4);
    let c = cont(&d).unwrap();
    assert_eq!(c.parts[0].ty, ElemType::Seg2);
    assert_eq!(nbel(&c), 8);
    assert!(close(lengths(&n, &c).iter().sum::<f64>(), 4.0));
    // Chained counter-clockwise from corner 1: exactly the four sides.
    let all = s[0].union(&s[1]).union(&s[2]).union(&s[3]);
    assert_eq!(c, all);
    let ends = cont(&s[0]).unwrap();
    assert_eq!(ends, Mesh::points(&[0, 1]));
    assert!(cont(&Mesh::points(&[0])).is_err());
}

#[test]
fn cont_of_quadratic_and_triangle_surfaces() {
    let mut n = Nodes::default();
    let (_, d) = square(&mut n, 2, ElemType::Qua8);
    let c = cont(&d).unwrap();
    assert_eq!(c.parts[0].ty, ElemType::Seg3);
    assert_eq!(nbel(&c), 8);
    let (_, t) = square(&mut n, 3, ElemType::Tri3);
    let c = cont(&t).unwrap();
    assert_eq!(nbel(&c), 12);
    assert!(close(lengths(&n, &c).iter().sum::<f64>(), 4.0));
}

#[test]
fn cote_returns_the_four_sides() {
    for ty in [ElemType::Qua4, ElemType::Tri3, ElemType::Qua8, ElemType::Tri6] {
        let mut n = Nodes::default();
        let (s, d) = square(&mut n, 2, ty);
        for (k, side) in s.iter().enumerate() {
            assert_eq!(&cote(&d, k as i64 + 1).unwrap(), side, "{ty:?} side {}", k + 1);
        }
    }
    let mut n = Nodes::default();
    let (s, _) = square(&mut n, 2, ElemType::Qua4);
    assert!(cote(&s[0], 1).is_err());
}

#[test]
fn elem_by_type_number_and_support() {
    let mut n = Nodes::default();
    let (s, d) = square(&mut n, 2, ElemType::Qua4);
    let mixed = d.union(&s[0]);
    assert_eq!(elem_type(&mixed, ElemType::Seg2), s[0]);
    assert_eq!(nbel_of_type(&mixed, ElemType::Qua4), 4);
    let e = elem_numbers(&mixed, None, &[5, 1]).unwrap();
    assert_eq!(e.parts[0].ty, ElemType::Seg2);
    assert_eq!(e.parts[1].conn, d.parts[0].elem(0).to_vec());
    let e = elem_numbers(&mixed, Some(ElemType::Seg2), &[2]).unwrap();
    assert_eq!(e.parts[0].conn, s[0].parts[0].elem(1).to_vec());
    assert!(elem_numbers(&mixed, None, &[7]).is_err());
    let on_bottom = elem_appui(&d, &s[0], false);
    assert_eq!(nbel(&on_bottom), 2);
    assert_eq!(nbel(&elem_appui(&d, &s[0], true)), 0);
}

#[test]
fn poin_forms() {
    let mut n = Nodes::default();
    let (s, d) = square(&mut n, 2, ElemType::Qua4);
    let pm = poin_proc(&n, &s[1], [1.0, 0.5, 0.0]).unwrap();
    assert_eq!(n.get(pm), [1.0, 0.5, 0.0]);
    let on_x1 = poin_droit(&n, &d, [1.0, 0.0, 0.0], [1.0, 2.0, 0.0], 1e-9).unwrap();
    assert_eq!(nbno(&on_x1), 3);
    assert_eq!(on_x1.parts[0].ty, ElemType::Poi1);
    let plane = poin_plan(&n, &d, [0.0; 3], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0], 1e-9).unwrap();
    assert_eq!(nbno(&plane), 3);
    assert!(poin_nth(&d, 0).is_err());
    assert!(poin_nth(&d, 10).is_err());
    assert!(poin_init(&d).is_err());
}

#[test]
fn cont_of_a_ring_has_two_loops() {
    // A 3x3 QUA4 grid with the centre element removed.
    let mut n = Nodes::default();
    let (_, d) = square(&mut n, 3, ElemType::Qua4);
    let ring = diff(&d, &elem_numbers(&d, None, &[5]).unwrap());
    assert_eq!(nbel(&ring), 8);
    let c = cont(&ring).unwrap();
    assert_eq!(nbel(&c), 16);
    assert!(close(lengths(&n, &c).iter().sum::<f64>(), 4.0 + 4.0 / 3.0));
    // The outer loop comes first (it holds element 1's first edge) and is
    // one closed chain of 12 edges.
    let outer = elem_numbers(&c, None, &(1..=12).collect::<Vec<_>>()).unwrap();
    assert_eq!(cont(&outer).unwrap().n_elements(), 0, "closed line: no end points");
    assert!(cote(&ring, 1).is_err(), "two boundaries: not a DALL surface");
}

#[test]
fn clockwise_contour_gives_clockwise_elements_and_3d_dall_works() {
    let mut n = Nodes::default();
    let p: Vec<usize> =
        [[0.0, 0.0], [0.0, 1.0], [1.0, 1.0], [1.0, 0.0]].iter().map(|x| pt(&mut n, x[0], x[1])).collect();
    let s: Vec<Mesh> =
        (0..4).map(|k| droi(&mut n, p[k], p[(k + 1) % 4], &Spacing::count(2), ElemType::Seg2).unwrap()).collect();
    let d = dall(&mut n, [&s[0], &s[1], &s[2], &s[3]], ElemType::Qua4).unwrap();
    assert!(areas(&n, &d).iter().all(|&a| close(a, -0.25)));
    // A tilted square in 3D: the interior node is at its centre.
    let q: Vec<usize> =
        [[0.0, 0.0, 0.0], [1.0, 0.0, 1.0], [1.0, 1.0, 1.0], [0.0, 1.0, 0.0]].iter().map(|x| n.push(*x, 0.0)).collect();
    let s: Vec<Mesh> =
        (0..4).map(|k| droi(&mut n, q[k], q[(k + 1) % 4], &Spacing::count(2), ElemType::Seg2).unwrap()).collect();
    let before = n.len();
    dall(&mut n, [&s[0], &s[1], &s[2], &s[3]], ElemType::Qua4).unwrap();
    let c = n.get(before);
    assert!(close(c[0], 0.5) && close(c[1], 0.5) && close(c[2], 0.5));
}
