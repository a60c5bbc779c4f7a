//! INCL: where points are with respect to a region: inside, on its
//! boundary, or outside. The region is closed lines or a surface in the
//! plane (triangles), or a volume of tetrahedra in space.
//!
//! A point of a simplex region is inside when its barycentric coordinates
//! in some simplex are all >= -eps; it is on the boundary when one of them
//! is ~0 and the facet opposite is on one simplex only (a facet shared by
//! two simplices is inside the region).

use std::collections::HashMap;

#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Where {
    Inside,
    Boundary,
    /// Outside; the least barycentric coordinate of the nearest simplex
    /// (how far outside, relative to the simplex's size).
    Outside(f64),
}

const EPS: f64 = 1e-9;

fn facet_count<const N: usize>(cells: &[[usize; N]]) -> HashMap<Vec<usize>, usize> {
    let mut count = HashMap::new();
    for c in cells {
        for k in 0..N {
            let mut f: Vec<usize> = (0..N).filter(|&j| j != k).map(|j| c[j]).collect();
            f.sort_unstable();
            *count.entry(f).or_insert(0) += 1;
        }
    }
    count
}

fn classify<const N: usize>(
    lambdas: impl Fn(usize) -> Option<[f64; N]>,
    cells: &[[usize; N]],
    count: &HashMap<Vec<usize>, usize>,
) -> Where {
    let mut best = f64::NEG_INFINITY;
    let mut inside = false;
    for (t, c) in cells.iter().enumerate() {
        let Some(l) = lambdas(t) else { continue };
        let m = l.iter().copied().fold(f64::INFINITY, f64::min);
        best = best.max(m);
        if m < -EPS {
            continue;
        }
        inside = true;
        for (k, lk) in l.iter().enumerate() {
            if lk.abs() <= EPS {
                let mut f: Vec<usize> = (0..N).filter(|&j| j != k).map(|j| c[j]).collect();
                f.sort_unstable();
                if count.get(&f) == Some(&1) {
                    return Where::Boundary;
                }
            }
        }
    }
    if inside {
        Where::Inside
    } else {
        Where::Outside(best)
    }
}

/// Points of the plane against triangles of `verts`.
pub fn in_triangles(pts: &[[f64; 2]], verts: &[[f64; 2]], tris: &[[usize; 3]]) -> Vec<Where> {
    let count = facet_count(tris);
    pts.iter()
        .map(|p| {
            let lam = |t: usize| {
                let [a, b, c] = tris[t].map(|i| verts[i]);
                let det = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
                if det == 0.0 {
                    return None;
                }
                let l1 = ((p[0] - a[0]) * (c[1] - a[1]) - (p[1] - a[1]) * (c[0] - a[0])) / det;
                let l2 = ((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])) / det;
                Some([1.0 - l1 - l2, l1, l2])
            };
            classify(lam, tris, &count)
        })
        .collect()
}

/// Points in space against tetrahedra of `verts`.
pub fn in_tetrahedra(pts: &[[f64; 3]], verts: &[[f64; 3]], tets: &[[usize; 4]]) -> Vec<Where> {
    let count = facet_count(tets);
    let det3 = |a: [f64; 3], b: [f64; 3], c: [f64; 3]| {
        a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])
    };
    let sub = |a: [f64; 3], b: [f64; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    pts.iter()
        .map(|p| {
            let lam = |t: usize| {
                let [a, b, c, d] = tets[t].map(|i| verts[i]);
                let (e1, e2, e3, q) = (sub(b, a), sub(c, a), sub(d, a), sub(*p, a));
                let det = det3(e1, e2, e3);
                if det == 0.0 {
                    return None;
                }
                let l1 = det3(q, e2, e3) / det;
                let l2 = det3(e1, q, e3) / det;
                let l3 = det3(e1, e2, q) / det;
                Some([1.0 - l1 - l2 - l3, l1, l2, l3])
            };
            classify(lam, tets, &count)
        })
        .collect()
}

/// Points of the plane against closed lines (even-odd rule); on a line
/// within 1e-9 of the lines' size is the boundary.
pub fn in_lines(pts: &[[f64; 2]], segs: &[[[f64; 2]; 2]]) -> Vec<Where> {
    let mut lo = [f64::INFINITY; 2];
    let mut hi = [f64::NEG_INFINITY; 2];
    for q in segs.iter().flatten() {
        for k in 0..2 {
            lo[k] = lo[k].min(q[k]);
            hi[k] = hi[k].max(q[k]);
        }
    }
    let size = (hi[0] - lo[0]).max(hi[1] - lo[1]);
    let tol = EPS * size.max(f64::MIN_POSITIVE);
    pts.iter()
        .map(|x| {
            let mut inside = false;
            for [a, b] in segs {
                let ab = [b[0] - a[0], b[1] - a[1]];
                let l2 = ab[0] * ab[0] + ab[1] * ab[1];
                let t =
                    if l2 > 0.0 { (((x[0] - a[0]) * ab[0] + (x[1] - a[1]) * ab[1]) / l2).clamp(0.0, 1.0) } else { 0.0 };
                let d = ((x[0] - a[0] - t * ab[0]).powi(2) + (x[1] - a[1] - t * ab[1]).powi(2)).sqrt();
                if d <= tol {
                    return Where::Boundary;
                }
                if (a[1] > x[1]) != (b[1] > x[1]) && a[0] + (x[1] - a[1]) / (b[1] - a[1]) * ab[0] > x[0] {
                    inside = !inside;
                }
            }
            if inside {
                Where::Inside
            } else {
                Where::Outside(f64::NEG_INFINITY)
            }
        })
        .collect()
}
