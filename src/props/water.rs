//! Water and steam properties for `VARI 'HLS'`, `'PSATT'` … (vari.notice,
//! 3rd form), in SI units: pressures in Pa, temperatures in K, enthalpies
//! in J/kg, densities in kg/m³.
//!
//! The public standard is IAPWS-IF97 (the industrial formulation of the
//! International Association for the Properties of Water and Steam):
//! region 1 for the liquid, region 2 for the steam, region 4 for the
//! saturation line, with the IAPWS 2008 viscosity and IAPWS 2011 thermal
//! conductivity. Regions 1 and 2 and the transport properties come from
//! the `seuif97` crate (which works in MPa, °C and kJ); the saturation
//! line is written here because `DPSAT` needs its exact derivative.
//!
//! A law is always evaluated with its own phase's equation, whatever side
//! of the saturation line the state is on: the steam laws at a pressure a
//! little above the saturation pressure give metastable (subcooled) steam,
//! the liquid laws below it metastable (superheated) liquid, as the
//! derivatives and finite differences near saturation need. Far from
//! their phase the equations mean nothing, so each law has a domain and
//! an input outside it is an error, never a made-up number.

use seuif97::{pt, OCP, OD, ODV, ODVDT, OH, OT, OTC, OV, OW};
use std::fmt;

/// Specific gas constant of water in IAPWS-IF97, J/(kg·K).
pub const R: f64 = 461.526;
/// Critical temperature (K) and pressure (Pa).
pub const T_CRIT: f64 = 647.096;
pub const P_CRIT: f64 = 22.064e6;
/// The lowest temperature of IF97 (K), and the saturation pressure there.
pub const T_MIN: f64 = 273.15;
pub const P_SAT_MIN: f64 = 611.212_677;
/// Upper temperatures of the liquid (region 1) and steam (region 2)
/// equations, and their upper pressure.
pub const T_MAX_LIQUID: f64 = 623.15;
pub const T_MAX_STEAM: f64 = 1073.15;
pub const P_MAX: f64 = 100.0e6;
/// How far above the saturation pressure the steam laws still go
/// (metastable steam), as a factor of it.
pub const STEAM_OVERPRESSURE: f64 = 1.2;

/// An input outside a law's domain, or a result that is not a number.
#[derive(Debug, Clone, PartialEq)]
pub struct WaterError(pub String);

impl fmt::Display for WaterError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

pub type Result<T> = std::result::Result<T, WaterError>;

fn within(what: &str, unit: &str, v: f64, lo: f64, hi: f64, range: &str) -> Result<()> {
    if !v.is_finite() {
        return Err(WaterError(format!("the {} is {}, not a finite number", what, v)));
    }
    if v < lo || v > hi {
        return Err(WaterError(format!(
            "the {} {} {} is outside the {} ({} to {} {})",
            what,
            fmt_num(v),
            unit,
            range,
            fmt_num(lo),
            fmt_num(hi),
            unit
        )));
    }
    Ok(())
}

/// Numbers in messages: short, and exact enough to find the bad input.
pub fn fmt_num(v: f64) -> String {
    if v != 0.0 && (v.abs() >= 1e6 || v.abs() < 1e-3) {
        let s = format!("{:.6e}", v);
        let (m, e) = s.split_once('e').unwrap_or((&s, "0"));
        let m = if m.contains('.') { m.trim_end_matches('0').trim_end_matches('.') } else { m };
        format!("{}e{}", m, e)
    } else {
        format!("{}", (v * 1e6).round() / 1e6)
    }
}

fn finite(what: &str, v: f64) -> Result<f64> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(WaterError(format!("the {} is not a finite number here", what)))
    }
}

// ---- region 4: the saturation line ------------------------------------

/// IF97 region 4 coefficients n1 … n10 (IAPWS-IF97, Table 34).
const N4: [f64; 10] = [
    0.116_705_214_527_67e4,
    -0.724_213_167_032_06e6,
    -0.170_738_469_400_92e2,
    0.120_208_247_024_70e5,
    -0.323_255_503_223_33e7,
    0.149_151_086_135_30e2,
    -0.482_326_573_615_91e4,
    0.405_113_405_420_57e6,
    -0.238_555_575_678_49,
    0.650_175_348_447_98e3,
];

