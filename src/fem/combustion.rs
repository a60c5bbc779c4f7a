//! Hydrogen combustion by the global reaction 2 H2 + O2 -> 2 H2O over one
//! time step, at one point (FLAM 'ARRHENIU' and 'HEAVYSID', flam.notice).
//!
//! The state is the three partial densities (kg/m³); nitrogen is inert and
//! absent. With ω the molar reaction rate (mol/m³/s), the densities move as
//! dρH2/dt = −2 M_H2 ω, dρO2/dt = −M_O2 ω, dρH2O/dt = +2 M_H2O ω, and the
//! heat released per volume is Q = −Σ Δρᵢ h0ᵢ with h0ᵢ the species'
//! energies at 0 K.
//!
//! The reaction is limited by the species in defect (compared in moles:
//! H2 against twice O2). 'HEAVYSID' burns it completely above the threshold
//! temperature. 'ARRHENIU' integrates ω = A T^−b ρH2^c ρO2 exp(−Ta/T) by a
//! linearly implicit Euler step on the limiting species, the other factors
//! taken at the start of the step: ρ' = ρ / (1 + λ Δt). The step then
//! never drives a density negative, whatever Δt against the chemical time
//! 1/λ (detonation rates are stiff).

/// Molar masses (kg/mol) from the standard atomic weights (H 1.008,
/// O 15.999). Water's is fixed by mass conservation of the reaction,
/// 2 M_H2 + M_O2 = 2 M_H2O, so no mass is created by rounding.
pub const M_H2: f64 = 2.016e-3;
pub const M_O2: f64 = 31.998e-3;
pub const M_H2O: f64 = (2.0 * M_H2 + M_O2) / 2.0;

/// Partial densities of the reacting species (kg/m³).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Mixture {
    pub h2: f64,
    pub o2: f64,
    pub h2o: f64,
}

/// Energies of formation at 0 K (J/kg) of H2, O2 and H2O.
#[derive(Debug, Clone, Copy)]
pub struct Formation {
    pub h2: f64,
    pub o2: f64,
    pub h2o: f64,
}

/// The Arrhenius law's constants: ω = A T^−b ρH2^c ρO2 exp(−Ta/T).
#[derive(Debug, Clone, Copy)]
pub struct Arrhenius {
    pub a: f64,
    pub b: f64,
    pub c: f64,
    pub ta: f64,
}

/// Whether O2 is the species in defect: more than two moles of H2 per mole
/// of O2.
fn oxygen_limits(m: &Mixture) -> bool {
    m.h2 / M_H2 > 2.0 * (m.o2 / M_O2)
}

fn check(m: &Mixture, t: f64) -> Result<(), String> {
    for (what, r) in [("H2", m.h2), ("O2", m.o2), ("H2O", m.h2o)] {
        if !r.is_finite() || r < 0.0 {
            return Err(format!("the density of {} must be finite and not negative, found {}", what, r));
        }
    }
    if !t.is_finite() || t <= 0.0 {
        return Err(format!("the temperature must be positive, found {}", t));
    }
    Ok(())
}

/// The mixture after `d` moles of reaction per m³ (d ≥ 0 burns), and the
/// heat released.
fn react(m: &Mixture, d: f64, h0: &Formation) -> Result<(Mixture, f64), String> {
    let dh2 = -2.0 * M_H2 * d;
    let do2 = -M_O2 * d;
    let dh2o = 2.0 * M_H2O * d;
    // The limiting species reaches exactly zero when it burns out: no
    // rounding residue of the subtraction.
    let keep = |r: f64, dr: f64| if -dr >= r { 0.0 } else { r + dr };
    let out = Mixture { h2: keep(m.h2, dh2), o2: keep(m.o2, do2), h2o: m.h2o + dh2o };
    let q = -(dh2 * h0.h2 + do2 * h0.o2 + dh2o * h0.h2o);
    if !q.is_finite() || !out.h2o.is_finite() {
        return Err(format!("the reaction gives a non-finite result (heat released {})", q));
    }
    Ok((out, q))
}

