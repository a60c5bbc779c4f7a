//! QUA8 → TRI6: each quadratic quadrangle cut along its first diagonal
//! (corner 1 to corner 3), as the linear cut of [`super::change_to_triangles`],
//! for the surfaces swept under `OPTI ELEM TRI6`. The diagonal's new
//! mid-side node is the QUA8's centre (its map at ξ = η = 0), so it lies
//! on the curved surface the element describes.

use super::mesh_of;
use crate::fem::mesh::{ElemType, Mesh, Nodes};
use crate::fem::shape::eval;

pub fn qua8_to_tri6(nodes: &mut Nodes, mesh: &Mesh) -> Mesh {
    let centre = eval(ElemType::Qua8, [0.0; 3]).n;
    let parts = mesh
        .parts
        .iter()
        .map(|p| {
            if p.ty != ElemType::Qua8 {
                return (p.ty, p.conn.clone());
            }
            let mut conn = Vec::with_capacity(2 * p.conn.len() * 6 / 8);
            for e in p.elems() {
                let x: [f64; 3] =
                    std::array::from_fn(|c| e.iter().zip(&centre).map(|(&n, w)| w * nodes.get(n)[c]).sum::<f64>());
                let d = [0, 2, 4, 6].iter().map(|&k| nodes.density[e[k]]).sum::<f64>() / 4.0;
                let m = nodes.push(x, d);
                conn.extend([e[0], e[1], e[2], e[3], e[4], m]);
                conn.extend([e[0], m, e[4], e[5], e[6], e[7]]);
            }
            (ElemType::Tri6, conn)
        })
        .collect();
    mesh_of(parts)
}