fn check_sat_t(t: f64) -> Result<()> {
    within("temperature", "K", t, T_MIN, T_CRIT, "saturation line of water")
}

/// Saturation pressure (Pa) at `t` (K) and its derivative (Pa/K), from
/// IF97's saturation equation in θ = T + n9/(T − n10).
fn psat_and_slope(t: f64) -> (f64, f64) {
    let n = &N4;
    let th = t + n[8] / (t - n[9]);
    let dth = 1.0 - n[8] / ((t - n[9]) * (t - n[9]));
    let a = th * th + n[0] * th + n[1];
    let b = n[2] * th * th + n[3] * th + n[4];
    let c = n[5] * th * th + n[6] * th + n[7];
    let (da, db, dc) = ((2.0 * th + n[0]) * dth, (2.0 * n[2] * th + n[3]) * dth, (2.0 * n[5] * th + n[6]) * dth);
    let s = (b * b - 4.0 * a * c).sqrt();
    let ds = (2.0 * b * db - 4.0 * (da * c + a * dc)) / (2.0 * s);
    let den = s - b;
    let x = 2.0 * c / den;
    let dx = (2.0 * dc * den - 2.0 * c * (ds - db)) / (den * den);
    // p = x⁴ MPa.
    (x.powi(4) * 1e6, 4.0 * x.powi(3) * dx * 1e6)
}

/// `PSATT`: saturation pressure (Pa) at the temperature `t` (K).
pub fn psat(t: f64) -> Result<f64> {
    check_sat_t(t)?;
    finite("saturation pressure", psat_and_slope(t).0)
}

/// `DPSAT`: derivative of the saturation pressure, Pa/K.
pub fn dpsat_dt(t: f64) -> Result<f64> {
    check_sat_t(t)?;
    finite("saturation pressure slope", psat_and_slope(t).1)
}

/// `TSATP`: saturation temperature (K) at the pressure `p` (Pa), IF97's
/// explicit inverse of the saturation equation.
pub fn tsat(p: f64) -> Result<f64> {
    within("pressure", "Pa", p, P_SAT_MIN, P_CRIT, "saturation line of water")?;
    let n = &N4;
    let beta = (p / 1e6).powf(0.25);
    let e = beta * beta + n[2] * beta + n[5];
    let f = n[0] * beta * beta + n[3] * beta + n[6];
    let g = n[1] * beta * beta + n[4] * beta + n[7];
    let d = 2.0 * g / (-f - (f * f - 4.0 * e * g).sqrt());
    let t = (n[9] + d - ((n[9] + d) * (n[9] + d) - 4.0 * (n[8] + n[9] * d)).sqrt()) / 2.0;
    finite("saturation temperature", t)
}

// ---- region 1: liquid water ------------------------------------------

fn check_liquid(p: f64, t: f64) -> Result<()> {
    within("temperature", "K", t, T_MIN, T_MAX_LIQUID, "range of liquid water")?;
    within("pressure", "Pa", p, f64::MIN_POSITIVE, P_MAX, "range of liquid water")
}

/// One IF97 region-1 property at (p Pa, t K), in the crate's units.
fn liquid(p: f64, t: f64, id: i32) -> f64 {
    pt(p / 1e6, t - 273.15, (id, 1))
}

/// `HLS`: specific enthalpy of liquid water, J/kg.
pub fn h_liquid(p: f64, t: f64) -> Result<f64> {
    check_liquid(p, t)?;
    finite("liquid enthalpy", liquid(p, t, OH) * 1e3)
}

/// Isobaric heat capacity of liquid water, J/(kg·K).
pub fn cp_liquid(p: f64, t: f64) -> Result<f64> {
    check_liquid(p, t)?;
    finite("liquid heat capacity", liquid(p, t, OCP) * 1e3)
}

/// Density of liquid water, kg/m³.
pub fn rho_liquid(p: f64, t: f64) -> Result<f64> {
    check_liquid(p, t)?;
    finite("liquid density", liquid(p, t, OD))
}

