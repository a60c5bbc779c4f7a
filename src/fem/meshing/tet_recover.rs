//! Boundary recovery: make the edges and triangles of a closed surface
//! appear in a tetrahedrisation of its vertices, by local flips only (no
//! point added, so the surface is kept as given).
//!
//! Two moves: the 2-3 flip (two tetrahedra sharing a face become three
//! around the edge joining their apexes) and the removal of an edge (the
//! tetrahedra around it are replaced by two fans over a triangulation of
//! the ring of its neighbours; with a ring of three this is the 3-2 flip,
//! of four the 4-4 flip). Each move is taken only if every new tetrahedron
//! is strictly positive, and never removes a face or edge of the surface.

use super::tet_delaunay::{Tets, NONE};
use std::collections::HashSet;

/// What a ring triangulation must contain.
#[derive(Clone, Copy)]
enum Need {
    Tri([usize; 3]),
    Edge([usize; 2]),
    Any,
}

pub struct Surface {
    pub faces: HashSet<[usize; 3]>,
    pub edges: HashSet<[usize; 2]>,
}

fn sorted2(a: usize, b: usize) -> [usize; 2] {
    if a < b {
        [a, b]
    } else {
        [b, a]
    }
}

fn with(t: &Tets, vs: &[usize]) -> Vec<usize> {
    t.around(vs[0]).filter(|&k| vs[1..].iter().all(|v| t.tets[k].contains(v))).collect()
}

/// The tetrahedra around edge `uv` in turning order, and the ring of
/// their other vertices (`orient(u, v, r[i], r[i+1]) > 0`); None if the
/// edge is on the outer boundary.
fn ring(t: &Tets, u: usize, v: usize) -> Option<(Vec<usize>, Vec<usize>)> {
    let around = with(t, &[u, v]);
    let t0 = *around.first()?;
    let others = |k: usize| -> (usize, usize) {
        let o: Vec<usize> = t.tets[k].iter().copied().filter(|&x| x != u && x != v).collect();
        if t.orient(u, v, o[0], o[1]) > 0.0 {
            (o[0], o[1])
        } else {
            (o[1], o[0])
        }
    };
    let (mut tets, mut verts) = (vec![], vec![]);
    let mut k = t0;
    loop {
        let (p, q) = others(k);
        tets.push(k);
        verts.push(p);
        let ip = t.tets[k].iter().position(|&x| x == p)?;
        let n = t.nb[k][ip];
        if n == NONE {
            return None;
        }
        let _ = q;
        k = n;
        if k == t0 {
            break;
        }
        if tets.len() > around.len() {
            return None;
        }
    }
    (tets.len() == around.len()).then_some((tets, verts))
}

/// Every triangulation of the polygon of `n` vertices (by index).
fn triangulations(i: usize, j: usize) -> Vec<Vec<[usize; 3]>> {
    if j < i + 2 {
        return vec![vec![]];
    }
    let mut out = vec![];
    for m in i + 1..j {
        for l in triangulations(i, m) {
            for r in triangulations(m, j) {
                let mut tri = l.clone();
                tri.push([i, m, j]);
                tri.extend(r.iter().copied());
                out.push(tri);
            }
        }
    }
    out
}

/// Remove edge `uv` if a valid ring triangulation meets `need`.
fn remove_edge_once(t: &mut Tets, s: &Surface, u: usize, v: usize, need: Need) -> bool {
    if s.edges.contains(&sorted2(u, v)) || u >= t.n_input || v >= t.n_input {
        return false;
    }
    let Some((old, r)) = ring(t, u, v) else { return false };
    if r.len() < 3 || r.len() > 9 {
        return false;
    }
    for tri in triangulations(0, r.len() - 1) {
        let tris: Vec<[usize; 3]> = tri.iter().map(|k| k.map(|i| r[i])).collect();
        let ok = match need {
            Need::Any => true,
            Need::Tri(f) => tris.iter().any(|x| {
                let mut y = *x;
                y.sort_unstable();
                y == f
            }),
            Need::Edge([a, b]) => tris.iter().any(|x| x.contains(&a) && x.contains(&b)),
        };
        if !ok {
            continue;
        }
        let mut new = vec![];
        let mut side = 0.0;
        let mut valid = true;
        for &[x, y, z] in &tris {
            let ou = t.orient(x, y, z, u);
            let ov = t.orient(x, y, z, v);
            if ou == 0.0 || ov == 0.0 || ou.signum() == ov.signum() || (side != 0.0 && ou.signum() != side) {
                valid = false;
                break;
            }
            side = ou.signum();
            if ou > 0.0 {
                new.push([x, y, z, u]);
                new.push([y, x, z, v]);
            } else {
                new.push([y, x, z, u]);
                new.push([x, y, z, v]);
            }
        }
        if valid {
            t.replace(&old, new);
            return true;
        }
    }
    false
}

