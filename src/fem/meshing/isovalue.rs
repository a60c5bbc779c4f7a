//! Isovalues of a field given at the nodes of linear elements (ISOV): the
//! places where a linearly interpolated field equals a value (one
//! dimension less than the element: points of segments, segments of
//! triangles, triangles or quadrangles of tetrahedra), or the parts of the
//! elements where it is at most / at least that value (same dimension).
//!
//! Each element is cut on its own, as the field may jump between
//! elements; a point on an edge is shared by the elements that cut that
//! edge with the same two end values, so a continuous field gives a
//! connected isovalue. A node where the field is exactly the value is used
//! as it is. Cubes are cut as six tetrahedra around their 1–7 diagonal
//! (degenerate cubes, with repeated nodes, lose their flat tetrahedra).

use super::{fail, MeshError};
use crate::fem::mesh::{ElemType, Mesh, Nodes, Part};
use std::collections::{HashMap, HashSet};

const OP: &str = "ISOV";

/// Which set ISOV builds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum IsoMode {
    /// f = v
    Equal,
    /// f <= v
    AtMost,
    /// f >= v
    AtLeast,
}

/// One element with the field's values at its nodes.
pub struct IsoElement<'a> {
    pub ty: ElemType,
    pub nodes: &'a [usize],
    pub values: &'a [f64],
}

/// Cube to six tetrahedra sharing the diagonal 0–6 (nodes 0–3 bottom,
/// 4–7 top, in Cast3M's order); each is positively oriented when the cube is.
const CUB8_TETS: [[usize; 4]; 6] = [[0, 1, 2, 6], [0, 2, 3, 6], [0, 3, 7, 6], [0, 7, 4, 6], [0, 4, 5, 6], [0, 5, 1, 6]];

/// A vertex of a cut: an existing node, or the point of an edge where the
/// field crosses the value.
#[derive(Clone, Copy)]
struct Vert {
    x: [f64; 3],
    s: f64,
    node: usize,
    /// For an edge point: the field at `node`, then the far end of the
    /// edge and the field there.
    other: Option<(f64, usize, f64)>,
}

struct Builder<'n> {
    nodes: &'n mut Nodes,
    edge_points: HashMap<(usize, u64, usize, u64), usize>,
    parts: Vec<(ElemType, Vec<usize>)>,
    seen: HashSet<(ElemType, Vec<usize>)>,
}

impl Builder<'_> {
    fn node(&mut self, v: &Vert) -> usize {
        let Some((sa, b, sb)) = v.other else { return v.node };
        let a = v.node;
        let key = if a < b { (a, sa.to_bits(), b, sb.to_bits()) } else { (b, sb.to_bits(), a, sa.to_bits()) };
        if let Some(&n) = self.edge_points.get(&key) {
            return n;
        }
        let t = sa / (sa - sb);
        let (xa, xb) = (self.nodes.get(a), self.nodes.get(b));
        let x = [0, 1, 2].map(|k| xa[k] + t * (xb[k] - xa[k]));
        let d = self.nodes.density[a] + t * (self.nodes.density[b] - self.nodes.density[a]);
        let n = self.nodes.push(x, d);
        self.edge_points.insert(key, n);
        n
    }

    /// Add an element unless an element of the same type on the same
    /// nodes is there already (a face on the value is found by both
    /// elements that share it).
    fn add(&mut self, ty: ElemType, verts: &[Vert]) {
        let conn: Vec<usize> = verts.iter().map(|v| self.node(v)).collect();
        let distinct: HashSet<usize> = conn.iter().copied().collect();
        if distinct.len() != conn.len() {
            return;
        }
        let mut key = conn.clone();
        key.sort_unstable();
        if !self.seen.insert((ty, key)) {
            return;
        }
        match self.parts.iter_mut().find(|(t, _)| *t == ty) {
            Some((_, c)) => c.extend(conn),
            None => self.parts.push((ty, conn)),
        }
    }
}

fn vert(nodes: &Nodes, n: usize, s: f64) -> Vert {
    Vert { x: nodes.get(n), s, node: n, other: None }
}

