//! Editing meshes: ELIM (merge close nodes), INTE/DIFF (element set
//! algebra), translated copies for PLUS/MOIN, INVE, element type changes
//! (CHAN) and the checks of MANU.

use super::extract::edges;
use super::vec3::{add, dist, lerp, V3};
use super::{check_node, check_nodes, fail, mesh_of, MeshError};
use crate::fem::mesh::{ElemType, Mesh, Nodes, Part};
use std::collections::{HashMap, HashSet};

/// A renumbering of nodes: `old -> new` for the nodes that changed; every
/// other node keeps its number. ELIM returns one so the caller can rewrite
/// every mesh that uses the merged nodes (in Cast3M the merge is global).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct NodeMap {
    pub map: HashMap<usize, usize>,
}

impl NodeMap {
    /// The new number of node `n`.
    pub fn get(&self, n: usize) -> usize {
        self.map.get(&n).copied().unwrap_or(n)
    }

    /// Number of nodes that changed.
    pub fn len(&self) -> usize {
        self.map.len()
    }

    pub fn is_empty(&self) -> bool {
        self.map.is_empty()
    }

    /// `mesh` with every node renumbered; elements are kept as they are,
    /// even if they become repeated or degenerate.
    pub fn apply(&self, mesh: &Mesh) -> Mesh {
        Mesh {
            parts: mesh
                .parts
                .iter()
                .map(|p| Part { ty: p.ty, conn: p.conn.iter().map(|&n| self.get(n)).collect(), colour: p.colour })
                .collect(),
        }
    }
}

/// `ELIM crit GEO`: merge the nodes of `mesh` lying within `tol` of each
/// other. Nodes are visited by increasing number and each is merged into
/// the lowest-numbered kept node within `tol`, so the lowest number always
/// survives. Returns `mesh` renumbered, with elements that became repeated
/// (same type, same set of nodes) kept once at their first place, and the
/// renumbering for the caller to apply to every other mesh.
pub fn elim(nodes: &Nodes, mesh: &Mesh, tol: f64) -> Result<(Mesh, NodeMap), MeshError> {
    check_nodes("ELIM", nodes, mesh)?;
    if !(tol >= 0.0 && tol.is_finite()) {
        return fail("ELIM", format!("the tolerance must be a non-negative number (got {tol})"));
    }
    let mut list = mesh.node_list();
    list.sort_unstable();
    // Kept nodes bucketed on a grid of cell `tol`: a match can only be in
    // the 27 cells around a node. A zero tolerance buckets exact positions.
    let h = if tol > 0.0 { tol } else { 1.0 };
    let cell = |x: V3| -> [i64; 3] {
        std::array::from_fn(|k| if tol > 0.0 { (x[k] / h).floor() as i64 } else { (x[k] + 0.0).to_bits() as i64 })
    };
    let mut grid: HashMap<[i64; 3], Vec<usize>> = HashMap::new();
    let mut map = NodeMap::default();
    for n in list {
        let x = nodes.get(n);
        let c = cell(x);
        let mut best: Option<usize> = None;
        let r = if tol > 0.0 { 1 } else { 0 };
        for dx in -r..=r {
            for dy in -r..=r {
                for dz in -r..=r {
                    let key = [c[0].saturating_add(dx), c[1].saturating_add(dy), c[2].saturating_add(dz)];
                    for &m in grid.get(&key).into_iter().flatten() {
                        if dist(nodes.get(m), x) <= tol && best.is_none_or(|b| m < b) {
                            best = Some(m);
                        }
                    }
                }
            }
        }
        match best {
            Some(m) => {
                map.map.insert(n, m);
            }
            None => grid.entry(c).or_default().push(n),
        }
    }
    Ok((dedupe(&map.apply(mesh)), map))
}

