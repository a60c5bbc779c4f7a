use super::helpers::*;
use crate::fem::mesh::{ElemType, Mesh, Nodes};
use crate::fem::meshing::*;

/// The four sides of a quadrilateral with corners `c`, `m x n` elements.
fn sides(n: &mut Nodes, c: [[f64; 2]; 4], m: i64, k: i64, ty: ElemType) -> [Mesh; 4] {
    let p: Vec<usize> = c.iter().map(|x| pt(n, x[0], x[1])).collect();
    let d = |n: &mut Nodes, a: usize, b: usize, c: i64| droi(n, a, b, &Spacing::count(c), ty).unwrap();
    [d(n, p[0], p[1], m), d(n, p[1], p[2], k), d(n, p[2], p[3], m), d(n, p[3], p[0], k)]
}

const SQUARE: [[f64; 2]; 4] = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];

#[test]
fn unit_square_2x2_qua4() {
    let mut n = Nodes::default();
    let s = sides(&mut n, SQUARE, 2, 2, ElemType::Qua4);
    let before = n.len();
    let d = dall(&mut n, [&s[0], &s[1], &s[2], &s[3]], ElemType::Qua4).unwrap();
    assert_eq!(n.len(), before + 1, "one interior node");
    assert_eq!(nbel(&d), 4);
    assert_eq!(nbno(&d), 9);
    let centre = n.get(before);
    assert!(close(centre[0], 0.5) && close(centre[1], 0.5));
    for a in areas(&n, &d) {
        assert!(close(a, 0.25), "{a}");
    }
    // Element 1 starts at the first corner along side 1.
    assert_eq!(d.parts[0].elem(0)[0], 0);
    let x = n.get(d.parts[0].elem(0)[1]);
    assert!(close(x[0], 0.5) && x[1] == 0.0);
    // The patch deck: the node of the right side nearest (1, 0.5).
    let pm = poin_proc(&n, &s[1], [1.0, 0.5, 0.0]).unwrap();
    assert_eq!(n.get(pm), [1.0, 0.5, 0.0]);
}

#[test]
fn distorted_quad_areas_sum_to_polygon_area() {
    let c = [[0.0, 0.0], [4.0, 0.5], [3.0, 3.0], [-0.5, 2.0]];
    let poly = 0.5 * (0..4).map(|i| c[i][0] * c[(i + 1) % 4][1] - c[(i + 1) % 4][0] * c[i][1]).sum::<f64>();
    for ty in [ElemType::Qua4, ElemType::Tri3, ElemType::Qua8, ElemType::Tri6] {
        let mut n = Nodes::default();
        let s = sides(&mut n, c, 3, 5, ty);
        let d = dall(&mut n, [&s[0], &s[1], &s[2], &s[3]], ty).unwrap();
        let a = areas(&n, &d);
        let per = if matches!(ty, ElemType::Tri3 | ElemType::Tri6) { 2 } else { 1 };
        assert_eq!(a.len(), 15 * per);
        assert!(a.iter().all(|&x| x > 0.0), "{ty:?} counter-clockwise");
        assert!(close(a.iter().sum::<f64>(), poly), "{ty:?}");
    }
}

#[test]
fn quadratic_dall_node_counts() {
    let mut n = Nodes::default();
    let s = sides(&mut n, SQUARE, 2, 2, ElemType::Qua8);
    let d = dall(&mut n, [&s[0], &s[1], &s[2], &s[3]], ElemType::Qua8).unwrap();
    assert_eq!(d.parts[0].ty, ElemType::Qua8);
    assert_eq!(nbno(&d), 21);
    let t = dall(&mut n, [&s[0], &s[1], &s[2], &s[3]], ElemType::Tri6).unwrap();
    assert_eq!(nbno(&t), 25);
    assert_eq!(nbel(&t), 8);
    // The mid-side nodes of QUA8 are at the middle of their edges.
    for e in d.parts[0].elems() {
        for k in [1, 3, 5, 7] {
            let (a, m, b) = (n.get(e[k - 1]), n.get(e[k]), n.get(e[(k + 1) % 8]));
            assert!(close(m[0], 0.5 * (a[0] + b[0])) && close(m[1], 0.5 * (a[1] + b[1])));
        }
    }
}

