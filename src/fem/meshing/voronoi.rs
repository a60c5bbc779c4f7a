//! VORO: the Voronoi partition of seed points, limited to a domain bounded
//! by closed lines (2D) or by a closed convex surface of triangles (3D);
//! with weights, the power diagram (a point x belongs to the seed p of
//! weight r that minimises |x - p|² - r²).
//!
//! A cell is the intersection of the domain with the half-planes (half-
//! spaces) of the seed's neighbours. Without weights those neighbours are
//! the seed's Delaunay neighbours (spade in 2D, `tet_delaunay` in 3D): a
//! Voronoi cell is exactly bounded by the bisectors of its Delaunay edges.
//! Weighted cells are cut by every other seed, as the power diagram's
//! neighbours are not the Delaunay ones.
//!
//! The cells are computed one by one, then welded: vertices closer than a
//! tolerance (1e-9 of the domain's size) are one, and a vertex at a node
//! of the boundary *is* that node. Edges are numbered once for the cells
//! on both sides (by their two vertices), faces once (by the two seeds, or
//! by the seed and the boundary plane they lie on). Cells with nothing in
//! the domain are left out. 3D cells are computed in `voronoi_3d`.

use super::{fail, MeshError};
use spade::{DelaunayTriangulation, Point2, Triangulation};
use std::collections::{HashMap, HashSet};

/// The partition: vertices, their edges, faces (3D) and the cells.
#[derive(Debug, Default)]
pub struct Partition {
    pub verts: Vec<[f64; 3]>,
    /// The boundary node a vertex is at (the partition reuses it).
    pub vert_node: Vec<Option<usize>>,
    /// Pairs of vertices.
    pub edges: Vec<[usize; 2]>,
    /// 3D: each face's edges, in order around it.
    pub faces: Vec<Vec<usize>>,
    pub cells: Vec<Cell>,
}

/// The cell of one seed (an index into the seeds).
#[derive(Debug, Default)]
pub struct Cell {
    pub seed: usize,
    /// Its edges (2D: its boundary; 3D: the edges of its faces).
    pub edges: Vec<usize>,
    /// 3D: its faces.
    pub faces: Vec<usize>,
    /// The seeds whose cell shares an edge (2D) or a face (3D) with it.
    pub neighbours: Vec<usize>,
}

/// Vertices merged within a tolerance, on a grid of buckets.
pub(super) struct Welder {
    tol: f64,
    grid: HashMap<[i64; 3], Vec<usize>>,
    pub verts: Vec<[f64; 3]>,
    pub node: Vec<Option<usize>>,
}

impl Welder {
    pub fn new(tol: f64) -> Self {
        Welder { tol, grid: HashMap::new(), verts: vec![], node: vec![] }
    }

    fn bucket(&self, p: [f64; 3]) -> [i64; 3] {
        p.map(|x| (x / (2.0 * self.tol)).floor() as i64)
    }

    fn find(&self, p: [f64; 3]) -> Option<usize> {
        let b = self.bucket(p);
        let mut best: Option<(f64, usize)> = None;
        for dx in -1..=1 {
            for dy in -1..=1 {
                for dz in -1..=1 {
                    let Some(list) = self.grid.get(&[b[0] + dx, b[1] + dy, b[2] + dz]) else { continue };
                    for &v in list {
                        let q = self.verts[v];
                        let d = ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt();
                        if d <= self.tol && best.is_none_or(|(bd, _)| d < bd) {
                            best = Some((d, v));
                        }
                    }
                }
            }
        }
        best.map(|(_, v)| v)
    }

    /// The vertex at `p` (a boundary node keeps its own position).
    pub fn add(&mut self, p: [f64; 3], node: Option<usize>) -> usize {
        if let Some(v) = self.find(p) {
            if node.is_some() && self.node[v].is_none() {
                self.node[v] = node;
                self.verts[v] = p;
            }
            return v;
        }
        let b = self.bucket(p);
        self.verts.push(p);
        self.node.push(node);
        let v = self.verts.len() - 1;
        self.grid.entry(b).or_default().push(v);
        v
    }
}

