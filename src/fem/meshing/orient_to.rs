//! `ORIE GEO ('DIRE') VEC` and `ORIE GEO 'POIN' P`: surface elements turned
//! so that their normal points along a vector, or towards the side of a
//! point.

use super::orient::{corners, flip_perm};
use super::vec3::{add, cross, dot, scale, sub, V3};
use super::{check_nodes, fail, MeshError};
use crate::fem::mesh::{Mesh, Nodes, Part};

/// What the normals must face.
#[derive(Debug, Clone, Copy)]
pub enum Towards {
    /// `normal · v > 0`.
    Direction(V3),
    /// `normal · (p - centre of the element) > 0`.
    Point(V3),
}

/// Every surface element (TRI3, TRI6, QUA4, QUA8) whose normal (from its
/// corner order, right-hand rule) faces away is turned over, keeping its
/// first node and its place; other elements are left as they are. An
/// element whose normal is square to the direction is left as it is.
pub fn orie_towards(nodes: &Nodes, mesh: &Mesh, to: Towards) -> Result<Mesh, MeshError> {
    check_nodes("ORIE", nodes, mesh)?;
    let v = match to {
        Towards::Direction(v) | Towards::Point(v) => v,
    };
    if v.iter().any(|c| !c.is_finite()) {
        return fail("ORIE", "the direction or the point has a coordinate that is not finite");
    }
    if let Towards::Direction(d) = to {
        if dot(d, d) == 0.0 {
            return fail("ORIE", "the direction is the zero vector");
        }
    }
    let parts = mesh
        .parts
        .iter()
        .map(|p| {
            if p.ty.dim() != 2 {
                return p.clone();
            }
            let perm = flip_perm(p.ty);
            let mut conn = Vec::with_capacity(p.conn.len());
            for e in p.elems() {
                let x: Vec<V3> = corners(p.ty).iter().map(|&k| nodes.get(e[k])).collect();
                // Newell's normal of the corner polygon, and its centre.
                let mut nrm = [0.0; 3];
                let mut c = [0.0; 3];
                for i in 0..x.len() {
                    nrm = add(nrm, cross(x[i], x[(i + 1) % x.len()]));
                    c = add(c, x[i]);
                }
                let c = scale(c, 1.0 / x.len() as f64);
                let aim = match to {
                    Towards::Direction(d) => d,
                    Towards::Point(q) => sub(q, c),
                };
                if dot(nrm, aim) < 0.0 {
                    conn.extend(perm.iter().map(|&k| e[k]));
                } else {
                    conn.extend_from_slice(e);
                }
            }
            Part { ty: p.ty, conn, colour: p.colour }
        })
        .collect();
    Ok(Mesh { parts })
}
