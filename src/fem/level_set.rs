//! Level sets of a crack (PSIP): the signed distance to the crack line or
//! surface (PHI), and the signed distances to the line or plane through a
//! crack tip or front, perpendicular to the crack (PSI, and TAU along the
//! front in 3D). X-FEM elements read their local crack frame from them.
//!
//! Near a free end of the crack PHI is the distance to the *extended*
//! line or plane of the nearest facet, not the distance to the tip: with
//! PSI this makes (PSI, PHI) the cartesian coordinates of the point in the
//! tip frame of a straight crack, which is what the crack-tip enrichment
//! and the G-theta procedure build their polar coordinates from.

use super::vec3::{cross, dot, sub, unit};

/// A facet of the crack: its corners (2 in 2D, 3 in 3D) and unit normal.
struct Facet {
    x: Vec<[f64; 3]>,
    n: [f64; 3],
}

/// A crack line (segments, 2D) or surface (triangles, 3D).
pub struct Crack {
    facets: Vec<Facet>,
}

/// The crack seen from a point: its nearest point, the signed distance
/// along the crack normal there, and the index of the nearest facet.
pub struct Nearest {
    pub point: [f64; 3],
    pub phi: f64,
    facet: usize,
}

/// A 2D crack tip: its position and the unit tangent pointing out of the
/// crack (the direction it would grow in).
pub struct Tip {
    pub p: [f64; 3],
    pub t: [f64; 3],
}

fn norm2(a: [f64; 3]) -> f64 {
    dot(a, a)
}

fn axpy(a: [f64; 3], s: f64, d: [f64; 3]) -> [f64; 3] {
    [a[0] + s * d[0], a[1] + s * d[1], a[2] + s * d[2]]
}

/// The point of segment [a, b] nearest to x.
fn closest_on_segment(a: [f64; 3], b: [f64; 3], x: [f64; 3]) -> [f64; 3] {
    let d = sub(b, a);
    let t = (dot(sub(x, a), d) / norm2(d)).clamp(0.0, 1.0);
    axpy(a, t, d)
}

/// The point of triangle abc nearest to p (by the Voronoi regions of its
/// corners, edges and face).
pub(crate) fn closest_on_triangle(a: [f64; 3], b: [f64; 3], c: [f64; 3], p: [f64; 3]) -> [f64; 3] {
    let (ab, ac, ap) = (sub(b, a), sub(c, a), sub(p, a));
    let (d1, d2) = (dot(ab, ap), dot(ac, ap));
    if d1 <= 0.0 && d2 <= 0.0 {
        return a;
    }
    let bp = sub(p, b);
    let (d3, d4) = (dot(ab, bp), dot(ac, bp));
    if d3 >= 0.0 && d4 <= d3 {
        return b;
    }
    let vc = d1 * d4 - d3 * d2;
    if vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0 {
        return axpy(a, d1 / (d1 - d3), ab);
    }
    let cp = sub(p, c);
    let (d5, d6) = (dot(ab, cp), dot(ac, cp));
    if d6 >= 0.0 && d5 <= d6 {
        return c;
    }
    let vb = d5 * d2 - d1 * d6;
    if vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0 {
        return axpy(a, d2 / (d2 - d6), ac);
    }
    let va = d3 * d6 - d5 * d4;
    if va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0 {
        return axpy(b, (d4 - d3) / ((d4 - d3) + (d5 - d6)), sub(c, b));
    }
    // A degenerate (flat) triangle has no face region: its corner will do.
    let sum = va + vb + vc;
    if sum.abs() < 1e-300 {
        return a;
    }
    let den = 1.0 / sum;
    axpy(axpy(a, vb * den, ab), vc * den, ac)
}

impl Crack {
    /// A 2D crack from its segments; the normal is the tangent turned a
    /// quarter turn counter-clockwise (PHI > 0 on the left of the line).
    pub fn from_segments(segs: &[[[f64; 3]; 2]]) -> Result<Crack, String> {
        let mut facets = Vec::with_capacity(segs.len());
        for (i, s) in segs.iter().enumerate() {
            let t = sub(s[1], s[0]);
            let l = norm2(t).sqrt();
            if l <= 0.0 || l.is_nan() {
                return Err(format!("segment {} of the crack has zero length", i + 1));
            }
            facets.push(Facet { x: s.to_vec(), n: [-t[1] / l, t[0] / l, 0.0] });
        }
        Crack::new(facets)
    }

    /// A 3D crack from its triangles; the normal follows the corner order
    /// (right-hand rule).
    pub fn from_triangles(tris: &[[[f64; 3]; 3]]) -> Result<Crack, String> {
        let mut facets = Vec::with_capacity(tris.len());
        for (i, t) in tris.iter().enumerate() {
            let n = cross(sub(t[1], t[0]), sub(t[2], t[0]));
            if norm2(n) <= 0.0 || norm2(n).is_nan() {
                return Err(format!("facet {} of the crack has zero area", i + 1));
            }
            facets.push(Facet { x: t.to_vec(), n: unit(n) });
        }
        Crack::new(facets)
    }

    fn new(facets: Vec<Facet>) -> Result<Crack, String> {
        if facets.is_empty() {
            return Err("the crack mesh has no segment or facet".into());
        }
        Ok(Crack { facets })
    }

