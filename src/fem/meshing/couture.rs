//! COUTURE: a strip of triangles stitching two lines together, or a fan
//! joining a line to a point.
//!
//! The two lines run the same way. The stitch walks along both from their
//! first points: with `a, a'` the current segment of the first line and
//! `b, b'` that of the second, it closes the triangle across the shorter
//! diagonal, `(a, a', b)` when `|a' b| < |a b'|` (advancing on the first
//! line), else `(a, b', b)` (advancing on the second); when one line is
//! used up the rest of the other is fanned to its last point. Triangles
//! turn like the ruled surface from the first line to the second (REGLER's
//! quadrangle `a a' b' b`). Lines of SEG3 give TRI6 with their middle
//! nodes kept.

use super::query::line_chain;
use super::vec3::dist;
use super::{change_to_quadratic, check_node, fail, mesh_of, MeshError};
use crate::fem::mesh::{ElemType, Mesh, Nodes, Part};

const OP: &str = "COUT";

/// What the first line is stitched to.
#[derive(Clone, Copy)]
pub enum Other<'a> {
    Line(&'a Mesh),
    Point(usize),
}

pub fn couture(nodes: &mut Nodes, line: &Mesh, other: Other) -> Result<Mesh, MeshError> {
    let (c1, quadratic) = corners(line)?;
    let mut conn = Vec::new();
    match other {
        Other::Point(p) => {
            check_node(OP, nodes, p)?;
            if c1.contains(&p) {
                return fail(OP, format!("the point (node {}) lies on the line", p + 1));
            }
            for w in c1.windows(2) {
                conn.extend([w[0], w[1], p]);
            }
        }
        Other::Line(l2) => {
            let (c2, q2) = corners(l2)?;
            if q2 != quadratic {
                return fail(OP, "the two lines must have the same element type (SEG2 or SEG3)");
            }
            let x = |n: usize| nodes.get(n);
            let (mut i, mut j) = (0, 0);
            while i + 1 < c1.len() || j + 1 < c2.len() {
                let first = if i + 1 == c1.len() {
                    false
                } else if j + 1 == c2.len() {
                    true
                } else {
                    dist(x(c1[i + 1]), x(c2[j])) < dist(x(c1[i]), x(c2[j + 1]))
                };
                let t = if first { [c1[i], c1[i + 1], c2[j]] } else { [c1[i], c2[j + 1], c2[j]] };
                if t[0] == t[1] || t[1] == t[2] || t[0] == t[2] {
                    return fail(OP, format!("a triangle would have node {} twice: the lines touch there", t[1] + 1));
                }
                conn.extend(t);
                if first {
                    i += 1;
                } else {
                    j += 1;
                }
            }
        }
    }
    let tri = mesh_of(vec![(ElemType::Tri3, conn)]);
    if !quadratic {
        return Ok(tri);
    }
    // CHAN's rule, with the lines alongside so their middle nodes are kept.
    let mut both = tri;
    both.parts.extend(line.parts.iter().filter(|p| p.ty == ElemType::Seg3).cloned());
    if let Other::Line(l2) = other {
        both.parts.extend(l2.parts.iter().filter(|p| p.ty == ElemType::Seg3).cloned());
    }
    let q = change_to_quadratic(nodes, &both).map_err(|e| MeshError::new(OP, e.message))?;
    Ok(Mesh { parts: q.parts.into_iter().filter(|p: &Part| p.ty != ElemType::Seg3).collect() })
}

/// The corner nodes of a line in order, and whether it is made of SEG3.
fn corners(line: &Mesh) -> Result<(Vec<usize>, bool), MeshError> {
    let chain = line_chain(OP, line)?;
    let quadratic = line.parts.iter().any(|p| p.ty == ElemType::Seg3);
    Ok((if quadratic { chain.into_iter().step_by(2).collect() } else { chain }, quadratic))
}
