//! The closed contours a free mesher fills (SURF), and the plane they lie
//! in.
//!
//! A contour is a line mesh (SEG2 or SEG3) made of one or more closed
//! loops: an outer boundary and, for holes, inner ones. The elements may
//! come in any order; each loop is walked from its first element in mesh
//! order, in that element's direction, and an element met the other way is
//! read reversed (decks build contours with `ET` of lines given either
//! way). Every node must join exactly two segments.

use super::vec3::{cross, dist, dot, norm, scale, sub, V3};
use super::{check_nodes, fail, MeshError};
use crate::fem::mesh::{ElemType, Mesh, Nodes};
use std::collections::HashMap;

/// One closed loop: `corners[i]` to `corners[i + 1]` (cyclically) is a
/// segment, whose middle node is `mids[i]` for SEG3 contours.
#[derive(Debug, Clone, PartialEq)]
pub struct Loop {
    pub corners: Vec<usize>,
    pub mids: Option<Vec<usize>>,
}

/// The loops of a contour, in the order their first element appears.
pub fn loops(op: &'static str, nodes: &Nodes, mesh: &Mesh) -> Result<Vec<Loop>, MeshError> {
    check_nodes(op, nodes, mesh)?;
    let mut segs: Vec<(usize, usize, Option<usize>)> = Vec::new();
    for p in mesh.parts.iter().filter(|p| !p.is_empty()) {
        match p.ty {
            ElemType::Seg2 => segs.extend(p.elems().map(|e| (e[0], e[1], None))),
            ElemType::Seg3 => segs.extend(p.elems().map(|e| (e[0], e[2], Some(e[1])))),
            other => {
                return fail(op, format!("the contour must be a line of SEG2 or SEG3 elements, not {}", other.name()))
            }
        }
    }
    if segs.is_empty() {
        return fail(op, "the contour is empty");
    }
    let quadratic = segs[0].2.is_some();
    if segs.iter().any(|s| s.2.is_some() != quadratic) {
        return fail(op, "the contour mixes SEG2 and SEG3 elements");
    }
    let mut at: HashMap<usize, Vec<usize>> = HashMap::new();
    for (k, s) in segs.iter().enumerate() {
        if s.0 == s.1 {
            return fail(op, format!("contour element {} starts and ends at the same node", k + 1));
        }
        at.entry(s.0).or_default().push(k);
        at.entry(s.1).or_default().push(k);
    }
    // Report the first node (in element order) that does not join two segments.
    for s in &segs {
        for n in [s.0, s.1] {
            let k = at[&n].len();
            if k == 1 {
                return fail(op, format!("node {} ends the line: the contour is not closed", n + 1));
            }
            if k != 2 {
                return fail(
                    op,
                    format!("the contour branches at node {} ({k} segments meet there, 2 are needed)", n + 1),
                );
            }
        }
    }
    let mut used = vec![false; segs.len()];
    let mut out = Vec::new();
    for first in 0..segs.len() {
        if used[first] {
            continue;
        }
        let start = segs[first].0;
        let (mut corners, mut mids) = (Vec::new(), Vec::new());
        let (mut k, mut from) = (first, start);
        loop {
            used[k] = true;
            let (a, b, m) = segs[k];
            let to = if a == from { b } else { a };
            corners.push(from);
            mids.extend(m);
            if to == start {
                break;
            }
            // The other segment at `to` (exactly two meet there).
            k = at[&to].iter().copied().find(|&j| j != k && !used[j]).unwrap_or(k);
            if used[k] {
                return fail(op, format!("the contour cannot be followed past node {}", to + 1));
            }
            from = to;
        }
        out.push(Loop { corners, mids: quadratic.then_some(mids) });
    }
    Ok(out)
}

/// An orthonormal frame of the contour's plane: local coordinates are
/// `(x - origin)·e1, (x - origin)·e2`, and `n = e1 × e2` is the normal the
/// loops turn about (counter-clockwise seen from `n`, for the loops taken
/// together: holes that turn the other way count against the outer one).
#[derive(Debug, Clone, Copy)]
pub struct Frame {
    pub origin: V3,
    pub e1: V3,
    pub e2: V3,
    pub n: V3,
}

