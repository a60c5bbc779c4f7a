//! The enrichment functions at a point, from the level sets interpolated
//! there: the jump H = ±1 (its side of the crack) and the four crack-tip
//! functions of the asymptotic displacement field,
//! √r sin θ/2, √r cos θ/2, √r sin θ/2 sin θ, √r cos θ/2 sin θ,
//! with (r, θ) the polar coordinates of the point in the tip frame whose
//! cartesian coordinates are (PSI, PHI). θ = ±π on the crack lips: the
//! side tells which, so a point of a sub-cell never takes the other lip's
//! value because of rounding.

/// A scalar function and its gradient.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fun {
    pub v: f64,
    pub g: [f64; 3],
}

/// The four tip functions at a point where the level sets are `psi`,
/// `phi` with gradients `gpsi`, `gphi`, on side `side` (±1) of the crack.
pub fn tip(psi: f64, phi: f64, gpsi: [f64; 3], gphi: [f64; 3], side: f64) -> [Fun; 4] {
    // A point at the tip itself (a sub-cell corner, never a quadrature
    // point) would divide by zero: nudge it.
    let r = (psi * psi + phi * phi).sqrt().max(1e-300);
    let mut th = phi.atan2(psi);
    // Behind the tip, the sign of θ is the side's.
    if psi < 0.0 && th * side < 0.0 {
        th = side * std::f64::consts::PI;
    }
    let sr = r.sqrt();
    let (s2, c2) = (th / 2.0).sin_cos();
    let (s1, c1) = th.sin_cos();
    // d/dr and d/dθ of each function.
    let drv = [
        (s2 / (2.0 * sr), sr * c2 / 2.0),
        (c2 / (2.0 * sr), -sr * s2 / 2.0),
        (s2 * s1 / (2.0 * sr), sr * (0.5 * c2 * s1 + s2 * c1)),
        (c2 * s1 / (2.0 * sr), sr * (-0.5 * s2 * s1 + c2 * c1)),
    ];
    let vals = [sr * s2, sr * c2, sr * s2 * s1, sr * c2 * s1];
    let mut out = [Fun { v: 0.0, g: [0.0; 3] }; 4];
    for k in 0..4 {
        let (dr, dt) = drv[k];
        let mut g = [0.0; 3];
        for c in 0..3 {
            let grad_r = (psi * gpsi[c] + phi * gphi[c]) / r;
            let grad_t = (psi * gphi[c] - phi * gpsi[c]) / (r * r);
            g[c] = dr * grad_r + dt * grad_t;
        }
        out[k] = Fun { v: vals[k], g };
    }
    out
}
