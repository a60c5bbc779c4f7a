//! Integration rules of a CUB8 cut by a crack (X-FEM element XC8R): the
//! reference cube is split into tetrahedra, each tetrahedron is cut by the
//! plane on which the normal level set, interpolated linearly on it,
//! vanishes, and every piece gets a Gauss rule. Each point carries the side
//! of the crack it lies on, so that the Heaviside enrichment is constant on
//! every piece and the discontinuity falls exactly on piece boundaries
//! (a Gauss rule across the jump would smear it).
//!
//! Everything is done in reference coordinates: the pieces are tetrahedra
//! of the reference cube, so the element's isoparametric mapping applies
//! unchanged to their points.

use super::quadrature::gauss_1d;

/// A reference point, its reference weight, and the side of the crack it
/// lies on (+1 or -1: the sign of the normal level set; 0 never occurs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SidedPoint {
    pub xi: [f64; 3],
    pub w: f64,
    pub side: f64,
}

type P3 = [f64; 3];

/// The six tetrahedra of the Kuhn split of a cube, one per ordering of the
/// axes: from the lowest corner, step along the axes in that order. All six
/// share the main diagonal, so the split is the same from any neighbour.
const KUHN: [[usize; 3]; 6] = [[0, 1, 2], [0, 2, 1], [1, 0, 2], [1, 2, 0], [2, 0, 1], [2, 1, 0]];

/// Conical (collapsed) product rule on the unit tetrahedron (0,0,0)
/// (1,0,0) (0,1,0) (0,0,1): n³ points, weights summing to 1/6, exact to
/// degree 2n-3 (the collapse adds (1-a)² to the integrand). Written here rather than in `quadrature` because only the cut
/// cells need a rule of chosen order on many small tetrahedra.
fn tet_conical(n: usize) -> Vec<(P3, f64)> {
    let g: Vec<(f64, f64)> = gauss_1d(n).into_iter().map(|(x, w)| ((x + 1.0) / 2.0, w / 2.0)).collect();
    let mut out = Vec::with_capacity(n * n * n);
    for &(a, wa) in &g {
        for &(b, wb) in &g {
            for &(c, wc) in &g {
                // (a, b, c) in the unit cube -> collapsed onto the tetrahedron.
                let x = a;
                let y = (1.0 - a) * b;
                let z = (1.0 - a) * (1.0 - b) * c;
                let jac = (1.0 - a) * (1.0 - a) * (1.0 - b);
                out.push(([x, y, z], wa * wb * wc * jac));
            }
        }
    }
    out
}

fn lerp(a: P3, b: P3, t: f64) -> P3 {
    [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])]
}

fn volume6(t: &[P3; 4]) -> f64 {
    let d = |k: usize| [t[k][0] - t[0][0], t[k][1] - t[0][1], t[k][2] - t[0][2]];
    let (a, b, c) = (d(1), d(2), d(3));
    (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])).abs()
}

/// The three tetrahedra of the prism with triangles a and b (a[k] above
/// b[k]). Degenerate prisms (a corner shared) give tetrahedra of zero
/// volume, which simply carry no weight.
fn prism(a: [P3; 3], b: [P3; 3]) -> [[P3; 4]; 3] {
    [[a[0], a[1], a[2], b[2]], [a[0], a[1], b[1], b[2]], [a[0], b[0], b[1], b[2]]]
}

/// The pieces of tetrahedron `t` (level set values `f` at its corners,
/// exact zeros meaning "on the crack") on each side: (tetrahedron, side).
fn cut_tet(t: [P3; 4], f: [f64; 4], out: &mut Vec<([P3; 4], f64)>) {
    let pos: Vec<usize> = (0..4).filter(|&k| f[k] > 0.0).collect();
    let neg: Vec<usize> = (0..4).filter(|&k| f[k] < 0.0).collect();
    if neg.is_empty() || pos.is_empty() {
        // Not cut: the side is that of the corners off the crack (a
        // tetrahedron lying in the crack plane has no volume anyway).
        out.push((t, if neg.is_empty() { 1.0 } else { -1.0 }));
        return;
    }
    for (side, set) in [(1.0, &pos), (-1.0, &neg)] {
        let others: Vec<usize> = (0..4).filter(|k| !set.contains(k)).collect();
        // Where the edge from corner s (on this side) to corner o leaves
        // the side: o itself when o is on the crack.
        let p = |s: usize, o: usize| if f[o] == 0.0 { t[o] } else { lerp(t[s], t[o], f[s] / (f[s] - f[o])) };
        match set.len() {
            1 => {
                let s = set[0];
                out.push(([t[s], p(s, others[0]), p(s, others[1]), p(s, others[2])], side));
            }
            2 => {
                let (s0, s1) = (set[0], set[1]);
                let (o0, o1) = (others[0], others[1]);
                for piece in prism([t[s0], p(s0, o0), p(s0, o1)], [t[s1], p(s1, o0), p(s1, o1)]) {
                    out.push((piece, side));
                }
            }
            _ => {
                let o = others[0];
                let top = [t[set[0]], t[set[1]], t[set[2]]];
                let bottom = [p(set[0], o), p(set[1], o), p(set[2], o)];
                for piece in prism(top, bottom) {
                    out.push((piece, side));
                }
            }
        }
    }
}

