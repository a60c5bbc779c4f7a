//! Integration of an enriched QUA4 by sub-cells: the reference square is
//! split into four triangles about its centre, each is cut along PHI = 0
//! (PHI linear on it, from its corners and the centre's mean value) into
//! sub-triangles lying wholly on one side of the crack, and a degree-5
//! triangle rule is used on each. The jump and the tip functions are
//! smooth on every sub-triangle, so the rule sees no discontinuity; near a
//! tip, where the tip functions' derivatives grow like r^-1/2, the
//! sub-triangles are further divided `levels` times.

use crate::fem::quadrature::{tri, QPoint};

/// A sub-cell point: reference coordinates, weight in the reference
/// square, and the side of the crack (±1).
pub type SidePoint = (QPoint, f64);

type P2 = [f64; 2];

fn lerp(a: P2, b: P2, fa: f64, fb: f64) -> P2 {
    let t = fa / (fa - fb);
    [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]
}

fn side_of(f: f64) -> f64 {
    if f < 0.0 {
        -1.0
    } else {
        1.0
    }
}

/// Sub-triangles of triangle `p` (values `f` at its corners) on one side
/// of f = 0 each, with their side.
fn cut(p: [P2; 3], f: [f64; 3], out: &mut Vec<([P2; 3], f64)>) {
    let pos = f.iter().filter(|v| **v > 0.0).count();
    let neg = f.iter().filter(|v| **v < 0.0).count();
    if pos == 0 || neg == 0 {
        out.push((p, if neg > 0 { -1.0 } else { 1.0 }));
        return;
    }
    if pos + neg == 2 {
        // One corner on the line: split through it.
        let z = f.iter().position(|v| *v == 0.0).unwrap_or(0);
        let (i, j) = ((z + 1) % 3, (z + 2) % 3);
        let m = lerp(p[i], p[j], f[i], f[j]);
        out.push(([p[z], p[i], m], side_of(f[i])));
        out.push(([p[z], m, p[j]], side_of(f[j])));
        return;
    }
    // The corner alone on its side, and the two others.
    let lone = (0..3).find(|&i| (f[i] > 0.0) == (pos == 1)).unwrap_or(0);
    let (j, k) = ((lone + 1) % 3, (lone + 2) % 3);
    let a = lerp(p[lone], p[j], f[lone], f[j]);
    let b = lerp(p[lone], p[k], f[lone], f[k]);
    out.push(([p[lone], a, b], side_of(f[lone])));
    out.push(([a, p[j], p[k]], side_of(f[j])));
    out.push(([a, p[k], b], side_of(f[j])));
}

fn split4(t: [P2; 3]) -> [[P2; 3]; 4] {
    let m = |a: P2, b: P2| [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0];
    let (m01, m12, m20) = (m(t[0], t[1]), m(t[1], t[2]), m(t[2], t[0]));
    [[t[0], m01, m20], [m01, t[1], m12], [m20, m12, t[2]], [m01, m12, m20]]
}

/// Quadrature of the reference square [-1, 1]² cut by the bilinear `phi`
/// given at its four corners (QUA4 order).
pub fn quad_rule(phi: &[f64], levels: usize) -> Vec<SidePoint> {
    let corners: [P2; 4] = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];
    let fc = phi.iter().sum::<f64>() / 4.0;
    let mut cells = Vec::new();
    for k in 0..4 {
        let l = (k + 1) % 4;
        cut([[0.0, 0.0], corners[k], corners[l]], [fc, phi[k], phi[l]], &mut cells);
    }
    for _ in 0..levels {
        cells = cells.into_iter().flat_map(|(t, s)| split4(t).into_iter().map(move |c| (c, s))).collect();
    }
    let rule = tri(7);
    let mut out = Vec::with_capacity(cells.len() * rule.len());
    for (t, s) in cells {
        let (e1, e2) = ([t[1][0] - t[0][0], t[1][1] - t[0][1]], [t[2][0] - t[0][0], t[2][1] - t[0][1]]);
        let det = (e1[0] * e2[1] - e1[1] * e2[0]).abs();
        if det == 0.0 {
            continue;
        }
        for (q, w) in &rule {
            let x = [t[0][0] + q[0] * e1[0] + q[1] * e2[0], t[0][1] + q[0] * e1[1] + q[1] * e2[1], 0.0];
            out.push(((x, w * det), s));
        }
    }
    out
}

