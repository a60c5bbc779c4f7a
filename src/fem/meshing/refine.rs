//! RAFF: refining a mesh until its elements are as small as a density
//! field asks, splitting each element into 4 (TRI3, TRI6, QUA4, QUA8) or
//! 8 (CUB8) children of its own type as often as needed. Neighbours may
//! end at different levels: a node of the finer side that lies inside an
//! edge (or face) of the coarser side is *hanging*, and a relation element
//! (MULT) ties it to the nodes of that side, so that RELA of a model keeps
//! the displacement conforming.
//!
//! Every point made is known exactly by its integer coordinates in the
//! reference element of the original (root) element it lies in, on a grid
//! of 2^`BITS` steps per side. A point is named by its weights on the
//! root's corner nodes (barycentric or multilinear, integers): a point on
//! a side shared by two roots gets the same name from both, so it is made
//! once, and a hanging node is found by looking up the grid points inside
//! the sides of the coarser elements. Positions and densities of new nodes
//! follow the root's own interpolation (a QUA8's curved sides stay curved).

use super::MeshError;
use crate::fem::integrate::measure;
use crate::fem::locate::locate;
use crate::fem::mesh::{Colour, ElemType, Mesh, Nodes, Part};
use crate::fem::shape;
use std::collections::{BTreeMap, HashMap};

const BITS: u32 = 20;
const N: i64 = 1 << BITS;
/// Levels of splitting at most: quadratic children need one more grid
/// level for their mid-side nodes.
const MAX_LEVEL: u32 = BITS - 2;

type Pt = [i64; 3];

/// Corner offsets of a square and a cube on the reference grid, in
/// Cast3M's node order (counter-clockwise; a cube's bottom then top).
const SQUARE: [[i64; 3]; 4] = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]];
const CUBE: [[i64; 3]; 8] = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]];
const CUBE_EDGES: [[usize; 2]; 12] =
    [[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 7], [7, 4], [0, 4], [1, 5], [2, 6], [3, 7]];

/// An element of the mesh to refine.
struct Root {
    ty: ElemType,
    conn: Vec<usize>,
    colour: Colour,
}

impl Root {
    /// Local numbers of the corner nodes.
    fn corners(&self) -> &'static [usize] {
        match self.ty {
            ElemType::Tri6 => &[0, 2, 4],
            ElemType::Qua8 => &[0, 2, 4, 6],
            ElemType::Tri3 => &[0, 1, 2],
            ElemType::Qua4 => &[0, 1, 2, 3],
            _ => &[0, 1, 2, 3, 4, 5, 6, 7],
        }
    }

    fn is_triangle(&self) -> bool {
        matches!(self.ty, ElemType::Tri3 | ElemType::Tri6)
    }

    fn quadratic(&self) -> bool {
        matches!(self.ty, ElemType::Tri6 | ElemType::Qua8)
    }

    /// The grid point as reference coordinates of the root's shape functions.
    fn reference(&self, p: Pt) -> [f64; 3] {
        let f = |c: i64| c as f64 / N as f64;
        if self.is_triangle() {
            [f(p[0]), f(p[1]), 0.0]
        } else if self.ty == ElemType::Cub8 {
            [2.0 * f(p[0]) - 1.0, 2.0 * f(p[1]) - 1.0, 2.0 * f(p[2]) - 1.0]
        } else {
            [2.0 * f(p[0]) - 1.0, 2.0 * f(p[1]) - 1.0, 0.0]
        }
    }

    /// The point's weights on the corner nodes, scaled to sum to N³ (the
    /// same scale for triangles, squares and cubes, so that a point on a
    /// side shared by a triangle and a square has one name).
    fn name(&self, p: Pt) -> Vec<(usize, i64)> {
        let c = self.corners();
        let mut w: Vec<(usize, i64)> = if self.is_triangle() {
            let b = [N - p[0] - p[1], p[0], p[1]];
            (0..3).map(|k| (self.conn[c[k]], b[k] * N * N)).collect()
        } else {
            let f = |k: usize, off: [i64; 3]| if off[k] == 1 { p[k] } else { N - p[k] };
            if self.ty == ElemType::Cub8 {
                (0..8).map(|k| (self.conn[c[k]], f(0, CUBE[k]) * f(1, CUBE[k]) * f(2, CUBE[k]))).collect()
            } else {
                (0..4).map(|k| (self.conn[c[k]], f(0, SQUARE[k]) * f(1, SQUARE[k]) * N)).collect()
            }
        };
        w.retain(|e| e.1 != 0);
        w.sort_unstable();
        w
    }

    /// The root's own node at a point named `name`: a corner, or the
    /// mid-side node of a quadratic root.
    fn own_node(&self, name: &[(usize, i64)]) -> Option<usize> {
        match name {
            [(n, _)] => Some(*n),
            [(a, wa), (b, wb)] if self.quadratic() && wa == wb => {
                let nc = self.corners().len();
                (0..nc).find_map(|k| {
                    let (p, q) = (self.conn[2 * k], self.conn[(2 * k + 2) % (2 * nc)]);
                    ((p == *a && q == *b) || (p == *b && q == *a)).then_some(self.conn[2 * k + 1])
                })
            }
            _ => None,
        }
    }

    /// Interpolation of nodal values `v` at a grid point.
    fn interpolate(&self, p: Pt, v: impl Fn(usize) -> [f64; 4]) -> [f64; 4] {
        let s = shape::eval(self.ty, self.reference(p));
        let mut out = [0.0; 4];
        for (k, n) in s.n.iter().enumerate() {
            let x = v(self.conn[k]);
            (0..4).for_each(|c| out[c] += n * x[c]);
        }
        out
    }
}

