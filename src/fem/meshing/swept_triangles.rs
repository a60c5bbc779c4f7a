//! Triangles of a line swept by TRAN under `OPTI ELEM TRI3`: each
//! quadrangle of the swept strip is cut along a diagonal that alternates
//! from one segment of the line to the next (the first segment's cut
//! joins its first node to the second node of the next layer), the same
//! in every layer. Cast3M's own thin-shell test decks (pinched cylinders
//! meshed this way) reproduce their reference deflections only with this
//! pattern, not with one diagonal everywhere.

use crate::fem::mesh::{ElemType, Mesh, Part};

/// The swept quadrangles `swept` (one QUA4 part, layer by layer, each
/// layer the segments of the line in order, as `sweep::tran` lists them)
/// cut into TRI3; `segments` is the count of segments of the line. None
/// when the mesh is not of that shape.
pub fn alternate(swept: &Mesh, segments: usize) -> Option<Mesh> {
    let [p] = swept.parts.as_slice() else { return None };
    if p.ty != ElemType::Qua4 || segments == 0 || p.len() % segments != 0 {
        return None;
    }
    let conn = p
        .elems()
        .enumerate()
        .flat_map(|(q, e)| {
            if (q % segments) % 2 == 0 {
                [e[0], e[1], e[2], e[0], e[2], e[3]]
            } else {
                [e[0], e[1], e[3], e[1], e[2], e[3]]
            }
        })
        .collect();
    Some(Mesh::single(Part { ty: ElemType::Tri3, conn, ..p.clone() }))
}
