//! Tension along a prestressing cable after its losses (PREC).
//!
//! The cable is a chain of points from the anchorage where the jack pulls.
//! Three losses, as the usual prestressing rules state them:
//!
//! - friction: `P(x) = P₀ exp(-(f α(x) + φ x))`, α the total angle the
//!   cable has turned through from the anchorage and x its length;
//! - anchorage slip g: near the anchorage the cable slides back and the
//!   friction reverses, so there the tension becomes `P(l)² / P(x)` (the
//!   friction profile mirrored about l), l being such that the lost
//!   elongation `∫₀ˡ (P - P(l)²/P) / EA dx` is g;
//! - steel relaxation: `ΔP = 6/100 · ρ₁₀₀₀ · (μ - μ₀) · P`, μ = σ / f_prg
//!   the stress over the guaranteed strength and ρ₁₀₀₀ the relaxation at
//!   1000 hours in percent, nothing when μ ≤ μ₀.
//!
//! The polyline turns at its nodes; the angle at a node is given half to
//! each side, and the ends take the angle of their neighbour, so a chain of
//! chords inscribed in an arc gets the arc's angle at every node.

use super::vec3::{dot, sub};

fn norm(a: [f64; 3]) -> f64 {
    dot(a, a).sqrt()
}

/// The losses to take into account.
#[derive(Debug, Clone, Copy)]
pub struct Losses {
    /// Angular friction coefficient f (per radian).
    pub ff: f64,
    /// Linear friction coefficient φ (per unit length).
    pub phif: f64,
    /// Anchorage slip g (length).
    pub ganc: f64,
    pub relaxation: Option<Relaxation>,
}

#[derive(Debug, Clone, Copy)]
pub struct Relaxation {
    pub mu0: f64,
    /// Guaranteed ultimate strength f_prg (stress).
    pub fprg: f64,
    /// Relaxation at 1000 hours, in percent.
    pub rh1000: f64,
}

/// The tension at every point of the chain `x` (the anchorage first) when
/// the jack pulls with `p0`; `ea` is the cable's axial stiffness E·A and
/// `area` its section.
pub fn tension_profile(x: &[[f64; 3]], p0: f64, ea: f64, area: f64, losses: &Losses) -> Result<Vec<f64>, String> {
    let n = x.len();
    if n < 2 {
        return Err("a cable needs at least two points".into());
    }
    let (s, alpha) = abscissa_and_angle(x)?;
    let mut p: Vec<f64> = s.iter().zip(&alpha).map(|(s, a)| p0 * (-(losses.ff * a + losses.phif * s)).exp()).collect();
    if losses.ganc > 0.0 {
        anchorage_slip(&s, &mut p, losses.ganc * ea)?;
    }
    if let Some(r) = losses.relaxation {
        for v in &mut p {
            let mu = *v / (area * r.fprg);
            if mu > r.mu0 {
                *v *= 1.0 - 0.06 * r.rh1000 * (mu - r.mu0);
            }
        }
    }
    if p.iter().any(|v| !v.is_finite()) {
        return Err("the tension is not a finite number".into());
    }
    Ok(p)
}

/// The length from the first point and the angle turned through at every
/// point.
fn abscissa_and_angle(x: &[[f64; 3]]) -> Result<(Vec<f64>, Vec<f64>), String> {
    let n = x.len();
    let seg: Vec<[f64; 3]> = x.windows(2).map(|w| sub(w[1], w[0])).collect();
    let mut s = vec![0.0; n];
    for (i, d) in seg.iter().enumerate() {
        let l = norm(*d);
        if l <= 0.0 {
            return Err(format!("the cable has two coincident successive points ({} and {})", i + 1, i + 2));
        }
        s[i + 1] = s[i] + l;
    }
    // Turn at the interior nodes, then at the ends as at their neighbour.
    let mut turn = vec![0.0; n];
    for i in 1..n - 1 {
        let (a, b) = (seg[i - 1], seg[i]);
        let c = (dot(a, b) / (norm(a) * norm(b))).clamp(-1.0, 1.0);
        turn[i] = c.acos();
    }
    if n > 2 {
        turn[0] = turn[1];
        turn[n - 1] = turn[n - 2];
    }
    let mut alpha = vec![0.0; n];
    for i in 1..n {
        alpha[i] = alpha[i - 1] + 0.5 * (turn[i - 1] + turn[i]);
    }
    Ok((s, alpha))
}