/// Infinitely fast combustion above `ts`: the species in defect burns out.
pub fn heaviside(m: &Mixture, t: f64, ts: f64, h0: &Formation) -> Result<(Mixture, f64), String> {
    check(m, t)?;
    if t <= ts {
        return Ok((*m, 0.0));
    }
    let moles = if oxygen_limits(m) { m.o2 / M_O2 } else { m.h2 / (2.0 * M_H2) };
    react(m, moles, h0)
}

/// One linearly implicit step `dt` of the Arrhenius rate above `ts`.
pub fn arrhenius(
    m: &Mixture,
    t: f64,
    ts: f64,
    law: &Arrhenius,
    h0: &Formation,
    dt: f64,
) -> Result<(Mixture, f64), String> {
    check(m, t)?;
    if t <= ts || m.h2 == 0.0 || m.o2 == 0.0 {
        return Ok((*m, 0.0));
    }
    let k = law.a * t.powf(-law.b) * (-law.ta / t).exp();
    let moles = if oxygen_limits(m) {
        // dρO2/dt = −λ ρO2 with λ = M_O2 k ρH2^c.
        let lambda = M_O2 * k * m.h2.powf(law.c);
        let o2 = m.o2 / (1.0 + lambda * dt);
        (m.o2 - o2) / M_O2
    } else {
        // dρH2/dt = −λ ρH2 with λ = 2 M_H2 k ρH2^(c−1) ρO2.
        let lambda = 2.0 * M_H2 * k * m.h2.powf(law.c - 1.0) * m.o2;
        let h2 = m.h2 / (1.0 + lambda * dt);
        (m.h2 - h2) / (2.0 * M_H2)
    };
    if !moles.is_finite() {
        return Err(format!("the reaction rate is not finite at T = {}", t));
    }
    react(m, moles, h0)
}

#[cfg(test)]
mod tests {
    use super::*;

    const H0: Formation = Formation { h2: -4.0e6, o2: -2.5e5, h2o: -1.4e7 };

    #[test]
    fn heaviside_burns_the_species_in_defect() {
        // 1 mol H2 (0.002016 kg) against 1 mol O2: H2 is in defect.
        let m = Mixture { h2: M_H2, o2: M_O2, h2o: 0.0 };
        let (r, q) = heaviside(&m, 1500.0, 1000.0, &H0).unwrap();
        assert_eq!(r.h2, 0.0);
        assert!((r.o2 - 0.5 * M_O2).abs() < 1e-15);
        assert!((r.h2o - M_H2O).abs() < 1e-15);
        let expect = -(-M_H2 * H0.h2 - 0.5 * M_O2 * H0.o2 + M_H2O * H0.h2o);
        assert!((q - expect).abs() < 1e-9 * expect.abs());
        // Below the threshold nothing moves.
        assert_eq!(heaviside(&m, 900.0, 1000.0, &H0).unwrap(), (m, 0.0));
    }

    #[test]
    fn arrhenius_step_conserves_mass_and_tends_to_complete_burning() {
        let law = Arrhenius { a: 1.0e10, b: 0.0, c: 1.0, ta: 0.0 };
        let m = Mixture { h2: 0.1, o2: 0.2, h2o: 0.01 };
        let (r, _) = arrhenius(&m, 2000.0, 1000.0, &law, &H0, 1e-6).unwrap();
        assert!(((r.h2 + r.o2 + r.h2o) - (m.h2 + m.o2 + m.h2o)).abs() < 1e-15);
        // O2 limits (0.1/2.016e-3 > 2 * 0.2/31.998e-3): λ = M_O2 A ρH2.
        let lambda = M_O2 * 1.0e10 * 0.1;
        assert!((r.o2 - 0.2 / (1.0 + lambda * 1e-6)).abs() < 1e-15);
        let (big, _) = arrhenius(&m, 2000.0, 1000.0, &law, &H0, 1e3).unwrap();
        assert!(big.o2 < 1e-8 && big.h2 > 0.0);
    }
}
