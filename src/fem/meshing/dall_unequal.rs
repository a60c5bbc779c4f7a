//! DALL with opposite sides of different element counts.
//!
//! No structured grid fits such a contour, so the inside is meshed freely
//! (the mesher of SURF, [`super::surf`]) with the contour's own nodes kept:
//! quadrangles paired from the triangles under QUA4 (a few triangles may
//! remain where the pairing cannot close), triangles under TRI3. Elements
//! turn like the contour, as DALL's do. Cast3M asks for an even total
//! number of contour points, the condition for an all-quadrangle mesh;
//! the free mesher does not need it, so it is not checked.

use super::surf::{surf, SurfOptions};
use super::{mesh_of, MeshError};
use crate::fem::mesh::{ElemType, Mesh, Nodes};

/// Planarity criterion of the free mesher (SURF's default): DALL sides of
/// unequal counts must lie in a plane.
const PLANE_CRIT: f64 = 1e-2;

/// `chains` are the four sides head to tail (side `k` ends where side
/// `k + 1` starts), as node chains (corners and middle nodes alternating
/// for the quadratic types QUA8 and TRI6).
pub fn dall_unequal(nodes: &mut Nodes, chains: &[Vec<usize>], ty: ElemType) -> Result<Mesh, MeshError> {
    let contour = if matches!(ty, ElemType::Qua8 | ElemType::Tri6) {
        let conn = chains.iter().flat_map(|c| c.windows(3).step_by(2).flat_map(|w| [w[0], w[1], w[2]]));
        mesh_of(vec![(ElemType::Seg3, conn.collect())])
    } else {
        let conn = chains.iter().flat_map(|c| c.windows(2).flat_map(|w| [w[0], w[1]]));
        mesh_of(vec![(ElemType::Seg2, conn.collect())])
    };
    let o = SurfOptions { space_dim: 3, crit: PLANE_CRIT, ..Default::default() };
    surf(nodes, &contour, ty, &o).map_err(|e| {
        MeshError::new(
            "DALL",
            format!("opposite sides have different element counts, so the contour is meshed freely: {}", e.message),
        )
    })
}