/// Remove edge `uv` as `remove_edge_once`, after shrinking its ring by 2-3
/// flips when no triangulation of the ring is valid (coplanar points make
/// this common: a ring vertex in the plane of a needed triangle).
fn remove_edge(t: &mut Tets, s: &Surface, u: usize, v: usize, need: Need) -> bool {
    let keep: Vec<usize> = match need {
        Need::Tri(f) => f.to_vec(),
        Need::Edge(e) => e.to_vec(),
        Need::Any => vec![],
    };
    for _ in 0..12 {
        if remove_edge_once(t, s, u, v, need) {
            return true;
        }
        if s.edges.contains(&sorted2(u, v)) {
            return false;
        }
        let Some((tets, r)) = ring(t, u, v) else { return false };
        let n = r.len();
        if n <= 3 {
            return false;
        }
        // Flip away ring vertex r[i]: face (u, v, r[i]) between tets[i-1]
        // and tets[i]; the tet tets[i-1] holds it opposite r[i-1].
        let shrunk = (0..n).filter(|&i| !keep.contains(&r[i])).any(|i| {
            let k = tets[(i + n - 1) % n];
            let prev = r[(i + n - 1) % n];
            match t.tets[k].iter().position(|&x| x == prev) {
                Some(j) => flip23(t, s, k, j),
                None => false,
            }
        });
        if !shrunk {
            return false;
        }
    }
    false
}

/// The 2-3 flip across face `i` of `k`, if the result is valid.
fn flip23(t: &mut Tets, s: &Surface, k: usize, i: usize) -> bool {
    let n = t.nb[k][i];
    if n == NONE {
        return false;
    }
    let q = t.tets[k];
    let a = q[i];
    let Some(j) = (0..4).find(|&j| t.nb[n][j] == k) else { return false };
    let e = t.tets[n][j];
    let f: Vec<usize> = (0..4).filter(|&m| m != i).map(|m| q[m]).collect();
    let mut key = [f[0], f[1], f[2]];
    key.sort_unstable();
    if s.faces.contains(&key) {
        return false;
    }
    let mut new = vec![];
    for (x, y) in [(f[0], f[1]), (f[1], f[2]), (f[2], f[0])] {
        let o = t.orient(x, y, a, e);
        if o == 0.0 {
            return false;
        }
        new.push(if o > 0.0 { [x, y, a, e] } else { [y, x, a, e] });
    }
    let signs: Vec<f64> =
        [(f[0], f[1]), (f[1], f[2]), (f[2], f[0])].iter().map(|&(x, y)| t.orient(x, y, a, e)).collect();
    if !(signs.iter().all(|&o| o > 0.0) || signs.iter().all(|&o| o < 0.0)) {
        return false;
    }
    t.replace(&[k, n], new);
    true
}

fn has_edge(t: &Tets, a: usize, b: usize) -> bool {
    t.around(a).any(|k| t.tets[k].contains(&b))
}

/// Make edge `ab` appear; false if the moves run out.
pub fn recover_edge(t: &mut Tets, s: &Surface, a: usize, b: usize) -> bool {
    for _ in 0..400 {
        if has_edge(t, a, b) {
            return true;
        }
        if !step_edge(t, s, a, b) && !step_edge(t, s, b, a) {
            break;
        }
    }
    false
}

