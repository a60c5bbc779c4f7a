//! Arcs of circle besides CERC's centre form: through three points (CER3,
//! `CERC 'PASS'`), and a point turned about an axis (`LIGN ... 'ROTA'`,
//! `CERC 'ROTA'`). Nodes and elements follow the conventions of
//! [`line`](super::line): an ordered chain from the first point, new nodes
//! in order along it, SEG3 middle nodes at mid-angle.

use super::grading::{fractions, Spacing};
use super::line::{chain, line_type};
use super::vec3::{add, cross, dot, norm, rotate, scale, sub, V3};
use super::{check_node, fail, MeshError};
use crate::fem::mesh::{ElemType, Mesh, Nodes};
use std::f64::consts::TAU;

/// The arc from node `p1` turned by `theta` radians about the axis through
/// `centre` of unit direction `k` (right-hand rule). It ends on `end` when
/// given (the caller has put `end` where the turn lands), else on a new
/// node, or back on `p1` after a full turn. The division applies
/// [`Spacing`] to the arc length.
#[allow(clippy::too_many_arguments)]
pub fn arc(
    op: &'static str,
    nodes: &mut Nodes,
    p1: usize,
    centre: V3,
    k: V3,
    theta: f64,
    end: Option<usize>,
    spacing: &Spacing,
    ty: ElemType,
) -> Result<Mesh, MeshError> {
    check_node(op, nodes, p1)?;
    if !(theta.is_finite() && theta != 0.0 && theta.abs() <= TAU * (1.0 + 1e-12)) {
        return fail(op, format!("the angle must be non-zero and at most 360 degrees (got {})", theta.to_degrees()));
    }
    let x1 = nodes.get(p1);
    let v = sub(x1, centre);
    let radius = norm(sub(v, scale(k, dot(v, k))));
    if radius == 0.0 {
        return fail(op, "the first point lies on the axis (or at the centre): the arc has no radius");
    }
    let closed = (theta.abs() - TAU).abs() <= 1e-9 * TAU;
    let d1 = nodes.density[p1];
    let last = match end {
        Some(e) => e,
        None if closed => p1,
        None => nodes.push(rotate(x1, centre, k, theta), d1),
    };
    let d2 = nodes.density[last];
    let t = fractions(op, spacing, radius * theta.abs(), d1, d2)?;
    let (dd1, dd2) = (spacing.dini.unwrap_or(d1), spacing.dfin.unwrap_or(d2));
    let place = |s: f64| (rotate(x1, centre, k, theta * s), dd1 + (dd2 - dd1) * s);
    Ok(chain(nodes, p1, last, &t, line_type(ty), place))
}

/// `CER3 (n) P1 P2 P3`: the arc from `p1` through `p2` to `p3`, on the
/// circle through the three points (the long way round when `p2` says so).
pub fn cer3(
    op: &'static str,
    nodes: &mut Nodes,
    p: [usize; 3],
    spacing: &Spacing,
    ty: ElemType,
) -> Result<Mesh, MeshError> {
    for &n in &p {
        check_node(op, nodes, n)?;
    }
    let [x1, x2, x3] = p.map(|n| nodes.get(n));
    let (u, v) = (sub(x2, x1), sub(x3, x1));
    let w = cross(u, v);
    let w2 = dot(w, w);
    let aligned = w2.is_nan() || w2 <= 1e-24 * dot(u, u) * dot(v, v);
    if aligned || p[0] == p[2] {
        return fail(op, "the three points are aligned (or two coincide): no circle passes through them");
    }
    // The circumcentre, and the sense p1 -> p2 -> p3 as the axis.
    let c = add(x1, scale(add(scale(cross(v, w), dot(u, u)), scale(cross(w, u), dot(v, v))), 0.5 / w2));
    let k = scale(w, 1.0 / w2.sqrt());
    let (a, b) = (sub(x1, c), sub(x3, c));
    let mut theta = dot(k, cross(a, b)).atan2(dot(a, b));
    if theta <= 0.0 {
        theta += TAU;
    }
    arc(op, nodes, p[0], c, k, theta, Some(p[2]), spacing, ty)
}

/// The unit axis of a turn: the z axis in 2D, else the given direction.
pub fn axis(op: &'static str, dir: Option<V3>) -> Result<V3, MeshError> {
    match dir {
        None => Ok([0.0, 0.0, 1.0]),
        Some(d) if norm(d) > 0.0 && d.iter().all(|c| c.is_finite()) => Ok(scale(d, 1.0 / norm(d))),
        Some(_) => fail(op, "the axis of the turn has no direction (its two points coincide)"),
    }
}
