//! TRIA with a target element size: the Delaunay triangulation of a point
//! set, or the filling of a closed surface, with nodes added so that the
//! elements come near that size.
//!
//! * Plane points: the convex hull's edges are cut into pieces of about the
//!   size, and the inside is meshed by `free::triangulate` (Delaunay
//!   refinement by size, as SURF): the input points are kept as nodes.
//! * Points in space: hull edges longer than the size are halved (the
//!   hull's triangles then come near the size), then the points of a
//!   body-centred cubic lattice of that spacing inside the hull, far
//!   enough from the hull's faces and from the points, are added, and the
//!   whole is tetrahedrised (Delaunay).
//! * A closed surface: the same lattice points inside the surface, far
//!   enough from its triangles, are the interior nodes of the filling
//!   (`tet_fill`); the surface is kept as given.

use super::free::triangulate;
use super::tet_delaunay::{face_key, Tets};
use super::vec3::{cross, dist, dot, norm, sub, V3};
use super::{fail, MeshError};
use std::collections::HashMap;

/// Hull edges longer than this many sizes are halved (as `free`'s
/// threshold: a Delaunay refinement stops there).
const TOO_LONG: f64 = 1.45;
/// No lattice point nearer than this many sizes to a point or the boundary.
const SPACING: f64 = 0.55;
/// A safety net on the node count: a size far too small for the region.
const MAX_POINTS: usize = 2_000_000;

/// Plane points and triangles of indices into them.
pub type Triangles2 = (Vec<[f64; 2]>, Vec<[usize; 3]>);

/// The sized triangulation of plane points: all points (the input first,
/// in order) and counter-clockwise triangles of indices into them. No
/// triangle (empty) when the points are all on one line.
pub fn points_2d(op: &'static str, pts: &[[f64; 2]], h: f64) -> Result<Triangles2, MeshError> {
    let tris = match super::delaunay::points_2d(op, pts) {
        Ok(t) => t,
        Err(_) if collinear_2d(pts) => return Ok((pts.to_vec(), vec![])),
        Err(e) => return Err(e),
    };
    // The hull: edges of one triangle, counter-clockwise, chained.
    let mut count: HashMap<[usize; 2], usize> = HashMap::new();
    for t in &tris {
        for i in 0..3 {
            let (a, b) = (t[i], t[(i + 1) % 3]);
            *count.entry([a.min(b), a.max(b)]).or_default() += 1;
        }
    }
    let mut next: HashMap<usize, usize> = HashMap::new();
    for t in &tris {
        for i in 0..3 {
            let (a, b) = (t[i], t[(i + 1) % 3]);
            if count[&[a.min(b), a.max(b)]] == 1 {
                next.insert(a, b);
            }
        }
    }
    let Some(&start) = next.keys().min() else { return fail(op, "the points have no hull") };
    let mut all = pts.to_vec();
    let mut hull = vec![];
    let mut a = start;
    for _ in 0..=next.len() {
        let b = next[&a];
        hull.push(a);
        let (p, q) = (pts[a], pts[b]);
        let len = ((q[0] - p[0]).powi(2) + (q[1] - p[1]).powi(2)).sqrt();
        let n = (len / h).round().max(1.0) as usize;
        for k in 1..n {
            let t = k as f64 / n as f64;
            hull.push(all.len());
            all.push([p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])]);
        }
        if all.len() > MAX_POINTS {
            return fail(op, format!("more than {MAX_POINTS} nodes: the size is far too small for the points"));
        }
        a = b;
        if a == start {
            break;
        }
    }
    let sizes = vec![h; all.len()];
    let planar = triangulate(op, &all, &sizes, &[hull])?;
    Ok((planar.points, planar.triangles))
}

fn collinear_2d(pts: &[[f64; 2]]) -> bool {
    let p: Vec<V3> = pts.iter().map(|q| [q[0], q[1], 0.0]).collect();
    collinear(&p)
}

/// Whether all the points are on one line (or fewer than three).
pub fn collinear(pts: &[V3]) -> bool {
    let Some(&p0) = pts.first() else { return true };
    let Some(&far) = pts.iter().max_by(|a, b| dist(**a, p0).total_cmp(&dist(**b, p0))) else { return true };
    let d = sub(far, p0);
    let l = norm(d);
    l == 0.0 || pts.iter().all(|p| norm(cross(d, sub(*p, p0))) <= 1e-9 * l * l)
}