/// `ELIM crit GEO1 GEO2`: merge only nodes of `g1` with nodes of `g2`
/// lying within `tol` (elim.notice: duplicates inside one object stay).
/// Merged groups keep their lowest-numbered node, as [`elim`] does.
pub fn elim_between(nodes: &Nodes, g1: &Mesh, g2: &Mesh, tol: f64) -> Result<(Mesh, NodeMap), MeshError> {
    check_nodes("ELIM", nodes, g1)?;
    check_nodes("ELIM", nodes, g2)?;
    if !(tol >= 0.0 && tol.is_finite()) {
        return fail("ELIM", format!("the tolerance must be a non-negative number (got {tol})"));
    }
    let h = if tol > 0.0 { tol } else { 1.0 };
    let cell = |x: V3| -> [i64; 3] {
        std::array::from_fn(|k| if tol > 0.0 { (x[k] / h).floor() as i64 } else { (x[k] + 0.0).to_bits() as i64 })
    };
    let mut grid: HashMap<[i64; 3], Vec<usize>> = HashMap::new();
    for n in g1.node_list() {
        grid.entry(cell(nodes.get(n))).or_default().push(n);
    }
    // Union-find over the cross pairs: a node of g2 near two of g1 joins
    // them into one point.
    let mut parent: HashMap<usize, usize> = HashMap::new();
    fn root(parent: &HashMap<usize, usize>, mut n: usize) -> usize {
        while let Some(&p) = parent.get(&n) {
            if p == n {
                break;
            }
            n = p;
        }
        n
    }
    let r = if tol > 0.0 { 1 } else { 0 };
    for n in g2.node_list() {
        let x = nodes.get(n);
        let c = cell(x);
        for dx in -r..=r {
            for dy in -r..=r {
                for dz in -r..=r {
                    let key = [c[0].saturating_add(dx), c[1].saturating_add(dy), c[2].saturating_add(dz)];
                    for &m in grid.get(&key).into_iter().flatten() {
                        if m != n && dist(nodes.get(m), x) <= tol {
                            let (a, b) = (root(&parent, m), root(&parent, n));
                            if a != b {
                                let (lo, hi) = (a.min(b), a.max(b));
                                parent.insert(hi, lo);
                                parent.entry(lo).or_insert(lo);
                            }
                        }
                    }
                }
            }
        }
    }
    let mut map = NodeMap::default();
    for &n in parent.keys() {
        let m = root(&parent, n);
        if m != n {
            map.map.insert(n, m);
        }
    }
    Ok((dedupe(&map.apply(&g1.union(g2))), map))
}

/// Sorted node set of an element: the identity used by ELIM, INTE and DIFF
/// (the same nodes in another order are the same element).
fn elem_key(ty: ElemType, e: &[usize]) -> (ElemType, Vec<usize>) {
    let mut k = e.to_vec();
    k.sort_unstable();
    (ty, k)
}

fn filter_elems(mesh: &Mesh, mut keep: impl FnMut(ElemType, &[usize]) -> bool) -> Mesh {
    let parts =
        mesh.parts.iter().map(|p| (p.ty, p.elems().filter(|e| keep(p.ty, e)).flatten().copied().collect())).collect();
    mesh_of(parts)
}

fn dedupe(mesh: &Mesh) -> Mesh {
    let mut seen = HashSet::new();
    filter_elems(mesh, |ty, e| seen.insert(elem_key(ty, e)))
}

fn key_set(mesh: &Mesh) -> HashSet<(ElemType, Vec<usize>)> {
    mesh.parts.iter().flat_map(|p| p.elems().map(move |e| elem_key(p.ty, e))).collect()
}

/// `G1 INTE G2`: the elements of `a` also in `b` (same type and nodes, in
/// any order), in `a`'s order and node order.
pub fn inte(a: &Mesh, b: &Mesh) -> Mesh {
    let kb = key_set(b);
    dedupe(&filter_elems(a, |ty, e| kb.contains(&elem_key(ty, e))))
}

