//! Questions about meshes: node and element counts, and the POIN forms
//! that pick nodes (`POIN n`, `'INIT'`, `'FINAL'`, `'PROC'`, `'DROIT'`,
//! `'PLAN'`).
//!
//! "Node order" below is always [`Mesh::node_list`]: distinct nodes in order
//! of first appearance in the connectivity, parts in order. For a line built
//! by DROI that is the order along the line.

use super::vec3::{cross, dist, dot, norm, sub, V3};
use super::{check_nodes, fail, MeshError};
use crate::fem::mesh::{ElemType, Mesh, Nodes};

/// `NBNO GEO`: the number of distinct nodes.
pub fn nbno(mesh: &Mesh) -> usize {
    mesh.node_list().len()
}

/// `NBEL GEO`: the number of elements of all types.
pub fn nbel(mesh: &Mesh) -> usize {
    mesh.n_elements()
}

/// `NBEL GEO (MOTS ty)`: the number of elements of one type.
pub fn nbel_of_type(mesh: &Mesh, ty: ElemType) -> usize {
    mesh.parts.iter().filter(|p| p.ty == ty).map(|p| p.len()).sum()
}

/// The nodes of a line mesh in order along it, middle nodes of SEG3
/// included (`P1, m1, n1, ..., mn, Pn`). The line must be a single chain
/// of one element type whose elements follow each other head to tail, as
/// DROI, CERC and `ET` of consecutive lines make them. `op` names the
/// calling operator in error messages.
pub fn line_chain(op: &'static str, mesh: &Mesh) -> Result<Vec<usize>, MeshError> {
    let parts: Vec<_> = mesh.parts.iter().filter(|p| !p.is_empty()).collect();
    let Some(first) = parts.first() else {
        return fail(op, "the line is empty");
    };
    let ty = first.ty;
    if ty.dim() != 1 {
        return fail(op, format!("expected a line (SEG2 or SEG3), got {} elements", ty.name()));
    }
    if let Some(other) = parts.iter().find(|p| p.ty != ty) {
        return fail(op, format!("the line mixes {} and {} elements", ty.name(), other.ty.name()));
    }
    let mut out: Vec<usize> = Vec::new();
    let mut count = 0;
    for e in parts.iter().flat_map(|p| p.elems()) {
        count += 1;
        match out.last() {
            None => out.extend_from_slice(e),
            Some(&end) if end == e[0] => out.extend_from_slice(&e[1..]),
            Some(_) => {
                return fail(
                    op,
                    format!(
                        "the line is not one continuous chain: element {count} does not \
                         start where element {} ends",
                        count - 1
                    ),
                )
            }
        }
    }
    Ok(out)
}

/// `LIG POIN 'INIT'`: the first node of the first element of a line.
pub fn poin_init(line: &Mesh) -> Result<usize, MeshError> {
    line_ends(line).map(|(a, _)| a)
}

/// `LIG POIN 'FINAL'`: the last node of the last element of a line.
pub fn poin_final(line: &Mesh) -> Result<usize, MeshError> {
    line_ends(line).map(|(_, b)| b)
}

fn line_ends(line: &Mesh) -> Result<(usize, usize), MeshError> {
    const OP: &str = "POIN";
    let parts: Vec<_> = line.parts.iter().filter(|p| !p.is_empty()).collect();
    if let Some(p) = parts.iter().find(|p| p.ty.dim() != 1) {
        return fail(OP, format!("'INIT' and 'FINAL' need a line, not {} elements", p.ty.name()));
    }
    match (parts.first(), parts.last()) {
        (Some(f), Some(l)) => Ok((f.elem(0)[0], l.elem(l.len() - 1)[l.ty.nodes() - 1])),
        _ => fail(OP, "the line is empty"),
    }
}

/// The nodes of a mesh as Cast3M lists them when it makes points of it
/// (`CHAN POI1`, `POIN n`): part by part, the first node of every element,
/// then the second node of every element, and so on, each node at its
/// first appearance. For a line this is the start of each element in
/// turn, then (SEG3) the middle nodes, then the end of the last element.
pub fn point_order(mesh: &Mesh) -> Vec<usize> {
    let mut seen = std::collections::HashSet::new();
    let mut out = Vec::new();
    for p in &mesh.parts {
        let k = p.ty.nodes();
        for i in 0..k {
            for e in p.conn.chunks(k) {
                if seen.insert(e[i]) {
                    out.push(e[i]);
                }
            }
        }
    }
    out
}

