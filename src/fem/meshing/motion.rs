//! Rigid and affine motions of nodes, applied in place (the DEPLACER
//! directive) or to copies of several objects at once (`a b = a b PLUS v`,
//! `p q = p q TOUR ...`), where nodes shared by the objects are copied once
//! so the copies stay connected as the originals were.

use super::symmetry::Mirror;
use super::transform::PointMap;
use super::vec3::{add, norm, rotate, scale, sub, V3};
use super::{check_nodes, fail, MeshError, NodeMap};
use crate::fem::mesh::{Mesh, Nodes};
use std::collections::HashMap;

/// How every point moves.
#[derive(Debug, Clone, Copy)]
pub enum Motion {
    Translate(V3),
    /// Angle in degrees about `centre` (2D: about z) or about the axis
    /// `centre` -> `axis_end` (3D, right-hand rule).
    Rotate {
        angle_deg: f64,
        centre: V3,
        axis_end: Option<V3>,
    },
    /// HOMO, AFFI, PROJ.
    Map(PointMap),
    Mirror(Mirror),
}

impl Motion {
    /// Check the motion once (a rotation axis with two equal points, a non
    /// finite number) so that [`image`](Self::image) cannot fail on it.
    fn checked(self, op: &'static str, dim: usize) -> Result<Motion, MeshError> {
        match self {
            Motion::Translate(v) if v.iter().any(|c| !c.is_finite()) => fail(op, "the vector is not finite"),
            Motion::Rotate { angle_deg, centre, axis_end } => {
                if !angle_deg.is_finite() {
                    return fail(op, "the angle is not finite");
                }
                if let Some(p2) = axis_end {
                    if norm(sub(p2, centre)) == 0.0 {
                        return fail(op, "the two points of the axis coincide");
                    }
                }
                Ok(self)
            }
            Motion::Mirror(m) => {
                m.check(dim)?;
                Ok(self)
            }
            Motion::Map(PointMap::Homothety { ratio, .. } | PointMap::Affinity { ratio, .. }) if !ratio.is_finite() => {
                fail(op, "the ratio is not a finite number")
            }
            _ => Ok(self),
        }
    }

    pub fn image(&self, x: V3) -> Result<V3, MeshError> {
        Ok(match *self {
            Motion::Translate(v) => add(x, v),
            Motion::Rotate { angle_deg, centre, axis_end } => {
                let k = match axis_end {
                    None => [0.0, 0.0, 1.0],
                    Some(p2) => {
                        let a = sub(p2, centre);
                        scale(a, 1.0 / norm(a))
                    }
                };
                rotate(x, centre, k, angle_deg.to_radians())
            }
            Motion::Map(m) => m.image(x)?,
            Motion::Mirror(m) => m.image(x),
        })
    }
}

/// DEPLACER: move every node of `meshes` (each once) to its image. Every
/// object holding those nodes sees them moved; no node is created.
pub fn move_in_place(nodes: &mut Nodes, meshes: &[&Mesh], motion: Motion, dim: usize) -> Result<(), MeshError> {
    let motion = motion.checked("DEPL", dim)?;
    let mut list = Vec::new();
    for m in meshes {
        check_nodes("DEPL", nodes, m)?;
        list.extend(m.node_list());
    }
    list.sort_unstable();
    list.dedup();
    // Images first, so that a failing projection leaves the mesh as it was.
    let moved: Vec<V3> = list.iter().map(|&n| motion.image(nodes.get(n))).collect::<Result<_, _>>()?;
    for (n, x) in list.into_iter().zip(moved) {
        nodes.coords[n] = x;
    }
    Ok(())
}

/// Copies of several meshes moved together: each node met is copied once
/// (in the order of the meshes and of their node lists) with its density,
/// and every copy is the original's elements on the copied nodes.
/// Orientation is kept (rotations and translations; a mirror is SYME's
/// business).
pub fn copy_together(nodes: &mut Nodes, meshes: &[&Mesh], motion: Motion, dim: usize) -> Result<Vec<Mesh>, MeshError> {
    let motion = motion.checked("PLUS", dim)?;
    let mut map: HashMap<usize, usize> = HashMap::new();
    for m in meshes {
        check_nodes("PLUS", nodes, m)?;
        for n in m.node_list() {
            if let std::collections::hash_map::Entry::Vacant(e) = map.entry(n) {
                let x = motion.image(nodes.get(n))?;
                e.insert(nodes.push(x, nodes.density[n]));
            }
        }
    }
    let nm = NodeMap { map };
    Ok(meshes.iter().map(|m| nm.apply(m)).collect())
}

/// Move nodes by a displacement: each `(node, axis, value)` adds `value`
/// to one coordinate (FORME). Checked first, so a bad node moves nothing.
pub fn displace(nodes: &mut Nodes, moves: &[(usize, usize, f64)]) -> Result<(), MeshError> {
    if let Some(&(n, _, _)) = moves.iter().find(|&&(n, k, _)| n >= nodes.len() || k > 2) {
        return fail("FORM", format!("node {n} of the displacement field does not exist"));
    }
    for &(n, k, v) in moves {
        nodes.coords[n][k] += v;
    }
    Ok(())
}

/// Put recorded coordinates back (FORME with a CONFIGURATION). Nodes made
/// after the recording keep where they are: the record knows nothing of them.
pub fn restore(nodes: &mut Nodes, coords: &[[f64; 3]]) {
    let n = coords.len().min(nodes.len());
    nodes.coords[..n].copy_from_slice(&coords[..n]);
}