/// Edges numbered once by their two vertices.
#[derive(Default)]
pub(super) struct EdgeSet {
    pub edges: Vec<[usize; 2]>,
    of: HashMap<[usize; 2], usize>,
}

impl EdgeSet {
    /// The edge from `a` to `b`, or None if they are one vertex.
    pub fn edge(&mut self, a: usize, b: usize) -> Option<usize> {
        if a == b {
            return None;
        }
        let k = [a.min(b), a.max(b)];
        Some(*self.of.entry(k).or_insert_with(|| {
            self.edges.push([a, b]);
            self.edges.len() - 1
        }))
    }
}

/// Pushes `x` if it is not in `v` yet (small lists: cells' edges).
pub(super) fn push_new(v: &mut Vec<usize>, x: usize) {
    if !v.contains(&x) {
        v.push(x);
    }
}

/// The seeds must be finite and distinct; weights finite, one per seed.
pub(super) fn check_seeds<const N: usize>(
    op: &'static str,
    seeds: &[[f64; N]],
    weights: Option<&[f64]>,
) -> Result<(), MeshError> {
    if seeds.is_empty() {
        return fail(op, "there is no seed point");
    }
    if seeds.iter().flatten().any(|x| !x.is_finite()) {
        return fail(op, "a seed has a coordinate that is not a finite number");
    }
    if let Some(w) = weights {
        if w.len() != seeds.len() || w.iter().any(|x| !x.is_finite()) {
            return fail(op, "every seed needs a finite weight");
        }
    }
    let mut seen: HashMap<[u64; N], usize> = HashMap::new();
    for (i, p) in seeds.iter().enumerate() {
        if let Some(j) = seen.insert(p.map(|x| (x + 0.0).to_bits()), i) {
            return fail(op, format!("seeds {} and {} are at the same place", j + 1, i + 1));
        }
    }
    Ok(())
}

/// Every pair of seeds (weighted cells, or too few seeds for a Delaunay).
pub(super) fn all_pairs(n: usize) -> Vec<Vec<usize>> {
    (0..n).map(|i| (0..n).filter(|&j| j != i).collect()).collect()
}

/// The half-plane (half-space) of seed `i` against seed `j`:
/// n·x <= d with n the unit vector from i to j.
pub(super) fn bisector<const N: usize>(seeds: &[[f64; N]], w: Option<&[f64]>, i: usize, j: usize) -> ([f64; N], f64) {
    let (p, q) = (seeds[i], seeds[j]);
    let mut n = [0.0; N];
    for k in 0..N {
        n[k] = q[k] - p[k];
    }
    let len = n.iter().map(|x| x * x).sum::<f64>().sqrt();
    let sq = |x: &[f64; N]| x.iter().map(|c| c * c).sum::<f64>();
    let (wi, wj) = w.map_or((0.0, 0.0), |w| (w[i], w[j]));
    let d = (sq(&q) - sq(&p) + wi * wi - wj * wj) / (2.0 * len);
    (n.map(|x| x / len), d)
}

/// The 2D Delaunay neighbours of each seed (spade), or every other seed
/// when the seeds are on one line.
fn delaunay_neighbours(seeds: &[[f64; 2]]) -> Result<Vec<Vec<usize>>, MeshError> {
    let mut dt: DelaunayTriangulation<Point2<f64>> = DelaunayTriangulation::new();
    for p in seeds {
        dt.insert(Point2::new(p[0], p[1])).map_err(|e| MeshError::new("VORO", format!("{e:?}")))?;
    }
    if dt.num_inner_faces() == 0 {
        return Ok(all_pairs(seeds.len()));
    }
    let mut nb = vec![vec![]; seeds.len()];
    for e in dt.undirected_edges() {
        let [a, b] = e.vertices().map(|v| v.fix().index());
        nb[a].push(b);
        nb[b].push(a);
    }
    Ok(nb)
}

