//! Compressible flow: primitive variables (velocity, pressure, temperature,
//! mass fractions) from the conservative ones of the Euler equations
//! (density ρ, momentum ρu, total energy per volume ρE, partial densities
//! ρYᵢ), one node at a time. The equations of state are those of PRIM
//! (prim.notice): a perfect gas with constant γ, a mixture of perfect gases
//! with constant cp and cv, one whose cv are polynomials of T, and the
//! stiffened gas of the Ghost Fluid method.
//!
//! Species lists put the species *not* carried by the equations last: its
//! mass fraction is what the others leave, 1 − ΣYᵢ.

/// The conservative state at one node.
#[derive(Debug, Clone, Copy)]
pub struct Conservative<'a> {
    pub rho: f64,
    pub momentum: &'a [f64],
    pub rho_e: f64,
    /// ρYᵢ of the species the equations carry (may be empty).
    pub rho_y: &'a [f64],
}

/// What PRIM gives back at one node.
#[derive(Debug, Clone, PartialEq)]
pub struct Primitive {
    pub velocity: Vec<f64>,
    pub pressure: f64,
    pub temperature: f64,
    /// Yᵢ of the carried species (same order as `rho_y`).
    pub y: Vec<f64>,
    pub gamma: f64,
}

impl Conservative<'_> {
    /// Velocity and internal energy per unit mass, e = E − ½|u|².
    fn kinematics(&self) -> Result<(Vec<f64>, f64), String> {
        if self.rho.is_nan() || self.rho <= 0.0 {
            return Err(format!("the density must be positive, found {}", self.rho));
        }
        let u: Vec<f64> = self.momentum.iter().map(|g| g / self.rho).collect();
        let k: f64 = u.iter().map(|v| v * v).sum::<f64>() * 0.5;
        Ok((u, self.rho_e / self.rho - k))
    }

    /// Mass fractions of every species, the carried ones then the last.
    fn fractions(&self) -> Result<Vec<f64>, String> {
        let mut y: Vec<f64> = self.rho_y.iter().map(|r| r / self.rho).collect();
        let rest = 1.0 - y.iter().sum::<f64>();
        if y.iter().any(|v| !(0.0..=1.0).contains(v)) || rest < 0.0 {
            return Err(format!("the mass fractions must lie in [0, 1] and add up to at most 1, found {:?}", y));
        }
        y.push(rest);
        Ok(y)
    }
}

fn check_gamma(gamma: f64) -> Result<(), String> {
    if gamma > 1.0 && gamma < 3.0 {
        Ok(())
    } else {
        Err(format!("gamma must lie strictly between 1 and 3, found {}", gamma))
    }
}

fn check_positive(what: &str, v: f64) -> Result<(), String> {
    if v > 0.0 && v.is_finite() {
        Ok(())
    } else {
        Err(format!("the {} must be positive, found {}", what, v))
    }
}

/// 'PERFMONO': one perfect gas, p = (γ − 1) ρ e.
pub fn perfect_mono(s: Conservative, gamma: f64) -> Result<Primitive, String> {
    check_gamma(gamma)?;
    let (velocity, e) = s.kinematics()?;
    let pressure = (gamma - 1.0) * s.rho * e;
    check_positive("pressure", pressure)?;
    Ok(Primitive { velocity, pressure, temperature: f64::NAN, y: vec![], gamma })
}

/// 'PERFMULT': a mixture of perfect gases with constant heats (`cp`, `cv`
/// per species, the uncarried one last): cv = ΣYₖcvₖ, T = e / cv,
/// γ = cp / cv, p = (γ − 1) ρ e.
pub fn perfect_mixture(s: Conservative, cp: &[f64], cv: &[f64]) -> Result<Primitive, String> {
    let (velocity, e) = s.kinematics()?;
    let y = s.fractions()?;
    let cv_mix: f64 = y.iter().zip(cv).map(|(y, c)| y * c).sum();
    let cp_mix: f64 = y.iter().zip(cp).map(|(y, c)| y * c).sum();
    check_positive("cv of the mixture", cv_mix)?;
    let gamma = cp_mix / cv_mix;
    check_gamma(gamma)?;
    let temperature = e / cv_mix;
    check_positive("temperature", temperature)?;
    let pressure = (gamma - 1.0) * s.rho * e;
    check_positive("pressure", pressure)?;
    Ok(Primitive { velocity, pressure, temperature, y: y[..y.len() - 1].to_vec(), gamma })
}

/// A perfect gas whose cv is a polynomial of T: cv(T) = Σⱼ aⱼ Tʲ.
#[derive(Debug, Clone)]
pub struct PolyGas {
    pub a: Vec<f64>,
    /// The gas constant R = cp − cv.
    pub r: f64,
}

impl PolyGas {
    fn cv(&self, t: f64) -> f64 {
        self.a.iter().rev().fold(0.0, |acc, c| acc * t + c)
    }
    /// ∫₀ᵀ cv: the internal energy measured from 0 K.
    fn energy(&self, t: f64) -> f64 {
        self.a.iter().enumerate().rev().fold(0.0, |acc, (j, c)| acc * t + c / (j + 1) as f64) * t
    }
}

