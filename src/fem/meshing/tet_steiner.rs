//! Steiner points for VOLU of a closed surface: when flips cannot make a
//! surface edge or triangle appear among the tetrahedra (a Schönhardt
//! prism is the classic case: no tetrahedrisation of its six corners
//! exists), the surface is refined and the mesh made again.
//!
//! An edge that is missing is cut at its middle, and so are the two
//! triangles on either side of it; a triangle that is missing (its three
//! edges being there) has its longest edge cut the same way. The new
//! points lie on the surface's own triangles, so the refined surface is
//! the same surface, bounding the same volume; only its triangulation is
//! finer, which is what conforming boundary recovery does (the envelope of
//! the volume then has those extra nodes and triangles).

/// A closed surface of triangles being refined: the points (given ones
/// first, then the points added) and the triangles, turning as given.
pub struct Refined {
    pub pts: Vec<[f64; 3]>,
    pub tris: Vec<[usize; 3]>,
    /// For each point added, the two ends of the edge it cut.
    pub added: Vec<[usize; 2]>,
}

impl Refined {
    /// Cut edge `ab` at its middle, with every triangle that has it.
    /// False if no triangle has it any more (cut in this round already).
    pub fn split_edge(&mut self, a: usize, b: usize) -> bool {
        let users: Vec<usize> =
            (0..self.tris.len()).filter(|&k| self.tris[k].contains(&a) && self.tris[k].contains(&b)).collect();
        if users.is_empty() {
            return false;
        }
        let (pa, pb) = (self.pts[a], self.pts[b]);
        let m = self.pts.len();
        self.pts.push([0, 1, 2].map(|k| 0.5 * (pa[k] + pb[k])));
        self.added.push([a, b]);
        for k in users {
            let t = self.tris[k];
            // The edge as the triangle runs it, from t[i] to t[i + 1]:
            // both halves keep the triangle's turning.
            let i = (0..3).find(|&i| {
                let (x, y) = (t[i], t[(i + 1) % 3]);
                (x == a && y == b) || (x == b && y == a)
            });
            let Some(i) = i else { continue };
            let (x, y, o) = (t[i], t[(i + 1) % 3], t[(i + 2) % 3]);
            self.tris[k] = [x, m, o];
            self.tris.push([m, y, o]);
        }
        true
    }

    /// Cut the longest edge of triangle `f` (given by its sorted corners).
    pub fn split_face(&mut self, f: [usize; 3]) -> bool {
        let len = |a: usize, b: usize| {
            let (p, q) = (self.pts[a], self.pts[b]);
            (0..3).map(|k| (p[k] - q[k]).powi(2)).sum::<f64>()
        };
        let mut edges = [(f[0], f[1]), (f[1], f[2]), (f[0], f[2])];
        edges.sort_by(|x, y| len(y.0, y.1).total_cmp(&len(x.0, x.1)));
        let (a, b) = edges[0];
        self.split_edge(a, b)
    }
}