/// `DHLDP`: (∂h/∂p)_T of liquid water, J/(kg·Pa) = v − T (∂v/∂T)_p.
pub fn dh_liquid_dp(p: f64, t: f64) -> Result<f64> {
    check_liquid(p, t)?;
    finite("liquid enthalpy slope", liquid(p, t, OV) - t * liquid(p, t, ODVDT))
}

/// `TLIQ`: temperature (K) of liquid water of enthalpy `h` (J/kg) at `p`:
/// the inverse of [`h_liquid`] (IF97's backward equation as the first
/// guess, then Newton on the forward one, so that TLIQ and HLS agree to
/// rounding).
pub fn t_liquid(p: f64, h: f64) -> Result<f64> {
    within("pressure", "Pa", p, f64::MIN_POSITIVE, P_MAX, "range of liquid water")?;
    let (lo, hi) = (h_liquid(p, T_MIN)?, h_liquid(p, T_MAX_LIQUID)?);
    within("enthalpy", "J/kg", h, lo, hi, &format!("liquid water's at {} Pa", fmt_num(p)))?;
    let mut t = seuif97::ph(p / 1e6, h / 1e3, (OT, 1)) + 273.15;
    if !t.is_finite() || !(T_MIN..=T_MAX_LIQUID).contains(&t) {
        t = T_MIN + (T_MAX_LIQUID - T_MIN) * (h - lo) / (hi - lo);
    }
    for _ in 0..50 {
        let f = liquid(p, t, OH) * 1e3 - h;
        let dt = f / (liquid(p, t, OCP) * 1e3);
        t = (t - dt).clamp(T_MIN, T_MAX_LIQUID);
        if dt.abs() <= 1e-13 * t {
            break;
        }
    }
    finite("liquid temperature", t)
}

// ---- region 2: steam --------------------------------------------------

fn check_steam(p: f64, t: f64) -> Result<()> {
    within("temperature", "K", t, T_MIN, T_MAX_STEAM, "range of steam")?;
    within("pressure", "Pa", p, f64::MIN_POSITIVE, P_MAX, "range of steam")?;
    if t < T_CRIT {
        let limit = STEAM_OVERPRESSURE * psat_and_slope(t).0;
        if p > limit {
            return Err(WaterError(format!(
                "at {} K steam exists up to {} Pa (its saturation pressure, +20% of metastable steam), not {} Pa: this is liquid water",
                fmt_num(t),
                fmt_num(limit),
                fmt_num(p)
            )));
        }
    }
    Ok(())
}

fn steam(p: f64, t: f64, id: i32) -> f64 {
    pt(p / 1e6, t - 273.15, (id, 2))
}

/// (∂v/∂p)_T of steam, m³/(kg·Pa), from the speed of sound, cp and
/// (∂v/∂T)_p: (∂v/∂p)_T = −v²/w² − T (∂v/∂T)²/cp. seuif97 2.3's own
/// region-2 (∂v/∂p)_T takes the ideal-gas γ°_ππ = +1/π² (it is −1/π²) and
/// has the wrong sign; the quantities used here do not go through it.
fn dv_dp_steam(p: f64, t: f64) -> f64 {
    let (v, w, dvdt, cp) = (steam(p, t, OV), steam(p, t, OW), steam(p, t, ODVDT), steam(p, t, OCP) * 1e3);
    -v * v / (w * w) - t * dvdt * dvdt / cp
}

/// `HVS`: specific enthalpy of steam, J/kg.
pub fn h_steam(p: f64, t: f64) -> Result<f64> {
    check_steam(p, t)?;
    finite("steam enthalpy", steam(p, t, OH) * 1e3)
}

/// `DHVDT`: isobaric heat capacity of steam, J/(kg·K).
pub fn cp_steam(p: f64, t: f64) -> Result<f64> {
    check_steam(p, t)?;
    finite("steam heat capacity", steam(p, t, OCP) * 1e3)
}

/// `DHVDP`: (∂h/∂p)_T of steam, J/(kg·Pa).
pub fn dh_steam_dp(p: f64, t: f64) -> Result<f64> {
    check_steam(p, t)?;
    finite("steam enthalpy slope", steam(p, t, OV) - t * steam(p, t, ODVDT))
}

