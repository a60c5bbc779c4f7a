//! ORDO on a mesh: points by growing distance to the first one, a line
//! (SEG2, SEG3) as one walk from one end to the other with every element
//! turned the way of the walk, other elements by vicinity (breadth first
//! over elements sharing a node). Procedures rely on the line form to read
//! a crack lip or a contour in order.

use super::{check_nodes, fail, MeshError};
use crate::fem::mesh::{ElemType, Mesh, Nodes, Part};
use std::collections::{HashMap, VecDeque};

pub fn ordo(nodes: &Nodes, mesh: &Mesh) -> Result<Mesh, MeshError> {
    check_nodes("ORDO", nodes, mesh)?;
    let Some(first) = mesh.parts.first() else { return Ok(mesh.clone()) };
    if mesh.parts.len() > 1 && mesh.parts.iter().any(|p| p.ty != first.ty) {
        return fail("ORDO", "the mesh mixes element types: order each type apart");
    }
    // One part of the type (a union of colours is one mesh to order).
    let mut conn = Vec::new();
    for p in &mesh.parts {
        conn.extend_from_slice(&p.conn);
    }
    let part = Part { conn, ..first.clone() };
    let ordered = match part.ty {
        ElemType::Poi1 => by_distance(nodes, &part),
        ElemType::Seg2 | ElemType::Seg3 => as_walk(&part)?,
        _ => by_vicinity(&part),
    };
    Ok(Mesh::single(ordered))
}

fn by_distance(nodes: &Nodes, part: &Part) -> Part {
    let x0 = nodes.get(part.conn[0]);
    let d = |n: usize| {
        let x = nodes.get(n);
        (0..3).map(|k| (x[k] - x0[k]).powi(2)).sum::<f64>()
    };
    let mut conn = part.conn.clone();
    conn.sort_by(|&a, &b| d(a).total_cmp(&d(b)));
    Part { conn, ..part.clone() }
}

/// Elements of a line chained end to end. The walk starts at an end (a
/// node met by one element), or where the first element starts when the
/// line is closed; a branching or broken line is refused.
fn as_walk(part: &Part) -> Result<Part, MeshError> {
    let k = part.ty.nodes();
    // SEG3 is (end, middle, end): the ends are the first and last nodes.
    let ends = |e: usize| (part.conn[e * k], part.conn[e * k + k - 1]);
    let mut at: HashMap<usize, Vec<usize>> = HashMap::new();
    for e in 0..part.len() {
        let (a, b) = ends(e);
        at.entry(a).or_default().push(e);
        at.entry(b).or_default().push(e);
    }
    if at.values().any(|v| v.len() > 2) {
        return fail("ORDO", "the line branches: a node ends more than two elements");
    }
    let mut start = ends(0).0;
    if let Some((&n, _)) = at.iter().filter(|(_, v)| v.len() == 1).min_by_key(|(_, v)| v[0]) {
        start = n;
    }
    let mut used = vec![false; part.len()];
    let mut conn = Vec::with_capacity(part.conn.len());
    let mut node = start;
    while let Some(&e) = at.get(&node).and_then(|v| v.iter().find(|&&e| !used[e])) {
        used[e] = true;
        let el = part.elem(e);
        let (a, b) = ends(e);
        if a == node {
            conn.extend_from_slice(el);
            node = b;
        } else {
            // Turned: read backwards (a middle node stays in the middle).
            conn.extend(el.iter().rev());
            node = a;
        }
    }
    if used.iter().any(|u| !u) {
        return fail("ORDO", "the line is in several pieces: it cannot be walked from one end to the other");
    }
    Ok(Part { conn, ..part.clone() })
}

fn by_vicinity(part: &Part) -> Part {
    let mut at: HashMap<usize, Vec<usize>> = HashMap::new();
    for (e, el) in part.elems().enumerate() {
        for &n in el {
            at.entry(n).or_default().push(e);
        }
    }
    let mut seen = vec![false; part.len()];
    let mut conn = Vec::with_capacity(part.conn.len());
    for root in 0..part.len() {
        if seen[root] {
            continue;
        }
        seen[root] = true;
        let mut queue = VecDeque::from([root]);
        while let Some(e) = queue.pop_front() {
            let el = part.elem(e);
            conn.extend_from_slice(el);
            for n in el {
                for &f in &at[n] {
                    if !seen[f] {
                        seen[f] = true;
                        queue.push_back(f);
                    }
                }
            }
        }
    }
    Part { conn, ..part.clone() }
}