/// `DIFF G1 G2`: the symmetric difference, the elements of `a` not in `b`
/// followed by those of `b` not in `a`, each in its mesh's order.
pub fn diff(a: &Mesh, b: &Mesh) -> Mesh {
    let (ka, kb) = (key_set(a), key_set(b));
    let only_a = filter_elems(a, |ty, e| !kb.contains(&elem_key(ty, e)));
    let only_b = filter_elems(b, |ty, e| !ka.contains(&elem_key(ty, e)));
    dedupe(&only_a.union(&only_b))
}

/// `GEO PLUS VEC` (and `MOIN` with `-VEC`): a copy of `mesh` on new nodes
/// shifted by `v`. New nodes are appended in the mesh's node order
/// ([`Mesh::node_list`]) with the densities of the originals; the copy has
/// the same elements in the same order.
pub fn translate_copy(nodes: &mut Nodes, mesh: &Mesh, v: V3) -> Result<Mesh, MeshError> {
    check_nodes("PLUS", nodes, mesh)?;
    let mut map = NodeMap::default();
    for n in mesh.node_list() {
        let m = nodes.push(add(nodes.get(n), v), nodes.density[n]);
        map.map.insert(n, m);
    }
    Ok(map.apply(mesh))
}

/// `GEO TOUR angle P1 (P2)`: a copy of `mesh` on new nodes turned by
/// `angle_deg` degrees about `centre` (2D: about z, counter-clockwise) or
/// about the axis `centre`→`axis_end` (3D, right-hand rule).
pub fn rotate_copy(
    nodes: &mut Nodes,
    mesh: &Mesh,
    angle_deg: f64,
    centre: V3,
    axis_end: Option<V3>,
) -> Result<Mesh, MeshError> {
    check_nodes("TOUR", nodes, mesh)?;
    let k = rotation_axis("TOUR", centre, axis_end)?;
    let mut map = NodeMap::default();
    for n in mesh.node_list() {
        let x = super::vec3::rotate(nodes.get(n), centre, k, angle_deg.to_radians());
        let m = nodes.push(x, nodes.density[n]);
        map.map.insert(n, m);
    }
    Ok(map.apply(mesh))
}

/// [`rotate_copy`] of one point: a new node.
pub fn rotate_point(
    nodes: &mut Nodes,
    p: usize,
    angle_deg: f64,
    centre: V3,
    axis_end: Option<V3>,
) -> Result<usize, MeshError> {
    let k = rotation_axis("TOUR", centre, axis_end)?;
    let x = super::vec3::rotate(nodes.get(p), centre, k, angle_deg.to_radians());
    Ok(nodes.push(x, nodes.density[p]))
}

/// The unit axis of a rotation: z in 2D, else from `centre` to `axis_end`.
fn rotation_axis(op: &'static str, centre: V3, axis_end: Option<V3>) -> Result<V3, MeshError> {
    match axis_end {
        None => Ok([0.0, 0.0, 1.0]),
        Some(p2) => {
            let a = super::vec3::sub(p2, centre);
            let l = super::vec3::norm(a);
            if l == 0.0 {
                return fail(op, "the two points of the axis coincide");
            }
            Ok(super::vec3::scale(a, 1.0 / l))
        }
    }
}

