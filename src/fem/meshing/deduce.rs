//! DEDU 'TRAN': the node-to-node mapping between two meshes of the same
//! topology, by which objects supported on the first are carried onto the
//! second.
//!
//! The meshes correspond part by part, element by element and node by
//! node: node `k` of element `e` of the first is sent to node `k` of
//! element `e` of the second. A node met twice must be sent to the same
//! node both times, else the two meshes do not have the same topology.

use super::{check_nodes, fail, MeshError};
use crate::fem::mesh::{Mesh, Nodes};
use std::collections::HashMap;

pub fn node_map(nodes: &Nodes, from: &Mesh, to: &Mesh) -> Result<HashMap<usize, usize>, MeshError> {
    const OP: &str = "DEDU";
    check_nodes(OP, nodes, from)?;
    check_nodes(OP, nodes, to)?;
    let (pa, pb): (Vec<_>, Vec<_>) =
        (from.parts.iter().filter(|p| !p.is_empty()).collect(), to.parts.iter().filter(|p| !p.is_empty()).collect());
    if pa.len() != pb.len() {
        return fail(OP, format!("the meshes differ: {} parts against {}", pa.len(), pb.len()));
    }
    let mut map = HashMap::new();
    for (k, (a, b)) in pa.iter().zip(&pb).enumerate() {
        if a.ty != b.ty || a.len() != b.len() {
            return fail(
                OP,
                format!(
                    "the meshes differ in part {}: {} {} elements against {} {} elements",
                    k + 1,
                    a.len(),
                    a.ty.name(),
                    b.len(),
                    b.ty.name()
                ),
            );
        }
        for (&x, &y) in a.conn.iter().zip(&b.conn) {
            if *map.entry(x).or_insert(y) != y {
                return fail(
                    OP,
                    format!("node {} of the first mesh has two images: the meshes differ in topology", x + 1),
                );
            }
        }
    }
    Ok(map)
}

/// DEDU's first form, `DEDU MAI2 MAI_ANC MAI_NOU`: the mesh MAI2 moved so
/// that its master nodes MAI_ANC go to MAI_NOU. gibi implements the case
/// where the masters fix an affine map (three points not on a line in 2D,
/// four not in a plane in 3D): every node of MAI2 is sent through that map
/// to a new node, a master node to its given image. The notice leaves how
/// other nodes follow many masters to Cast3M's mesher; that case is
/// refused.
pub fn moved_masters(nodes: &mut Nodes, mesh: &Mesh, old: &Mesh, new: &Mesh, dim: usize) -> Result<Mesh, MeshError> {
    const OP: &str = "DEDU";
    check_nodes(OP, nodes, mesh)?;
    check_nodes(OP, nodes, old)?;
    check_nodes(OP, nodes, new)?;
    let (src, dst) = (old.node_list(), new.node_list());
    if src.len() != dst.len() {
        return fail(OP, format!("{} master nodes but {} images", src.len(), dst.len()));
    }
    let d = dim.clamp(2, 3);
    if src.len() != d + 1 {
        return fail(
            OP,
            format!(
                "moving a mesh by {} master nodes is not implemented: gibi moves it by {} masters fixing an affine map",
                src.len(),
                d + 1
            ),
        );
    }
    let x: Vec<[f64; 3]> = src.iter().map(|&n| nodes.get(n)).collect();
    let y: Vec<[f64; 3]> = dst.iter().map(|&n| nodes.get(n)).collect();
    // Columns of the edge vectors from the first master, before and after.
    let edge = |p: &[[f64; 3]], j: usize, i: usize| p[j + 1][i] - p[0][i];
    let mut e = [[0.0; 3]; 3];
    let mut f = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            e[i][j] = if i < d && j < d {
                edge(&x, j, i)
            } else if i == j {
                1.0
            } else {
                0.0
            };
            f[i][j] = if i < d && j < d {
                edge(&y, j, i)
            } else if i == j {
                1.0
            } else {
                0.0
            };
        }
    }
    let Some(inv) = inverse3(&e) else {
        return fail(OP, "the master nodes do not fix an affine map (they are aligned, or in one plane in 3D)");
    };
    // A = F E⁻¹, x' = y0 + A (x − x0).
    let mut a = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            a[i][j] = (0..3).map(|k| f[i][k] * inv[k][j]).sum();
        }
    }
    let masters: HashMap<usize, usize> = src.iter().copied().zip(dst.iter().copied()).collect();
    let mut image: HashMap<usize, usize> = HashMap::new();
    let mut out = mesh.clone();
    for p in &mut out.parts {
        for n in &mut p.conn {
            let m = match (image.get(n), masters.get(n)) {
                (Some(&m), _) | (None, Some(&m)) => m,
                (None, None) => {
                    let p0 = nodes.get(*n);
                    let mut q = y[0];
                    for i in 0..d {
                        q[i] += (0..d).map(|j| a[i][j] * (p0[j] - x[0][j])).sum::<f64>();
                    }
                    if dim < 3 {
                        q[2] = p0[2];
                    }
                    let density = nodes.density[*n];
                    nodes.push(q, density)
                }
            };
            image.insert(*n, m);
            *n = m;
        }
    }
    Ok(out)
}

/// The inverse of a 3×3 matrix, None when it is singular (relative to its
/// size).
fn inverse3(m: &[[f64; 3]; 3]) -> Option<[[f64; 3]; 3]> {
    let c = |i: usize, j: usize| {
        let (r0, r1) = ((i + 1) % 3, (i + 2) % 3);
        let (c0, c1) = ((j + 1) % 3, (j + 2) % 3);
        m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0]
    };
    let det: f64 = (0..3).map(|j| m[0][j] * c(0, j)).sum();
    let scale = m.iter().flatten().fold(0.0f64, |s, v| s.max(v.abs()));
    if !det.is_finite() || det.abs() <= 1e-12 * scale.powi(3) {
        return None;
    }
    // The adjugate over the determinant: entry (j, i) is cofactor (i, j).
    Some(std::array::from_fn(|j| std::array::from_fn(|i| c(i, j) / det)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fem::mesh::{ElemType, Part};

    #[test]
    fn maps_node_by_node_and_refuses_two_images() {
        let mut nodes = Nodes::default();
        let ids: Vec<usize> = (0..6).map(|k| nodes.push([k as f64, 0.0, 0.0], 1.0)).collect();
        let a = Mesh::single(Part::with(ElemType::Seg2, vec![ids[0], ids[1], ids[1], ids[2]]));
        let b = Mesh::single(Part::with(ElemType::Seg2, vec![ids[3], ids[4], ids[4], ids[5]]));
        let m = node_map(&nodes, &a, &b).unwrap();
        assert_eq!(m[&ids[1]], ids[4]);
        let c = Mesh::single(Part::with(ElemType::Seg2, vec![ids[3], ids[4], ids[5], ids[3]]));
        assert!(node_map(&nodes, &a, &c).is_err());
    }
}
