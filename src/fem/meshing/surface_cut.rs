//! INTE 'GEOM': where two triangulated surfaces of space cross, and each
//! surface cut along that curve so that the curve is made of element edges.
//!
//! # The rule
//!
//! * Two triangles that are not coplanar meet along a segment of the line
//!   where their planes cross: the overlap of the two chords that each
//!   triangle cuts on that line. Coplanar pairs are left alone (the
//!   operation is the crossing of surfaces, not their overlap).
//! * Each end of such a segment is a node of each surface: an existing
//!   vertex when it lies on one, else a new node. A new node that lies on an
//!   edge is shared by the two triangles of that edge, so the cut surface
//!   stays conforming and the curve separates it into sides.
//! * A triangle that the curve touches is replaced by the constrained
//!   Delaunay triangulation (spade) of its vertices, the new nodes on its
//!   edges and inside it, with the curve's segments as imposed edges. The
//!   original nodes are kept: the cut surface shares them with the input.
//! * Each side gets its own nodes on the curve, so that the two cut
//!   surfaces are not joined; the curve is returned twice, once on the
//!   nodes of each side (SEG2).

use super::vec3::{cross, dot, norm, sub, V3};
use super::{check_nodes, fail, MeshError};
use crate::fem::mesh::{ElemType, Mesh, Nodes, Part};
use spade::{ConstrainedDelaunayTriangulation, Point2, Triangulation};
use std::collections::HashMap;

/// The two cut surfaces and the crossing curve on the nodes of each.
#[derive(Debug, Clone)]
pub struct Cut {
    pub first: Mesh,
    pub second: Mesh,
    pub curve_first: Mesh,
    pub curve_second: Mesh,
}

/// One triangle of an input surface, by part and rank.
struct Tri {
    nodes: [usize; 3],
    x: [V3; 3],
    normal: V3,
    lo: V3,
    hi: V3,
}

/// Where a point of the curve sits on a triangle of one surface.
#[derive(Clone, Copy)]
enum Place {
    Vertex(usize),
    Edge(usize, usize),
    Inside,
}

/// The new nodes of one side and what each triangle must be cut with.
struct Side<'a> {
    tris: &'a [Tri],
    edge_nodes: HashMap<(usize, usize), Vec<usize>>,
    inner_nodes: HashMap<usize, Vec<usize>>,
    segments: HashMap<usize, Vec<[usize; 2]>>,
    curve: Vec<usize>,
    /// New nodes by position (quantised), to find one again.
    grid: HashMap<[i64; 3], Vec<usize>>,
    snap: f64,
}

pub fn cut_surfaces(nodes: &mut Nodes, a: &Mesh, b: &Mesh) -> Result<Cut, MeshError> {
    const OP: &str = "INTE";
    check_nodes(OP, nodes, a)?;
    check_nodes(OP, nodes, b)?;
    for m in [a, b] {
        if let Some(p) = m.parts.iter().find(|p| p.ty != ElemType::Tri3 && !p.is_empty()) {
            return fail(
                OP,
                format!(
                    "'GEOM' cuts surfaces of TRI3 elements: this mesh has {} elements (CHAN 'TRI3' first)",
                    p.ty.name()
                ),
            );
        }
    }
    let (ta, tb) = (triangles(nodes, a), triangles(nodes, b));
    let (lo, hi) = ta.iter().chain(&tb).fold(([f64::MAX; 3], [f64::MIN; 3]), |(lo, hi), t| {
        (std::array::from_fn(|k| lo[k].min(t.lo[k])), std::array::from_fn(|k| hi[k].max(t.hi[k])))
    });
    let diag = norm(sub(hi, lo));
    if !diag.is_finite() {
        return fail(OP, "a node has a coordinate that is not a finite number");
    }
    let tol = 1e-9 * diag.max(f64::MIN_POSITIVE);
    // Points of the curve closer than this are one node: the same crossing
    // computed from two pairs of triangles differs by rounding, and by more
    // where a vertex lies almost on the other surface.
    let edges = ta.iter().chain(&tb).map(|t| norm(sub(t.x[1], t.x[0])));
    let mean_edge = edges.clone().sum::<f64>() / edges.count().max(1) as f64;
    let snap = (1e-5 * mean_edge).max(tol);
    let mut sa = Side::new(&ta, snap);
    let mut sb = Side::new(&tb, snap);
    // Candidate pairs by overlapping boxes, the second surface sorted by
    // its lowest x so each triangle scans only a window of it.
    let mut order: Vec<usize> = (0..tb.len()).collect();
    order.sort_by(|&i, &j| tb[i].lo[0].total_cmp(&tb[j].lo[0]));
    for (i, t) in ta.iter().enumerate() {
        for &j in &order {
            let u = &tb[j];
            if u.lo[0] > t.hi[0] + tol {
                break;
            }
            if (0..3).any(|k| u.hi[k] < t.lo[k] - tol || u.lo[k] > t.hi[k] + tol) {
                continue;
            }
            if let Some([p, q]) = crossing(t, u, tol) {
                let (pa, qa) = (sa.node(nodes, i, p), sa.node(nodes, i, q));
                let (pb, qb) = (sb.node(nodes, j, p), sb.node(nodes, j, q));
                if pa != qa {
                    sa.segments.entry(i).or_default().push([pa, qa]);
                    sa.curve.extend([pa, qa]);
                }
                if pb != qb {
                    sb.segments.entry(j).or_default().push([pb, qb]);
                    sb.curve.extend([pb, qb]);
                }
            }
        }
    }
    Ok(Cut {
        first: sa.cut_mesh(nodes, a)?,
        second: sb.cut_mesh(nodes, b)?,
        curve_first: Mesh::single(Part::with(ElemType::Seg2, sa.curve)),
        curve_second: Mesh::single(Part::with(ElemType::Seg2, sb.curve)),
    })
}