/// Mirror the profile about the length l that gives back the elongation
/// `lost` (= g·EA); the tension varies linearly between points.
fn anchorage_slip(s: &[f64], p: &mut [f64], lost: f64) -> Result<(), String> {
    if p.iter().any(|v| *v <= 0.0) {
        return Err("the tension must be positive to compute the anchorage slip".into());
    }
    let at = |l: f64| -> f64 {
        let k = s.partition_point(|v| *v <= l).clamp(1, s.len() - 1);
        let t = (l - s[k - 1]) / (s[k] - s[k - 1]);
        p[k - 1] + t * (p[k] - p[k - 1])
    };
    // Elongation given back when the mirror point is l.
    let given = |l: f64| -> f64 {
        let pl2 = at(l).powi(2);
        let f = |v: f64| v - pl2 / v;
        let mut sum = 0.0;
        for k in 1..s.len() {
            if s[k - 1] >= l {
                break;
            }
            let b = s[k].min(l);
            let pb = if s[k] <= l { p[k] } else { at(l) };
            sum += 0.5 * (f(p[k - 1]) + f(pb)) * (b - s[k - 1]);
        }
        sum
    };
    let total = *s.last().unwrap_or(&0.0);
    if given(total) < lost {
        // The slip reaches the far end: a uniform drop on top of the mirror.
        let pl2 = p[p.len() - 1].powi(2);
        let drop = (lost - given(total)) / total;
        for v in p.iter_mut() {
            *v = pl2 / *v - drop;
        }
        if p.iter().any(|v| *v <= 0.0) {
            return Err("the anchorage slip releases the whole cable".into());
        }
        return Ok(());
    }
    let (mut lo, mut hi) = (0.0, total);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if given(mid) < lost {
            lo = mid;
        } else {
            hi = mid;
        }
        if hi - lo <= 1e-14 * total {
            break;
        }
    }
    let l = 0.5 * (lo + hi);
    let pl2 = at(l).powi(2);
    for (v, sv) in p.iter_mut().zip(s) {
        if *sv < l {
            *v = pl2 / *v;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn arc(r: f64, n: usize, angle: f64) -> Vec<[f64; 3]> {
        (0..=n)
            .map(|i| {
                let t = angle * i as f64 / n as f64;
                [r * t.sin(), r * (1.0 - t.cos()), 0.0]
            })
            .collect()
    }

    #[test]
    fn friction_on_an_arc_follows_the_exponential() {
        let x = arc(10.0, 400, 2.0);
        let l = Losses { ff: 0.2, phif: 0.001, ganc: 0.0, relaxation: None };
        let p = tension_profile(&x, 1000.0, 1e9, 1e-3, &l).unwrap();
        let t: f64 = 2.0;
        let want = 1000.0 * (-(0.2 * t + 0.001 * 10.0 * t)).exp();
        assert!((p[400] - want).abs() < 1e-3 * want, "{} {}", p[400], want);
    }

    #[test]
    fn anchorage_slip_gives_back_the_slip() {
        // A straight cable with linear friction: check the lost elongation.
        let x: Vec<[f64; 3]> = (0..=1000).map(|i| [0.01 * i as f64, 0.0, 0.0]).collect();
        // sqrt(g EA φ / P0) = 0.1: the slip is taken back over about 2.1 m.
        let (ea, g) = (2e5, 1e-3);
        let l = Losses { ff: 0.0, phif: 0.05, ganc: g, relaxation: None };
        let before = tension_profile(&x, 1000.0, ea, 1.0, &Losses { ganc: 0.0, ..l }).unwrap();
        let after = tension_profile(&x, 1000.0, ea, 1.0, &l).unwrap();
        let lost: f64 = (1..x.len()).map(|k| 0.005 * ((before[k] - after[k]) + (before[k - 1] - after[k - 1]))).sum();
        // (1000 segments: the trapezoid rule leaves 5e-6 of the slip.)
        assert!((lost / ea - g).abs() < 2e-5 * g, "{}", lost / ea);
        // Analytically l = -ln(1 - sqrt(g EA φ / P0)) / φ.
        let la = -(1.0 - (g * ea * 0.05 / 1000.0f64).sqrt()).ln() / 0.05;
        let k = (la / 0.01) as usize + 3;
        assert!((after[k] - before[k]).abs() < 1e-9 && after[k - 6] < before[k - 6]);
    }
}
