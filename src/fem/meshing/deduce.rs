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
