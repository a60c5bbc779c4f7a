//! Stresses and strains through a shell's thickness from its generalised
//! ones (CALP): at the fibre ζ (−t/2 ≤ ζ ≤ t/2 along the element normal),
//! σ = N/t + 12 M ζ/t³ and ε = e + ζ κ, in the element's own axes (1 → XX,
//! 2 → YY; no rotation). The skins are ζ = +t/2 ('SUPE', on the side of
//! the normal) and ζ = −t/2 ('INFE'); ζ = 0 is the mid-surface ('MOYE').

use super::element::{FemError, Formulation, GaussField};

const STRESS: [&str; 4] = ["SMXX", "SMYY", "SMZZ", "SMXY"];
const STRAIN: [&str; 4] = ["EPXX", "EPYY", "EPZZ", "GAXY"];

/// The field at fibre `zeta` of a shell of thickness `t`: stresses when
/// `g` holds N11 …, strains when it holds EPSS ….
pub fn at_fibre(f: Formulation, g: &GaussField, t: f64, zeta: f64) -> Result<GaussField, FemError> {
    if !f.is_shell() {
        return Err(FemError::NotFor { what: "stresses in the thickness (CALP)", form: f.name() });
    }
    let has = |c: &str| g.comps.contains(&c);
    let at = |v: &[f64], c: &str| g.comps.iter().position(|n| *n == c).map_or(0.0, |i| v[i]);
    if has("N11") || has("M11") {
        let (a, b) = (1.0 / t, 12.0 * zeta / (t * t * t));
        let values = g
            .values
            .iter()
            .map(|v| {
                let s = |n: &str, m: &str| a * at(v, n) + b * at(v, m);
                vec![s("N11", "M11"), s("N22", "M22"), 0.0, s("N12", "M12")]
            })
            .collect();
        Ok(GaussField { comps: STRESS.to_vec(), values })
    } else if has("EPSS") || has("RTSS") {
        let values = g
            .values
            .iter()
            .map(|v| {
                let e = |m: &str, k: &str| at(v, m) + zeta * at(v, k);
                vec![e("EPSS", "RTSS"), e("EPTT", "RTTT"), 0.0, e("GAST", "RTST")]
            })
            .collect();
        Ok(GaussField { comps: STRAIN.to_vec(), values })
    } else {
        Err(FemError::MissingComponent { comp: "N11", elem: f.name() })
    }
}