/// `INVE GEO`: reverse orientation. A line is run backwards (elements in
/// reverse order, each reversed); a surface element keeps its first node
/// and turns the other way; points come in reverse order.
pub fn inve(mesh: &Mesh) -> Result<Mesh, MeshError> {
    let mut parts = Vec::new();
    for p in &mesh.parts {
        let perm: &[usize] = match p.ty {
            ElemType::Poi1 => &[0],
            ElemType::Seg2 => &[1, 0],
            ElemType::Seg3 => &[2, 1, 0],
            ElemType::Tri3 => &[0, 2, 1],
            ElemType::Qua4 => &[0, 3, 2, 1],
            ElemType::Tri6 => &[0, 5, 4, 3, 2, 1],
            ElemType::Qua8 => &[0, 7, 6, 5, 4, 3, 2, 1],
            t if t.dim() == 3 && t.joint_face().is_none() => super::symmetry::turn_over(t),
            other => return fail("INVE", format!("cannot reverse {} elements", other.name())),
        };
        let mut elems: Vec<Vec<usize>> = p.elems().map(|e| perm.iter().map(|&k| e[k]).collect()).collect();
        if p.ty.dim() <= 1 {
            elems.reverse();
        }
        parts.push((p.ty, elems.concat()));
    }
    if mesh.parts.iter().all(|p| p.ty.dim() <= 1) {
        parts.reverse();
    }
    Ok(mesh_of(parts))
}

/// `CHAN 'POI1' GEO`: a POI1 mesh of the nodes, in Cast3M's point order
/// ([`point_order`](super::query::point_order)).
pub fn change_to_poi1(mesh: &Mesh) -> Mesh {
    Mesh::points(&super::query::point_order(mesh))
}

/// `CHAN QUA8 GEO` (or SEG3, TRI6): every linear element becomes quadratic
/// (SEG2→SEG3, TRI3→TRI6, QUA4→QUA8; POI1 and quadratic parts unchanged).
/// An edge shared by several elements, in any part, gets one mid-side node,
/// reusing the middle node of an already quadratic edge. New nodes sit at
/// the middle of their edge with the mean density of its ends, and are
/// appended in order of first use (elements in order, edges in local
/// order: `(0,1), (1,2), ...`).
pub fn change_to_quadratic(nodes: &mut Nodes, mesh: &Mesh) -> Result<Mesh, MeshError> {
    check_nodes("CHAN", nodes, mesh)?;
    let mut mid: HashMap<(usize, usize), usize> = HashMap::new();
    let key = |a: usize, b: usize| (a.min(b), a.max(b));
    for p in &mesh.parts {
        let quad_edges: &[&[usize]] = if p.ty == ElemType::Seg3 { &[&[0, 1, 2]] } else { edges(p.ty) };
        if matches!(p.ty, ElemType::Seg3 | ElemType::Tri6 | ElemType::Qua8) {
            for e in p.elems() {
                for ed in quad_edges {
                    mid.entry(key(e[ed[0]], e[ed[2]])).or_insert(e[ed[1]]);
                }
            }
        }
    }
    let mut parts = Vec::new();
    for p in &mesh.parts {
        let (ty, lin): (ElemType, &[&[usize]]) = match p.ty {
            ElemType::Seg2 => (ElemType::Seg3, &[&[0, 1]]),
            ElemType::Tri3 => (ElemType::Tri6, edges(ElemType::Tri3)),
            ElemType::Qua4 => (ElemType::Qua8, edges(ElemType::Qua4)),
            ElemType::Poi1 | ElemType::Seg3 | ElemType::Tri6 | ElemType::Qua8 => {
                parts.push((p.ty, p.conn.clone()));
                continue;
            }
            other => {
                return fail("CHAN", format!("{} has no quadratic counterpart among the known elements", other.name()))
            }
        };
        let mut conn = Vec::with_capacity(p.len() * ty.nodes());
        for e in p.elems() {
            for ed in lin {
                let (a, b) = (e[ed[0]], e[ed[1]]);
                let m = *mid.entry(key(a, b)).or_insert_with(|| {
                    let d = 0.5 * (nodes.density[a] + nodes.density[b]);
                    nodes.push(lerp(nodes.get(a), nodes.get(b), 0.5), d)
                });
                conn.push(a);
                conn.push(m);
            }
            if p.ty == ElemType::Seg2 {
                conn.push(e[1]);
            }
        }
        parts.push((ty, conn));
    }
    Ok(merge_same_types(parts))
}

