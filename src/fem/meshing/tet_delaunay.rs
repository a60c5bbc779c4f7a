//! Delaunay tetrahedrisation of points in space (Bowyer-Watson insertion),
//! with the local re-triangulations that boundary recovery needs.
//!
//! Orientation and in-sphere tests are the `robust` crate's exact adaptive
//! predicates (Shewchuk's), so the decisions are exact: a tetrahedron kept
//! here has a strictly positive orientation (`orient3d > 0` in Shewchuk's
//! sign, the reverse of Cast3M's positive TET4). No 3D Delaunay crate with a
//! permissive licence was at hand (TetGen, behind `tritet`, is AGPL); the
//! predicates, the delicate part, are the crate's.
//!
//! The points are inserted into a large enclosing tetrahedron whose four
//! corners are the last four points; tetrahedra touching them are outside
//! the points' hull.

use super::{fail, MeshError};
use robust::{insphere, orient3d, Coord3D};
use std::collections::HashMap;

pub const NONE: usize = usize::MAX;

fn c(p: [f64; 3]) -> Coord3D<f64> {
    Coord3D { x: p[0], y: p[1], z: p[2] }
}

/// A tetrahedrisation with face adjacency: `nb[t][i]` is the tetrahedron
/// across the face opposite vertex `i` of `t` (or NONE).
pub struct Tets {
    pub pts: Vec<[f64; 3]>,
    pub tets: Vec<[usize; 4]>,
    pub nb: Vec<[usize; 4]>,
    pub alive: Vec<bool>,
    /// The first of the four enclosing corners (they are the last points).
    pub n_input: usize,
    last: usize,
    /// For each vertex, the tetrahedra ever made on it (dead ones too:
    /// tetrahedra are only appended, so the list is filtered on reading).
    /// Boundary recovery asks "which tetrahedra touch this vertex" at every
    /// move; scanning all tetrahedra made VOLU quadratic on large surfaces.
    star: Vec<Vec<usize>>,
}

/// The face opposite vertex `i`, as a sorted triple (a key).
pub fn face_key(t: &[usize; 4], i: usize) -> [usize; 3] {
    let mut f = [0; 3];
    let mut k = 0;
    for (j, &v) in t.iter().enumerate() {
        if j != i {
            f[k] = v;
            k += 1;
        }
    }
    f.sort_unstable();
    f
}

impl Tets {
    pub fn orient(&self, a: usize, b: usize, c3: usize, d: usize) -> f64 {
        orient3d(c(self.pts[a]), c(self.pts[b]), c(self.pts[c3]), c(self.pts[d]))
    }

    /// Orientation of `t` with vertex `i` replaced by point `p`.
    fn orient_with(&self, t: &[usize; 4], i: usize, p: usize) -> f64 {
        let mut q = *t;
        q[i] = p;
        self.orient(q[0], q[1], q[2], q[3])
    }

    /// The Delaunay tetrahedrisation of `pts` (all finite, none repeated).
    pub fn delaunay(op: &'static str, pts: &[[f64; 3]]) -> Result<Tets, MeshError> {
        if pts.iter().flatten().any(|x| !x.is_finite()) {
            return fail(op, "a point has a coordinate that is not a finite number");
        }
        let (lo, hi) = bounding_box(pts);
        let mid = [0, 1, 2].map(|k| 0.5 * (lo[k] + hi[k]));
        let size = (0..3).map(|k| hi[k] - lo[k]).fold(0.0, f64::max).max(1e-300);
        // Far corners: the hull tetrahedra they spoil are only the very flat
        // ones, of no volume to speak of.
        let r = 1e5 * size;
        let corners = [[r, r, r], [r, -r, -r], [-r, r, -r], [-r, -r, r]].map(|d| [0, 1, 2].map(|k| mid[k] + d[k]));
        let n = pts.len();
        let mut all = pts.to_vec();
        all.extend(corners);
        let mut t = Tets { pts: all, tets: vec![], nb: vec![], alive: vec![], n_input: n, last: 0, star: vec![] };
        let mut first = [n, n + 1, n + 2, n + 3];
        if t.orient(first[0], first[1], first[2], first[3]) < 0.0 {
            first.swap(2, 3);
        }
        t.tets.push(first);
        t.nb.push([NONE; 4]);
        t.alive.push(true);
        t.note_star(0);
        // A fixed pseudo-random order: expected linear walks, reproducible.
        let mut order: Vec<usize> = (0..n).collect();
        let mut s: u64 = 0x9e37_79b9_7f4a_7c15;
        for i in (1..n).rev() {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            order.swap(i, (s % (i as u64 + 1)) as usize);
        }
        for p in order {
            t.insert(op, p)?;
        }
        Ok(t)
    }

    /// The tetrahedron containing point `p` (walking from the last one made).
    fn locate(&self, p: usize) -> Option<usize> {
        let mut t = self.last;
        if !self.alive[t] {
            t = self.alive.iter().rposition(|&a| a)?;
        }
        let mut turn = 0usize;
        for _ in 0..(4 * self.tets.len() + 16) {
            let tet = self.tets[t];
            let mut moved = false;
            for k in 0..4 {
                let i = (k + turn) % 4;
                if self.orient_with(&tet, i, p) < 0.0 {
                    if self.nb[t][i] == NONE {
                        return None;
                    }
                    t = self.nb[t][i];
                    moved = true;
                    break;
                }
            }
            if !moved {
                return Some(t);
            }
            turn = turn.wrapping_add(1);
        }
        // The walk cycled (it cannot on a Delaunay set): search them all.
        (0..self.tets.len()).find(|&t| self.alive[t] && (0..4).all(|i| self.orient_with(&self.tets[t], i, p) >= 0.0))
    }

