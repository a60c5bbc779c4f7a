use super::helpers::*;
use crate::fem::mesh::{ElemType, Mesh, Nodes};
use crate::fem::meshing::surf::{surf, SurfOptions};
use crate::fem::meshing::*;

fn opts(dim: usize) -> SurfOptions {
    SurfOptions { space_dim: dim, crit: 1e-2, ..Default::default() }
}

/// A closed polygon through `c` (2D), `k` equal segments per side.
fn polygon(n: &mut Nodes, c: &[[f64; 2]], k: i64) -> Mesh {
    let p: Vec<usize> = c.iter().map(|x| pt(n, x[0], x[1])).collect();
    let mut m = Mesh::default();
    for i in 0..p.len() {
        m = m.union(&droi(n, p[i], p[(i + 1) % p.len()], &Spacing::count(k), ElemType::Seg2).unwrap());
    }
    m
}

/// Smallest corner angle (degrees) of the TRI3 elements.
fn min_angle(n: &Nodes, m: &Mesh) -> f64 {
    let mut worst: f64 = 180.0;
    for p in m.parts.iter().filter(|p| p.ty == ElemType::Tri3) {
        for e in p.elems() {
            for k in 0..3 {
                let (o, a, b) = (n.get(e[k]), n.get(e[(k + 1) % 3]), n.get(e[(k + 2) % 3]));
                let u = [a[0] - o[0], a[1] - o[1]];
                let v = [b[0] - o[0], b[1] - o[1]];
                let ang = (u[0] * v[1] - u[1] * v[0]).atan2(u[0] * v[0] + u[1] * v[1]).to_degrees();
                worst = worst.min(ang.abs());
            }
        }
    }
    worst
}

const SQUARE: [[f64; 2]; 4] = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];

#[test]
fn square_tri3_keeps_the_contour_and_fills_it() {
    let mut n = Nodes::default();
    let c = polygon(&mut n, &SQUARE, 10);
    let before = n.len();
    let s = surf(&mut n, &c, ElemType::Tri3, &opts(2)).unwrap();
    let a = areas(&n, &s);
    // Every triangle counter-clockwise, the areas add up to the square's.
    assert!(a.iter().all(|&x| x > 0.0));
    assert!(close(a.iter().sum::<f64>(), 1.0), "{}", a.iter().sum::<f64>());
    // The contour of the surface is the given one: same 40 segments.
    let k = cont(&s).unwrap();
    assert_eq!(nbel(&k), 40);
    let mut kn = k.node_list();
    let mut cn = c.node_list();
    kn.sort_unstable();
    cn.sort_unstable();
    assert_eq!(kn, cn);
    // Size 0.1 from the spacing of the contour: an equilateral triangle of
    // side 0.1 has area 0.00433, so about 230 triangles; 64 + 40 nodes.
    let ne = nbel(&s);
    assert!((180..=300).contains(&ne), "{ne} triangles");
    assert_eq!(nbno(&s), n.len() - before + 40);
    assert!(min_angle(&n, &s) > 25.0, "min angle {}", min_angle(&n, &s));
}

#[test]
fn density_of_the_points_sets_the_size() {
    // The same square with node densities 0.05: four times as many
    // triangles as with the contour's own spacing of 0.1.
    let mut n = Nodes::default();
    let c = polygon(&mut n, &SQUARE, 10);
    let coarse = nbel(&surf(&mut n.clone(), &c, ElemType::Tri3, &opts(2)).unwrap()) as f64;
    for d in n.density.iter_mut() {
        *d = 0.05;
    }
    let fine = nbel(&surf(&mut n, &c, ElemType::Tri3, &opts(2)).unwrap()) as f64;
    assert!((3.0..5.5).contains(&(fine / coarse)), "{fine} / {coarse}");
}

