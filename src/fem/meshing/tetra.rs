//! CHAN 'TET4': volume elements cut into tetrahedra.
//!
//! * CUB8 into six TET4 around its diagonal from node 1 to node 7 (the
//!   Kuhn cut): every face is cut along its diagonal through node 1 or
//!   node 7 (local corners `(0,0,0)` and `(1,1,1)`), so two hexahedra of a grid made by TRAN/VOLU (same local frame) cut their
//!   common face the same way and the tetrahedra are conforming.
//! * PRI6 into three, PYR5 into two (across the base diagonal from node 1
//!   to node 3); TET4 are kept.
//!
//! Each tetrahedron turns like the element it comes from (its volume has
//! the sign of the element's), so a mesh of positive elements gives
//! positive tetrahedra. Tetrahedra come element by element, in order.

use super::vec3::{cross, dot, sub};
use super::{check_nodes, fail, mesh_of, MeshError};
use crate::fem::mesh::{ElemType, Mesh, Nodes};

/// The six Kuhn paths from local node 0 to local node 6 of a CUB8 (Cast3M
/// order: bottom face 0 1 2 3, node k + 4 above node k).
const CUB8: [[usize; 4]; 6] = [[0, 1, 2, 6], [0, 1, 5, 6], [0, 3, 2, 6], [0, 3, 7, 6], [0, 4, 5, 6], [0, 4, 7, 6]];
const PRI6: [[usize; 4]; 3] = [[0, 1, 2, 3], [1, 2, 3, 4], [2, 3, 4, 5]];
const TET4: [[usize; 4]; 1] = [[0, 1, 2, 3]];
const PYR5: [[usize; 4]; 2] = [[0, 1, 2, 4], [0, 2, 3, 4]];

/// The triple product of the edges from `a` to `b`, `c`, `d`.
fn volume6(nodes: &Nodes, a: usize, b: usize, c: usize, d: usize) -> f64 {
    let o = nodes.get(a);
    dot(sub(nodes.get(b), o), cross(sub(nodes.get(c), o), sub(nodes.get(d), o)))
}

/// `CHAN 'TET4' mesh`.
pub fn to_tet4(nodes: &Nodes, mesh: &Mesh) -> Result<Mesh, MeshError> {
    check_nodes("CHAN", nodes, mesh)?;
    let mut conn = Vec::new();
    for p in mesh.parts.iter().filter(|p| !p.is_empty()) {
        // The element's own orientation: its corner at local node 0 and the
        // three edges from there, as in the reference element.
        let (cut, corner): (&[[usize; 4]], [usize; 4]) = match p.ty {
            ElemType::Cub8 => (&CUB8, [0, 1, 3, 4]),
            ElemType::Pri6 => (&PRI6, [0, 1, 2, 3]),
            ElemType::Tet4 => (&TET4, [0, 1, 2, 3]),
            ElemType::Pyr5 => (&PYR5, [0, 1, 3, 4]),
            other => {
                return fail(
                    "CHAN",
                    format!("'TET4' cuts CUB8, PRI6, PYR5 and TET4 elements into tetrahedra, not {}", other.name()),
                )
            }
        };
        for e in p.elems() {
            let sign = volume6(nodes, e[corner[0]], e[corner[1]], e[corner[2]], e[corner[3]]);
            for t in cut {
                let mut t = t.map(|k| e[k]);
                if volume6(nodes, t[0], t[1], t[2], t[3]) * sign < 0.0 {
                    t.swap(2, 3);
                }
                conn.extend(t);
            }
        }
    }
    Ok(mesh_of(vec![(ElemType::Tet4, conn)]))
}
