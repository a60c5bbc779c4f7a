//! Magnetostatic fields of given currents in vacuum (Biot–Savart): the
//! vector potential A and the induction B of circular coils (closed or
//! arcs) and straight bars, of rectangular or trapezoidal cross section,
//! down to sheets and wires when a dimension is zero.
//!
//! A circular filament has the closed form in complete elliptic integrals
//! (Jackson, Classical Electrodynamics, §5.5); a straight segment has its
//! elementary closed form; an arc of filament is integrated along its
//! angle. Thick conductors integrate filaments over the cross section with
//! Gauss–Legendre panels graded towards the point where the field is
//! wanted, since the integrand is singular there when the point lies inside
//! the conductor (logarithmically for A, as 1/d for B: both integrable).

use crate::fem::meshing::vec3::{add, cross, dot, norm, scale, sub, V3};

/// What is computed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Quantity {
    Potential,
    Induction,
}

/// A cross section: width along the first local axis (radius for a coil,
/// y for a bar), height at mid-width along the second, and the slopes of
/// its lower and upper sides (a trapezoid; 0 and 0 for a rectangle).
#[derive(Debug, Clone, Copy)]
pub struct Section {
    pub width: f64,
    pub height: f64,
    pub slopes: (f64, f64),
}

/// A conductor carrying a current density over its section (A/m² for a
/// solid one, A/m for a sheet, A for a wire).
#[derive(Debug, Clone, Copy)]
pub enum Conductor {
    /// A coil about `axis` (unit) through `centre`, between radii
    /// `r_in` and `r_in + section.width`, over the angle `angle` from
    /// `start` (unit, in the coil's plane), turning positively about
    /// `axis`; 2π for a closed coil.
    Coil { centre: V3, axis: V3, start: V3, r_in: f64, angle: f64, section: Section },
    /// A straight bar from `from` to `to` (centres of its end sections),
    /// `y` the unit axis of its section's width.
    Bar { from: V3, to: V3, y: V3, section: Section },
}

/// The field (A or B) at `x` of `density` flowing in the conductor.
pub fn field(c: &Conductor, q: Quantity, density: f64, mu0: f64, x: V3) -> V3 {
    match *c {
        Conductor::Coil { centre, axis, start, r_in, angle, section } => {
            let d = sub(x, centre);
            let z = dot(d, axis);
            let rv = sub(d, scale(axis, z));
            let r = norm(rv);
            let e_r = if r > 0.0 { scale(rv, 1.0 / r) } else { start };
            let e_phi = cross(axis, e_r);
            let closed = angle >= 2.0 * std::f64::consts::PI * (1.0 - 1e-12);
            let mut total = [0.0; 3];
            over_section(&section, r_in, r, z, |rp, zp, w| {
                let f = if closed {
                    let (a_phi, b_r, b_z) = loop_field(rp, r, z - zp, mu0 * density * w);
                    match q {
                        Quantity::Potential => scale(e_phi, a_phi),
                        Quantity::Induction => add(scale(e_r, b_r), scale(axis, b_z)),
                    }
                } else {
                    arc_field(centre, axis, start, angle, rp, zp, q, mu0 * density * w, x)
                };
                total = add(total, f);
            });
            total
        }
        Conductor::Bar { from, to, y, section } => {
            let u = sub(to, from);
            let len = norm(u);
            if len == 0.0 {
                return [0.0; 3];
            }
            let u = scale(u, 1.0 / len);
            let zax = cross(u, y);
            let d = sub(x, from);
            let (y0, z0) = (dot(d, y), dot(d, zax));
            let mut total = [0.0; 3];
            // The section's width runs from -w/2: shift so it starts at 0.
            over_section(&section, -section.width / 2.0, y0, z0, |yp, zp, w| {
                let off = add(scale(y, yp), scale(zax, zp));
                let f = segment_field(add(from, off), add(to, off), q, mu0 * density * w, x);
                total = add(total, f);
            });
            total
        }
    }
}

