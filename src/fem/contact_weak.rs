//! Segment-to-segment contact in 2D, the weak form of IMPO 'MAIL' 'FAIB':
//! non-penetration imposed on average over the part of two facing
//! segments that overlap, one condition per pair of segments.
//!
//! Two segments a→b (first line) and c→d (second line) face each other
//! when they run in opposite directions. The contact direction τ is the
//! mean tangent (b − a) − (d − c), normalised; the normal n = (τ_y, −τ_x)
//! is on the right of a→b, the side where the second line must stay
//! (impo.notice: contact acts on the right of oriented lines). Both
//! segments are projected on τ; where the projections overlap, the mean
//! normal separation of the two segments over the overlap must not fall
//! below the gap allowed:
//! `n·(ū_cd − ū_ab) ≥ jeu − n·(x̄_cd − x̄_ab)`,
//! the bars being means over the overlap (exact with the mean of the
//! interpolation weights at its two ends, the weights being linear).

/// A pair of facing segments and its condition.
#[derive(Debug, Clone, PartialEq)]
pub struct WeakPair {
    /// a, b, c, d: the first segment, then the second.
    pub nodes: [usize; 4],
    /// Mean interpolation weights over the overlap, in the order of
    /// `nodes` (a, b sum to 1; c, d sum to 1).
    pub weights: [f64; 4],
    /// Unit normal, on the right of a→b.
    pub normal: [f64; 2],
    /// Initial mean separation over the overlap (positive when open).
    pub gap: f64,
    /// Length of the overlap: the condition's share of the contact line.
    pub length: f64,
}

impl WeakPair {
    /// Terms (node, translation index, coefficient) of `Σ c·u ≥ jeu − gap`.
    pub fn terms(&self) -> Vec<(usize, usize, f64)> {
        let mut out = Vec::with_capacity(8);
        for (i, (&node, &w)) in self.nodes.iter().zip(&self.weights).enumerate() {
            let s = if i < 2 { -w } else { w };
            for (k, nk) in self.normal.iter().enumerate() {
                let c = s * nk;
                if c.abs() > 1e-12 {
                    out.push((node, k, c));
                }
            }
        }
        out
    }
}

/// The condition of two segments, or None when they do not face each
/// other: same direction, no overlap along the contact direction, or the
/// second segment entirely away from the first (both its ends outside the
/// circle of diameter three times |ab| about the middle of ab; a far
/// segment facing the first one across the body gives no condition).
pub fn facing(x: &[[f64; 3]], nodes: [usize; 4]) -> Option<WeakPair> {
    let p = |k: usize| [x[nodes[k]][0], x[nodes[k]][1]];
    let (a, b, c, d) = (p(0), p(1), p(2), p(3));
    let t1 = [b[0] - a[0], b[1] - a[1]];
    let t2 = [d[0] - c[0], d[1] - c[1]];
    let l1 = (t1[0] * t1[0] + t1[1] * t1[1]).sqrt();
    let l2 = (t2[0] * t2[0] + t2[1] * t2[1]).sqrt();
    if l1 == 0.0 || l2 == 0.0 || nodes[..2].iter().any(|n| nodes[2..].contains(n)) {
        return None;
    }
    if t1[0] * t2[0] + t1[1] * t2[1] > 0.0 {
        return None;
    }
    // Ends of ab pushed out by |ab| on each side: c or d must lie in the
    // circle on that diameter.
    let (ae, be) = ([a[0] - t1[0], a[1] - t1[1]], [b[0] + t1[0], b[1] + t1[1]]);
    let outside = |q: [f64; 2]| (q[0] - ae[0]) * (q[0] - be[0]) + (q[1] - ae[1]) * (q[1] - be[1]) > 0.0;
    if outside(c) && outside(d) {
        return None;
    }
    let mut tau = [t1[0] - t2[0], t1[1] - t2[1]];
    let tl = (tau[0] * tau[0] + tau[1] * tau[1]).sqrt();
    tau = [tau[0] / tl, tau[1] / tl];
    let normal = [tau[1], -tau[0]];
    let s = |q: [f64; 2]| q[0] * tau[0] + q[1] * tau[1];
    let (sa, sb, sc, sd) = (s(a), s(b), s(c), s(d));
    let lo = sa.min(sb).max(sc.min(sd));
    let hi = sa.max(sb).min(sc.max(sd));
    let length = hi - lo;
    if length <= 1e-10 * l1.max(l2) {
        return None;
    }
    // Weights of a point at abscissa σ on a segment p→q.
    let w = |sp: f64, sq: f64, sig: f64| ((sq - sig) / (sq - sp), (sig - sp) / (sq - sp));
    let mean = |sp: f64, sq: f64| {
        let (w0, w1) = w(sp, sq, lo);
        let (v0, v1) = w(sp, sq, hi);
        ((w0 + v0) / 2.0, (w1 + v1) / 2.0)
    };
    let (wa, wb) = mean(sa, sb);
    let (wc, wd) = mean(sc, sd);
    let n = |q: [f64; 2]| q[0] * normal[0] + q[1] * normal[1];
    let gap = (wc * n(c) + wd * n(d)) - (wa * n(a) + wb * n(b));
    Some(WeakPair { nodes, weights: [wa, wb, wc, wd], normal, gap, length })
}