/// A piece of a root: its corners on the grid and its level of splitting.
#[derive(Clone)]
struct Leaf {
    root: usize,
    level: u32,
    corners: Vec<Pt>,
}

fn mid(a: Pt, b: Pt) -> Pt {
    [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2]
}

fn children(tri: bool, leaf: &Leaf) -> Vec<Leaf> {
    let child = |corners: Vec<Pt>| Leaf { root: leaf.root, level: leaf.level + 1, corners };
    let c = &leaf.corners;
    if tri {
        let (m01, m12, m20) = (mid(c[0], c[1]), mid(c[1], c[2]), mid(c[2], c[0]));
        return vec![
            child(vec![c[0], m01, m20]),
            child(vec![m01, c[1], m12]),
            child(vec![m20, m12, c[2]]),
            child(vec![m01, m12, m20]),
        ];
    }
    let half = (c[1][0] - c[0][0]) / 2;
    let offsets: &[[i64; 3]] = if c.len() == 8 { &CUBE } else { &SQUARE };
    offsets
        .iter()
        .map(|o| {
            let base = [c[0][0] + o[0] * half, c[0][1] + o[1] * half, c[0][2] + o[2] * half];
            child(
                offsets.iter().map(|d| [base[0] + d[0] * half, base[1] + d[1] * half, base[2] + d[2] * half]).collect(),
            )
        })
        .collect()
}

/// The grid points of a leaf's element, in the node order of its type.
fn element_points(root: &Root, leaf: &Leaf) -> Vec<Pt> {
    if !root.quadratic() {
        return leaf.corners.clone();
    }
    let nc = leaf.corners.len();
    (0..nc).flat_map(|k| [leaf.corners[k], mid(leaf.corners[k], leaf.corners[(k + 1) % nc])]).collect()
}

/// The sides of a leaf on which a node of a finer neighbour may hang:
/// (geometry, local numbers in `element_points`) of its edges, and of its
/// faces for a cube.
fn sides(root: &Root) -> Vec<(ElemType, Vec<usize>)> {
    match root.ty {
        ElemType::Tri3 => {
            vec![(ElemType::Seg2, vec![0, 1]), (ElemType::Seg2, vec![1, 2]), (ElemType::Seg2, vec![2, 0])]
        }
        ElemType::Qua4 => (0..4).map(|k| (ElemType::Seg2, vec![k, (k + 1) % 4])).collect(),
        ElemType::Tri6 | ElemType::Qua8 => {
            let n = root.ty.nodes();
            (0..n / 2).map(|k| (ElemType::Seg3, vec![2 * k, 2 * k + 1, (2 * k + 2) % n])).collect()
        }
        _ => {
            let mut v: Vec<_> = CUBE_EDGES.iter().map(|e| (ElemType::Seg2, e.to_vec())).collect();
            v.extend(shape::faces(ElemType::Cub8));
            v
        }
    }
}

/// A point's name: its weights on nodes that do not hang, scaled to sum
/// to N³.
type Name = Vec<(usize, i128)>;

/// Scale of the weights of a hanging node on the corners of its side.
const TIE_BITS: u32 = 30;