/// The sized tetrahedrisation of points in space: all points (the input
/// first, in order) and the Delaunay tetrahedra over them (Cast3M's
/// positive orientation). Points in one plane are the caller's case.
pub fn points_3d(op: &'static str, pts: &[V3], h: f64) -> Result<(Vec<V3>, Vec<[usize; 4]>), MeshError> {
    let mut all = pts.to_vec();
    let mut grid = Grid::new(h, &all);
    // Halve the long hull edges until none is left (the midpoint of a hull
    // edge stays on the hull).
    let mut hull;
    loop {
        let t = Tets::delaunay(op, &all)?;
        hull = hull_faces(&t);
        if hull.is_empty() {
            return fail(op, "the points are all in one plane: there is no tetrahedron to make");
        }
        let mut added = 0;
        let mut edges: Vec<[usize; 2]> =
            hull.iter().flat_map(|(f, _)| [[f[0], f[1]], [f[1], f[2]], [f[0], f[2]]]).collect();
        edges.sort_unstable();
        edges.dedup();
        for [a, b] in edges {
            if dist(all[a], all[b]) > TOO_LONG * h {
                let m = [0, 1, 2].map(|k| 0.5 * (all[a][k] + all[b][k]));
                if !grid.near(&all, m, SPACING * h) {
                    grid.add(all.len(), m);
                    all.push(m);
                    added += 1;
                }
            }
        }
        if all.len() > MAX_POINTS {
            return fail(op, format!("more than {MAX_POINTS} nodes: the size is far too small for the points"));
        }
        if added == 0 {
            break;
        }
    }
    // The hull's planes, outward normals (faces of almost no area have no
    // reliable normal; their neighbours bound the hull as well).
    let (lo, hi) = super::tet_delaunay::bounding_box(&all);
    let scale = (0..3).map(|k| hi[k] - lo[k]).fold(0.0, f64::max);
    let planes: Vec<(V3, V3)> = hull
        .iter()
        .filter_map(|&(f, inner)| {
            let (a, b, c) = (all[f[0]], all[f[1]], all[f[2]]);
            let n = cross(sub(b, a), sub(c, a));
            let l = norm(n);
            if l <= 1e-12 * scale * scale {
                return None;
            }
            let n = n.map(|x| x / l);
            let n = if dot(n, sub(all[inner], a)) > 0.0 { n.map(|x| -x) } else { n };
            Some((a, n))
        })
        .collect();
    for p in lattice(lo, hi, h) {
        if planes.iter().all(|(a, n)| dot(*n, sub(p, *a)) < -SPACING * h) && !grid.near(&all, p, SPACING * h) {
            grid.add(all.len(), p);
            all.push(p);
            if all.len() > MAX_POINTS {
                return fail(op, format!("more than {MAX_POINTS} nodes: the size is far too small for the points"));
            }
        }
    }
    let tets = super::tet_fill::points_3d(op, &all)?;
    Ok((all, tets))
}

/// The faces of the hull of a tetrahedrisation (sorted vertex triples),
/// each with the fourth vertex of its tetrahedron (inside).
fn hull_faces(t: &Tets) -> Vec<([usize; 3], usize)> {
    let inner = t.inner();
    let mut count: HashMap<[usize; 3], (usize, usize)> = HashMap::new();
    for tet in &inner {
        for i in 0..4 {
            count.entry(face_key(tet, i)).or_insert((0, tet[i])).0 += 1;
        }
    }
    let mut faces: Vec<([usize; 3], usize)> =
        count.into_iter().filter(|(_, (n, _))| *n == 1).map(|(f, (_, v))| (f, v)).collect();
    faces.sort_unstable();
    faces
}

