//! Node-to-facet contact geometry (IMPO): which master facet a slave node
//! faces, and the linearised gap condition between them.
//!
//! A facet is an oriented SEG2 (2D) or TRI3 (3D) of the master side. Its
//! unit normal `n` points to the *admissible* side, where slave nodes must
//! stay:
//! * 2D, segment a→b with tangent t: `n = (t_y, −t_x)`, the right-hand
//!   side of the oriented line (impo.notice: "contact acts on the
//!   right-hand side"). A counter-clockwise contour (matter on its left,
//!   as CONT gives it) thus keeps other bodies outside.
//! * 3D, triangle a b c: `n = (b−a)×(c−a)`, the side from which a b c turn
//!   anticlockwise; the outer side of a surface oriented like the 2D line.
//!
//! The condition is that the slave node s stays on that side of the point
//! of the facet it projects onto, whose weights w (1−ξ, ξ for a segment;
//! barycentric for a triangle) are frozen at the initial geometry:
//! `n·u_s − Σ w_i n·u_i ≥ −g0`, with `g0 = n·(x_s − x_a)` the initial gap
//! (small displacements: the normal and the weights are not updated).

/// Where a projection parameter may overshoot a facet's ends and still
/// count as inside: a slave node facing a master node exactly (matching
/// meshes) must find a facet despite rounding.
const INSIDE_TOL: f64 = 1e-8;

/// One slave node against one master facet.
#[derive(Debug, Clone, PartialEq)]
pub struct Pair {
    pub slave: usize,
    /// The master facet's nodes, in the facet's order.
    pub facet: Vec<usize>,
    /// The weight of each facet node at the projection (they sum to 1).
    pub weights: Vec<f64>,
    /// Unit normal towards the admissible side (3 components; z is 0 in 2D).
    pub normal: [f64; 3],
    /// Initial signed gap: positive when open, negative when the slave
    /// node is already behind the facet.
    pub gap: f64,
}

impl Pair {
    /// The condition's terms as (node, translation index, coefficient):
    /// `Σ c·u ≥ −gap`. Coefficients below 1e-12 (zero normal components
    /// polluted by rounding, as with a facet turned by exactly 90°) are
    /// dropped, so a horizontal facet does not couple the UX unknowns.
    pub fn terms(&self, ndim: usize) -> Vec<(usize, usize, f64)> {
        let mut out = Vec::new();
        let mut push = |node: usize, w: f64| {
            for (k, nk) in self.normal.iter().enumerate().take(ndim) {
                let c = w * nk;
                if c.abs() > 1e-12 {
                    out.push((node, k, c));
                }
            }
        };
        push(self.slave, 1.0);
        for (&node, &w) in self.facet.iter().zip(&self.weights) {
            push(node, -w);
        }
        out
    }
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

/// Why a facet gives no pair.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Miss {
    /// The facet has no length or area (repeated or aligned nodes).
    Degenerate,
    /// The slave node projects outside the facet.
    Outside,
}

/// Project slave node `s` on `facet` (2 nodes: segment in the xy plane;
/// 3 nodes: triangle). With `inside_only`, a projection outside the facet
/// is a [`Miss::Outside`]; otherwise the weights are clamped into the facet
/// (IMPO 'BLOC', where the pairing is given).
pub fn project(coords: &[[f64; 3]], s: usize, facet: &[usize], inside_only: bool) -> Result<Pair, Miss> {
    let xs = coords[s];
    let xa = coords[facet[0]];
    let d = sub(xs, xa);
    let (normal, mut weights) = match facet {
        [_, b] => {
            let t = sub(coords[*b], xa);
            let len2 = t[0] * t[0] + t[1] * t[1];
            if len2 == 0.0 {
                return Err(Miss::Degenerate);
            }
            let len = len2.sqrt();
            let xi = (d[0] * t[0] + d[1] * t[1]) / len2;
            ([t[1] / len, -t[0] / len, 0.0], vec![1.0 - xi, xi])
        }
        [_, b, c] => {
            let (e1, e2) = (sub(coords[*b], xa), sub(coords[*c], xa));
            let nv = cross(e1, e2);
            let area2 = dot(nv, nv).sqrt();
            if area2 == 0.0 {
                return Err(Miss::Degenerate);
            }
            let n = [nv[0] / area2, nv[1] / area2, nv[2] / area2];
            // Barycentric coordinates of the projection: the normal part
            // of d drops out of both triple products.
            let lb = dot(cross(d, e2), n) / area2;
            let lc = dot(cross(e1, d), n) / area2;
            (n, vec![1.0 - lb - lc, lb, lc])
        }
        _ => unreachable!("a contact facet has 2 or 3 nodes"),
    };
    if inside_only && weights.iter().any(|w| *w < -INSIDE_TOL) {
        return Err(Miss::Outside);
    }
    // Clamp into the facet and renormalise: within the tolerance this
    // moves the point by rounding only; for a given pairing ('BLOC') it
    // takes the nearest point of the facet's edge.
    for w in weights.iter_mut() {
        *w = w.max(0.0);
    }
    let sum: f64 = weights.iter().sum();
    weights.iter_mut().for_each(|w| *w /= sum);
    Ok(Pair { slave: s, facet: facet.to_vec(), weights, normal, gap: dot(d, normal) })
}

