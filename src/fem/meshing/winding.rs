//! Closed contours and envelopes: which way a contour runs (SENS) and
//! whether a point lies inside (DEDA).
//!
//! * The sense of a closed plane contour is the sign of its signed area
//!   (the shoelace sum over its segments): +1 counter-clockwise.
//! * A point is inside a closed oriented boundary when the signed angle
//!   (2D, SEG2 lines) or solid angle (3D, TRI3 surfaces) the boundary
//!   subtends from it sums to a non-zero total (2 pi resp. 4 pi for a
//!   simple boundary, 0 outside). A point on the boundary itself counts as
//!   inside: there the angles are ill-defined (half a turn, of either sign),
//!   so it is detected by its distance to the elements instead.

use super::{check_nodes, fail, MeshError};
use crate::fem::mesh::{ElemType, Mesh, Nodes};

type V3 = [f64; 3];

fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn cross(a: V3, b: V3) -> V3 {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}
fn norm(a: V3) -> f64 {
    dot(a, a).sqrt()
}

/// The straight segments of a line mesh (a SEG3 is its two halves).
fn segments(op: &'static str, mesh: &Mesh) -> Result<Vec<[usize; 2]>, MeshError> {
    let mut out = Vec::new();
    for p in mesh.parts.iter().filter(|p| !p.is_empty()) {
        match p.ty {
            ElemType::Seg2 => out.extend(p.elems().map(|e| [e[0], e[1]])),
            ElemType::Seg3 => out.extend(p.elems().flat_map(|e| [[e[0], e[1]], [e[1], e[2]]])),
            other => {
                return fail(op, format!("expected a line of SEG2 or SEG3 elements, got {} elements", other.name()))
            }
        }
    }
    Ok(out)
}

/// The triangles of a surface mesh (a QUA4 is cut along its diagonal 1-3;
/// quadratic faces by their corners, as flat facets).
fn triangles(op: &'static str, mesh: &Mesh) -> Result<Vec<[usize; 3]>, MeshError> {
    let mut out = Vec::new();
    for p in mesh.parts.iter().filter(|p| !p.is_empty()) {
        match p.ty {
            ElemType::Tri3 => out.extend(p.elems().map(|e| [e[0], e[1], e[2]])),
            ElemType::Tri6 => out.extend(p.elems().map(|e| [e[0], e[2], e[4]])),
            ElemType::Qua4 => out.extend(p.elems().flat_map(|e| [[e[0], e[1], e[2]], [e[0], e[2], e[3]]])),
            ElemType::Qua8 => out.extend(p.elems().flat_map(|e| [[e[0], e[2], e[4]], [e[0], e[4], e[6]]])),
            other => {
                return fail(
                    op,
                    format!("expected a surface of TRI3 (or QUA4) elements, got {} elements", other.name()),
                )
            }
        }
    }
    Ok(out)
}

/// +1 when the closed plane line `mesh` runs counter-clockwise in the
/// (x, y) plane, -1 clockwise (SENS).
pub fn sense(nodes: &Nodes, mesh: &Mesh) -> Result<i64, MeshError> {
    const OP: &str = "SENS";
    check_nodes(OP, nodes, mesh)?;
    let segs = segments(OP, mesh)?;
    if segs.is_empty() {
        return fail(OP, "the contour is empty");
    }
    let area: f64 = segs
        .iter()
        .map(|&[a, b]| {
            let (p, q) = (nodes.get(a), nodes.get(b));
            p[0] * q[1] - q[0] * p[1]
        })
        .sum();
    if area == 0.0 || !area.is_finite() {
        return fail(OP, "the contour encloses no area: its sense is undefined");
    }
    Ok(if area > 0.0 { 1 } else { -1 })
}

/// Whether point `x` is inside the closed oriented boundary `mesh` (DEDA):
/// a line in the (x, y) plane or a surface in space. `tol` bounds the
/// total angle (radians, steradians) taken as zero.
pub fn inside(nodes: &Nodes, mesh: &Mesh, x: V3, tol: f64) -> Result<bool, MeshError> {
    const OP: &str = "DEDA";
    check_nodes(OP, nodes, mesh)?;
    let is_line = mesh.parts.iter().any(|p| !p.is_empty() && p.ty.dim() == 1);
    let total = if is_line {
        let segs = segments(OP, mesh)?;
        let flat = |n: usize| {
            let c = nodes.get(n);
            [c[0] - x[0], c[1] - x[1], 0.0]
        };
        let mut total = 0.0;
        for [a, b] in segs {
            let (u, v) = (flat(a), flat(b));
            if on_segment(u, v) {
                return Ok(true);
            }
            total += cross(u, v)[2].atan2(dot(u, v));
        }
        total
    } else {
        let tris = triangles(OP, mesh)?;
        if tris.is_empty() {
            return fail(OP, "the boundary is empty");
        }
        let mut total = 0.0;
        for [a, b, c] in tris {
            let (u, v, w) = (sub(nodes.get(a), x), sub(nodes.get(b), x), sub(nodes.get(c), x));
            if on_triangle(u, v, w) {
                return Ok(true);
            }
            total += solid_angle(u, v, w);
        }
        total
    };
    if !total.is_finite() {
        return fail(OP, "the angles summed to a non-finite number");
    }
    Ok(total.abs() > tol)
}

