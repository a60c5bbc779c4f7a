//! RACC and LIAI: joint elements between two facing meshes. Each element
//! of the first mesh whose nodes all lie within the criterion of the
//! nodes of one element of the second mesh gives one joint element: its
//! own nodes (side 1), then the matching nodes of side 2 in the same
//! order. Side 1's order therefore sets the joint's local frame, whichever
//! way side 2 runs.

use super::{fail, MeshError};
use crate::fem::mesh::{ElemType, Mesh, Nodes, Part};

/// The joint geometry built on elements of type `face`.
fn joint_of(face: ElemType) -> Option<ElemType> {
    ElemType::ALL.into_iter().find(|t| t.joint_face() == Some(face))
}

/// Joint elements between `a` (side 1) and `b` (side 2). `lines` says
/// which operator is meshing: RACC (lines) or LIAI (surfaces).
pub fn joints(op: &'static str, nodes: &Nodes, a: &Mesh, b: &Mesh, crit: f64, lines: bool) -> Result<Mesh, MeshError> {
    if crit.is_nan() || crit < 0.0 || !crit.is_finite() {
        return fail(op, format!("the distance criterion must be a finite positive number, not {}", crit));
    }
    let d2 = |p: usize, q: usize| {
        let (x, y) = (nodes.get(p), nodes.get(q));
        (0..3).map(|c| (x[c] - y[c]).powi(2)).sum::<f64>()
    };
    let mut out = Mesh::default();
    for pa in a.parts.iter().filter(|p| !p.is_empty()) {
        let joint = joint_of(pa.ty).filter(|j| (j.dim() == 1) == lines).ok_or_else(|| {
            let want = if lines { "lines of SEG2 or SEG3" } else { "surfaces of TRI3 or QUA4" };
            MeshError::new(op, format!("joins {}, not {} elements", want, pa.ty.name()))
        })?;
        let mut conn = Vec::new();
        for e1 in pa.elems() {
            let found = b.parts.iter().filter(|pb| pb.ty == pa.ty).flat_map(|pb| pb.elems()).find_map(|e2| {
                let mut side2 = Vec::with_capacity(e1.len());
                for &n1 in e1 {
                    let n2 = e2
                        .iter()
                        .copied()
                        .filter(|&n2| d2(n1, n2) <= crit * crit)
                        .min_by(|&p, &q| d2(n1, p).total_cmp(&d2(n1, q)))?;
                    if side2.contains(&n2) {
                        return None;
                    }
                    side2.push(n2);
                }
                Some(side2)
            });
            if let Some(side2) = found {
                conn.extend_from_slice(e1);
                conn.extend(side2);
            }
        }
        if !conn.is_empty() {
            out = out.union(&Mesh::single(Part::with(joint, conn)));
        }
    }
    if out.parts.is_empty() {
        return fail(op, format!("no element of the first mesh faces one of the second within {}", crit));
    }
    Ok(out)
}