/// 'PERFTEMP': perfect gases with cv(T) polynomials (uncarried one last).
/// T solves Σ Yₖ ∫₀ᵀ cvₖ = e by Newton's method from `guess`, kept inside
/// a bracket so that it cannot run away; p = ρ (ΣYₖRₖ) T.
pub fn perfect_poly(s: Conservative, gases: &[PolyGas], guess: Option<f64>) -> Result<Primitive, String> {
    let (velocity, e) = s.kinematics()?;
    let y = s.fractions()?;
    check_positive("internal energy", e)?;
    let mix_e = |t: f64| -> f64 { y.iter().zip(gases).map(|(y, g)| y * g.energy(t)).sum() };
    let mix_cv = |t: f64| -> f64 { y.iter().zip(gases).map(|(y, g)| y * g.cv(t)).sum() };
    // Bracket [lo, hi] with e(lo) < e ≤ e(hi); e(0) = 0.
    let mut t = guess.filter(|g| *g > 0.0 && g.is_finite()).unwrap_or(300.0);
    let (mut lo, mut hi) = (0.0, t);
    while mix_e(hi) < e {
        lo = hi;
        hi *= 2.0;
        if hi > 1e12 {
            return Err(format!("no temperature gives the internal energy {}", e));
        }
    }
    for _ in 0..200 {
        let f = mix_e(t) - e;
        if f < 0.0 {
            lo = lo.max(t);
        } else {
            hi = hi.min(t);
        }
        let d = mix_cv(t);
        let mut next = if d > 0.0 { t - f / d } else { f64::NAN };
        if !(next > lo && next < hi) {
            next = 0.5 * (lo + hi);
        }
        let done = (next - t).abs() <= 1e-14 * t.abs() || hi - lo <= 1e-15 * hi;
        t = next;
        if done {
            break;
        }
    }
    check_positive("temperature", t)?;
    let cv = mix_cv(t);
    check_positive("cv of the mixture", cv)?;
    let r: f64 = y.iter().zip(gases).map(|(y, g)| y * g.r).sum();
    let gamma = (cv + r) / cv;
    check_gamma(gamma)?;
    let pressure = s.rho * r * t;
    check_positive("pressure", pressure)?;
    Ok(Primitive { velocity, pressure, temperature: t, y: y[..y.len() - 1].to_vec(), gamma })
}

/// A stiffened gas: p = (γ − 1) ρ e − γ p∞.
#[derive(Debug, Clone, Copy)]
pub struct Stiffened {
    pub gamma: f64,
    pub p_inf: f64,
}

/// 'GFMP': stiffened gases mixed by volume fractions `alpha` of the carried
/// species (the uncarried one, listed last in `phases`, fills the rest):
/// the mixture's 1/(γ − 1) and γp∞/(γ − 1) are the α-weighted sums.
pub fn stiffened(s: Conservative, phases: &[Stiffened], alpha: &[f64]) -> Result<Primitive, String> {
    let (velocity, e) = s.kinematics()?;
    let y: Vec<f64> = s.rho_y.iter().map(|r| r / s.rho).collect();
    let rest = 1.0 - alpha.iter().sum::<f64>();
    let (mut a, mut b) = (0.0, 0.0);
    for (k, ph) in phases.iter().enumerate() {
        check_gamma(ph.gamma)?;
        let al = alpha.get(k).copied().unwrap_or(rest);
        a += al / (ph.gamma - 1.0);
        b += al * ph.gamma * ph.p_inf / (ph.gamma - 1.0);
    }
    check_positive("mixture's 1/(gamma - 1)", a)?;
    let pressure = (s.rho * e - b) / a;
    if !pressure.is_finite() {
        return Err(format!("the pressure is not a finite number: {}", pressure));
    }
    Ok(Primitive { velocity, pressure, temperature: f64::NAN, y, gamma: 1.0 + 1.0 / a })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mono_by_hand() {
        // ρ = 2, u = (3, 4), p = 10, γ = 1.4: ρE = 10/0.4 + ½·2·25 = 50.
        let s = Conservative { rho: 2.0, momentum: &[6.0, 8.0], rho_e: 50.0, rho_y: &[] };
        let p = perfect_mono(s, 1.4).unwrap();
        assert_eq!(p.velocity, vec![3.0, 4.0]);
        assert!((p.pressure - 10.0).abs() < 1e-12);
        assert!(perfect_mono(s, 3.5).is_err());
    }

    #[test]
    fn poly_recovers_temperature() {
        let g = [PolyGas { a: vec![700.0, 0.1], r: 287.0 }];
        // e(T) = 700 T + 0.05 T²; at T = 1000: 750000.
        let s = Conservative { rho: 1.0, momentum: &[0.0], rho_e: 750000.0, rho_y: &[] };
        let p = perfect_poly(s, &g, None).unwrap();
        assert!((p.temperature - 1000.0).abs() < 1e-9);
        assert!((p.pressure - 287000.0).abs() < 1e-6);
    }
}
