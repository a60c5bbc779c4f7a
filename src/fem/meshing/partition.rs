//! PART: a mesh split into disjoint sub-meshes whose union is the mesh.
//!
//! * Arlequin pattern: element `k` (counted over the parts in order) goes
//!   to zone `k mod n`, so neighbouring elements of a row land in
//!   different zones; there are `min(n, elements)` zones, none empty.
//! * Connected components: elements sharing a node are in the same zone;
//!   zones come in the order of their first element.
//!
//! Inside a zone, elements keep their order and their type's part.

use super::partition_more::{elements, root, zones};
use crate::fem::mesh::{Mesh, Part};

/// Split `mesh` into `n >= 1` zones, element `k` to zone `k mod n`.
pub fn arlequin(mesh: &Mesh, n: usize) -> Vec<Mesh> {
    let total = mesh.n_elements();
    let zones = n.min(total).max(1);
    let mut out: Vec<Mesh> = vec![Mesh::default(); zones];
    let mut k = 0;
    for p in &mesh.parts {
        let mut pieces: Vec<Vec<usize>> = vec![Vec::new(); zones];
        for e in p.elems() {
            pieces[k % zones].extend_from_slice(e);
            k += 1;
        }
        for (z, conn) in pieces.into_iter().enumerate() {
            if !conn.is_empty() {
                out[z].parts.push(Part { conn, ..p.clone() });
            }
        }
    }
    out
}

/// The connected components of `mesh` (elements joined by shared nodes).
pub fn connected(mesh: &Mesh) -> Vec<Mesh> {
    let elems = elements(mesh);
    // Union-find over elements, joined through the first element met at
    // each node.
    let mut parent: Vec<usize> = (0..elems.len()).collect();
    let mut first_at: std::collections::HashMap<usize, usize> = std::collections::HashMap::new();
    for (k, (_, e)) in elems.iter().enumerate() {
        for &n in e.iter() {
            let other = *first_at.entry(n).or_insert(k);
            let (a, b) = (root(&mut parent, k), root(&mut parent, other));
            if a != b {
                parent[a.max(b)] = a.min(b);
            }
        }
    }
    let label: Vec<usize> = (0..elems.len()).map(|k| root(&mut parent, k)).collect();
    zones(mesh, &elems, &label)
}