const BOX: usize = usize::MAX;

/// A convex polygon, counter-clockwise; `tag[k]` names what bounds its
/// edge from vertex k to k+1 (a seed, or BOX).
struct Convex {
    pts: Vec<[f64; 2]>,
    tag: Vec<usize>,
}

impl Convex {
    /// Keeps the part where n·x <= d; the new edge is tagged `tag`.
    fn clip(&self, n: [f64; 2], d: f64, tag: usize, eps: f64) -> Convex {
        let s = |p: [f64; 2]| n[0] * p[0] + n[1] * p[1] - d;
        if self.pts.iter().all(|&p| s(p) <= eps) {
            return Convex { pts: self.pts.clone(), tag: self.tag.clone() };
        }
        let m = self.pts.len();
        let mut out = Convex { pts: vec![], tag: vec![] };
        for k in 0..m {
            let (a, b) = (self.pts[k], self.pts[(k + 1) % m]);
            let (sa, sb) = (s(a), s(b));
            if sa <= eps {
                out.pts.push(a);
                // From a vertex on the line to one beyond it, the next
                // vertex kept is back on the line: the edge is the cut.
                out.tag.push(if sa >= -eps && sb > eps { tag } else { self.tag[k] });
            }
            if (sa < -eps && sb > eps) || (sa > eps && sb < -eps) {
                let t = sa / (sa - sb);
                out.pts.push([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]);
                // Leaving: the cut follows; entering: the rest of the edge.
                out.tag.push(if sa < -eps { tag } else { self.tag[k] });
            }
        }
        if out.pts.len() < 3 {
            out.pts.clear();
            out.tag.clear();
        }
        out
    }

    /// The parameters [t0, t1] of the part of segment p→q inside, if any.
    fn segment_inside(&self, p: [f64; 2], q: [f64; 2], tol: f64) -> Option<(f64, f64)> {
        let (mut t0, mut t1) = (0.0f64, 1.0f64);
        let m = self.pts.len();
        for k in 0..m {
            let (a, b) = (self.pts[k], self.pts[(k + 1) % m]);
            // Inside is on the left: f(x) = cross(b - a, x - a) >= 0.
            // (signed distances; a segment along the edge, within the
            // tolerance, is inside: both cells keep it, numbered once).
            let l = ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt();
            if l <= tol {
                continue;
            }
            let f = |x: [f64; 2]| ((b[0] - a[0]) * (x[1] - a[1]) - (b[1] - a[1]) * (x[0] - a[0])) / l;
            let (fp, fq) = (f(p), f(q));
            if fp < -tol && fq < -tol {
                return None;
            }
            if fp < -tol {
                t0 = t0.max(fp / (fp - fq));
            } else if fq < -tol {
                t1 = t1.min(fp / (fp - fq));
            }
        }
        (t0 < t1).then_some((t0, t1))
    }
}

/// The boundary of a 2D domain: closed lines of segments between points.
pub struct Lines<'a> {
    pub pts: &'a [[f64; 2]],
    /// The node of each point.
    pub nodes: &'a [usize],
    pub segs: &'a [[usize; 2]],
}