/// `CHAN SEG2/TRI3/QUA4 GEO`: drop the mid-side nodes of quadratic elements
/// (the nodes themselves stay in the table).
pub fn change_to_linear(mesh: &Mesh) -> Mesh {
    let parts = mesh
        .parts
        .iter()
        .map(|p| {
            let (ty, keep): (ElemType, &[usize]) = match p.ty {
                ElemType::Seg3 => (ElemType::Seg2, &[0, 2]),
                ElemType::Tri6 => (ElemType::Tri3, &[0, 2, 4]),
                ElemType::Qua8 => (ElemType::Qua4, &[0, 2, 4, 6]),
                ElemType::Cu20 => (ElemType::Cub8, &[0, 2, 4, 6, 12, 14, 16, 18]),
                ElemType::Pr15 => (ElemType::Pri6, &[0, 2, 4, 9, 11, 13]),
                t => return (t, p.conn.clone()),
            };
            (ty, p.elems().flat_map(|e| keep.iter().map(move |&k| e[k])).collect())
        })
        .collect();
    merge_same_types(parts)
}

/// `CHAN 'TRI3'`: linear elements, each QUA4 cut along its first
/// diagonal into two TRI3 (1-2-3 and 1-3-4, the orientation kept).
pub fn change_to_triangles(mesh: &Mesh) -> Mesh {
    let lin = change_to_linear(mesh);
    let parts = lin
        .parts
        .iter()
        .map(|p| match p.ty {
            ElemType::Qua4 => (ElemType::Tri3, p.elems().flat_map(|e| [e[0], e[1], e[2], e[0], e[2], e[3]]).collect()),
            t => (t, p.conn.clone()),
        })
        .collect();
    merge_same_types(parts)
}

/// `CHAN 'SEG2'`: a line of SEG3 becomes the same line of SEG2, each SEG3
/// cut at its middle node into two SEG2 (every node kept, the line's
/// node order unchanged, as procedures counting nodes along it expect);
/// other elements as `change_to_linear`.
pub fn change_to_seg2(mesh: &Mesh) -> Mesh {
    let parts = mesh
        .parts
        .iter()
        .flat_map(|p| match p.ty {
            ElemType::Seg3 => vec![(ElemType::Seg2, p.elems().flat_map(|e| [e[0], e[1], e[1], e[2]]).collect())],
            _ => change_to_linear(&Mesh::single(p.clone())).parts.into_iter().map(|q| (q.ty, q.conn)).collect(),
        })
        .collect();
    merge_same_types(parts)
}

fn merge_same_types(parts: Vec<(ElemType, Vec<usize>)>) -> Mesh {
    let mut out: Vec<(ElemType, Vec<usize>)> = Vec::new();
    for (ty, conn) in parts {
        match out.iter_mut().find(|(t, _)| *t == ty) {
            Some((_, c)) => c.extend(conn),
            None => out.push((ty, conn)),
        }
    }
    mesh_of(out)
}

/// `MANU type P1 ... Pn`: one element of type `ty` on the given nodes, in
/// the order given (POI1 takes any number of points, one element each).
/// The node count must match the type and an element may not repeat a node.
pub fn manu(nodes: &Nodes, ty: ElemType, pts: &[usize]) -> Result<Mesh, MeshError> {
    for &n in pts {
        check_node("MANU", nodes, n)?;
    }
    if ty == ElemType::Poi1 && !pts.is_empty() {
        return Ok(Mesh::points(pts));
    }
    if pts.len() != ty.nodes() {
        return fail("MANU", format!("a {} element needs {} points, got {}", ty.name(), ty.nodes(), pts.len()));
    }
    let mut seen = HashSet::new();
    if let Some(&n) = pts.iter().find(|&&n| !seen.insert(n)) {
        return fail("MANU", format!("the {} element uses node {n} twice", ty.name()));
    }
    Ok(mesh_of(vec![(ty, pts.to_vec())]))
}