/// `GEO POIN n`. Of points and lines (Cast3M's case): the first node of
/// element n (1-based, elements counted over the parts in order), or the
/// last node of the last element for n = NBEL + 1; of a POI1 mesh, its
/// n-th point. For a DROI line, SEG2 or SEG3, this is the n-th point along
/// it. Of surfaces and volumes (which Cast3M refuses), the n-th node in
/// node order.
pub fn poin_nth(mesh: &Mesh, n: i64) -> Result<usize, MeshError> {
    if mesh.parts.iter().any(|p| p.ty.dim() > 1) {
        let list = mesh.node_list();
        if n < 1 || n as usize > list.len() {
            return fail("POIN", format!("node number {n} is out of range (the mesh has {} nodes)", list.len()));
        }
        return Ok(list[n as usize - 1]);
    }
    let elems: Vec<(&[usize], ElemType)> = mesh.parts.iter().flat_map(|p| p.elems().map(move |e| (e, p.ty))).collect();
    let count = elems.len();
    let last_end = elems.last().filter(|(_, t)| *t != ElemType::Poi1).map(|(e, _)| e[e.len() - 1]);
    if n >= 1 && (n as usize) <= count {
        return Ok(elems[n as usize - 1].0[0]);
    }
    if let (true, Some(end)) = (n >= 1 && n as usize == count + 1, last_end) {
        return Ok(end);
    }
    let top = count + usize::from(last_end.is_some());
    fail("POIN", format!("point number {n} is out of range (the mesh has {count} elements, so 1 to {top})"))
}

/// `GEO POIN 'PROC' P`: the node of `mesh` nearest to `x`; on a tie, the
/// first in node order.
pub fn poin_proc(nodes: &Nodes, mesh: &Mesh, x: V3) -> Result<usize, MeshError> {
    check_nodes("POIN", nodes, mesh)?;
    let mut best: Option<(f64, usize)> = None;
    for n in mesh.node_list() {
        let d = dist(nodes.get(n), x);
        if best.is_none_or(|(bd, _)| d < bd) {
            best = Some((d, n));
        }
    }
    match best {
        Some((_, n)) => Ok(n),
        None => fail("POIN", "'PROC' in an empty mesh"),
    }
}

/// `GEO POIN 'DROIT' P1 P2 crit`: a POI1 mesh of the nodes of `mesh` at a
/// distance at most `tol` from the infinite line through `a` and `b`, in
/// node order.
pub fn poin_droit(nodes: &Nodes, mesh: &Mesh, a: V3, b: V3, tol: f64) -> Result<Mesh, MeshError> {
    check_nodes("POIN", nodes, mesh)?;
    let ab = sub(b, a);
    let l = norm(ab);
    if l == 0.0 {
        return fail("POIN", "'DROIT': the two points defining the line coincide");
    }
    let keep = |x: V3| norm(cross(ab, sub(x, a))) / l <= tol;
    Ok(select(nodes, mesh, keep))
}

/// `GEO POIN 'PLAN' P1 P2 P3 crit`: a POI1 mesh of the nodes of `mesh` at a
/// distance at most `tol` from the plane through `a`, `b`, `c`, in node
/// order.
pub fn poin_plan(nodes: &Nodes, mesh: &Mesh, a: V3, b: V3, c: V3, tol: f64) -> Result<Mesh, MeshError> {
    check_nodes("POIN", nodes, mesh)?;
    let nrm = cross(sub(b, a), sub(c, a));
    let l = norm(nrm);
    if l == 0.0 {
        return fail("POIN", "'PLAN': the three points defining the plane are aligned");
    }
    let keep = |x: V3| dot(nrm, sub(x, a)).abs() / l <= tol;
    Ok(select(nodes, mesh, keep))
}

pub(super) fn select(nodes: &Nodes, mesh: &Mesh, keep: impl Fn(V3) -> bool) -> Mesh {
    let picked: Vec<usize> = mesh.node_list().into_iter().filter(|&n| keep(nodes.get(n))).collect();
    super::mesh_of(vec![(ElemType::Poi1, picked)])
}