/// For every slave node, the facet it faces: among the facets it projects
/// onto (and that do not contain it), the one with the smallest |gap|; the
/// first in facet order on a tie (a node facing the vertex shared by two
/// facets of a straight line). Nodes that project onto no facet get no
/// pair. Degenerate facets are reported by their index.
pub fn pairs(coords: &[[f64; 3]], slaves: &[usize], facets: &[&[usize]]) -> Result<Vec<Pair>, usize> {
    if let Some(i) = facets.iter().position(|f| project(coords, f[0], f, false) == Err(Miss::Degenerate)) {
        return Err(i);
    }
    let mut out = Vec::new();
    for &s in slaves {
        let mut best: Option<Pair> = None;
        for f in facets {
            if f.contains(&s) {
                continue;
            }
            if let Ok(p) = project(coords, s, f, true) {
                if best.as_ref().is_none_or(|b| p.gap.abs() < b.gap.abs()) {
                    best = Some(p);
                }
            }
        }
        out.extend(best);
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() < 1e-12
    }

    #[test]
    fn segment_normal_is_on_the_right_and_weights_interpolate() {
        // Line from (2,0) to (0,0): its right-hand side is y > 0.
        let x = [[2.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.5, 0.25, 0.0]];
        let p = project(&x, 2, &[0, 1], true).unwrap();
        assert_eq!(p.normal, [0.0, 1.0, 0.0]);
        assert!(close(p.gap, 0.25));
        assert!(close(p.weights[0], 0.25) && close(p.weights[1], 0.75));
        // n·u_s − 0.25 n·u_a − 0.75 n·u_b: UY only.
        assert_eq!(p.terms(2), vec![(2, 1, 1.0), (0, 1, -0.25), (1, 1, -0.75)]);
    }

    #[test]
    fn outside_projection_and_own_facet_give_no_pair() {
        let x = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.5, -1.0, 0.0], [0.5, -2.0, 0.0]];
        assert_eq!(project(&x, 2, &[0, 1], true), Err(Miss::Outside));
        let ps = pairs(&x, &[1, 2, 3], &[&[0, 1]]).unwrap();
        // Node 1 is on its own facet; node 2 projects beyond it; node 3 faces it.
        assert_eq!(ps.len(), 1);
        assert_eq!(ps[0].slave, 3);
        assert!(close(ps[0].gap, 2.0));
    }

    #[test]
    fn nearest_facet_wins_and_degenerate_facets_are_reported() {
        let x = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 3.0, 0.0], [0.0, 3.0, 0.0], [0.5, 1.0, 0.0]];
        let ps = pairs(&x, &[4], &[&[1, 0], &[3, 2]]).unwrap();
        assert_eq!(ps[0].facet, vec![1, 0]);
        assert!(close(ps[0].gap, 1.0));
        assert_eq!(pairs(&x, &[4], &[&[1, 0], &[2, 2]]), Err(1));
    }

    #[test]
    fn triangle_normal_barycentric_weights_and_gap() {
        let x = [[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.5, 0.5, -0.1]];
        let p = project(&x, 3, &[0, 1, 2], true).unwrap();
        assert_eq!(p.normal, [0.0, 0.0, 1.0]);
        assert!(close(p.gap, -0.1));
        assert!(close(p.weights[0], 0.5) && close(p.weights[1], 0.25) && close(p.weights[2], 0.25));
        assert_eq!(project(&x, 3, &[0, 2, 1], true).unwrap().normal, [0.0, 0.0, -1.0]);
    }
}
