//! Cast3M's meshing operators as language-free algorithms.
//!
//! Every generator works on the global node table ([`Nodes`]) and returns a
//! [`Mesh`] of node numbers, exactly as Cast3M does: a POINT is a node, new
//! nodes are appended to the table, and meshes that share a point share the
//! node. Decks depend on *which* node and element come first (`POIN n`,
//! `COTE n`, `EXTR ... n`), so each function documents its ordering. The
//! common conventions are:
//!
//! * lines are ordered chains: element `i` ends where element `i + 1` starts;
//!   SEG3 elements are `(end, middle, end)`;
//! * TRI6 and QUA8 interleave corners and mid-side nodes, as Cast3M does:
//!   `(c1, m12, c2, m23, c3, m31)` and `(c1, m12, c2, m23, c3, m34, c4, m41)`;
//! * CUB8 and PRI6 list the bottom face then the top face, with node `k + 4`
//!   (resp. `k + 3`) above node `k`;
//! * density grading follows one rule, described in [`grading`].
//!
//! Errors never panic: they come back as a [`MeshError`] whose message names
//! the operator and says what is wrong with the input.

pub mod arcs;
pub mod between;
pub mod cont_order;
pub mod containing;
pub mod contour;
pub mod cote_swept;
pub mod couture;
pub mod dall;
pub mod dall_support;
pub mod dall_unequal;
pub mod deduce;
pub mod delaunay;
pub mod edges;
pub mod edit;
pub mod extract;
pub mod free;
pub mod generatrix;
pub mod grading;
pub mod grid;
pub mod inclusion;
pub mod isovalue;
pub mod joints;
pub mod line;
pub mod motion;
pub mod order;
pub mod orient;
pub mod orient_check;
pub mod orient_to;
pub mod pairing;
pub mod partition;
pub mod partition_more;
pub mod points;
pub mod polyline;
pub mod query;
pub mod refine;
pub mod regenerate;
pub mod select;
pub mod surf;
pub mod surf_sphere;
pub mod surface_cut;
pub mod sweep;
pub mod symmetry;
pub mod tet_delaunay;
pub mod tet_fill;
pub mod tet_pyramids;
pub mod tet_recover;
pub mod tet_steiner;
pub mod tetra;
pub mod transform;
pub mod tri6_split;
pub mod tria_sized;
pub(crate) mod vec3;
pub mod verify;
pub mod voronoi;
pub mod voronoi_3d;
pub mod winding;

#[cfg(test)]
mod tests;

pub use dall::dall;
pub use edit::{
    change_to_linear, change_to_poi1, change_to_quadratic, change_to_seg2, change_to_triangles, diff, elim,
    elim_between, inte, inve, manu, rotate_copy, rotate_point, translate_copy, NodeMap,
};
pub use extract::{cont, cote, elem_appui, elem_numbers, elem_type, face};
pub use grading::Spacing;
pub use line::{cerc, droi, droi_extend, line_type};
pub use orient::orie;
pub use query::{
    line_chain, nbel, nbel_of_type, nbno, poin_droit, poin_final, poin_init, poin_nth, poin_plan, poin_proc,
};
pub use sweep::{rota, tran, volu};
pub use symmetry::{syme, syme_together, Mirror};
pub use transform::{barycentre, map_copy, map_point, PointMap, Target};

use crate::fem::mesh::{ElemType, Mesh, Nodes, Part};

/// A meshing operator refused its input. `op` is the Cast3M operator name,
/// so the message reads like "DALL: side 3 has 4 elements but side 1 has 2".
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{op}: {message}")]
pub struct MeshError {
    pub op: &'static str,
    pub message: String,
}

impl MeshError {
    pub fn new(op: &'static str, message: impl Into<String>) -> Self {
        MeshError { op, message: message.into() }
    }
}

/// Shorthand for the error path of every operator.
pub(crate) fn fail<T>(op: &'static str, message: impl Into<String>) -> Result<T, MeshError> {
    Err(MeshError::new(op, message))
}

/// Check that every node number of `mesh` exists in `nodes`, so that the
/// algorithms below can index the table without panicking on a stale mesh.
pub(crate) fn check_nodes(op: &'static str, nodes: &Nodes, mesh: &Mesh) -> Result<(), MeshError> {
    for p in &mesh.parts {
        if p.conn.len() % p.ty.nodes() != 0 {
            return fail(op, format!("a {} part has a truncated connectivity", p.ty.name()));
        }
        if let Some(&bad) = p.conn.iter().find(|&&n| n >= nodes.len()) {
            return fail(op, format!("node {bad} does not exist (the table has {} nodes)", nodes.len()));
        }
    }
    Ok(())
}

/// Check a single node number.
pub(crate) fn check_node(op: &'static str, nodes: &Nodes, n: usize) -> Result<(), MeshError> {
    if n >= nodes.len() {
        return fail(op, format!("node {n} does not exist (the table has {} nodes)", nodes.len()));
    }
    Ok(())
}

/// Build a mesh from `(type, connectivity)` pairs, dropping empty parts and
/// keeping the order given.
pub(crate) fn mesh_of(parts: Vec<(ElemType, Vec<usize>)>) -> Mesh {
    Mesh { parts: parts.into_iter().filter(|(_, c)| !c.is_empty()).map(|(ty, conn)| Part::with(ty, conn)).collect() }
}