impl Frame {
    /// The plane of `loops`: through their node centroid, normal by Newell's
    /// formula. In 2D (`space_dim < 3`) the normal is ±z. Nodes farther
    /// from the plane than `crit` times their distance to the centroid make
    /// the contour not plane (an error); `crit` is the notice's 'PLAN'
    /// criterion.
    pub fn of(
        op: &'static str,
        nodes: &Nodes,
        loops: &[Loop],
        space_dim: usize,
        crit: f64,
    ) -> Result<Frame, MeshError> {
        let all: Vec<usize> = loops.iter().flat_map(|l| l.corners.iter().copied()).collect();
        let mut origin = [0.0; 3];
        for &k in &all {
            origin = super::vec3::add(origin, nodes.get(k));
        }
        origin = scale(origin, 1.0 / all.len() as f64);
        let mut nrm = [0.0; 3];
        for l in loops {
            let c = &l.corners;
            for i in 0..c.len() {
                let (p, q) = (sub(nodes.get(c[i]), origin), sub(nodes.get(c[(i + 1) % c.len()]), origin));
                nrm = super::vec3::add(nrm, cross(p, q));
            }
        }
        if space_dim < 3 {
            nrm = [0.0, 0.0, nrm[2]];
        }
        let len = norm(nrm);
        if !(len > 0.0 && len.is_finite()) {
            return fail(op, "the contour encloses no area (its points are aligned)");
        }
        let n = scale(nrm, 1.0 / len);
        let frame = if space_dim < 3 {
            // In the plane the frame is the axes themselves (mirrored when
            // the contour turns clockwise), so coordinates go through
            // unchanged.
            Frame { origin: [0.0; 3], e1: [1.0, 0.0, 0.0], e2: cross(n, [1.0, 0.0, 0.0]), n }
        } else {
            // e1 towards the node farthest from the centroid, made
            // orthogonal to n.
            let far =
                all.iter()
                    .map(|&k| sub(nodes.get(k), origin))
                    .fold([0.0; 3], |b, v| if norm(v) > norm(b) { v } else { b });
            let t = sub(far, scale(n, dot(far, n)));
            let e1 = scale(t, 1.0 / norm(t));
            Frame { origin, e1, e2: cross(n, e1), n }
        };
        if space_dim >= 3 {
            for &k in &all {
                let v = sub(nodes.get(k), origin);
                let off = dot(v, n).abs();
                if off > crit * norm(v) {
                    return fail(
                        op,
                        format!(
                            "the contour is not plane: node {} lies {:.3e} off the mean plane \
                             (more than {} times its distance to the centre)",
                            k + 1,
                            off,
                            crit
                        ),
                    );
                }
            }
        }
        Ok(frame)
    }

    pub fn local(&self, x: V3) -> [f64; 2] {
        let v = sub(x, self.origin);
        [dot(v, self.e1), dot(v, self.e2)]
    }

    pub fn global(&self, u: [f64; 2]) -> V3 {
        super::vec3::add(self.origin, super::vec3::add(scale(self.e1, u[0]), scale(self.e2, u[1])))
    }
}

/// The target element size at each corner of each loop: the node's density
/// when it is positive, else the mean length of its two contour segments
/// (Cast3M stores density 0 unless `OPTI DENS` or DINI/DFIN set one, and
/// then meshes at the contour's own spacing).
pub fn corner_sizes(nodes: &Nodes, l: &Loop) -> Vec<f64> {
    let c = &l.corners;
    let n = c.len();
    (0..n)
        .map(|i| {
            let d = nodes.density[c[i]];
            if d > 0.0 && d.is_finite() {
                return d;
            }
            let x = nodes.get(c[i]);
            0.5 * (dist(x, nodes.get(c[(i + n - 1) % n])) + dist(x, nodes.get(c[(i + 1) % n])))
        })
        .collect()
}