fn triangles(nodes: &Nodes, m: &Mesh) -> Vec<Tri> {
    let mut out = Vec::new();
    for p in &m.parts {
        for e in p.elems() {
            let x = [nodes.get(e[0]), nodes.get(e[1]), nodes.get(e[2])];
            let n = cross(sub(x[1], x[0]), sub(x[2], x[0]));
            let len = norm(n);
            let normal = if len > 0.0 { [n[0] / len, n[1] / len, n[2] / len] } else { [0.0; 3] };
            let lo = std::array::from_fn(|k| x[0][k].min(x[1][k]).min(x[2][k]));
            let hi = std::array::from_fn(|k| x[0][k].max(x[1][k]).max(x[2][k]));
            out.push(Tri { nodes: [e[0], e[1], e[2]], x, normal, lo, hi });
        }
    }
    out
}

/// The chord that the plane of `other` cuts on triangle `t`: its points
/// (one or two), or None when the triangle lies on one side or in the plane.
fn chord(t: &Tri, other: &Tri, tol: f64) -> Option<Vec<V3>> {
    let d: Vec<f64> = t.x.iter().map(|x| dot(other.normal, sub(*x, other.x[0]))).collect();
    let zero = |v: f64| v.abs() <= tol;
    if d.iter().all(|&v| zero(v)) || d.iter().all(|&v| v > tol) || d.iter().all(|&v| v < -tol) {
        return None;
    }
    let mut pts: Vec<V3> = (0..3).filter(|&k| zero(d[k])).map(|k| t.x[k]).collect();
    for (i, j) in [(0, 1), (1, 2), (2, 0)] {
        if (d[i] > tol && d[j] < -tol) || (d[i] < -tol && d[j] > tol) {
            let s = d[i] / (d[i] - d[j]);
            pts.push(std::array::from_fn(|k| t.x[i][k] + s * (t.x[j][k] - t.x[i][k])));
        }
    }
    Some(pts)
}

/// The segment two non-coplanar triangles share, if it has a length.
fn crossing(t: &Tri, u: &Tri, tol: f64) -> Option<[V3; 2]> {
    let dir = cross(t.normal, u.normal);
    if norm(dir) < 1e-9 {
        return None;
    }
    let (ct, cu) = (chord(t, u, tol)?, chord(u, t, tol)?);
    let ends = |c: &[V3]| {
        let mut v: Vec<(f64, V3)> = c.iter().map(|p| (dot(dir, *p), *p)).collect();
        v.sort_by(|a, b| a.0.total_cmp(&b.0));
        (v[0], v[v.len() - 1])
    };
    let ((t0, pt0), (t1, pt1)) = ends(&ct);
    let ((u0, pu0), (u1, pu1)) = ends(&cu);
    let (lo, plo) = if t0 >= u0 { (t0, pt0) } else { (u0, pu0) };
    let (hi, phi) = if t1 <= u1 { (t1, pt1) } else { (u1, pu1) };
    (hi - lo > tol * norm(dir).recip().max(1.0)).then_some([plo, phi])
}

impl<'a> Side<'a> {
    fn new(tris: &'a [Tri], snap: f64) -> Self {
        Side {
            tris,
            edge_nodes: HashMap::new(),
            inner_nodes: HashMap::new(),
            segments: HashMap::new(),
            curve: Vec::new(),
            grid: HashMap::new(),
            snap,
        }
    }

    /// Where `x` sits on triangle `i`: on a vertex or an edge when closer
    /// to it than the snapping distance.
    fn place(&self, i: usize, x: V3) -> Place {
        let t = &self.tris[i];
        if let Some(k) = (0..3).find(|&k| norm(sub(x, t.x[k])) <= self.snap) {
            return Place::Vertex(t.nodes[k]);
        }
        for (i, j) in [(0, 1), (1, 2), (2, 0)] {
            let e = sub(t.x[j], t.x[i]);
            let off = norm(cross(e, sub(x, t.x[i]))) / norm(e).max(f64::MIN_POSITIVE);
            if off <= self.snap {
                return Place::Edge(t.nodes[i], t.nodes[j]);
            }
        }
        Place::Inside
    }