/// Call `f(s, t, weight)` at the quadrature nodes of the section: `s`
/// from `s_in` over the width, `t` between the sloped sides (centred on 0
/// at mid-width). Panels are graded towards (s0, t0). A zero width or
/// height makes a sheet (weights are lengths), both a wire (weight 1).
fn over_section(sec: &Section, s_in: f64, s0: f64, t0: f64, mut f: impl FnMut(f64, f64, f64)) {
    let mid = s_in + sec.width / 2.0;
    let (p1, p2) = sec.slopes;
    let lo = |s: f64| -sec.height / 2.0 + p1 * (s - mid);
    let hi = |s: f64| sec.height / 2.0 + p2 * (s - mid);
    let scale = sec.width.abs().max(sec.height.abs()).max(s_in.abs()).max(1e-300);
    let thin_w = sec.width.abs() <= 1e-12 * scale;
    let flat = sec.height.abs() <= 1e-12 * scale && (p1 - p2).abs() <= 1e-12;
    match (thin_w, flat) {
        (true, true) => f(s_in, 0.0, 1.0),
        (true, false) => {
            for (t, w) in graded(lo(s_in), hi(s_in), t0) {
                f(s_in, t, w)
            }
        }
        (false, true) => {
            // A sheet along the slanted side: the length along it.
            let stretch = (1.0 + p1 * p1).sqrt();
            for (s, w) in graded(s_in, s_in + sec.width, s0) {
                f(s, lo(s), w * stretch)
            }
        }
        (false, false) => {
            for (s, ws) in graded(s_in, s_in + sec.width, s0) {
                for (t, wt) in graded(lo(s), hi(s), t0) {
                    f(s, t, ws * wt)
                }
            }
        }
    }
}

/// 6-point Gauss–Legendre on [-1, 1].
const GL6: [(f64, f64); 6] = [
    (-0.932_469_514_203_152, 0.171_324_492_379_170),
    (-0.661_209_386_466_265, 0.360_761_573_048_139),
    (-0.238_619_186_083_197, 0.467_913_934_572_691),
    (0.238_619_186_083_197, 0.467_913_934_572_691),
    (0.661_209_386_466_265, 0.360_761_573_048_139),
    (0.932_469_514_203_152, 0.171_324_492_379_170),
];

/// Nodes and weights on [a, b]: panels graded geometrically towards `s`
/// when it lies inside (or on an end), else four even panels.
fn graded(a: f64, b: f64, s: f64) -> Vec<(f64, f64)> {
    let (a, b) = if a <= b { (a, b) } else { (b, a) };
    let mut cuts: Vec<f64> = Vec::new();
    if b - a <= 0.0 {
        return Vec::new();
    }
    if s > a && s < b {
        for (from, to) in [(a, s), (s, b)] {
            cuts.extend(towards(from, to, to == s));
        }
    } else {
        let near_a = (s - a).abs() <= (s - b).abs();
        let gap = (s - a).abs().min((s - b).abs());
        if gap < (b - a) {
            cuts.extend(towards(a, b, !near_a));
        } else {
            cuts.extend((0..=4).map(|i| a + (b - a) * i as f64 / 4.0));
        }
    }
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    let mut out = Vec::with_capacity(cuts.len() * 6);
    for w in cuts.windows(2) {
        let (u, v) = (w[0], w[1]);
        let (m, h) = ((u + v) / 2.0, (v - u) / 2.0);
        if h > 0.0 {
            out.extend(GL6.iter().map(|&(x, wt)| (m + h * x, wt * h)));
        }
    }
    out
}

/// Breakpoints of [from, to] refined geometrically towards `to` (when
/// `at_end`) or towards `from`.
fn towards(from: f64, to: f64, at_end: bool) -> Vec<f64> {
    const LEVELS: i32 = 10;
    const RATIO: f64 = 0.3;
    let len = to - from;
    let mut c = vec![from, to];
    for k in 1..=LEVELS {
        let d = len * RATIO.powi(k);
        c.push(if at_end { to - d } else { from + d });
    }
    c
}