/// Relative distance below which a point is taken on an element.
const ON: f64 = 1e-10;

/// Whether the origin lies on the segment from `u` to `v`.
fn on_segment(u: V3, v: V3) -> bool {
    let d = sub(v, u);
    let l2 = dot(d, d);
    if l2 == 0.0 {
        return norm(u) == 0.0;
    }
    let s = (-dot(u, d) / l2).clamp(0.0, 1.0);
    let closest = [u[0] + s * d[0], u[1] + s * d[1], u[2] + s * d[2]];
    norm(closest) <= ON * l2.sqrt()
}

/// Whether the origin lies on the triangle (`u`, `v`, `w`).
fn on_triangle(u: V3, v: V3, w: V3) -> bool {
    let n = cross(sub(v, u), sub(w, u));
    let size = norm(sub(v, u)).max(norm(sub(w, u))).max(norm(sub(w, v)));
    let nn = norm(n);
    if nn == 0.0 {
        return on_segment(u, v) || on_segment(v, w) || on_segment(w, u);
    }
    // Off the plane: not on it.
    if (dot(n, u) / nn).abs() > ON * size {
        return false;
    }
    // In the plane: inside the triangle or on one of its edges.
    let s1 = dot(cross(u, v), n);
    let s2 = dot(cross(v, w), n);
    let s3 = dot(cross(w, u), n);
    (s1 >= 0.0 && s2 >= 0.0 && s3 >= 0.0) || on_segment(u, v) || on_segment(v, w) || on_segment(w, u)
}

/// The signed solid angle of the triangle (`u`, `v`, `w`) seen from the
/// origin (Van Oosterom and Strackee's formula).
fn solid_angle(u: V3, v: V3, w: V3) -> f64 {
    let (a, b, c) = (norm(u), norm(v), norm(w));
    let num = dot(u, cross(v, w));
    let den = a * b * c + dot(u, v) * c + dot(u, w) * b + dot(v, w) * a;
    2.0 * num.atan2(den)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fem::mesh::Part;

    fn square(nodes: &mut Nodes, ccw: bool) -> Mesh {
        let c = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]];
        let ids: Vec<usize> = c.iter().map(|&x| nodes.push(x, 1.0)).collect();
        let order: Vec<usize> = if ccw { vec![0, 1, 2, 3] } else { vec![0, 3, 2, 1] };
        let conn = (0..4).flat_map(|k| [ids[order[k]], ids[order[(k + 1) % 4]]]).collect();
        Mesh::single(Part::with(ElemType::Seg2, conn))
    }

    #[test]
    fn sense_and_inside_of_a_square() {
        let mut nodes = Nodes::default();
        let m = square(&mut nodes, true);
        assert_eq!(sense(&nodes, &m).unwrap(), 1);
        assert!(inside(&nodes, &m, [0.5, 0.5, 0.0], 1e-9).unwrap());
        assert!(inside(&nodes, &m, [1.0, 0.5, 0.0], 1e-9).unwrap());
        assert!(!inside(&nodes, &m, [1.5, 0.5, 0.0], 1e-9).unwrap());
        let r = square(&mut nodes, false);
        assert_eq!(sense(&nodes, &r).unwrap(), -1);
    }

    #[test]
    fn inside_a_tetrahedron() {
        let mut nodes = Nodes::default();
        let c = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        let ids: Vec<usize> = c.iter().map(|&x| nodes.push(x, 1.0)).collect();
        let faces = [[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]];
        let conn = faces.iter().flat_map(|f| f.iter().map(|&k| ids[k])).collect();
        let m = Mesh::single(Part::with(ElemType::Tri3, conn));
        assert!(inside(&nodes, &m, [0.1, 0.1, 0.1], 1e-9).unwrap());
        assert!(inside(&nodes, &m, [0.2, 0.2, 0.0], 1e-9).unwrap());
        assert!(!inside(&nodes, &m, [0.5, 0.5, 0.5], 1e-9).unwrap());
    }
}