    fn closest(&self, f: &Facet, x: [f64; 3]) -> [f64; 3] {
        match f.x.len() {
            2 => closest_on_segment(f.x[0], f.x[1], x),
            _ => closest_on_triangle(f.x[0], f.x[1], f.x[2], x),
        }
    }

    /// The nearest point of the crack to x and PHI there. Where several
    /// facets are nearest (a point facing a corner of the crack), the sign
    /// comes from their mean normal.
    pub fn nearest(&self, x: [f64; 3]) -> Nearest {
        let d: Vec<(f64, [f64; 3])> = self
            .facets
            .iter()
            .map(|f| {
                let c = self.closest(f, x);
                (norm2(sub(x, c)), c)
            })
            .collect();
        let (best, &(dmin, c)) =
            d.iter().enumerate().min_by(|a, b| a.1 .0.total_cmp(&b.1 .0)).expect("a crack has facets");
        let scale = self.facets[best].x.iter().map(|p| norm2(sub(*p, c))).fold(0.0, f64::max);
        let tol = dmin * 1e-9 + scale * 1e-20;
        let mut n = [0.0; 3];
        for (f, (di, _)) in self.facets.iter().zip(&d) {
            if *di <= dmin + tol {
                n = axpy(n, 1.0, f.n);
            }
        }
        let n = if norm2(n) > 1e-12 { unit(n) } else { self.facets[best].n };
        Nearest { point: c, phi: dot(sub(x, c), n), facet: best }
    }

    /// The tip of a 2D crack nearest to p: the end of its segments nearest
    /// to p, with the tangent of that segment pointing out of the crack.
    pub fn tip(&self, p: [f64; 3]) -> Tip {
        let mut best = (f64::INFINITY, [0.0; 3], [0.0; 3]);
        for f in &self.facets {
            for (end, other) in [(f.x[1], f.x[0]), (f.x[0], f.x[1])] {
                let d = norm2(sub(p, end));
                if d < best.0 {
                    best = (d, end, unit(sub(end, other)));
                }
            }
        }
        Tip { p: best.1, t: best.2 }
    }

    /// PSI and TAU of a 3D crack at x: with f the point of the front nearest
    /// to x, τ the front's tangent there and b the direction in the crack
    /// plane perpendicular to the front pointing out of the crack,
    /// PSI = (x − f)·b and TAU = (x − f)·τ.
    pub fn front_levels(&self, front: &[[[f64; 3]; 2]], x: [f64; 3]) -> (f64, f64) {
        let mut best = (f64::INFINITY, [0.0; 3], [1.0, 0.0, 0.0]);
        for s in front {
            let c = closest_on_segment(s[0], s[1], x);
            let d = norm2(sub(x, c));
            if d < best.0 {
                best = (d, c, unit(sub(s[1], s[0])));
            }
        }
        let (f, tau) = (best.1, best.2);
        let near = self.nearest(f);
        let facet = &self.facets[near.facet];
        let mut b = cross(tau, facet.n);
        if norm2(b) < 1e-24 {
            b = sub(f, near.point);
        }
        let b = unit(b);
        let g = facet.x.iter().fold([0.0; 3], |acc, p| axpy(acc, 1.0 / facet.x.len() as f64, *p));
        let b = if dot(b, sub(f, g)) < 0.0 { [-b[0], -b[1], -b[2]] } else { b };
        let r = sub(x, f);
        (dot(r, b), dot(r, tau))
    }
}

/// PSI of a 2D point: its signed distance to the line through the nearest
/// tip, perpendicular to the crack (positive ahead of the tip).
pub fn tip_level(tips: &[Tip], x: [f64; 3]) -> f64 {
    let t = tips.iter().min_by(|a, b| norm2(sub(x, a.p)).total_cmp(&norm2(sub(x, b.p)))).expect("at least one tip");
    dot(sub(x, t.p), t.t)
}

/// The largest coordinate difference between two points (the "infinity
/// norm" distance PSIP's criterion compares with).
pub fn inf_distance(a: [f64; 3], b: [f64; 3]) -> f64 {
    sub(a, b).iter().fold(0.0, |m, v| m.max(v.abs()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn straight_crack_2d_gives_tip_coordinates() {
        let c =
            Crack::from_segments(&[[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]], [[1.0, 0.0, 0.0], [2.0, 0.0, 0.0]]]).unwrap();
        let x = [3.0, -0.5, 0.0];
        assert!((c.nearest(x).phi + 0.5).abs() < 1e-14);
        let tips = [c.tip([2.0, 0.0, 0.0]), c.tip([0.0, 0.0, 0.0])];
        assert!((tip_level(&tips, x) - 1.0).abs() < 1e-14);
        assert!((tip_level(&tips, [-0.5, 1.0, 0.0]) - 0.5).abs() < 1e-14);
    }

    #[test]
    fn plane_crack_3d() {
        let c = Crack::from_triangles(&[[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0]]]).unwrap();
        assert!((c.nearest([0.8, 0.2, -0.3]).phi + 0.3).abs() < 1e-14);
        let (psi, tau) = c.front_levels(&[[[1.0, 0.0, 0.0], [1.0, 1.0, 0.0]]], [1.5, 0.5, 0.2]);
        assert!((psi - 0.5).abs() < 1e-14 && (tau - 0.0).abs() < 1e-14);
    }
}
