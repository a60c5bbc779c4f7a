//! DALL: a structured surface from four sides, by transfinite (Coons)
//! interpolation.

use super::grading::MAX_COUNT;
use super::query::line_chain;
use super::vec3::{add, dist, scale, sub, V3};
use super::{check_nodes, fail, mesh_of, MeshError};
use crate::fem::mesh::{ElemType, Mesh, Nodes};

const OP: &str = "DALL";

/// `DALL c1 c2 c3 c4`: a structured mesh of QUA4, TRI3, QUA8 or TRI6 (`ty`,
/// the current `OPTI ELEM`) filling the contour `c1 c2 c3 c4`.
///
/// The sides must follow each other around the contour, each one in either
/// direction: as Cast3M does, a side that runs the other way is read
/// reversed (see [`orient_sides`]). Opposite sides may
/// have different numbers of elements (see [`super::dall_unequal`]).
/// Linear elements need SEG2 sides, quadratic ones SEG3 sides.
///
/// Think of the surface as a grid `N(i, j)`, `i` running along side 1 (from
/// its start `A`) and `j` from side 1 towards side 3; side 2 is `i = max`,
/// side 3 `j = max` (run backwards) and side 4 `i = 0` (run backwards).
/// Interior positions come from the Coons patch of the four sides, with
/// grid parameters blended from the arc-length positions of the side nodes
/// so graded sides stay graded inside. Densities are interpolated the same
/// way.
///
/// * New nodes are appended row by row (`j` outer, `i` inner), skipping the
///   element centres that QUA8 does not use.
/// * Elements come row by row from the corner `A`: cell `(i, j)` is the
///   QUA4 `N(i,j) N(i+1,j) N(i+1,j+1) N(i,j+1)`, so element 1 starts at `A`
///   along side 1, and every element turns like the contour (counter-
///   clockwise in 2D when the contour is). TRI3 split each cell along its
///   `N(i,j)–N(i+1,j+1)` diagonal, first the triangle on side 1's side.
///   QUA8/TRI6 are the same on the grid of element corners, with the
///   interleaved corner/mid-side node order of Cast3M.
pub fn dall(nodes: &mut Nodes, sides: [&Mesh; 4], ty: ElemType) -> Result<Mesh, MeshError> {
    let quadratic = match ty {
        ElemType::Qua4 | ElemType::Tri3 => false,
        ElemType::Qua8 | ElemType::Tri6 => true,
        other => {
            return fail(OP, format!("makes QUA4, TRI3, QUA8 or TRI6 elements, not {} (check OPTI ELEM)", other.name()))
        }
    };
    let want = if quadratic { ElemType::Seg3 } else { ElemType::Seg2 };
    let mut chains: Vec<Vec<usize>> = Vec::with_capacity(4);
    for (k, side) in sides.iter().enumerate() {
        check_nodes(OP, nodes, side)?;
        if let Some(p) = side.parts.iter().find(|p| !p.is_empty() && p.ty != want) {
            return fail(
                OP,
                format!(
                    "{} elements need {} sides; side {} is made of {} (build the sides with the same OPTI ELEM)",
                    ty.name(),
                    want.name(),
                    k + 1,
                    p.ty.name()
                ),
            );
        }
        // A side whose elements are not listed head to tail (`l2 ET l1`)
        // is put in order first, as ORIE does for lines.
        let c = line_chain(OP, side)
            .or_else(|e| super::orie(nodes, side, 3).and_then(|o| line_chain(OP, &o)).map_err(|_| e))
            .map_err(|e| super::MeshError::new(OP, format!("side {}: {}", k + 1, e.message)))?;
        chains.push(c);
    }
    orient_sides(&mut chains);
    check_contour(nodes, &chains)?;
    let per_elem = if quadratic { 2 } else { 1 };
    let unequal = [(2, 0), (3, 1)].iter().any(|&(k, opp)| chains[k].len() != chains[opp].len());
    if unequal {
        return super::dall_unequal::dall_unequal(nodes, &chains, ty);
    }
    for (k, opp) in [(2, 0), (3, 1)] {
        if chains[k].len() != chains[opp].len() {
            return fail(
                OP,
                format!(
                    "opposite sides must have the same number of elements: side {} has {} but side {} has {}",
                    k + 1,
                    (chains[k].len() - 1) / per_elem,
                    opp + 1,
                    (chains[opp].len() - 1) / per_elem
                ),
            );
        }
    }
    // Each side is at most MAX_COUNT long, but the grid is their product.
    let cells = (chains[0].len() - 1).saturating_mul(chains[1].len() - 1) / (per_elem * per_elem);
    if cells > MAX_COUNT {
        return fail(OP, format!("{cells} elements is more than the {MAX_COUNT} allowed"));
    }
    let grid = Grid::build(nodes, &chains, |i, j| !(ty == ElemType::Qua8 && i % 2 == 1 && j % 2 == 1));
    Ok(grid.elements(ty))
}