    /// The node of this side at `x` on triangle `i`: a vertex, a new node
    /// found again, or a new node.
    fn node(&mut self, nodes: &mut Nodes, i: usize, x: V3) -> usize {
        let place = self.place(i, x);
        if let Place::Vertex(n) = place {
            return n;
        }
        let key = |x: V3, s: f64| -> [i64; 3] { std::array::from_fn(|k| (x[k] / s).floor() as i64) };
        let cell = self.snap;
        let c = key(x, cell);
        let mut found = None;
        'search: for dx in -1..=1 {
            for dy in -1..=1 {
                for dz in -1..=1 {
                    for &n in self.grid.get(&[c[0] + dx, c[1] + dy, c[2] + dz]).into_iter().flatten() {
                        if norm(sub(nodes.get(n), x)) <= self.snap {
                            found = Some(n);
                            break 'search;
                        }
                    }
                }
            }
        }
        // A new node takes the mean density of the triangle it cuts.
        let density = self.tris[i].nodes.iter().map(|&n| nodes.density[n]).sum::<f64>() / 3.0;
        let n = found.unwrap_or_else(|| {
            let n = nodes.push(x, density);
            self.grid.entry(c).or_default().push(n);
            n
        });
        let list = match place {
            Place::Edge(p, q) => self.edge_nodes.entry((p.min(q), p.max(q))).or_default(),
            _ => self.inner_nodes.entry(i).or_default(),
        };
        if !list.contains(&n) {
            list.push(n);
        }
        n
    }

    /// The surface with every touched triangle replaced by its pieces, in
    /// place, each part keeping its colour.
    fn cut_mesh(&self, nodes: &Nodes, m: &Mesh) -> Result<Mesh, MeshError> {
        let mut out = Mesh::default();
        let mut i = 0;
        for p in &m.parts {
            let mut part = Part { ty: p.ty, conn: Vec::new(), colour: p.colour };
            for _ in 0..p.len() {
                for tri in self.pieces(nodes, i)? {
                    part.conn.extend(tri);
                }
                i += 1;
            }
            out.parts.push(part);
        }
        Ok(out)
    }

    fn pieces(&self, nodes: &Nodes, i: usize) -> Result<Vec<[usize; 3]>, MeshError> {
        let t = &self.tris[i];
        let v = t.nodes;
        let mut pts: Vec<usize> = v.to_vec();
        let mut on_edge: HashMap<usize, usize> = HashMap::new();
        for (k, (p, q)) in [(v[0], v[1]), (v[1], v[2]), (v[2], v[0])].into_iter().enumerate() {
            for &n in self.edge_nodes.get(&(p.min(q), p.max(q))).into_iter().flatten() {
                on_edge.insert(n, k);
                pts.push(n);
            }
        }
        pts.extend(self.inner_nodes.get(&i).into_iter().flatten().filter(|n| !on_edge.contains_key(n)));
        let segs = self.segments.get(&i).map(Vec::as_slice).unwrap_or(&[]);
        if pts.len() == 3 && segs.is_empty() {
            return Ok(vec![v]);
        }
        // A frame of the triangle's plane in which it turns counter-clockwise.
        let e1 = sub(t.x[1], t.x[0]);
        let l1 = norm(e1);
        let e1 = [e1[0] / l1, e1[1] / l1, e1[2] / l1];
        let e2 = cross(t.normal, e1);
        let mut cdt: ConstrainedDelaunayTriangulation<Point2<f64>> = ConstrainedDelaunayTriangulation::new();
        let mut node_of = HashMap::new();
        let mut handle = HashMap::new();
        for &n in &pts {
            let d = sub(nodes.get(n), t.x[0]);
            let h = cdt
                .insert(Point2::new(dot(d, e1), dot(d, e2)))
                .map_err(|e| MeshError::new("INTE", format!("node {} cannot be placed ({e:?})", n + 1)))?;
            node_of.insert(h.index(), n);
            handle.insert(n, h);
        }
        for s in segs {
            let (Some(&h0), Some(&h1)) = (handle.get(&s[0]), handle.get(&s[1])) else { continue };
            if h0 != h1 && cdt.can_add_constraint(h0, h1) {
                cdt.add_constraint(h0, h1);
            }
        }
        // The edge a node lies on (vertices lie on two): three nodes of one
        // edge make a flat sliver, not an element.
        let edges_of = |n: usize| -> Vec<usize> {
            match v.iter().position(|&w| w == n) {
                Some(k) => vec![k, (k + 2) % 3],
                None => on_edge.get(&n).map(|&k| vec![k]).unwrap_or_default(),
            }
        };
        let mut out = Vec::new();
        for f in cdt.inner_faces() {
            let tri = f.vertices().map(|h| node_of[&h.fix().index()]);
            let flat = (0..3).any(|k| tri.iter().all(|&n| edges_of(n).contains(&k)));
            if !flat {
                out.push(tri);
            }
        }
        Ok(out)
    }
}