    fn insert(&mut self, op: &'static str, p: usize) -> Result<(), MeshError> {
        let t0 = self.locate(p).ok_or_else(|| MeshError::new(op, "a point is outside the enclosing tetrahedron"))?;
        if let Some(&q) = self.tets[t0].iter().find(|&&q| self.pts[q] == self.pts[p]) {
            return fail(op, format!("points {} and {} are at the same place (merge them with ELIM)", q + 1, p + 1));
        }
        let mut inside = vec![t0];
        let mut mark: HashMap<usize, ()> = HashMap::new();
        mark.insert(t0, ());
        let mut k = 0;
        while k < inside.len() {
            let t = inside[k];
            k += 1;
            for i in 0..4 {
                let n = self.nb[t][i];
                if n == NONE || mark.contains_key(&n) {
                    continue;
                }
                let q = self.tets[n];
                if insphere(c(self.pts[q[0]]), c(self.pts[q[1]]), c(self.pts[q[2]]), c(self.pts[q[3]]), c(self.pts[p]))
                    > 0.0
                {
                    mark.insert(n, ());
                    inside.push(n);
                }
            }
        }
        // The cavity must see each of its faces from p: a face p lies on
        // (cospherical or coplanar points) takes in the tetrahedron beyond.
        loop {
            let mut grow = None;
            'scan: for &t in &inside {
                for i in 0..4 {
                    let n = self.nb[t][i];
                    if n != NONE && mark.contains_key(&n) {
                        continue;
                    }
                    if self.orient_with(&self.tets[t], i, p) <= 0.0 {
                        if n == NONE {
                            return fail(op, "a point lies on the enclosing tetrahedron");
                        }
                        grow = Some(n);
                        break 'scan;
                    }
                }
            }
            match grow {
                Some(n) => {
                    mark.insert(n, ());
                    inside.push(n);
                }
                None => break,
            }
        }
        let mut new = Vec::new();
        for &t in &inside {
            for i in 0..4 {
                let n = self.nb[t][i];
                if n == NONE || !mark.contains_key(&n) {
                    let mut q = self.tets[t];
                    q[i] = p;
                    new.push(q);
                }
            }
        }
        self.replace(&inside, new);
        Ok(())
    }

    fn note_star(&mut self, id: usize) {
        for v in self.tets[id] {
            if self.star.len() <= v {
                self.star.resize_with(v + 1, Vec::new);
            }
            self.star[v].push(id);
        }
    }

    /// The living tetrahedra that have vertex `v`.
    pub fn around(&self, v: usize) -> impl Iterator<Item = usize> + '_ {
        self.star.get(v).into_iter().flatten().copied().filter(move |&k| self.alive[k] && self.tets[k].contains(&v))
    }

    /// Replace tetrahedra `old` by `new` (filling the same region, each
    /// positively oriented), keeping the adjacency. Returns the new indices.
    pub fn replace(&mut self, old: &[usize], new: Vec<[usize; 4]>) -> Vec<usize> {
        let mut outer: HashMap<[usize; 3], (usize, usize)> = HashMap::new();
        let olds: std::collections::HashSet<usize> = old.iter().copied().collect();
        for &t in old {
            for i in 0..4 {
                let n = self.nb[t][i];
                if n != NONE && !olds.contains(&n) {
                    let j = (0..4).find(|&j| self.nb[n][j] == t).unwrap_or(0);
                    outer.insert(face_key(&self.tets[t], i), (n, j));
                }
            }
            self.alive[t] = false;
        }
        let mut ids = Vec::with_capacity(new.len());
        let mut open: HashMap<[usize; 3], (usize, usize)> = HashMap::new();
        for q in new {
            let id = self.tets.len();
            self.tets.push(q);
            self.nb.push([NONE; 4]);
            self.alive.push(true);
            self.note_star(id);
            ids.push(id);
            for i in 0..4 {
                let key = face_key(&q, i);
                if let Some((n, j)) = outer.remove(&key) {
                    self.nb[id][i] = n;
                    self.nb[n][j] = id;
                } else if let Some((m, j)) = open.remove(&key) {
                    self.nb[id][i] = m;
                    self.nb[m][j] = id;
                } else {
                    open.insert(key, (id, i));
                }
            }
        }
        if let Some(&l) = ids.last() {
            self.last = l;
        }
        ids
    }

    /// Whether `t` has one of the enclosing corners.
    pub fn touches_corner(&self, t: usize) -> bool {
        self.tets[t].iter().any(|&v| v >= self.n_input)
    }

    /// The living tetrahedra made only of input points.
    pub fn inner(&self) -> Vec<[usize; 4]> {
        (0..self.tets.len()).filter(|&t| self.alive[t] && !self.touches_corner(t)).map(|t| self.tets[t]).collect()
    }
}

/// The smallest and largest coordinates of the points.
pub(crate) fn bounding_box(pts: &[[f64; 3]]) -> ([f64; 3], [f64; 3]) {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for p in pts {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    (lo, hi)
}