/// Turn the sides head to tail: side 1 keeps its direction unless only its
/// start touches side 2, and each next side starts where the previous one
/// ends, reversed if it ends there instead.
fn orient_sides(c: &mut [Vec<usize>]) {
    let ends = |v: &Vec<usize>| (v[0], *v.last().unwrap_or(&v[0]));
    let (s1, e1) = ends(&c[0]);
    let (s2, e2) = ends(&c[1]);
    if e1 != s2 && e1 != e2 && (s1 == s2 || s1 == e2) {
        c[0].reverse();
    }
    for k in 1..4 {
        let prev = *c[k - 1].last().unwrap_or(&usize::MAX);
        if c[k][0] != prev && c[k].last() == Some(&prev) {
            c[k].reverse();
        }
    }
}

/// The contour must close: report the first break, with a hint when the
/// break is two distinct points at the same place.
fn check_contour(nodes: &Nodes, c: &[Vec<usize>]) -> Result<(), MeshError> {
    for k in 0..4 {
        let next = (k + 1) % 4;
        let end = *c[k].last().unwrap_or(&usize::MAX);
        let start = c[next][0];
        if end == start {
            continue;
        }
        let hint = if dist(nodes.get(end), nodes.get(start)) == 0.0 {
            " (they are different points at the same place: merge them with ELIM)"
        } else {
            ""
        };
        let what = if next == 0 {
            "side 1 does not start where side 4 ends".to_string()
        } else {
            format!("side {} does not start where side {} ends", next + 1, k + 1)
        };
        return fail(OP, format!("the four sides do not form a closed contour ({what}){hint}"));
    }
    Ok(())
}

/// The node grid `N(i, j)`, `0 <= i <= m1`, `0 <= j <= m2`, on the finest
/// lattice (mid-side nodes included for quadratic elements).
struct Grid {
    m1: usize,
    m2: usize,
    ids: Vec<usize>,
}

impl Grid {
    fn at(&self, i: usize, j: usize) -> usize {
        self.ids[j * (self.m1 + 1) + i]
    }

    /// Place the side nodes and create the interior ones for which `needed`
    /// holds (the others get `usize::MAX` and must never be used).
    fn build(nodes: &mut Nodes, c: &[Vec<usize>], needed: impl Fn(usize, usize) -> bool) -> Grid {
        let (m1, m2) = (c[0].len() - 1, c[1].len() - 1);
        let w = m1 + 1;
        let mut ids = vec![usize::MAX; w * (m2 + 1)];
        for i in 0..=m1 {
            ids[i] = c[0][i];
            ids[m2 * w + i] = c[2][m1 - i];
        }
        for j in 0..=m2 {
            ids[j * w + m1] = c[1][j];
            ids[j * w] = c[3][m2 - j];
        }
        // Arc-length positions of the side nodes, all running in the grid's
        // i (sides 1, 3) or j (sides 2, 4) direction.
        let u1 = arc_fractions(nodes, &c[0]);
        let v2 = arc_fractions(nodes, &c[1]);
        let u3: Vec<f64> = arc_fractions(nodes, &c[2]).iter().rev().map(|s| 1.0 - s).collect();
        let v4: Vec<f64> = arc_fractions(nodes, &c[3]).iter().rev().map(|s| 1.0 - s).collect();
        // The sides' nodes in grid order (i for sides 1 and 3, j for 2 and 4).
        let c1: Vec<usize> = (0..=m1).map(|i| ids[i]).collect();
        let c3: Vec<usize> = (0..=m1).map(|i| ids[m2 * w + i]).collect();
        let c2: Vec<usize> = (0..=m2).map(|j| ids[j * w + m1]).collect();
        let c4: Vec<usize> = (0..=m2).map(|j| ids[j * w]).collect();
        let p = |n: usize| (nodes.get(n), nodes.density[n]);
        let corners = [p(c[0][0]), p(c[1][0]), p(c[2][0]), p(c[3][0])];
        let mut new = Vec::new();
        for j in 1..m2 {
            for i in 1..m1 {
                if !needed(i, j) {
                    continue;
                }
                // Solve u = (1-v) u1 + v u3, v = (1-u) v4 + u v2 (a 2x2
                // linear system whose determinant stays positive because all
                // fractions lie in [0, 1]).
                let (du, dv) = (u3[i] - u1[i], v2[j] - v4[j]);
                let u = (u1[i] + v4[j] * du) / (1.0 - du * dv);
                let v = v4[j] + u * dv;
                // Each side at the point's own parameter (not at the side
                // node of the same index): with unequal gradings on opposite
                // sides the index-sampled patch folds rows out of the contour.
                let sides = [
                    along(nodes, &c1, &u1, u),
                    along(nodes, &c2, &v2, v),
                    along(nodes, &c3, &u3, u),
                    along(nodes, &c4, &v4, v),
                ];
                let w_side = [1.0 - v, u, v, 1.0 - u];
                let w_corner = [(1.0 - u) * (1.0 - v), u * (1.0 - v), u * v, (1.0 - u) * v];
                let mut x: V3 = [0.0; 3];
                let mut d = 0.0;
                for k in 0..4 {
                    x = add(x, sub(scale(sides[k].0, w_side[k]), scale(corners[k].0, w_corner[k])));
                    d += w_side[k] * sides[k].1 - w_corner[k] * corners[k].1;
                }
                new.push((j * w + i, x, d));
            }
        }
        for (idx, x, d) in new {
            ids[idx] = nodes.push(x, d);
        }
        Grid { m1, m2, ids }
    }

