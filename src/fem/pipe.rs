//! TUYA: the pipe element, a beam (POUT) on SEG2 whose section is a thin
//! tube given by its outer radius RAYO and wall thickness EPAI, straight,
//! or an elbow of bend radius RACO.
//!
//! The section: A = π(Re² − Ri²), I = π(Re⁴ − Ri⁴)/4 about both axes,
//! J = 2I, shear areas A/2 (a thin tube's). An elbow bends more easily
//! than a straight tube of the same section because its cross-section
//! ovalises: its bending inertias are divided by the flexibility factor
//! k = 1.65/λ (at least 1), λ = EPAI·RACO/r² the elbow characteristic,
//! r the mean radius (von Kármán's thin-elbow result as the piping codes
//! state it). An internal pressure PRES stiffens the elbow against
//! ovalisation: k is divided by 1 + 6 (P/E) (r/e)^(7/3) (R/r)^(1/3) when
//! the modulus is known. Torsion and stretching are those of the tube.
//! The elbow itself is meshed by straight segments along its arc (CERC),
//! whose local y axis (CARA 'VECT') is normal to the elbow plane.

/// Section properties of a tube from the TUYA data, as the beam names
/// them (SECT, INRY, INRZ, TORS, SECY, SECZ), or an error text.
pub fn section(
    epai: f64,
    rayo: f64,
    raco: Option<f64>,
    pres: Option<f64>,
    young: Option<f64>,
) -> Result<Vec<(&'static str, f64)>, String> {
    if !(epai.is_finite() && rayo.is_finite() && epai > 0.0 && rayo > 0.0) {
        return Err(format!("TUYA needs a positive EPAI ({}) and RAYO ({})", epai, rayo));
    }
    if epai > rayo {
        return Err(format!("TUYA: the thickness EPAI {} exceeds the outer radius RAYO {}", epai, rayo));
    }
    let ri = rayo - epai;
    let pi = std::f64::consts::PI;
    let a = pi * (rayo * rayo - ri * ri);
    let i = pi * (rayo.powi(4) - ri.powi(4)) / 4.0;
    let k = match raco {
        Some(r) if r.is_finite() && r > 0.0 => flexibility(epai, rayo, r, pres, young),
        Some(r) => return Err(format!("TUYA: the bend radius RACO must be positive, not {}", r)),
        None => 1.0,
    };
    Ok(vec![("SECT", a), ("INRY", i / k), ("INRZ", i / k), ("TORS", 2.0 * i), ("SECY", a / 2.0), ("SECZ", a / 2.0)])
}

/// The elbow's flexibility factor (see the module doc).
pub fn flexibility(epai: f64, rayo: f64, raco: f64, pres: Option<f64>, young: Option<f64>) -> f64 {
    let r = rayo - epai / 2.0;
    let lambda = epai * raco / (r * r);
    let mut k = 1.65 / lambda;
    if let (Some(p), Some(e)) = (pres, young) {
        if p > 0.0 && e > 0.0 {
            k /= 1.0 + 6.0 * (p / e) * (r / epai).powf(7.0 / 3.0) * (raco / r).powf(1.0 / 3.0);
        }
    }
    k.max(1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn straight_tube() {
        let s = section(0.01, 0.1, None, None, None).unwrap();
        let get = |n: &str| s.iter().find(|(k, _)| *k == n).unwrap().1;
        let pi = std::f64::consts::PI;
        assert!((get("SECT") - pi * (0.01 - 0.0081)).abs() < 1e-15);
        assert!((get("TORS") - 2.0 * get("INRY")).abs() < 1e-18);
    }

    #[test]
    fn elbow_is_softer() {
        // λ = 0.01·0.3/0.095² ≈ 0.332, k ≈ 4.96.
        let k = flexibility(0.01, 0.1, 0.3, None, None);
        assert!((k - 1.65 * 0.095 * 0.095 / 0.003).abs() < 1e-12);
        assert!(flexibility(0.01, 0.1, 0.3, Some(1e7), Some(2e11)) < k);
    }
}