#[test]
fn hole_turning_the_other_way_is_left_empty() {
    let mut n = Nodes::default();
    let outer = polygon(&mut n, &[[0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [0.0, 3.0]], 8);
    let hole = polygon(&mut n, &[[1.0, 1.0], [1.0, 2.0], [3.0, 2.0], [3.0, 1.0]], 3);
    let s = surf(&mut n, &outer.union(&hole), ElemType::Tri3, &opts(2)).unwrap();
    let a = areas(&n, &s);
    assert!(a.iter().all(|&x| x > 0.0));
    assert!(close(a.iter().sum::<f64>(), 12.0 - 2.0), "{}", a.iter().sum::<f64>());
    // The contour of the result has both loops: 32 + 12 segments.
    assert_eq!(nbel(&cont(&s).unwrap()), 44);
}

#[test]
fn clockwise_contour_gives_clockwise_elements() {
    let mut n = Nodes::default();
    let rev: Vec<[f64; 2]> = SQUARE.iter().rev().copied().collect();
    let c = polygon(&mut n, &rev, 4);
    let s = surf(&mut n, &c, ElemType::Tri3, &opts(2)).unwrap();
    let a = areas(&n, &s);
    assert!(a.iter().all(|&x| x < 0.0));
    assert!(close(a.iter().sum::<f64>(), -1.0));
}

#[test]
fn qua4_pairs_triangles_into_convex_quadrangles() {
    let mut n = Nodes::default();
    let c = polygon(&mut n, &SQUARE, 10);
    let s = surf(&mut n, &c, ElemType::Qua4, &opts(2)).unwrap();
    let a = areas(&n, &s);
    assert!(a.iter().all(|&x| x > 0.0));
    assert!(close(a.iter().sum::<f64>(), 1.0));
    let (q, t) = (nbel_of_type(&s, ElemType::Qua4), nbel_of_type(&s, ElemType::Tri3));
    // Mostly quadrangles: at most one element in ten left a triangle.
    assert!(q > 0 && t * 10 <= q + t, "{q} QUA4, {t} TRI3");
}

#[test]
fn tri6_reuses_the_middle_nodes_of_a_seg3_contour() {
    let mut n = Nodes::default();
    let p: Vec<usize> = SQUARE.iter().map(|x| pt(&mut n, x[0], x[1])).collect();
    let mut c = Mesh::default();
    for i in 0..4 {
        c = c.union(&droi(&mut n, p[i], p[(i + 1) % 4], &Spacing::count(3), ElemType::Seg3).unwrap());
    }
    let before = n.len();
    let s = surf(&mut n, &c, ElemType::Tri6, &opts(2)).unwrap();
    assert_eq!(s.parts.len(), 1);
    assert_eq!(s.parts[0].ty, ElemType::Tri6);
    // Every contour node, middle ones included, is a node of the surface,
    // and no new node lies on the contour.
    let nodes = s.node_list();
    assert!(c.node_list().iter().all(|k| nodes.contains(k)));
    for k in before..n.len() {
        let x = n.get(k);
        assert!(x[0] > 1e-9 && x[0] < 1.0 - 1e-9 && x[1] > 1e-9 && x[1] < 1.0 - 1e-9, "{x:?}");
    }
    assert!(close(areas(&n, &s).iter().sum::<f64>(), 1.0));
}

#[test]
fn plane_contour_in_space() {
    // The unit square turned about the x axis by 30°: area 1, normal
    // (0, -sin 30, cos 30) as the contour turns.
    let mut n = Nodes::default();
    let (s30, c30) = (0.5_f64, 3f64.sqrt() / 2.0);
    let p: Vec<usize> = SQUARE.iter().map(|x| n.push([x[0], x[1] * c30, x[1] * s30], 0.0)).collect();
    let mut c = Mesh::default();
    for i in 0..4 {
        c = c.union(&droi(&mut n, p[i], p[(i + 1) % 4], &Spacing::count(5), ElemType::Seg2).unwrap());
    }
    let s = surf(&mut n, &c, ElemType::Tri3, &opts(3)).unwrap();
    let mut total = 0.0;
    for e in s.parts[0].elems() {
        let (a, b, d) = (n.get(e[0]), n.get(e[1]), n.get(e[2]));
        let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
        let v = [d[0] - a[0], d[1] - a[1], d[2] - a[2]];
        let w = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
        // Each element's normal is the contour's.
        let proj = 0.5 * (w[1] * -s30 + w[2] * c30);
        let len = 0.5 * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]).sqrt();
        assert!(close(proj, len), "{proj} {len}");
        total += len;
        // On the plane y sin30 = z cos30... i.e. z = y tan 30.
        for x in [a, b, d] {
            assert!((x[2] * c30 - x[1] * s30).abs() < 1e-12);
        }
    }
    assert!(close(total, 1.0), "{total}");
}

#[test]
fn refusals() {
    let mut n = Nodes::default();
    // An open line.
    let a = pt(&mut n, 0.0, 0.0);
    let b = pt(&mut n, 1.0, 0.0);
    let l = droi(&mut n, a, b, &Spacing::count(2), ElemType::Seg2).unwrap();
    let e = surf(&mut n, &l, ElemType::Tri3, &opts(2)).unwrap_err();
    assert!(e.message.contains("not closed"), "{}", e.message);
    // A contour off its plane in 3D.
    let mut n = Nodes::default();
    let p: Vec<usize> =
        [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.5], [0.0, 1.0, 0.0]].iter().map(|x| n.push(*x, 0.0)).collect();
    let mut c = Mesh::default();
    for i in 0..4 {
        c = c.union(&droi(&mut n, p[i], p[(i + 1) % 4], &Spacing::count(2), ElemType::Seg2).unwrap());
    }
    let e = surf(&mut n, &c, ElemType::Tri3, &opts(3)).unwrap_err();
    assert!(e.message.contains("not plane"), "{}", e.message);
    // Two loops that cross.
    let mut n = Nodes::default();
    let a = polygon(&mut n, &SQUARE, 3);
    let c = a.union(&polygon(&mut n, &[[0.5, 0.2], [1.5, 0.2], [1.5, 0.8], [0.5, 0.8]], 3));
    let e = surf(&mut n, &c, ElemType::Tri3, &opts(2)).unwrap_err();
    assert!(e.message.contains("crosses itself"), "{}", e.message);
}