/// The weights of each hanging node of `mesh` (its MULT elements) on the
/// corners of the side it lies on (a SEG3's middle node does not name a
/// place: the weights are the linear ones of its ends).
fn hanging_places(nodes: &Nodes, mesh: &Mesh) -> Result<HashMap<usize, Vec<(usize, i128)>>, MeshError> {
    let mut out = HashMap::new();
    for p in &mesh.parts {
        let Some(side) = p.ty.tie_side() else { continue };
        for e in p.elems() {
            let xs: Vec<[f64; 3]> = e[1..].iter().map(|&n| nodes.get(n)).collect();
            let xi = locate(side, &xs, nodes.get(e[0])).ok_or_else(|| {
                MeshError::new("RAFF", format!("the hanging node {} is not on the side it is tied to", e[0] + 1))
            })?;
            let (corners, w): (Vec<usize>, Vec<f64>) = match side {
                ElemType::Seg3 => (vec![e[1], e[3]], shape::eval(ElemType::Seg2, xi).n),
                _ => (e[1..].to_vec(), shape::eval(side, xi).n),
            };
            let scale = (1i64 << TIE_BITS) as f64;
            let ws = corners.into_iter().zip(w).map(|(n, w)| (n, (w * scale).round() as i128)).filter(|x| x.1 != 0);
            out.insert(e[0], ws.collect());
        }
    }
    Ok(out)
}

/// A root's name of a point, with the hanging nodes replaced by their
/// places: the same point gets one name from every element it is in.
fn expand(name: Vec<(usize, i64)>, alias: &HashMap<usize, Vec<(usize, i128)>>) -> Name {
    let mut acc: BTreeMap<usize, i128> = BTreeMap::new();
    let mut stack: Vec<(usize, i128, u32)> = name.into_iter().map(|(n, w)| (n, w as i128, 0)).collect();
    while let Some((n, w, depth)) = stack.pop() {
        match alias.get(&n) {
            // A chain of ties longer than this would be a loop.
            Some(ms) if depth < 64 => stack.extend(ms.iter().map(|&(m, t)| (m, (w * t) >> TIE_BITS, depth + 1))),
            _ => *acc.entry(n).or_default() += w,
        }
    }
    acc.into_iter().filter(|e| e.1 != 0).collect()
}

