//! `ORDO GEO` (ordo.notice): a mesh put in order. The elements of a line
//! follow each other from one end to the other (each turned to start where
//! the previous one ends); points are ordered by growing distance to the
//! first of them.

use super::vec3::dist;
use super::{fail, MeshError};
use crate::fem::mesh::{ElemType, Mesh, Nodes, Part};
use std::collections::HashMap;

/// The mesh in order. Lines (one element type, SEG2 or SEG3) become chains
/// starting at an end: the first node met, in element order, that only one
/// element touches (any node of a closed loop otherwise); a line in several
/// pieces gives its pieces one after the other. Surfaces and volumes are
/// refused: gibi does not reorder them by vicinity.
pub fn order(nodes: &Nodes, mesh: &Mesh) -> Result<Mesh, MeshError> {
    let parts: Vec<&Part> = mesh.parts.iter().filter(|p| !p.is_empty()).collect();
    let Some(first) = parts.first() else { return Ok(mesh.clone()) };
    let ty = first.ty;
    if parts.iter().any(|p| p.ty != ty) {
        return fail("ORDO", "the mesh mixes element types: ORDO orders points or a line of one element type");
    }
    match ty {
        ElemType::Poi1 => {
            let pts: Vec<usize> = parts.iter().flat_map(|p| p.conn.iter().copied()).collect();
            let x0 = nodes.get(pts[0]);
            let mut sorted = pts.clone();
            // Stable: points at the same distance keep their order.
            sorted.sort_by(|&p, &q| dist(nodes.get(p), x0).total_cmp(&dist(nodes.get(q), x0)));
            Ok(Mesh::single(Part { ty, conn: sorted, colour: first.colour }))
        }
        t if t.dim() == 1 => Ok(Mesh::single(Part { ty, conn: chain(&parts), colour: first.colour })),
        t => {
            fail("ORDO", format!("ordering {} elements by vicinity is not available (points and lines are)", t.name()))
        }
    }
}

/// Elements of a line chained head to tail, turned where needed.
fn chain(parts: &[&Part]) -> Vec<usize> {
    let elems: Vec<&[usize]> = parts.iter().flat_map(|p| p.elems()).collect();
    let ends = |e: &[usize]| (e[0], e[e.len() - 1]);
    let mut at: HashMap<usize, Vec<usize>> = HashMap::new();
    for (i, e) in elems.iter().enumerate() {
        let (a, b) = ends(e);
        at.entry(a).or_default().push(i);
        at.entry(b).or_default().push(i);
    }
    let mut used = vec![false; elems.len()];
    let mut out = Vec::with_capacity(elems.iter().map(|e| e.len()).sum());
    while let Some(start_elem) = (0..elems.len()).find(|&i| !used[i]) {
        // Prefer a free end (a node of one unused element) to start from.
        let free = |n: usize| at[&n].iter().filter(|&&j| !used[j]).count() == 1;
        let start = elems
            .iter()
            .enumerate()
            .filter(|(i, _)| !used[*i])
            .flat_map(|(_, e)| [e[0], e[e.len() - 1]])
            .find(|&n| free(n))
            .unwrap_or(ends(elems[start_elem]).0);
        let mut here = start;
        while let Some(&j) = at[&here].iter().find(|&&j| !used[j]) {
            used[j] = true;
            let e = elems[j];
            if e[0] == here {
                out.extend_from_slice(e);
                here = e[e.len() - 1];
            } else {
                out.extend(e.iter().rev());
                here = e[0];
            }
        }
    }
    out
}