/// The points of a body-centred cubic lattice of spacing `h` over a box:
/// the cube corners and centres (neighbours at 0.87 h and h).
fn lattice(lo: V3, hi: V3, h: f64) -> Vec<V3> {
    let n = [0, 1, 2].map(|k| ((hi[k] - lo[k]) / h).floor() as i64 + 1);
    let mut out = vec![];
    for i in 0..=n[0] {
        for j in 0..=n[1] {
            for k in 0..=n[2] {
                for s in [0.0, 0.5] {
                    out.push([lo[0] + (i as f64 + s) * h, lo[1] + (j as f64 + s) * h, lo[2] + (k as f64 + s) * h]);
                }
            }
        }
    }
    out
}

/// The lattice points inside the closed surface `tris` (of points `pts`)
/// at least `SPACING h` from every triangle: the interior nodes of a
/// filling of that size.
pub fn interior_points(op: &'static str, pts: &[V3], tris: &[[usize; 3]], h: f64) -> Result<Vec<V3>, MeshError> {
    let (lo, hi) = super::tet_delaunay::bounding_box(pts);
    let n: f64 = (0..3).map(|k| (hi[k] - lo[k]) / h + 2.0).product();
    if 2.0 * n > MAX_POINTS as f64 {
        return fail(op, format!("more than {MAX_POINTS} nodes: the size is far too small for the surface"));
    }
    let boxes: Vec<(V3, V3)> = tris
        .iter()
        .map(|t| {
            let (a, b) = super::tet_delaunay::bounding_box(&t.map(|v| pts[v]));
            (a, b)
        })
        .collect();
    let gap = SPACING * h;
    // A direction of no special alignment: a ray along it meets edges and
    // vertices only by accident.
    let dir = [0.5773, 0.5779, 0.5767];
    let mut out = vec![];
    for p in lattice(lo, hi, h) {
        let mut far = true;
        for (t, (a, b)) in tris.iter().zip(&boxes) {
            if (0..3).all(|k| p[k] > a[k] - gap && p[k] < b[k] + gap) {
                let q = crate::fem::level_set::closest_on_triangle(pts[t[0]], pts[t[1]], pts[t[2]], p);
                if dist(p, q) < gap {
                    far = false;
                    break;
                }
            }
        }
        if !far {
            continue;
        }
        let hits = tris.iter().filter(|t| ray_hits(p, dir, pts[t[0]], pts[t[1]], pts[t[2]])).count();
        if hits % 2 == 1 {
            out.push(p);
        }
    }
    Ok(out)
}

/// Whether the ray from `o` along `d` crosses triangle `abc` (Möller-Trumbore).
fn ray_hits(o: V3, d: V3, a: V3, b: V3, c: V3) -> bool {
    let (e1, e2) = (sub(b, a), sub(c, a));
    let p = cross(d, e2);
    let det = dot(e1, p);
    if det.abs() < 1e-300 {
        return false;
    }
    let s = sub(o, a);
    let u = dot(s, p) / det;
    if !(0.0..=1.0).contains(&u) {
        return false;
    }
    let q = cross(s, e1);
    let v = dot(d, q) / det;
    if v < 0.0 || u + v > 1.0 {
        return false;
    }
    dot(e2, q) / det > 0.0
}

/// Points bucketed by cells of the size, for "is a point nearer than r".
struct Grid {
    h: f64,
    cells: HashMap<[i64; 3], Vec<usize>>,
}

impl Grid {
    fn new(h: f64, pts: &[V3]) -> Grid {
        let mut g = Grid { h, cells: HashMap::new() };
        for (i, p) in pts.iter().enumerate() {
            g.add(i, *p);
        }
        g
    }

    fn cell(&self, p: V3) -> [i64; 3] {
        p.map(|x| (x / self.h).floor() as i64)
    }

    fn add(&mut self, i: usize, p: V3) {
        let c = self.cell(p);
        self.cells.entry(c).or_default().push(i);
    }

    /// Whether a point of `pts` is nearer than `r` (at most the cell size).
    fn near(&self, pts: &[V3], p: V3, r: f64) -> bool {
        let c = self.cell(p);
        for dx in -1..=1 {
            for dy in -1..=1 {
                for dz in -1..=1 {
                    if let Some(v) = self.cells.get(&[c[0] + dx, c[1] + dy, c[2] + dz]) {
                        if v.iter().any(|&i| dist(pts[i], p) < r) {
                            return true;
                        }
                    }
                }
            }
        }
        false
    }
}