/// Complete elliptic integrals K(m), E(m), m = k² in [0, 1), by the
/// arithmetic–geometric mean.
fn elliptic_ke(m: f64) -> (f64, f64) {
    let (mut a, mut b) = (1.0, (1.0 - m).sqrt());
    let mut sum = m / 2.0;
    let mut pow = 0.5;
    for _ in 0..60 {
        let c = (a - b) / 2.0;
        let (an, bn) = ((a + b) / 2.0, (a * b).sqrt());
        pow *= 2.0;
        sum += pow * c * c;
        a = an;
        b = bn;
        if c.abs() <= 1e-16 * a {
            break;
        }
    }
    let k = std::f64::consts::PI / (2.0 * a);
    (k, k * (1.0 - sum))
}

/// A circular filament of radius `a` on the axis, current `mu_i` (μ0·I),
/// at radius `r`, height `z` above its plane: (A_φ, B_r, B_z).
fn loop_field(a: f64, r: f64, z: f64, mu_i: f64) -> (f64, f64, f64) {
    use std::f64::consts::PI;
    if a <= 0.0 {
        return (0.0, 0.0, 0.0);
    }
    let apr2 = (a + r) * (a + r) + z * z;
    let amr2 = (a - r) * (a - r) + z * z;
    if amr2 <= 1e-24 * a * a {
        // On the filament: a set of no area of the section.
        return (0.0, 0.0, 0.0);
    }
    if r <= 1e-12 * a {
        let bz = mu_i * a * a / (2.0 * (a * a + z * z).powf(1.5));
        return (0.0, 0.0, bz);
    }
    let m = (4.0 * a * r / apr2).min(1.0 - 1e-16);
    let (kk, ee) = elliptic_ke(m);
    let k = m.sqrt();
    let a_phi = mu_i / (PI * k) * (a / r).sqrt() * ((1.0 - m / 2.0) * kk - ee);
    let s = apr2.sqrt();
    let b_r = mu_i * z / (2.0 * PI * r * s) * (-kk + (a * a + r * r + z * z) / amr2 * ee);
    let b_z = mu_i / (2.0 * PI * s) * (kk + (a * a - r * r - z * z) / amr2 * ee);
    (a_phi, b_r, b_z)
}

/// A straight filament from `p` to `q`, current `mu_i` (μ0·I) from p to q.
fn segment_field(p: V3, q: V3, quantity: Quantity, mu_i: f64, x: V3) -> V3 {
    use std::f64::consts::PI;
    let l = sub(q, p);
    let len = norm(l);
    if len == 0.0 {
        return [0.0; 3];
    }
    let u = scale(l, 1.0 / len);
    let d = sub(x, p);
    let a1 = dot(d, u);
    let a2 = a1 - len;
    let perp = sub(d, scale(u, a1));
    let rho = norm(perp);
    let tiny = 1e-12 * len;
    match quantity {
        Quantity::Potential => {
            // ln((a1 + R1) / (a2 + R2)), each term written without
            // cancellation for negative a.
            let g = |a: f64| {
                let r = (a * a + rho * rho).sqrt();
                if a >= 0.0 {
                    a + r
                } else {
                    rho * rho / (r - a)
                }
            };
            let (g1, g2) = (g(a1), g(a2));
            if g1 <= 0.0 || g2 <= 0.0 || rho <= tiny && a1 > 0.0 && a2 < 0.0 {
                return [0.0; 3];
            }
            scale(u, mu_i / (4.0 * PI) * (g1 / g2).ln())
        }
        Quantity::Induction => {
            if rho <= tiny {
                return [0.0; 3];
            }
            let c = a1 / (a1 * a1 + rho * rho).sqrt() - a2 / (a2 * a2 + rho * rho).sqrt();
            let dir = cross(u, scale(perp, 1.0 / rho));
            scale(dir, mu_i / (4.0 * PI * rho) * c)
        }
    }
}

