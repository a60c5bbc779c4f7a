//! VORO in 3D: Voronoi (or power) cells of seeds inside a closed convex
//! surface of triangles. See `voronoi` for the partition's form.
//!
//! The domain is the intersection of the half-spaces of its triangles'
//! planes (hence convex: a concave surface is refused). Each cell is that
//! convex polyhedron cut by the bisector planes of the seed's neighbours
//! (its Delaunay neighbours from `tet_delaunay`, or every seed when
//! weighted); every face remembers the plane that made it, which names it
//! in the partition: the two seeds, or the seed and the boundary plane.

use super::tet_delaunay::Tets;
use super::vec3::{cross, dot, lerp, norm, sub, V3};
use super::voronoi::{all_pairs, bisector, check_seeds, push_new, Cell, EdgeSet, Partition, Welder};
use super::{fail, MeshError};
use std::collections::HashMap;

#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
enum Tag {
    Box,
    Plane(usize),
    Seed(usize),
}

#[derive(Debug, Clone)]
struct Face {
    /// Vertices in order around the face.
    poly: Vec<V3>,
    tag: Tag,
}

/// Drops vertices equal (within eps) to the one before them.
fn dedupe(mut v: Vec<V3>, eps: f64) -> Vec<V3> {
    v.dedup_by(|b, a| norm(sub(*a, *b)) <= eps);
    while v.len() > 1 && norm(sub(v[0], v[v.len() - 1])) <= eps {
        v.pop();
    }
    v
}

fn area(poly: &[V3]) -> f64 {
    let mut s = [0.0; 3];
    for k in 1..poly.len().saturating_sub(1) {
        let c = cross(sub(poly[k], poly[0]), sub(poly[k + 1], poly[0]));
        s = [s[0] + c[0], s[1] + c[1], s[2] + c[2]];
    }
    0.5 * norm(s)
}

/// The part of the convex polyhedron `faces` where n·x <= d (n a unit
/// vector); the new face is tagged `tag`. Empty if nothing is left.
fn clip(faces: &[Face], n: V3, d: f64, tag: Tag, eps: f64) -> Vec<Face> {
    let s = |x: &V3| dot(n, *x) - d;
    let all = || faces.iter().flat_map(|f| f.poly.iter());
    if all().all(|x| s(x) <= eps) {
        return faces.to_vec();
    }
    if all().all(|x| s(x) >= -eps) {
        return vec![];
    }
    let mut out = vec![];
    let mut cut: Vec<V3> = vec![];
    for f in faces {
        let m = f.poly.len();
        let mut q = vec![];
        for k in 0..m {
            let (a, b) = (f.poly[k], f.poly[(k + 1) % m]);
            let (sa, sb) = (s(&a), s(&b));
            if sa <= eps {
                q.push(a);
                if sa >= -eps {
                    cut.push(a);
                }
            }
            if (sa < -eps && sb > eps) || (sa > eps && sb < -eps) {
                let x = lerp(a, b, sa / (sa - sb));
                q.push(x);
                cut.push(x);
            }
        }
        let q = dedupe(q, eps);
        if q.len() >= 3 {
            out.push(Face { poly: q, tag: f.tag });
        }
    }
    // The cut points, in turn around their centre (they are convex).
    let mut pts: Vec<V3> = vec![];
    for x in cut {
        if pts.iter().all(|p| norm(sub(*p, x)) > eps) {
            pts.push(x);
        }
    }
    if pts.len() >= 3 {
        let k = pts.len() as f64;
        let c = pts.iter().fold([0.0; 3], |a, p| [a[0] + p[0] / k, a[1] + p[1] / k, a[2] + p[2] / k]);
        let helper = if n[0].abs() < 0.9 { [1.0, 0.0, 0.0] } else { [0.0, 1.0, 0.0] };
        let u = cross(n, helper);
        let u = u.map(|x| x / norm(u));
        let v = cross(n, u);
        let angle = |p: &V3| dot(sub(*p, c), v).atan2(dot(sub(*p, c), u));
        pts.sort_by(|a, b| angle(a).total_cmp(&angle(b)));
        out.push(Face { poly: pts, tag });
    }
    out
}

/// The boundary: triangles of points, each point a node.
pub struct Surface<'a> {
    pub pts: &'a [V3],
    pub nodes: &'a [usize],
    pub tris: &'a [[usize; 3]],
}

/// The distinct planes of the triangles, as n·x <= d with n pointing out
/// of the domain; an error if the surface is not convex.
fn planes(op: &'static str, s: &Surface, tol: f64) -> Result<Vec<(V3, f64)>, MeshError> {
    let k = s.pts.len() as f64;
    let centre = s.pts.iter().fold([0.0; 3], |a, p| [a[0] + p[0] / k, a[1] + p[1] / k, a[2] + p[2] / k]);
    let mut out: Vec<(V3, f64)> = vec![];
    for t in s.tris {
        let [a, b, c] = t.map(|i| s.pts[i]);
        let m = cross(sub(b, a), sub(c, a));
        let l = norm(m);
        if l <= tol * tol {
            continue;
        }
        let mut n = m.map(|x| x / l);
        let mut d = dot(n, a);
        if dot(n, centre) > d {
            n = n.map(|x| -x);
            d = -d;
        }
        if s.pts.iter().any(|p| dot(n, *p) - d > tol) {
            return fail(op, "in 3D the boundary must be convex (a plane of its triangles cuts it)");
        }
        if !out.iter().any(|(m, e)| norm(sub(*m, n)) <= 1e-9 && (e - d).abs() <= tol) {
            out.push((n, d));
        }
    }
    if out.len() < 4 {
        return fail(op, "the boundary encloses no volume");
    }
    Ok(out)
}