/// Quadrature of the reference square for an element holding the crack
/// tip at reference point `tip`: triangles fanned from the tip, cut along
/// PHI = 0 (which passes through the tip, so every piece keeps the tip as
/// a corner), each integrated by a collapsed (Duffy) Gauss rule of n × n
/// points, whose Jacobian vanishes at the tip like r and so cancels the
/// 1/r of the tip functions' strain energy. Each piece is fanned into
/// `fan` thinner ones, each with 6 × 6 points; the radial coordinate is
/// u = s², which makes the √r of the tip functions polynomial in s.
pub fn tip_rule(phi: &[f64], tip: [f64; 2], fan: usize) -> Vec<SidePoint> {
    let corners: [P2; 4] = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];
    let mut cells = Vec::new();
    for k in 0..4 {
        let l = (k + 1) % 4;
        cut([tip, corners[k], corners[l]], [0.0, phi[k], phi[l]], &mut cells);
    }
    let g = gauss_legendre(6);
    let mut out = Vec::new();
    for (t, s) in cells {
        // Put the tip first: `cut` keeps it as the first corner of each piece.
        let t = if t[0] == tip {
            t
        } else if t[1] == tip {
            [t[1], t[2], t[0]]
        } else if t[2] == tip {
            [t[2], t[0], t[1]]
        } else {
            t
        };
        for f in 0..fan {
            let at = |k: usize| {
                let s = k as f64 / fan as f64;
                [t[1][0] + s * (t[2][0] - t[1][0]), t[1][1] + s * (t[2][1] - t[1][1])]
            };
            duffy([t[0], at(f), at(f + 1)], s, &g, &mut out);
        }
    }
    out
}

/// The collapsed Gauss rule on triangle `t`, singular corner first.
fn duffy(t: [P2; 3], s: f64, g: &[(f64, f64)], out: &mut Vec<SidePoint>) {
    {
        let (e1, e2) = ([t[1][0] - t[0][0], t[1][1] - t[0][1]], [t[2][0] - t[0][0], t[2][1] - t[0][1]]);
        let det = (e1[0] * e2[1] - e1[1] * e2[0]).abs();
        if det <= 1e-14 {
            return;
        }
        for &(a, wa) in g {
            let sv = (a + 1.0) / 2.0;
            let u = sv * sv;
            for &(b, wb) in g {
                let v = (b + 1.0) / 2.0;
                let x =
                    [t[0][0] + u * ((1.0 - v) * e1[0] + v * e2[0]), t[0][1] + u * ((1.0 - v) * e1[1] + v * e2[1]), 0.0];
                out.push(((x, wa * wb / 4.0 * 2.0 * sv * u * det), s));
            }
        }
    }
}

/// Gauss–Legendre points and weights on [-1, 1] (Newton on Pₙ).
fn gauss_legendre(n: usize) -> Vec<(f64, f64)> {
    (0..n)
        .map(|i| {
            let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            let mut dp = 1.0;
            for _ in 0..100 {
                let (mut p0, mut p1) = (1.0, x);
                for k in 2..=n {
                    let p2 = ((2 * k - 1) as f64 * x * p1 - (k - 1) as f64 * p0) / k as f64;
                    p0 = p1;
                    p1 = p2;
                }
                dp = n as f64 * (x * p1 - p0) / (x * x - 1.0);
                let dx = p1 / dp;
                x -= dx;
                if dx.abs() < 1e-15 {
                    break;
                }
            }
            (x, 2.0 / ((1.0 - x * x) * dp * dp))
        })
        .collect()
}