/// Every pair of facing segments between two lines: the segments of the
/// first against those of the second.
pub fn pairs(x: &[[f64; 3]], first: &[[usize; 2]], second: &[[usize; 2]]) -> Vec<WeakPair> {
    let mut out = Vec::new();
    for s1 in first {
        for s2 in second {
            if let Some(p) = facing(x, [s1[0], s1[1], s2[0], s2[1]]) {
                out.push(p);
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() < 1e-12
    }

    /// Segment (0,1)→(2,1) over (3,0.5)→(1,0.5): overlap [1, 2] along x,
    /// the second line below (on the right of the first), 0.5 apart.
    #[test]
    fn overlap_weights_gap_and_terms() {
        let x = [[0.0, 1.0, 0.0], [2.0, 1.0, 0.0], [3.0, 0.5, 0.0], [1.0, 0.5, 0.0]];
        let p = facing(&x, [0, 1, 2, 3]).unwrap();
        assert_eq!(p.normal, [0.0, -1.0]);
        assert!(close(p.length, 1.0));
        assert!(close(p.gap, 0.5), "{}", p.gap);
        // Mean of the weights at x = 1 and x = 2 on each segment.
        assert!(close(p.weights[0], 0.25) && close(p.weights[1], 0.75));
        assert!(close(p.weights[2], 0.25) && close(p.weights[3], 0.75));
        // −n·ū_ab + n·ū_cd: UY only, +w on ab, −w on cd (n = −y).
        assert_eq!(p.terms(), vec![(0, 1, 0.25), (1, 1, 0.75), (2, 1, -0.25), (3, 1, -0.75)]);
    }

    #[test]
    fn same_direction_far_or_disjoint_segments_do_not_face() {
        let x = [
            [0.0, 1.0, 0.0],
            [2.0, 1.0, 0.0],
            [1.0, 0.5, 0.0],
            [3.0, 0.5, 0.0],
            [30.0, 0.5, 0.0],
            [28.0, 0.5, 0.0],
            [1.0, -20.0, 0.0],
            [0.0, -20.0, 0.0],
        ];
        assert!(facing(&x, [0, 1, 2, 3]).is_none(), "same direction");
        assert!(facing(&x, [0, 1, 4, 5]).is_none(), "no overlap");
        assert!(facing(&x, [0, 1, 6, 7]).is_none(), "far away");
        assert_eq!(pairs(&x, &[[0, 1]], &[[3, 2], [5, 4], [7, 6]]).len(), 1);
    }
}