/// `ROVAP`: density of steam, kg/m³.
pub fn rho_steam(p: f64, t: f64) -> Result<f64> {
    check_steam(p, t)?;
    finite("steam density", steam(p, t, OD))
}

/// `DRVDP`: (∂ρ/∂p)_T of steam, kg/(m³·Pa).
pub fn drho_steam_dp(p: f64, t: f64) -> Result<f64> {
    check_steam(p, t)?;
    let rho = steam(p, t, OD);
    finite("steam density slope", -rho * rho * dv_dp_steam(p, t))
}

/// `DRVDT`: (∂ρ/∂T)_p of steam, kg/(m³·K).
pub fn drho_steam_dt(p: f64, t: f64) -> Result<f64> {
    check_steam(p, t)?;
    let rho = steam(p, t, OD);
    finite("steam density slope", -rho * rho * steam(p, t, ODVDT))
}

/// `DZVDP`: (∂Z/∂p)_T of the compressibility factor Z = p v/(R T), 1/Pa.
pub fn dz_steam_dp(p: f64, t: f64) -> Result<f64> {
    check_steam(p, t)?;
    let (v, dv) = (steam(p, t, OV), dv_dp_steam(p, t));
    finite("compressibility slope", (v + p * dv) / (R * t))
}

/// `DZVDT`: (∂Z/∂T)_p of the compressibility factor, 1/K.
pub fn dz_steam_dt(p: f64, t: f64) -> Result<f64> {
    check_steam(p, t)?;
    let (v, dv) = (steam(p, t, OV), steam(p, t, ODVDT));
    finite("compressibility slope", p * (t * dv - v) / (R * t * t))
}

/// `PVAP`: pressure (Pa) of steam of density `rho` at `t`: the inverse of
/// [`rho_steam`] (Newton from the ideal gas).
pub fn p_steam(rho: f64, t: f64) -> Result<f64> {
    within("temperature", "K", t, T_MIN, T_MAX_STEAM, "range of steam")?;
    within("density", "kg/m3", rho, f64::MIN_POSITIVE, f64::MAX, "range of steam")?;
    let p_max = if t < T_CRIT { STEAM_OVERPRESSURE * psat_and_slope(t).0 } else { P_MAX };
    let rho_max = steam(p_max, t, OD);
    if !rho_max.is_finite() || rho > rho_max {
        return Err(WaterError(format!(
            "steam at {} K is at most {} kg/m3 dense (up to {} Pa), not {} kg/m3: this is liquid water",
            fmt_num(t),
            fmt_num(rho_max),
            fmt_num(p_max),
            fmt_num(rho)
        )));
    }
    let mut p = (rho * R * t).min(p_max);
    for _ in 0..100 {
        let f = steam(p, t, OD) - rho;
        let rho_now = steam(p, t, OD);
        let slope = -rho_now * rho_now * dv_dp_steam(p, t);
        let dp = f / slope;
        p = (p - dp).clamp(f64::MIN_POSITIVE, p_max);
        if dp.abs() <= 1e-14 * p {
            break;
        }
    }
    finite("steam pressure", p)
}

/// `ZVAP`: compressibility factor p/(ρ R T) of steam of density `rho` at `t`.
pub fn z_steam(rho: f64, t: f64) -> Result<f64> {
    let p = p_steam(rho, t)?;
    finite("compressibility factor", p / (rho * R * t))
}

// ---- transport properties of the liquid --------------------------------

/// `MULIQ`: dynamic viscosity (Pa·s) of liquid water at `t` on its
/// saturation line (IAPWS 2008).
pub fn mu_liquid(t: f64) -> Result<f64> {
    within("temperature", "K", t, T_MIN, T_MAX_LIQUID, "range of liquid water")?;
    let p = psat_and_slope(t).0;
    finite("liquid viscosity", liquid(p, t, ODV))
}

/// `LBDALIQ`: thermal conductivity (W/(m·K)) of liquid water (IAPWS 2011).
pub fn lambda_liquid(p: f64, t: f64) -> Result<f64> {
    check_liquid(p, t)?;
    finite("liquid conductivity", liquid(p, t, OTC))
}

#[cfg(test)]
#[path = "water_tests.rs"]
mod tests;