fn edge_point(a: &Vert, b: &Vert) -> Vert {
    let t = a.s / (a.s - b.s);
    Vert { x: [0, 1, 2].map(|k| a.x[k] + t * (b.x[k] - a.x[k])), s: 0.0, node: a.node, other: Some((a.s, b.node, b.s)) }
}

/// The isovalue (or sub-level set) of `v` over the elements.
pub fn isovalue(nodes: &mut Nodes, elems: &[IsoElement], v: f64, mode: IsoMode) -> Result<Mesh, MeshError> {
    let mut b = Builder { nodes, edge_points: HashMap::new(), parts: Vec::new(), seen: HashSet::new() };
    for e in elems {
        if e.values.len() != e.nodes.len() {
            return fail(
                OP,
                format!("a {} element has {} values for {} nodes", e.ty.name(), e.values.len(), e.nodes.len()),
            );
        }
        if let Some(&n) = e.nodes.iter().find(|&&n| n >= b.nodes.len()) {
            return fail(OP, format!("node {n} does not exist"));
        }
        if let Some(x) = e.values.iter().find(|x| !x.is_finite()) {
            return fail(OP, format!("the field is not finite ({x})"));
        }
        // Signed distance to the value, positive inside the wanted set for
        // the sub-level modes.
        let s: Vec<f64> = e
            .values
            .iter()
            .map(|&f| match mode {
                IsoMode::Equal | IsoMode::AtLeast => f - v,
                IsoMode::AtMost => v - f,
            })
            .collect();
        let vs: Vec<Vert> = e.nodes.iter().zip(&s).map(|(&n, &s)| vert(b.nodes, n, s)).collect();
        match e.ty {
            ElemType::Poi1 => {
                if s[0] == 0.0 || (mode != IsoMode::Equal && s[0] > 0.0) {
                    b.add(ElemType::Poi1, &vs);
                }
            }
            ElemType::Seg2 => cut_simplex(&mut b, &vs, mode),
            ElemType::Tri3 => cut_simplex(&mut b, &vs, mode),
            ElemType::Qua4 => {
                for t in [[0, 1, 2], [0, 2, 3]] {
                    cut_simplex(&mut b, &t.map(|k| vs[k]), mode);
                }
            }
            ElemType::Tet4 => cut_simplex(&mut b, &vs, mode),
            ElemType::Cub8 => {
                if mode != IsoMode::Equal {
                    return fail(
                        OP,
                        "the parts of CUB8 elements below or above a value are not available: cut them as TET4",
                    );
                }
                for t in CUB8_TETS {
                    let ids: HashSet<usize> = t.iter().map(|&k| e.nodes[k]).collect();
                    if ids.len() == 4 {
                        cut_simplex(&mut b, &t.map(|k| vs[k]), mode);
                    }
                }
            }
            other => {
                return fail(
                    OP,
                    format!(
                        "the field's elements must be linear (POI1, SEG2, TRI3, QUA4, TET4, CUB8), not {}",
                        other.name()
                    ),
                )
            }
        }
    }
    Ok(Mesh { parts: b.parts.into_iter().filter(|(_, c)| !c.is_empty()).map(|(t, c)| Part::with(t, c)).collect() })
}

/// Cut a simplex (2, 3 or 4 vertices).
fn cut_simplex(b: &mut Builder, vs: &[Vert], mode: IsoMode) {
    match mode {
        IsoMode::Equal => level(b, vs),
        _ => sublevel(b, vs),
    }
}

