//! QUELCONQUE: a broken line through given points, in their order.

use super::{check_node, fail, mesh_of, MeshError};
use crate::fem::mesh::{ElemType, Mesh, Nodes};

/// `QUEL 'SEG2'|'SEG3' P1 P2 ... Pn`: SEG2 join consecutive points; SEG3
/// take them three by three, `(P1 P2 P3) (P3 P4 P5) ...`, the middle one
/// being the middle node, so `n` must be odd. A point may come back (a
/// closed line ends on its first point).
pub fn quel(nodes: &Nodes, pts: &[usize], ty: ElemType) -> Result<Mesh, MeshError> {
    const OP: &str = "QUEL";
    for &p in pts {
        check_node(OP, nodes, p)?;
    }
    let step = match ty {
        ElemType::Seg2 => 1,
        ElemType::Seg3 => 2,
        other => return fail(OP, format!("makes SEG2 or SEG3 lines, not {}", other.name())),
    };
    if pts.len() < step + 1 || !(pts.len() - 1).is_multiple_of(step) {
        return fail(
            OP,
            match step {
                1 => format!("a line needs at least 2 points, got {}", pts.len()),
                _ => format!("SEG3 elements need an odd number of points, at least 3 (got {})", pts.len()),
            },
        );
    }
    let mut conn = Vec::new();
    for k in (0..pts.len() - 1).step_by(step) {
        let e = &pts[k..=k + step];
        if e.windows(2).any(|w| w[0] == w[1]) || e[0] == e[step] {
            return fail(OP, format!("element {} would join node {} to itself", k / step + 1, e[0] + 1));
        }
        conn.extend_from_slice(e);
    }
    Ok(mesh_of(vec![(ty, conn)]))
}