/// Refine `mesh` (TRI3, TRI6, QUA4, QUA8 or CUB8 elements, and the MULT
/// elements of an earlier refinement) until every
/// element's size (the side of a square of its area, of a cube of its
/// volume; a triangle counts as half a square) is at most the smallest
/// density at its corners, `density` giving it at the mesh's nodes.
pub fn refine(nodes: &mut Nodes, mesh: &Mesh, density: &dyn Fn(usize) -> Option<f64>) -> Result<Mesh, MeshError> {
    let fail = |m: String| MeshError::new("RAFF", m);
    let mut roots = Vec::new();
    let alias = hanging_places(nodes, mesh)?;
    for p in mesh.parts.iter().filter(|p| p.ty.tie_side().is_none()) {
        if !matches!(p.ty, ElemType::Tri3 | ElemType::Tri6 | ElemType::Qua4 | ElemType::Qua8 | ElemType::Cub8) {
            return Err(fail(format!(
                "{} elements cannot be refined (TRI3, TRI6, QUA4, QUA8 and CUB8 can)",
                p.ty.name()
            )));
        }
        for e in p.elems() {
            roots.push(Root { ty: p.ty, conn: e.to_vec(), colour: p.colour });
        }
    }
    // Position and density of the mesh's nodes (new nodes are pushed while
    // these are read).
    let mut data: HashMap<usize, [f64; 4]> = HashMap::new();
    for r in &roots {
        for &n in &r.conn {
            let d = density(n).ok_or_else(|| fail(format!("the density field has no value at node {}", n + 1)))?;
            if !(d.is_finite() && d > 0.0) {
                return Err(fail(format!("the density must be positive and finite (node {}: {d})", n + 1)));
            }
            let x = nodes.get(n);
            data.insert(n, [x[0], x[1], x[2], d]);
        }
    }
    let value = |n: usize| data[&n];
    // Split depth first, so that the children of an element follow it.
    let mut leaves: Vec<Leaf> = Vec::new();
    for (ri, r) in roots.iter().enumerate() {
        let start: Vec<Pt> = if r.is_triangle() {
            vec![[0, 0, 0], [N, 0, 0], [0, N, 0]]
        } else if r.ty == ElemType::Cub8 {
            CUBE.iter().map(|o| [o[0] * N, o[1] * N, o[2] * N]).collect()
        } else {
            SQUARE.iter().map(|o| [o[0] * N, o[1] * N, 0]).collect()
        };
        let mut stack = vec![Leaf { root: ri, level: 0, corners: start }];
        while let Some(leaf) = stack.pop() {
            let at: Vec<[f64; 4]> = leaf.corners.iter().map(|&p| r.interpolate(p, value)).collect();
            let xs: Vec<[f64; 3]> = at.iter().map(|v| [v[0], v[1], v[2]]).collect();
            let wanted = at.iter().map(|v| v[3]).fold(f64::INFINITY, f64::min);
            let size = match xs.len() {
                3 => (2.0 * measure(ElemType::Tri3, &xs)).abs().sqrt(),
                4 => measure(ElemType::Qua4, &xs).abs().sqrt(),
                _ => measure(ElemType::Cub8, &xs).abs().cbrt(),
            };
            if size > wanted && leaf.level < MAX_LEVEL {
                let mut ch = children(r.is_triangle(), &leaf);
                ch.reverse();
                stack.extend(ch);
            } else {
                leaves.push(leaf);
            }
        }
    }
    let deepest = leaves.iter().map(|l| l.level).max().unwrap_or(0);
    // The nodes of the leaves, made once per name.
    let mut made: HashMap<Name, usize> = HashMap::new();
    // A node that hangs in the mesh given (a mesh refined before) is the
    // point of the coarser side it lies on: named so, the coarser
    // element's points there find it.
    for &h in alias.keys() {
        made.insert(expand(vec![(h, N * N * N)], &alias), h);
    }
    let mut parts: BTreeMap<(ElemType, Colour), Vec<usize>> = BTreeMap::new();
    let mut leaf_nodes: Vec<Vec<usize>> = Vec::with_capacity(leaves.len());
    for leaf in &leaves {
        let r = &roots[leaf.root];
        let mut conn = Vec::new();
        for p in element_points(r, leaf) {
            let name = r.name(p);
            let n = match r.own_node(&name) {
                Some(n) => n,
                None => *made.entry(expand(name, &alias)).or_insert_with(|| {
                    let v = r.interpolate(p, value);
                    nodes.push([v[0], v[1], v[2]], v[3])
                }),
            };
            conn.push(n);
        }
        parts.entry((r.ty, r.colour)).or_default().extend(&conn);
        leaf_nodes.push(conn);
    }
    // Hanging nodes: grid points inside a leaf's sides that are nodes of
    // other leaves. A node inside several sides follows the coarsest.
    let step = N >> (deepest + 1);
    let mut hanging: BTreeMap<usize, (u32, ElemType, Vec<usize>)> = BTreeMap::new();
    for (leaf, conn) in leaves.iter().zip(&leaf_nodes) {
        let r = &roots[leaf.root];
        let pts = element_points(r, leaf);
        for (side, local) in sides(r) {
            let own: Vec<usize> = local.iter().map(|&k| conn[k]).collect();
            let corners: Vec<Pt> = match side {
                ElemType::Seg3 => vec![pts[local[0]], pts[local[2]]],
                _ => local.iter().map(|&k| pts[k]).collect(),
            };
            let len = (N >> leaf.level) / step;
            let mut visit = |p: Pt| {
                let name = r.name(p);
                let found = r.own_node(&name).or_else(|| made.get(&expand(name, &alias)).copied());
                if let Some(n) = found.filter(|n| !own.contains(n)) {
                    if hanging.get(&n).is_none_or(|h| h.0 > leaf.level) {
                        hanging.insert(n, (leaf.level, side, own.clone()));
                    }
                }
            };
            let along = |a: Pt, b: Pt, i: i64| -> Pt {
                [a[0] + (b[0] - a[0]) / len * i, a[1] + (b[1] - a[1]) / len * i, a[2] + (b[2] - a[2]) / len * i]
            };
            if corners.len() == 2 {
                (1..len).for_each(|i| visit(along(corners[0], corners[1], i)));
            } else {
                // A square face: corners 0, 1 and 3 span it.
                for i in 1..len {
                    for j in 1..len {
                        let p = along(corners[0], corners[1], i);
                        let q = along(corners[0], corners[3], j);
                        visit([p[0] + q[0] - corners[0][0], p[1] + q[1] - corners[0][1], p[2] + q[2] - corners[0][2]]);
                    }
                }
            }
        }
    }
    let mut out = Mesh { parts: Vec::new() };
    for ((ty, colour), conn) in parts {
        let mut p = Part::with(ty, conn);
        p.colour = colour;
        out.parts.push(p);
    }
    let mut ties: BTreeMap<ElemType, Vec<usize>> = BTreeMap::new();
    for (n, (_, side, masters)) in hanging {
        let ty = match side {
            ElemType::Seg2 => ElemType::Mult3,
            ElemType::Seg3 => ElemType::Mult4,
            _ => ElemType::Mult5,
        };
        let c = ties.entry(ty).or_default();
        c.push(n);
        c.extend(masters);
    }
    out.parts.extend(ties.into_iter().map(|(ty, conn)| Part::with(ty, conn)));
    Ok(out)
}
