//! Lines: DROI (straight) and CERC (arc of circle).
//!
//! Both produce an ordered chain from the first given point to the last:
//! the end points are the given nodes, the new nodes are appended to the
//! table in order along the line, and element `i` joins node `i` to node
//! `i + 1` of the chain. With SEG3 elements the chain alternates end and
//! middle nodes (`P1, m1, n1, m2, ..., mn, P2`), each element being
//! `(end, middle, end)`.

use super::grading::{fractions, Spacing};
use super::query::poin_final;
use super::vec3::{add, cross, dist, dot, lerp, norm, scale, sub, V3};
use super::{check_node, fail, MeshError};
use crate::fem::mesh::{ElemType, Mesh, Nodes, Part};

/// The line element matching the current element type (`OPTI ELEM`):
/// quadratic types (SEG3, TRI6, QUA8) give SEG3, every other type SEG2,
/// which is how Cast3M's line generators read `OPTI ELEM`.
pub fn line_type(ty: ElemType) -> ElemType {
    match ty {
        ElemType::Seg3 | ElemType::Tri6 | ElemType::Qua8 | ElemType::Cu20 | ElemType::Pr15 => ElemType::Seg3,
        _ => ElemType::Seg2,
    }
}

/// `DROI (n) P1 P2 ('DINI' d1) ('DFIN' d2)`: a straight line from node `p1`
/// to node `p2`.
///
/// The division follows [`Spacing`] and the rule of
/// [`grading`](super::grading); the end-point densities are those stored
/// in `nodes`. `ty` is the current element type (see [`line_type`]). New
/// nodes are appended in order from `p1` to `p2` (for SEG3, middle nodes
/// included, at the middle of each element); their density is the target
/// size interpolated between the two ends.
pub fn droi(nodes: &mut Nodes, p1: usize, p2: usize, spacing: &Spacing, ty: ElemType) -> Result<Mesh, MeshError> {
    const OP: &str = "DROI";
    check_node(OP, nodes, p1)?;
    check_node(OP, nodes, p2)?;
    if p1 == p2 {
        return fail(OP, format!("the two end points are the same point (node {p1})"));
    }
    let (x1, x2) = (nodes.get(p1), nodes.get(p2));
    let (nd1, nd2) = (nodes.density[p1], nodes.density[p2]);
    let t = fractions(OP, spacing, dist(x1, x2), nd1, nd2)?;
    let (dd1, dd2) = (spacing.dini.unwrap_or(nd1), spacing.dfin.unwrap_or(nd2));
    let place = |s: f64| (lerp(x1, x2, s), dd1 + (dd2 - dd1) * s);
    Ok(chain(nodes, p1, p2, &t, line_type(ty), place))
}

/// `DROI (n) LIG P2 ...`: prolong the line `line` from its final point to
/// node `p2`. The result is `line` followed by the new elements (which
/// follow the ordering of [`droi`]).
pub fn droi_extend(
    nodes: &mut Nodes,
    line: &Mesh,
    p2: usize,
    spacing: &Spacing,
    ty: ElemType,
) -> Result<Mesh, MeshError> {
    let start = poin_final(line).map_err(|e| super::MeshError::new("DROI", e.message))?;
    let ext = droi(nodes, start, p2, spacing, ty)?;
    Ok(line.union(&ext))
}

/// `CERC (n) P1 C P2`: an arc from node `p1` to node `p2` about the centre
/// `c`, in the plane of the three points, the short way round.
///
/// If the radii of `p1` and `p2` differ the radius varies linearly with the
/// angle, so the arc still ends exactly on both points. When `p1`, `c` and
/// `p2` are aligned the plane is undefined; in 2D (all z = 0) the half
/// circle is then taken counter-clockwise, in 3D it is an error. The
/// division applies [`Spacing`] to the arc length, nodes are ordered from
/// `p1` to `p2` as in [`droi`], and SEG3 middle nodes sit at mid-angle.
pub fn cerc(
    nodes: &mut Nodes,
    p1: usize,
    c: usize,
    p2: usize,
    spacing: &Spacing,
    ty: ElemType,
) -> Result<Mesh, MeshError> {
    const OP: &str = "CERC";
    for n in [p1, c, p2] {
        check_node(OP, nodes, n)?;
    }
    if p1 == p2 {
        return fail(OP, "the arc starts and ends on the same point");
    }
    let (x1, xc, x2) = (nodes.get(p1), nodes.get(c), nodes.get(p2));
    let (a, b) = (sub(x1, xc), sub(x2, xc));
    let (r1, r2) = (norm(a), norm(b));
    if r1 == 0.0 || r2 == 0.0 {
        return fail(OP, "an end point of the arc coincides with the centre");
    }
    let e1 = scale(a, 1.0 / r1);
    let mut k = cross(a, b);
    let tol = 1e-10 * r1 * r2;
    if norm(k) <= tol {
        let planar = [x1, xc, x2].iter().all(|x| x[2] == 0.0);
        if dot(a, b) > 0.0 {
            return fail(OP, "the two end points lie in the same direction from the centre");
        }
        if !planar {
            return fail(OP, "the end points are opposite about the centre: the plane of the arc is undefined");
        }
        k = [0.0, 0.0, 1.0];
    }
    let k = scale(k, 1.0 / norm(k));
    let e2 = cross(k, e1);
    let theta = dot(b, e2).atan2(dot(b, e1));
    let arc = theta.abs() * 0.5 * (r1 + r2);
    let (nd1, nd2) = (nodes.density[p1], nodes.density[p2]);
    let t = fractions(OP, spacing, arc, nd1, nd2)?;
    let (dd1, dd2) = (spacing.dini.unwrap_or(nd1), spacing.dfin.unwrap_or(nd2));
    let place = |s: f64| {
        let (sn, cs) = (theta * s).sin_cos();
        let r = r1 + (r2 - r1) * s;
        let x: V3 = add(xc, add(scale(e1, r * cs), scale(e2, r * sn)));
        (x, dd1 + (dd2 - dd1) * s)
    };
    Ok(chain(nodes, p1, p2, &t, line_type(ty), place))
}

/// Create the nodes of a chain at fractions `t` (ends excluded: they are
/// `first` and `last`) and connect them as SEG2 or SEG3. `place` maps a
/// fraction to a position and a density.
pub(super) fn chain(
    nodes: &mut Nodes,
    first: usize,
    last: usize,
    t: &[f64],
    ty: ElemType,
    place: impl Fn(f64) -> (V3, f64),
) -> Mesh {
    let n = t.len() - 1;
    let mut push = |s: f64| {
        let (x, d) = place(s);
        nodes.push(x, d)
    };
    let mut part = Part::new(ty);
    let mut prev = first;
    for i in 0..n {
        let mid = (ty == ElemType::Seg3).then(|| push(0.5 * (t[i] + t[i + 1])));
        let next = if i + 1 == n { last } else { push(t[i + 1]) };
        part.conn.push(prev);
        part.conn.extend(mid);
        part.conn.push(next);
        prev = next;
    }
    Mesh::single(part)
}
