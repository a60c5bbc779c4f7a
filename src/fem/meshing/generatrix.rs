//! GENERATRICE: the surface swept by a line moved parallel to itself along
//! a second line (the generatrix).
//!
//! Layer `j` is the first line translated by `Q_j - Q_0`, where `Q_0..Q_m`
//! are the nodes of the second line in order; layer 0 is the first line
//! itself. When the first line passes through `Q_0`, that node's copies are
//! the generatrix's own nodes, so the two lines stay edges of the surface.
//! Elements come strip by strip (between layers `j` and `j + 1`), each
//! strip in the order of the first line's elements; a SEG2 `(a, b)` gives
//! the QUA4 `(a_j, b_j, b_j+1, a_j+1)`, as TRAN makes them.

use super::query::line_chain;
use super::{check_nodes, fail, mesh_of, MeshError};
use crate::fem::mesh::{ElemType, Mesh, Nodes};
use std::collections::HashMap;

pub fn generatrix(nodes: &mut Nodes, line: &Mesh, along: &Mesh) -> Result<Mesh, MeshError> {
    const OP: &str = "GENE";
    check_nodes(OP, nodes, line)?;
    check_nodes(OP, nodes, along)?;
    if let Some(p) = line.parts.iter().chain(&along.parts).find(|p| !p.is_empty() && p.ty != ElemType::Seg2) {
        return fail(OP, format!("both lines must be made of SEG2 elements, got {} elements", p.ty.name()));
    }
    let path = line_chain(OP, along)?;
    let base = line.node_list();
    if base.is_empty() {
        return fail(OP, "the line to move is empty");
    }
    let q0 = nodes.get(path[0]);
    let index: HashMap<usize, usize> = base.iter().enumerate().map(|(k, &n)| (n, k)).collect();
    let mut layers: Vec<Vec<usize>> = vec![base.clone()];
    for &q in &path[1..] {
        let shift = {
            let x = nodes.get(q);
            [x[0] - q0[0], x[1] - q0[1], x[2] - q0[2]]
        };
        let layer = base
            .iter()
            .map(|&n| {
                if n == path[0] {
                    q
                } else {
                    let x = nodes.get(n);
                    nodes.push([x[0] + shift[0], x[1] + shift[1], x[2] + shift[2]], nodes.density[n])
                }
            })
            .collect();
        layers.push(layer);
    }
    let mut conn = Vec::new();
    for j in 0..layers.len() - 1 {
        for p in &line.parts {
            for e in p.elems() {
                let (a, b) = (index[&e[0]], index[&e[1]]);
                conn.extend([layers[j][a], layers[j][b], layers[j + 1][b], layers[j + 1][a]]);
            }
        }
    }
    Ok(mesh_of(vec![(ElemType::Qua4, conn)]))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fem::mesh::Part;

    #[test]
    fn a_line_moved_along_another_makes_a_grid() {
        let mut nodes = Nodes::default();
        let a: Vec<usize> = [0.0, 1.0, 3.0].iter().map(|&x| nodes.push([x, 0.0, 0.0], 1.0)).collect();
        let line = Mesh::single(Part::with(ElemType::Seg2, vec![a[0], a[1], a[1], a[2]]));
        let q1 = nodes.push([0.0, 2.0, 0.0], 1.0);
        let along = Mesh::single(Part::with(ElemType::Seg2, vec![a[0], q1]));
        let s = generatrix(&mut nodes, &line, &along).unwrap();
        assert_eq!(s.n_elements(), 2);
        let e = s.parts[0].elem(1);
        assert_eq!(nodes.get(e[2]), [3.0, 2.0, 0.0]);
        assert_eq!(s.parts[0].elem(0)[3], q1);
    }
}