impl Lines<'_> {
    fn seg(&self, s: usize) -> ([f64; 2], [f64; 2]) {
        (self.pts[self.segs[s][0]], self.pts[self.segs[s][1]])
    }

    /// Even-odd rule (the point is not on the lines).
    fn inside(&self, x: [f64; 2]) -> bool {
        let mut inside = false;
        for s in 0..self.segs.len() {
            let (a, b) = self.seg(s);
            if (a[1] > x[1]) != (b[1] > x[1]) {
                let xc = a[0] + (x[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
                if xc > x[0] {
                    inside = !inside;
                }
            }
        }
        inside
    }

    fn distance(&self, x: [f64; 2]) -> f64 {
        (0..self.segs.len())
            .map(|s| {
                let (a, b) = self.seg(s);
                let ab = [b[0] - a[0], b[1] - a[1]];
                let l2 = ab[0] * ab[0] + ab[1] * ab[1];
                let t =
                    if l2 > 0.0 { (((x[0] - a[0]) * ab[0] + (x[1] - a[1]) * ab[1]) / l2).clamp(0.0, 1.0) } else { 0.0 };
                ((x[0] - a[0] - t * ab[0]).powi(2) + (x[1] - a[1] - t * ab[1]).powi(2)).sqrt()
            })
            .fold(f64::INFINITY, f64::min)
    }

    /// The parameters along u→v where the lines meet it (crossings, and
    /// the ends of lines that touch or run along it).
    fn cuts(&self, u: [f64; 2], v: [f64; 2], tol: f64) -> Vec<f64> {
        let e = [v[0] - u[0], v[1] - u[1]];
        let len = (e[0] * e[0] + e[1] * e[1]).sqrt();
        let mut ts = vec![];
        for s in 0..self.segs.len() {
            let (a, b) = self.seg(s);
            let f = [b[0] - a[0], b[1] - a[1]];
            // Signed distances of a and b to the line u→v.
            let da = (e[0] * (a[1] - u[1]) - e[1] * (a[0] - u[0])) / len;
            let db = (e[0] * (b[1] - u[1]) - e[1] * (b[0] - u[0])) / len;
            let along = |x: [f64; 2]| ((x[0] - u[0]) * e[0] + (x[1] - u[1]) * e[1]) / (len * len);
            if da.abs() <= tol {
                ts.push(along(a));
            }
            if db.abs() <= tol {
                ts.push(along(b));
            }
            if (da < -tol && db > tol) || (da > tol && db < -tol) {
                let t = da / (da - db);
                ts.push(along([a[0] + t * f[0], a[1] + t * f[1]]));
            }
        }
        ts.retain(|t| *t > 0.0 && *t < 1.0);
        ts
    }
}

/// The Voronoi partition of plane seeds inside closed lines.
pub fn partition_2d(
    op: &'static str,
    seeds: &[[f64; 2]],
    weights: Option<&[f64]>,
    lines: &Lines,
) -> Result<Partition, MeshError> {
    check_seeds(op, seeds, weights)?;
    if lines.segs.is_empty() {
        return fail(op, "the boundary has no segment");
    }
    if lines.pts.iter().flatten().any(|x| !x.is_finite()) {
        return fail(op, "a boundary point has a coordinate that is not a finite number");
    }
    let mut degree: HashMap<usize, usize> = HashMap::new();
    for s in lines.segs {
        *degree.entry(s[0]).or_default() += 1;
        *degree.entry(s[1]).or_default() += 1;
    }
    // The first open end in node order, so that the message is the same
    // from one run to the next (a HashMap iterates in a random order).
    if let Some(p) = degree.iter().filter(|(_, &d)| d % 2 == 1).map(|(&p, _)| p).min_by_key(|&p| lines.nodes[p]) {
        return fail(op, format!("the boundary is not closed: its node {} ends a line", lines.nodes[p] + 1));
    }
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for p in lines.pts {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let size = (hi[0] - lo[0]).max(hi[1] - lo[1]);
    if size <= 0.0 {
        return fail(op, "the boundary encloses no area");
    }
    let tol = 1e-9 * size;
    let nb = match weights {
        Some(_) => all_pairs(seeds.len()),
        None => delaunay_neighbours(seeds)?,
    };
    let mut weld = Welder::new(tol);
    for (k, p) in lines.pts.iter().enumerate() {
        weld.add([p[0], p[1], 0.0], Some(lines.nodes[k]));
    }
    let boundary_vertex: Vec<usize> = lines.pts.iter().map(|p| weld.add([p[0], p[1], 0.0], None)).collect();
    let mut es = EdgeSet::default();
    let mut cells = vec![];
    let (a, b) = ([lo[0] - size, lo[1] - size], [hi[0] + size, hi[1] + size]);
    let start = Convex { pts: vec![a, [b[0], a[1]], b, [a[0], b[1]]], tag: vec![BOX; 4] };
    for (i, nbi) in nb.iter().enumerate() {
        let mut poly = Convex { pts: start.pts.clone(), tag: start.tag.clone() };
        for &j in nbi {
            let (n, d) = bisector(seeds, weights, i, j);
            poly = poly.clip(n, d, j, tol);
            if poly.pts.is_empty() {
                break;
            }
        }
        if poly.pts.is_empty() {
            continue;
        }
        let mut cell = Cell { seed: i, ..Cell::default() };
        // The boundary's segments, as far as they are in the cell.
        for (s, seg) in lines.segs.iter().enumerate() {
            let (p, q) = lines.seg(s);
            let Some((t0, t1)) = poly.segment_inside(p, q, tol) else { continue };
            let len = ((q[0] - p[0]).powi(2) + (q[1] - p[1]).powi(2)).sqrt();
            if (t1 - t0) * len <= tol {
                continue;
            }
            let mut at = |t: f64, end: usize| {
                if t <= 0.0 || t >= 1.0 {
                    boundary_vertex[seg[end]]
                } else {
                    weld.add([p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]), 0.0], None)
                }
            };
            let (va, vb) = (at(t0, 0), at(t1, 1));
            if let Some(e) = es.edge(va, vb) {
                push_new(&mut cell.edges, e);
            }
        }
        // The cell's own edges, as far as they are inside the boundary.
        let m = poly.pts.len();
        for k in 0..m {
            if poly.tag[k] == BOX {
                continue;
            }
            let (u, v) = (poly.pts[k], poly.pts[(k + 1) % m]);
            let len = ((v[0] - u[0]).powi(2) + (v[1] - u[1]).powi(2)).sqrt();
            if len <= tol {
                continue;
            }
            let mut ts = lines.cuts(u, v, tol);
            ts.push(0.0);
            ts.push(1.0);
            ts.sort_by(f64::total_cmp);
            let at = |t: f64| [u[0] + t * (v[0] - u[0]), u[1] + t * (v[1] - u[1])];
            for w in ts.windows(2) {
                if (w[1] - w[0]) * len <= tol {
                    continue;
                }
                let mid = at(0.5 * (w[0] + w[1]));
                if lines.distance(mid) <= tol || !lines.inside(mid) {
                    continue;
                }
                let (x, y) = (at(w[0]), at(w[1]));
                let va = weld.add([x[0], x[1], 0.0], None);
                let vb = weld.add([y[0], y[1], 0.0], None);
                if let Some(e) = es.edge(va, vb) {
                    push_new(&mut cell.edges, e);
                    push_new(&mut cell.neighbours, poly.tag[k]);
                }
            }
        }
        if !cell.edges.is_empty() {
            cells.push(cell);
        }
    }
    if cells.is_empty() {
        return fail(op, "no seed has a cell inside the boundary");
    }
    // Neighbours both ways: a cell sees the other's edge even when its own
    // copy of the bisector was cut to nothing by rounding.
    let index: HashMap<usize, usize> = cells.iter().enumerate().map(|(k, c)| (c.seed, k)).collect();
    let pairs: HashSet<(usize, usize)> =
        cells.iter().flat_map(|c| c.neighbours.iter().map(move |&j| (c.seed, j))).collect();
    for &(i, j) in &pairs {
        if let Some(&k) = index.get(&j) {
            push_new(&mut cells[k].neighbours, i);
        }
    }
    for c in &mut cells {
        c.neighbours.retain(|j| index.contains_key(j));
        c.neighbours.sort_unstable();
    }
    Ok(Partition { verts: weld.verts, vert_node: weld.node, edges: es.edges, faces: vec![], cells })
}