/// An arc of filament of radius `rp`, `zp` above the plane through
/// `centre`, over `angle` from `start`, by Gauss panels along the angle.
#[allow(clippy::too_many_arguments)]
fn arc_field(centre: V3, axis: V3, start: V3, angle: f64, rp: f64, zp: f64, q: Quantity, mu_i: f64, x: V3) -> V3 {
    use std::f64::consts::PI;
    let side = cross(axis, start);
    let d = sub(x, centre);
    let phi0 = dot(d, side).atan2(dot(d, start)).rem_euclid(2.0 * PI);
    let mut total = [0.0; 3];
    for (phi, w) in graded(0.0, angle, phi0) {
        let (c, s) = (phi.cos(), phi.sin());
        let e_r = add(scale(start, c), scale(side, s));
        let tangent = add(scale(start, -s), scale(side, c));
        let src = add(centre, add(scale(e_r, rp), scale(axis, zp)));
        let rv = sub(x, src);
        let dist = norm(rv);
        if dist <= 1e-12 * rp.max(1e-300) {
            continue;
        }
        let dl = scale(tangent, rp * w);
        let f = match q {
            Quantity::Potential => scale(dl, 1.0 / dist),
            Quantity::Induction => scale(cross(dl, rv), 1.0 / (dist * dist * dist)),
        };
        total = add(total, scale(f, mu_i / (4.0 * PI)));
    }
    total
}

/// The field of circular filaments about the z axis (radius `a`, height
/// `zl`, current `i`, wire section area `e`) at `x`: (B, flux of B
/// through the circle about z through x). A point on a wire is taken at
/// the wire's surface (radius √(e/π)) for the flux.
pub fn axial_loops(loops: &[(f64, f64, f64, f64)], mu0: f64, x: V3) -> (V3, f64) {
    use std::f64::consts::PI;
    let r = (x[0] * x[0] + x[1] * x[1]).sqrt();
    let (mut b, mut flux) = ([0.0; 3], 0.0);
    for &(a, zl, i, e) in loops {
        let z = x[2] - zl;
        let wire = (e.max(0.0) / PI).sqrt();
        let dist = ((r - a) * (r - a) + z * z).sqrt();
        let (a_phi, b_r, b_z) = if dist < wire {
            // Inside the wire: the field at its surface, towards the axis.
            loop_field(a, (a - wire).max(0.0), 0.0, mu0 * i)
        } else {
            loop_field(a, r, z, mu0 * i)
        };
        if dist >= wire && r > 0.0 {
            b[0] += b_r * x[0] / r;
            b[1] += b_r * x[1] / r;
        }
        b[2] += b_z;
        let rr = if dist < wire { (a - wire).max(0.0) } else { r };
        flux += 2.0 * PI * rr * a_phi;
    }
    (b, flux)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn loop_on_axis_and_far_away() {
        // Centre of a loop: B = μ0 I / 2a.
        let (_, _, bz) = loop_field(2.0, 0.0, 0.0, 1.0);
        assert!((bz - 0.25).abs() < 1e-14);
        // Far away: a dipole, A_φ = μ0 m sinθ / (4π R²), m = I π a².
        let (a_phi, _, _) = loop_field(0.01, 10.0, 0.0, 1.0);
        let want = PI * 1e-4 / (4.0 * PI * 100.0);
        assert!((a_phi - want).abs() < 1e-6 * want);
        // Near the axis the closed form agrees with the axis limit.
        let (_, _, bz) = loop_field(1.0, 1e-6, 0.5, 1.0);
        assert!((bz - 1.0 / (2.0 * 1.25f64.powf(1.5))).abs() < 1e-9);
    }

    #[test]
    fn long_wire_and_graded_rules() {
        // B of a long wire at distance 1: μ0 I / 2π.
        let b = segment_field([0.0, 0.0, -1e4], [0.0, 0.0, 1e4], Quantity::Induction, 1.0, [1.0, 0.0, 0.0]);
        assert!((b[1] - 1.0 / (2.0 * PI)).abs() < 1e-8 && b[0].abs() < 1e-15);
        // The graded rule integrates ln|x - 0.3| on [0, 1].
        let f = |x: f64| (x - 0.3f64).abs().ln();
        let s: f64 = graded(0.0, 1.0, 0.3).iter().map(|&(x, w)| w * f(x)).sum();
        let exact = 0.3 * 0.3f64.ln() + 0.7 * 0.7f64.ln() - 1.0;
        // (1.3e-7 off with the rule's points: a logarithmic singularity is
        // integrated to about 1e-7, enough for a field's few digits.)
        assert!((s - exact).abs() < 1e-6, "{} {}", s, exact);
    }
}