    /// Elements row by row on the grid of element corners (step 2 for
    /// quadratic types).
    fn elements(&self, ty: ElemType) -> Mesh {
        let s = if matches!(ty, ElemType::Qua8 | ElemType::Tri6) { 2 } else { 1 };
        let h = s / 2;
        let mut conn = Vec::with_capacity(ty.nodes() * (self.m1 / s) * (self.m2 / s) * 2);
        for j in (0..self.m2).step_by(s) {
            for i in (0..self.m1).step_by(s) {
                let (a, b) = (self.at(i, j), self.at(i + s, j));
                let (c, d) = (self.at(i + s, j + s), self.at(i, j + s));
                match ty {
                    ElemType::Qua4 => conn.extend([a, b, c, d]),
                    ElemType::Tri3 => conn.extend([a, b, c, a, c, d]),
                    _ => {
                        let (ab, bc) = (self.at(i + h, j), self.at(i + s, j + h));
                        let (cd, da) = (self.at(i + h, j + s), self.at(i, j + h));
                        if ty == ElemType::Qua8 {
                            conn.extend([a, ab, b, bc, c, cd, d, da]);
                        } else {
                            let o = self.at(i + h, j + h);
                            conn.extend([a, ab, b, bc, c, o, a, o, c, cd, d, da]);
                        }
                    }
                }
            }
        }
        mesh_of(vec![(ty, conn)])
    }
}

/// The point (and density) at fraction `s` of a side whose nodes `chain`
/// sit at the increasing fractions `fr`, linear between nodes.
fn along(nodes: &Nodes, chain: &[usize], fr: &[f64], s: f64) -> (V3, f64) {
    let k = fr.windows(2).position(|w| s <= w[1]).unwrap_or(fr.len().saturating_sub(2)).min(chain.len() - 1);
    if k + 1 >= chain.len() {
        return (nodes.get(chain[k]), nodes.density[chain[k]]);
    }
    let span = fr[k + 1] - fr[k];
    let t = if span > 0.0 { ((s - fr[k]) / span).clamp(0.0, 1.0) } else { 0.0 };
    let (a, b) = (chain[k], chain[k + 1]);
    let x = add(scale(nodes.get(a), 1.0 - t), scale(nodes.get(b), t));
    (x, (1.0 - t) * nodes.density[a] + t * nodes.density[b])
}

/// Cumulative arc length of a chain as fractions of its total (index
/// fractions if the chain has no length).
fn arc_fractions(nodes: &Nodes, chain: &[usize]) -> Vec<f64> {
    let mut s = vec![0.0];
    for w in chain.windows(2) {
        let last = *s.last().unwrap_or(&0.0);
        s.push(last + dist(nodes.get(w[0]), nodes.get(w[1])));
    }
    let total = *s.last().unwrap_or(&0.0);
    let n = (chain.len() - 1).max(1) as f64;
    s.iter().enumerate().map(|(k, &x)| if total > 0.0 { x / total } else { k as f64 / n }).collect()
}