/// One move that brings edge `ab` nearer, walking from `a`.
fn step_edge(t: &mut Tets, s: &Surface, a: usize, b: usize) -> bool {
    for k in with(t, &[a]) {
        if !t.alive[k] {
            continue;
        }
        let q = t.tets[k];
        let i = q.iter().position(|&x| x == a).unwrap_or(0);
        // b beyond the face opposite a?
        let mut r = q;
        r[i] = b;
        if t.orient(r[0], r[1], r[2], r[3]) >= 0.0 {
            continue;
        }
        // The face, in one of its turning orders: the three signs below
        // agree for a crossing whichever way it turns.
        let f: Vec<usize> = (1..4).map(|m| q[(i + m) % 4]).collect();
        let (x, y, z) = (f[0], f[1], f[2]);
        let o = [t.orient(a, b, x, y), t.orient(a, b, y, z), t.orient(a, b, z, x)];
        let pos = o.iter().all(|&v| v >= 0.0);
        let neg = o.iter().all(|&v| v <= 0.0);
        if !(pos || neg) {
            continue;
        }
        let zeros: Vec<usize> = (0..3).filter(|&m| o[m] == 0.0).collect();
        let edges = [(x, y), (y, z), (z, x)];
        match zeros.len() {
            0 => {
                let n = t.nb[k][i];
                let e = if n == NONE { None } else { t.tets[n].iter().copied().find(|v| !q.contains(v)) };
                if flip23(t, s, k, i) {
                    return true;
                }
                for &(u, v) in &edges {
                    let need = e.map_or(Need::Any, |e| Need::Edge([a, e]));
                    if remove_edge(t, s, u, v, need) {
                        return true;
                    }
                }
                for &(u, v) in &edges {
                    if remove_edge(t, s, u, v, Need::Any) {
                        return true;
                    }
                }
            }
            1 => {
                let (u, v) = edges[zeros[0]];
                if remove_edge(t, s, u, v, Need::Edge([a, b])) || remove_edge(t, s, u, v, Need::Any) {
                    return true;
                }
            }
            _ => return false,
        }
    }
    false
}

/// Make triangle `abc` (whose edges exist) a face; false if the moves run out.
pub fn recover_face(t: &mut Tets, s: &Surface, f: [usize; 3]) -> bool {
    let [a, b, c] = f;
    for _ in 0..400 {
        if !with(t, &[a, b, c]).is_empty() {
            return true;
        }
        let mut moved = false;
        'axes: for (p, m, q) in [(a, b, c), (b, c, a), (c, a, b)] {
            for k in with(t, &[p, q]) {
                if !t.alive[k] {
                    continue;
                }
                let o: Vec<usize> = t.tets[k].iter().copied().filter(|&x| x != p && x != q).collect();
                let (u, v) = (o[0], o[1]);
                let (ou, ov) = (t.orient(a, b, c, u), t.orient(a, b, c, v));
                if ou == 0.0 || ov == 0.0 || ou.signum() == ov.signum() {
                    continue;
                }
                let e = [t.orient(u, v, a, b), t.orient(u, v, b, c), t.orient(u, v, c, a)];
                if !(e.iter().all(|&x| x > 0.0) || e.iter().all(|&x| x < 0.0)) {
                    continue;
                }
                let _ = m;
                let mut key = f;
                key.sort_unstable();
                if remove_edge(t, s, u, v, Need::Tri(key)) || remove_edge(t, s, u, v, Need::Any) {
                    moved = true;
                    break 'axes;
                }
            }
        }
        if !moved {
            break;
        }
    }
    false
}

/// One flip that removes the flat tetrahedron `k` (four coplanar points,
/// with the true coordinates now in `t`): a 2-3 flip with a neighbour, or
/// the removal of one of its edges. Recovery runs on perturbed points,
/// where such slivers are not flat.
pub fn unflat(t: &mut Tets, s: &Surface, k: usize) -> bool {
    if (0..4).any(|i| flip23(t, s, k, i)) {
        return true;
    }
    let q = t.tets[k];
    (0..4).any(|a| (a + 1..4).any(|b| remove_edge_once(t, s, q[a], q[b], Need::Any)))
}

/// Whether tetrahedron `k` has no volume.
pub fn flat(t: &Tets, k: usize) -> bool {
    let q = t.tets[k];
    t.orient(q[0], q[1], q[2], q[3]) <= 0.0
}