/// The sided rule of the reference cube [-1, 1]³: `level(ξ)` is the normal
/// level set, `cells` the number of sub-cubes along each axis (more near a
/// crack front, whose enrichment is singular), `order` the number of
/// points per direction of each piece's conical rule. Level values below
/// `tol` in magnitude count as exactly on the crack, so that a crack
/// lying on element faces gives whole cells rather than slivers.
pub fn sided_rule(level: impl Fn(P3) -> f64, cells: usize, order: usize, tol: f64) -> Vec<SidedPoint> {
    let rule = tet_conical(order);
    let h = 2.0 / cells as f64;
    let mut pieces = Vec::new();
    let snap = |v: f64| if v.abs() <= tol { 0.0 } else { v };
    for i in 0..cells {
        for j in 0..cells {
            for k in 0..cells {
                let lo = [-1.0 + h * i as f64, -1.0 + h * j as f64, -1.0 + h * k as f64];
                for axes in KUHN {
                    let mut t = [lo; 4];
                    for s in 0..3 {
                        t[s + 1] = t[s];
                        t[s + 1][axes[s]] += h;
                    }
                    let f = [snap(level(t[0])), snap(level(t[1])), snap(level(t[2])), snap(level(t[3]))];
                    cut_tet(t, f, &mut pieces);
                }
            }
        }
    }
    let mut out = Vec::with_capacity(pieces.len() * rule.len());
    for (t, side) in pieces {
        let v6 = volume6(&t);
        if v6 <= 1e-14 * h * h * h {
            continue;
        }
        for &(l, w) in &rule {
            let mut xi = t[0];
            for (c, lc) in l.iter().enumerate() {
                for (d, x) in xi.iter_mut().enumerate() {
                    *x += lc * (t[c + 1][d] - t[0][d]);
                }
            }
            out.push(SidedPoint { xi, w: w * v6, side });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn total(r: &[SidedPoint], side: f64, f: impl Fn(P3) -> f64) -> f64 {
        r.iter().filter(|p| p.side == side).map(|p| p.w * f(p.xi)).sum()
    }

    #[test]
    fn conical_rule_integrates_polynomials() {
        let r = tet_conical(3);
        let vol: f64 = r.iter().map(|p| p.1).sum();
        assert!((vol - 1.0 / 6.0).abs() < 1e-14);
        // ∫ x y z over the unit tetrahedron = 1!·1!·1!/(3+3)! = 1/720.
        let v: f64 = r.iter().map(|(p, w)| w * p[0] * p[1] * p[2]).sum();
        assert!((v - 1.0 / 720.0).abs() < 1e-15);
    }

    #[test]
    fn plane_cut_splits_the_cube_exactly() {
        // The plane x + 0.5 y - 0.3 z = 0.2 is linear, so every piece is
        // exact: each side's volume and first moment match the analytic ones.
        let level = |p: P3| p[0] + 0.5 * p[1] - 0.3 * p[2] - 0.2;
        for cells in [1, 2, 3] {
            let r = sided_rule(level, cells, 3, 0.0);
            let (vp, vm) = (total(&r, 1.0, |_| 1.0), total(&r, -1.0, |_| 1.0));
            assert!((vp + vm - 8.0).abs() < 1e-12);
            // ∫ level over the cube is -0.2·8; the sides split it.
            let ip = total(&r, 1.0, level);
            let im = total(&r, -1.0, level);
            assert!((ip + im + 1.6).abs() < 1e-12);
            assert!(ip > 0.0 && im < 0.0);
            assert!(r.iter().all(|p| level(p.xi) * p.side >= -1e-12));
        }
        // Volume on the positive side of x = 0.2 alone: 0.8·4.
        let r = sided_rule(|p| p[0] - 0.2, 1, 2, 0.0);
        assert!((total(&r, 1.0, |_| 1.0) - 3.2).abs() < 1e-12);
    }

    #[test]
    fn crack_on_a_face_leaves_the_cube_whole() {
        let r = sided_rule(|p| p[2] + 1.0, 1, 2, 1e-12);
        assert!((total(&r, 1.0, |_| 1.0) - 8.0).abs() < 1e-12);
        assert!(r.iter().all(|p| p.side == 1.0));
    }
}
