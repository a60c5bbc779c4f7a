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

use super::vec3::{cross, dot, sub};

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
    pairs_with(coords, slaves, facets, BRUTE_MAX)
}

/// [`pairs`], with the grid used above `brute_max` node × facet checks.
fn pairs_with(
    coords: &[[f64; 3]],
    slaves: &[usize],
    facets: &[&[usize]],
    brute_max: usize,
) -> Result<Vec<Pair>, usize> {
    if let Some(i) = facets.iter().position(|f| project(coords, f[0], f, false) == Err(Miss::Degenerate)) {
        return Err(i);
    }
    // Every facet against every node is fine for deck-sized contacts; a
    // grid of facet boxes keeps large 3D surfaces near-linear.
    let grid = (slaves.len() * facets.len() > brute_max).then(|| Grid::new(coords, facets));
    let mut out = Vec::new();
    let mut stamp = vec![usize::MAX; facets.len()];
    for (k, &s) in slaves.iter().enumerate() {
        let mut best: Option<(Pair, usize)> = None;
        let best_gap = std::cell::Cell::new(f64::INFINITY);
        let mut consider = |i: usize| {
            let f = facets[i];
            if f.contains(&s) {
                return;
            }
            if let Ok(p) = project(coords, s, f, true) {
                // Smallest |gap|, then the first facet on a tie: the same
                // choice whatever order the facets are met in.
                if best.as_ref().is_none_or(|(b, j)| (p.gap.abs(), i) < (b.gap.abs(), *j)) {
                    best_gap.set(p.gap.abs());
                    best = Some((p, i));
                }
            }
        };
        match &grid {
            None => (0..facets.len()).for_each(&mut consider),
            Some(g) => g.search(coords[s], k, &mut stamp, &mut consider, |pending| {
                // A facet whose box is farther than the best |gap| cannot
                // hold a nearer projection (the foot of a projection is in
                // the facet, within the box).
                pending <= best_gap.get()
            }),
        }
        out.extend(best.map(|(p, _)| p));
    }
    Ok(out)
}

/// Node × facet count above which the facet grid is used.
const BRUTE_MAX: usize = 200_000;

/// A uniform grid over the facets' bounding boxes.
struct Grid {
    lo: [f64; 3],
    h: f64,
    dims: [usize; 3],
    /// Facets overlapping each cell.
    cells: Vec<Vec<usize>>,
}

impl Grid {
    fn new(coords: &[[f64; 3]], facets: &[&[usize]]) -> Self {
        let boxes: Vec<([f64; 3], [f64; 3])> = facets.iter().map(|f| bbox(coords, f)).collect();
        let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
        let mut size = 0.0;
        for (a, b) in &boxes {
            for k in 0..3 {
                lo[k] = lo[k].min(a[k]);
                hi[k] = hi[k].max(b[k]);
            }
            size += (0..3).map(|k| b[k] - a[k]).fold(0.0, f64::max);
        }
        // Cells about the mean facet size, at most a few per facet.
        let extent = (0..3).map(|k| hi[k] - lo[k]).fold(0.0, f64::max);
        let mut h = (size / facets.len() as f64).max(extent * 1e-9).max(f64::MIN_POSITIVE);
        let count = |h: f64| (0..3).map(|k| ((hi[k] - lo[k]) / h) as usize + 1).product::<usize>();
        while count(h) > 8 * facets.len() + 8 {
            h *= 2.0;
        }
        let dims = [0, 1, 2].map(|k| ((hi[k] - lo[k]) / h) as usize + 1);
        let mut cells = vec![Vec::new(); dims[0] * dims[1] * dims[2]];
        let cell = |x: f64, k: usize| (((x - lo[k]) / h) as usize).min(dims[k] - 1);
        for (i, (a, b)) in boxes.iter().enumerate() {
            for z in cell(a[2], 2)..=cell(b[2], 2) {
                for y in cell(a[1], 1)..=cell(b[1], 1) {
                    for x in cell(a[0], 0)..=cell(b[0], 0) {
                        cells[(z * dims[1] + y) * dims[0] + x].push(i);
                    }
                }
            }
        }
        Grid { lo, h, dims, cells }
    }