#[test]
fn graded_sides_stay_graded_inside() {
    let mut n = Nodes::default();
    let p: Vec<usize> = SQUARE.iter().map(|x| pt(&mut n, x[0], x[1])).collect();
    let g = Spacing::count(4).densities(0.1, 0.4);
    let g_back = Spacing::count(4).densities(0.4, 0.1);
    let c1 = droi(&mut n, p[0], p[1], &g, ElemType::Seg2).unwrap();
    let c2 = droi(&mut n, p[1], p[2], &Spacing::count(2), ElemType::Seg2).unwrap();
    let c3 = droi(&mut n, p[2], p[3], &g_back, ElemType::Seg2).unwrap();
    let c4 = droi(&mut n, p[3], p[0], &Spacing::count(2), ElemType::Seg2).unwrap();
    let first_x = n.get(c1.parts[0].conn[1])[0];
    let before = n.len();
    let d = dall(&mut n, [&c1, &c2, &c3, &c4], ElemType::Qua4).unwrap();
    assert!(close(n.get(before)[0], first_x), "interior row follows the grading");
    assert!(close(areas(&n, &d).iter().sum::<f64>(), 1.0));
}

#[test]
fn dall_refuses_open_contours_and_meshes_unequal_sides() {
    let mut n = Nodes::default();
    let s = sides(&mut n, SQUARE, 2, 2, ElemType::Qua4);
    let e = dall(&mut n, [&s[0], &s[2], &s[1], &s[3]], ElemType::Qua4).unwrap_err();
    assert_eq!(
        e.to_string(),
        "DALL: the four sides do not form a closed contour (side 2 does not start where side 1 ends)"
    );
    let e = dall(&mut n, [&s[1], &s[0], &s[2], &s[3]], ElemType::Qua4).unwrap_err();
    assert!(e.to_string().contains("closed contour"));
    let t = sides(&mut n, SQUARE, 2, 3, ElemType::Qua4);
    let bad3 =
        droi(&mut n, t[2].parts[0].conn[0], *t[3].parts[0].conn.first().unwrap(), &Spacing::count(3), ElemType::Seg2)
            .unwrap();
    // Unequal opposite sides are meshed freely (the notice allows it): the
    // pieces still tile the square exactly, counter-clockwise.
    let d = dall(&mut n, [&t[0], &t[1], &bad3, &t[3]], ElemType::Qua4).unwrap();
    let a = areas(&n, &d);
    assert!(a.iter().all(|&x| x > 0.0), "{a:?}");
    assert!(close(a.iter().sum::<f64>(), 1.0), "{a:?}");
    let e = dall(&mut n, [&s[0], &s[1], &s[2], &s[3]], ElemType::Qua8).unwrap_err();
    assert!(e.to_string().contains("need SEG3 sides"), "{e}");
}

#[test]
fn dall_reads_sides_given_the_other_way() {
    let mut n = Nodes::default();
    let s = sides(&mut n, SQUARE, 2, 3, ElemType::Qua4);
    let inv: Vec<Mesh> = s.iter().map(|m| inve(m).unwrap()).collect();
    // Side 2 reversed: the same counter-clockwise square.
    let d = dall(&mut n, [&s[0], &inv[1], &s[2], &s[3]], ElemType::Qua4).unwrap();
    let a = areas(&n, &d);
    assert_eq!(a.len(), 6);
    assert!(a.iter().all(|&x| close(x, 1.0 / 6.0)), "{a:?}");
    // The contour given backwards from side 1 (side 2 hangs on side 1's
    // start): side 1 is read reversed and the square turns clockwise.
    let d = dall(&mut n, [&s[0], &s[3], &s[2], &s[1]], ElemType::Qua4).unwrap();
    let a = areas(&n, &d);
    assert!(a.iter().all(|&x| close(x, -1.0 / 6.0)), "{a:?}");
    // Every side reversed: clockwise too.
    let d = dall(&mut n, [&inv[0], &inv[3], &inv[2], &inv[1]], ElemType::Qua4).unwrap();
    assert!(close(areas(&n, &d).iter().sum::<f64>(), -1.0));
}