/// The zero set of a simplex: the nodes at zero and the edge crossings.
/// Only a piece of one dimension less than the simplex is kept (a
/// triangle touching the value at one node gives nothing).
fn level(b: &mut Builder, vs: &[Vert]) {
    let n = vs.len();
    let mut pts: Vec<Vert> = vs.iter().filter(|v| v.s == 0.0).copied().collect();
    if pts.len() == n {
        return; // the whole simplex is at the value: no boundary of it
    }
    for i in 0..n {
        for j in i + 1..n {
            if vs[i].s * vs[j].s < 0.0 {
                pts.push(edge_point(&vs[i], &vs[j]));
            }
        }
    }
    match (n, pts.len()) {
        (2, 1) => b.add(ElemType::Poi1, &pts),
        (3, 2) => {
            // Oriented with the larger values on the left.
            let g = gradient_2d(vs);
            let d = [pts[1].x[0] - pts[0].x[0], pts[1].x[1] - pts[0].x[1]];
            if d[0] * g[1] - d[1] * g[0] > 0.0 {
                pts.swap(0, 1);
            }
            b.add(ElemType::Seg2, &pts);
        }
        (4, 3) | (4, 4) => {
            let ordered = around(vs, pts);
            let ty = if ordered.len() == 3 { ElemType::Tri3 } else { ElemType::Qua4 };
            b.add(ty, &ordered);
        }
        _ => {}
    }
}

/// The part of a simplex where s >= 0, as simplices of its dimension.
fn sublevel(b: &mut Builder, vs: &[Vert]) {
    let inside: Vec<usize> = (0..vs.len()).filter(|&k| vs[k].s >= 0.0).collect();
    let outside: Vec<usize> = (0..vs.len()).filter(|&k| vs[k].s < 0.0).collect();
    if inside.is_empty() {
        return;
    }
    let ty = match vs.len() {
        2 => ElemType::Seg2,
        3 => ElemType::Tri3,
        _ => ElemType::Tet4,
    };
    if outside.is_empty() {
        b.add(ty, vs);
        return;
    }
    // Replace each outside vertex by the crossing on its edges: the piece
    // is the convex hull of the inside vertices and those crossings,
    // triangulated by a fan from its first inside vertex with the vertex
    // order of the simplex kept where possible.
    match vs.len() {
        2 => {
            let (i, o) = (inside[0], outside[0]);
            let mut seg = [vs[0], vs[1]];
            seg[o] = if vs[i].s == 0.0 { return } else { edge_point(&vs[i], &vs[o]) };
            b.add(ty, &seg);
        }
        3 => {
            // Walk the boundary keeping inside vertices and crossings: a
            // convex polygon of 3 or 4 vertices, in the triangle's order.
            let mut poly = Vec::new();
            for k in 0..3 {
                let (p, q) = (vs[k], vs[(k + 1) % 3]);
                if p.s >= 0.0 {
                    poly.push(p);
                }
                if (p.s > 0.0 && q.s < 0.0) || (p.s < 0.0 && q.s > 0.0) {
                    poly.push(edge_point(&p, &q));
                }
            }
            for k in 1..poly.len().saturating_sub(1) {
                b.add(ty, &[poly[0], poly[k], poly[k + 1]]);
            }
        }
        _ => {
            let mut out = vs.to_vec();
            match inside.len() {
                1 => {
                    let i = inside[0];
                    for &o in &outside {
                        out[o] = edge_point(&vs[i], &vs[o]);
                    }
                    if vs[i].s > 0.0 {
                        b.add(ty, &out);
                    }
                }
                // A prism between the inside face (or edge) and the
                // crossings: split into three tetrahedra.
                _ => {
                    let cross = |i: usize, o: usize| edge_point(&vs[i], &vs[o]);
                    if inside.len() == 3 {
                        let o = outside[0];
                        let [i0, i1, i2] = [inside[0], inside[1], inside[2]];
                        let (c0, c1, c2) = (cross(i0, o), cross(i1, o), cross(i2, o));
                        prism(b, [vs[i0], vs[i1], vs[i2]], [c0, c1, c2]);
                    } else {
                        let [i0, i1] = [inside[0], inside[1]];
                        let [o0, o1] = [outside[0], outside[1]];
                        // Triangles (i0, c(i0,o0), c(i0,o1)) and (i1, c(i1,o0), c(i1,o1)).
                        let a = [vs[i0], cross(i0, o0), cross(i0, o1)];
                        let c = [vs[i1], cross(i1, o0), cross(i1, o1)];
                        prism(b, a, c);
                    }
                }
            }
        }
    }
}