    /// Offers the facets to `consider` by rings of cells around `x`, while
    /// `go_on(lower bound of the distance to the next ring)` holds.
    fn search(
        &self,
        x: [f64; 3],
        key: usize,
        stamp: &mut [usize],
        consider: &mut dyn FnMut(usize),
        go_on: impl Fn(f64) -> bool,
    ) {
        let at: [i64; 3] = [0, 1, 2].map(|k| ((x[k] - self.lo[k]) / self.h).floor() as i64);
        let d: [i64; 3] = [0, 1, 2].map(|k| self.dims[k] as i64);
        // Beyond this ring every cell is outside the grid.
        let max_r = (0..3).map(|k| at[k].abs().max((d[k] - 1 - at[k]).abs())).max().unwrap_or(0);
        let span = |k: usize, r: i64| (at[k] - r).max(0)..=(at[k] + r).min(d[k] - 1);
        let mut visit = |xx: i64, y: i64, z: i64| {
            let c = ((z * d[1] + y) * d[0] + xx) as usize;
            for &i in &self.cells[c] {
                if stamp[i] != key {
                    stamp[i] = key;
                    consider(i);
                }
            }
        };
        for r in 0..=max_r {
            // Points of ring r are at least (r − 1)·h away from x.
            if r > 1 && !go_on((r - 1) as f64 * self.h) {
                return;
            }
            // The shell of the cube of cells at Chebyshev distance r.
            for z in span(2, r) {
                for y in span(1, r) {
                    if (z - at[2]).abs() == r || (y - at[1]).abs() == r {
                        span(0, r).for_each(|xx| visit(xx, y, z));
                    } else {
                        for xx in [at[0] - r, at[0] + r] {
                            if xx >= 0 && xx < d[0] {
                                visit(xx, y, z);
                            }
                        }
                    }
                }
            }
        }
    }
}

/// A facet's bounding box, widened by the projection tolerance.
fn bbox(coords: &[[f64; 3]], f: &[usize]) -> ([f64; 3], [f64; 3]) {
    let (mut a, mut b) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for &n in f {
        for k in 0..3 {
            a[k] = a[k].min(coords[n][k]);
            b[k] = b[k].max(coords[n][k]);
        }
    }
    let pad = 1e-6 * (0..3).map(|k| b[k] - a[k]).fold(0.0, f64::max);
    ([0, 1, 2].map(|k| a[k] - pad), [0, 1, 2].map(|k| b[k] + pad))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() < 1e-12
    }

    /// The facet grid picks exactly the facets the brute-force scan picks:
    /// a wavy triangulated surface, slave nodes above, below, beside it and
    /// on its vertices (ties between facets sharing the vertex).
    #[test]
    fn grid_search_matches_brute_force() {
        let nx = 30;
        let mut x = Vec::new();
        for j in 0..=nx {
            for i in 0..=nx {
                let (u, v) = (i as f64 / nx as f64, j as f64 / nx as f64);
                x.push([u, v, 0.1 * (7.0 * u).sin() * (5.0 * v).cos()]);
            }
        }
        let id = |i: usize, j: usize| j * (nx + 1) + i;
        let mut tris = Vec::new();
        for j in 0..nx {
            for i in 0..nx {
                tris.push(vec![id(i, j), id(i + 1, j), id(i + 1, j + 1)]);
                tris.push(vec![id(i, j), id(i + 1, j + 1), id(i, j + 1)]);
            }
        }
        let mut seed = 12345u64;
        let mut rnd = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut slaves = Vec::new();
        for k in 0..400 {
            let p = [1.4 * rnd() - 0.2, 1.4 * rnd() - 0.2, if k % 2 == 0 { 0.5 } else { -0.3 } * rnd()];
            slaves.push(x.len());
            x.push(p);
        }
        for j in (0..=nx).step_by(7) {
            let v = x[id(j, (j * 3) % (nx + 1))];
            slaves.push(x.len());
            x.push([v[0], v[1], v[2] + 0.05]);
        }
        let refs: Vec<&[usize]> = tris.iter().map(|t| t.as_slice()).collect();
        let brute = pairs_with(&x, &slaves, &refs, usize::MAX).unwrap();
        let grid = pairs_with(&x, &slaves, &refs, 0).unwrap();
        assert!(brute.len() > 100, "{} pairs", brute.len());
        assert_eq!(brute, grid);
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
