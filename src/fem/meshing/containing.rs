//! `GEO ELEM 'CONTENANT' P ('TOUS')`: the elements of a mesh that contain
//! a point. A point on a face, an edge or a node is in every element that
//! shares it (the reference coordinates are tested with `locate`'s
//! tolerance), so 'TOUS' gives all of them; without it, the first in the
//! mesh's element order.

use crate::fem::locate::locate;
use crate::fem::mesh::{ElemType, Mesh, Nodes, Part};

/// The elements of `mesh` containing node `p`, each part keeping its type
/// and colour; only the first one found unless `all`.
pub fn containing(mesh: &Mesh, nodes: &Nodes, p: usize, all: bool) -> Mesh {
    let x = nodes.get(p);
    let mut parts = Vec::new();
    for part in &mesh.parts {
        let mut conn = Vec::new();
        for e in part.elems() {
            if contains(part.ty, e, nodes, p, x) {
                conn.extend_from_slice(e);
                if !all {
                    parts.push(Part { ty: part.ty, conn, colour: part.colour });
                    return Mesh { parts };
                }
            }
        }
        if !conn.is_empty() {
            parts.push(Part { ty: part.ty, conn, colour: part.colour });
        }
    }
    Mesh { parts }
}

fn contains(ty: ElemType, e: &[usize], nodes: &Nodes, p: usize, x: [f64; 3]) -> bool {
    // One of its nodes: no geometry needed (and a POI1 has no other test).
    if e.contains(&p) {
        return true;
    }
    if ty.dim() == 0 {
        return e.iter().any(|&n| nodes.get(n) == x);
    }
    let xs: Vec<[f64; 3]> = e.iter().map(|&n| nodes.get(n)).collect();
    locate(ty, &xs, x).is_some()
}