/// Three tetrahedra filling the prism between triangles `a` and `c`
/// (a[k] joined to c[k]), each turned to a positive volume; flat ones
/// (a crossing at a node) are dropped.
fn prism(b: &mut Builder, a: [Vert; 3], c: [Vert; 3]) {
    for t in [[a[0], a[1], a[2], c[2]], [a[0], a[1], c[2], c[1]], [a[0], c[1], c[2], c[0]]] {
        let vol = signed_volume(&t);
        if vol.abs() <= 0.0 {
            continue;
        }
        let t = if vol < 0.0 { [t[0], t[2], t[1], t[3]] } else { t };
        b.add(ElemType::Tet4, &t);
    }
}

fn signed_volume(t: &[Vert; 4]) -> f64 {
    let d = |p: &Vert| [p.x[0] - t[0].x[0], p.x[1] - t[0].x[1], p.x[2] - t[0].x[2]];
    let (u, v, w) = (d(&t[1]), d(&t[2]), d(&t[3]));
    (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0])) / 6.0
}

/// The in-plane gradient of the linear interpolant over a triangle.
fn gradient_2d(vs: &[Vert]) -> [f64; 2] {
    let (p0, p1, p2) = (vs[0].x, vs[1].x, vs[2].x);
    let (a, b) = ([p1[0] - p0[0], p1[1] - p0[1]], [p2[0] - p0[0], p2[1] - p0[1]]);
    let det = a[0] * b[1] - a[1] * b[0];
    if det == 0.0 {
        return [0.0, 0.0];
    }
    let (d1, d2) = (vs[1].s - vs[0].s, vs[2].s - vs[0].s);
    [(d1 * b[1] - d2 * a[1]) / det, (a[0] * d2 - b[0] * d1) / det]
}

/// The gradient of the linear interpolant over a tetrahedron.
fn gradient_3d(vs: &[Vert]) -> [f64; 3] {
    let e = |k: usize| [vs[k].x[0] - vs[0].x[0], vs[k].x[1] - vs[0].x[1], vs[k].x[2] - vs[0].x[2]];
    let (a, b, c) = (e(1), e(2), e(3));
    let cross =
        |u: [f64; 3], v: [f64; 3]| [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
    let (bc, ca, ab) = (cross(b, c), cross(c, a), cross(a, b));
    let det = a[0] * bc[0] + a[1] * bc[1] + a[2] * bc[2];
    if det == 0.0 {
        return [0.0; 3];
    }
    let (d1, d2, d3) = (vs[1].s - vs[0].s, vs[2].s - vs[0].s, vs[3].s - vs[0].s);
    [0, 1, 2].map(|k| (d1 * bc[k] + d2 * ca[k] + d3 * ab[k]) / det)
}

/// The points of a plane cut of a tetrahedron in turn around their centre,
/// counter-clockwise seen from the side of larger values.
fn around(vs: &[Vert], mut pts: Vec<Vert>) -> Vec<Vert> {
    let g = gradient_3d(vs);
    let m = pts.len() as f64;
    let c = [0, 1, 2].map(|k| pts.iter().map(|p| p.x[k]).sum::<f64>() / m);
    // A frame of the plane: u towards the first point, w = g x u.
    let u = [0, 1, 2].map(|k| pts[0].x[k] - c[k]);
    let w = [g[1] * u[2] - g[2] * u[1], g[2] * u[0] - g[0] * u[2], g[0] * u[1] - g[1] * u[0]];
    let angle = |p: &Vert| {
        let d = [0, 1, 2].map(|k| p.x[k] - c[k]);
        let x = d[0] * u[0] + d[1] * u[1] + d[2] * u[2];
        let y = d[0] * w[0] + d[1] * w[1] + d[2] * w[2];
        y.atan2(x)
    };
    pts.sort_by(|p, q| angle(p).total_cmp(&angle(q)));
    pts
}
