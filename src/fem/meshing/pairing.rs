//! Quadrangles from triangles, for SURF under `OPTI ELEM QUA4`/`QUA8`.
//!
//! Cast3M's notice says SURF then meshes with "quadrangles and triangles".
//! We get such a mesh by pairing the triangles of the free triangulation
//! two by two across a shared edge: every possible pair is scored by how
//! far its worst corner is from a right angle, and pairs are taken best
//! first while both triangles are free. Then, as in a maximum matching,
//! each triangle left alone looks for an alternating chain of pairs to
//! re-pair (t u)(w x)… so that it and another lone triangle both find a
//! partner. Pairs whose quadrangle would not be convex enough (a corner
//! beyond 150° or below 30°) are never taken; the triangles left over stay
//! triangles. The result is mostly quadrangles with a few triangles, the
//! contour kept as it was.

use std::collections::HashMap;

/// Worst corner angle allowed in a quadrangle, in degrees from 90°.
const MAX_SKEW: f64 = 60.0;

/// The quadrangles (counter-clockwise, like the triangles) and the
/// triangles left unpaired, both in the order of their first triangle.
pub fn pair(points: &[[f64; 2]], tris: &[[usize; 3]]) -> (Vec<[usize; 4]>, Vec<[usize; 3]>) {
    let mut owner: HashMap<(usize, usize), usize> = HashMap::new();
    for (t, tri) in tris.iter().enumerate() {
        for k in 0..3 {
            owner.insert((tri[k], tri[(k + 1) % 3]), t);
        }
    }
    // Candidate pairs: triangle t = (a, b, c) and its neighbour u across
    // the edge a-b, which holds (b, a, d); the quadrangle is (a, d, b, c).
    let mut cands: Vec<(f64, usize, usize, [usize; 4])> = Vec::new();
    for (t, tri) in tris.iter().enumerate() {
        for k in 0..3 {
            let (a, b, c) = (tri[k], tri[(k + 1) % 3], tri[(k + 2) % 3]);
            let Some(&u) = owner.get(&(b, a)) else { continue };
            if u < t {
                continue;
            }
            let d = tris[u].iter().copied().find(|&n| n != a && n != b).unwrap_or(a);
            let q = [a, d, b, c];
            if let Some(skew) = skew(points, q) {
                cands.push((skew, t, u, q));
            }
        }
    }
    cands.sort_by(|x, y| x.0.total_cmp(&y.0).then(x.1.cmp(&y.1)));
    let mut mate: Vec<Option<usize>> = vec![None; tris.len()];
    let mut quad: HashMap<(usize, usize), [usize; 4]> = HashMap::new();
    let mut near: Vec<Vec<usize>> = vec![Vec::new(); tris.len()];
    for &(_, t, u, q) in &cands {
        quad.insert((t, u), q);
        near[t].push(u);
        near[u].push(t);
        if mate[t].is_none() && mate[u].is_none() {
            mate[t] = Some(u);
            mate[u] = Some(t);
        }
    }
    for t in 0..tris.len() {
        if mate[t].is_none() {
            augment(t, &near, &mut mate);
        }
    }
    let mut quads: Vec<(usize, [usize; 4])> = Vec::new();
    for (t, m) in mate.iter().enumerate() {
        if let Some(u) = *m {
            if t < u {
                quads.push((t, quad[&(t, u)]));
            }
        }
    }
    let left = tris.iter().zip(&mate).filter(|(_, m)| m.is_none()).map(|(t, _)| *t).collect();
    (quads.into_iter().map(|x| x.1).collect(), left)
}

/// Longest alternating chain tried from a lone triangle.
const MAX_CHAIN: usize = 24;

/// Breadth-first search of an alternating chain from the lone triangle
/// `t`: t - u1 = w1 - u2 = w2 … - uk with uk alone (`-` a possible pair,
/// `=` a current one); flipping the chain pairs t and uk. Every triangle
/// is visited once, so the chain is simple and the flip is valid.
fn augment(t: usize, near: &[Vec<usize>], mate: &mut [Option<usize>]) -> bool {
    let mut parent: HashMap<usize, usize> = HashMap::new(); // u -> the w (or t) it was reached from
    let mut seen: std::collections::HashSet<usize> = std::collections::HashSet::from([t]);
    let mut layer = vec![t];
    for _ in 0..MAX_CHAIN {
        let mut next = Vec::new();
        for &w in &layer {
            for &u in &near[w] {
                if !seen.insert(u) {
                    continue;
                }
                parent.insert(u, w);
                match mate[u] {
                    None => {
                        // Flip the chain back to t.
                        let mut u = u;
                        loop {
                            let w = parent[&u];
                            let prev = mate[w];
                            mate[w] = Some(u);
                            mate[u] = Some(w);
                            match prev {
                                Some(p) if w != t => u = p,
                                _ => return true,
                            }
                        }
                    }
                    Some(x) => {
                        if seen.insert(x) {
                            next.push(x);
                        }
                    }
                }
            }
        }
        if next.is_empty() {
            break;
        }
        layer = next;
    }
    false
}

/// The largest deviation from 90° of the corners of the quadrangle, or
/// None when a corner is too flat, too sharp or turns the wrong way.
fn skew(p: &[[f64; 2]], q: [usize; 4]) -> Option<f64> {
    let mut worst: f64 = 0.0;
    for i in 0..4 {
        let (o, a, b) = (p[q[i]], p[q[(i + 1) % 4]], p[q[(i + 3) % 4]]);
        let (u, v) = ([a[0] - o[0], a[1] - o[1]], [b[0] - o[0], b[1] - o[1]]);
        let cross = u[0] * v[1] - u[1] * v[0];
        if cross <= 0.0 {
            return None;
        }
        let angle = cross.atan2(u[0] * v[0] + u[1] * v[1]).to_degrees();
        worst = worst.max((angle - 90.0).abs());
    }
    (worst <= MAX_SKEW).then_some(worst)
}