/// The Delaunay neighbours of each seed, or every seed when there are too
/// few of them or they are in one plane.
fn neighbours(op: &'static str, seeds: &[V3]) -> Result<Vec<Vec<usize>>, MeshError> {
    if seeds.len() < 5 {
        return Ok(all_pairs(seeds.len()));
    }
    let tets = Tets::delaunay(op, seeds)?.inner();
    if tets.is_empty() {
        return Ok(all_pairs(seeds.len()));
    }
    let mut nb = vec![vec![]; seeds.len()];
    for t in tets {
        for i in 0..4 {
            for j in 0..4 {
                if i != j {
                    push_new(&mut nb[t[i]], t[j]);
                }
            }
        }
    }
    Ok(nb)
}

/// The Voronoi partition of seeds in space inside a convex closed surface.
pub fn partition_3d(
    op: &'static str,
    seeds: &[V3],
    weights: Option<&[f64]>,
    surf: &Surface,
) -> Result<Partition, MeshError> {
    check_seeds(op, seeds, weights)?;
    if s_invalid(surf) {
        return fail(op, "a boundary point has a coordinate that is not a finite number");
    }
    let (lo, hi) = super::tet_delaunay::bounding_box(surf.pts);
    let size = (0..3).map(|k| hi[k] - lo[k]).fold(0.0, f64::max);
    if surf.tris.is_empty() || size <= 0.0 {
        return fail(op, "the boundary encloses no volume");
    }
    let tol = 1e-9 * size;
    let planes = planes(op, surf, tol)?;
    // The domain: a box around it cut by its planes.
    let (a, b) = (lo.map(|x| x - size), hi.map(|x| x + size));
    let corner = |i: usize| {
        [
            if i & 1 == 0 { a[0] } else { b[0] },
            if i & 2 == 0 { a[1] } else { b[1] },
            if i & 4 == 0 { a[2] } else { b[2] },
        ]
    };
    let quads = [[0, 2, 6, 4], [1, 5, 7, 3], [0, 4, 5, 1], [2, 3, 7, 6], [0, 1, 3, 2], [4, 6, 7, 5]];
    let mut domain: Vec<Face> =
        quads.iter().map(|q| Face { poly: q.iter().map(|&i| corner(i)).collect(), tag: Tag::Box }).collect();
    for (k, &(n, d)) in planes.iter().enumerate() {
        domain = clip(&domain, n, d, Tag::Plane(k), tol);
    }
    if domain.is_empty() || domain.iter().any(|f| f.tag == Tag::Box) {
        return fail(op, "the boundary does not enclose a volume");
    }
    let nb = match weights {
        Some(_) => all_pairs(seeds.len()),
        None => neighbours(op, seeds)?,
    };
    let mut weld = Welder::new(tol);
    for (k, p) in surf.pts.iter().enumerate() {
        weld.add(*p, Some(surf.nodes[k]));
    }
    let mut es = EdgeSet::default();
    let mut faces: Vec<Vec<usize>> = vec![];
    let mut face_of: HashMap<(usize, Tag), usize> = HashMap::new();
    let mut cells = vec![];
    for (i, nbi) in nb.iter().enumerate() {
        let mut poly = domain.clone();
        for &j in nbi {
            let (n, d) = bisector(seeds, weights, i, j);
            poly = clip(&poly, n, d, Tag::Seed(j), tol);
            if poly.is_empty() {
                break;
            }
        }
        let mut cell = Cell { seed: i, ..Cell::default() };
        for f in &poly {
            if area(&f.poly) <= tol * tol {
                continue;
            }
            // A face between two cells is named by both seeds, lowest first.
            let key = match f.tag {
                Tag::Seed(j) => (i.min(j), Tag::Seed(i.max(j))),
                t => (i, t),
            };
            let id = match face_of.get(&key) {
                Some(&id) => id,
                None => {
                    let mut vs: Vec<usize> = f.poly.iter().map(|p| weld.add(*p, None)).collect();
                    vs.dedup();
                    while vs.len() > 1 && vs[0] == vs[vs.len() - 1] {
                        vs.pop();
                    }
                    if vs.len() < 3 {
                        continue;
                    }
                    let m = vs.len();
                    let edges: Vec<usize> = (0..m).filter_map(|k| es.edge(vs[k], vs[(k + 1) % m])).collect();
                    faces.push(edges);
                    face_of.insert(key, faces.len() - 1);
                    faces.len() - 1
                }
            };
            push_new(&mut cell.faces, id);
            for &e in &faces[id] {
                push_new(&mut cell.edges, e);
            }
            if let Tag::Seed(j) = f.tag {
                push_new(&mut cell.neighbours, j);
            }
        }
        if !cell.faces.is_empty() {
            cells.push(cell);
        }
    }
    if cells.is_empty() {
        return fail(op, "no seed has a cell inside the boundary");
    }
    for c in &mut cells {
        c.neighbours.sort_unstable();
    }
    Ok(Partition { verts: weld.verts, vert_node: weld.node, edges: es.edges, faces, cells })
}

fn s_invalid(s: &Surface) -> bool {
    s.pts.iter().flatten().any(|x| !x.is_finite())
}
