//! Checks against the verification values that IAPWS publishes with its
//! releases (IF97 Tables 5, 15, 35, 36; IAPWS 2008 viscosity and 2011
//! conductivity), and consistency of each derivative with finite
//! differences of the law it differentiates.

use super::*;

fn close(got: f64, want: f64, rel: f64) {
    assert!(((got - want) / want).abs() <= rel, "got {got}, want {want} (relative tolerance {rel})");
}

#[test]
fn saturation_line_matches_if97_tables_35_and_36() {
    close(psat(300.0).unwrap(), 0.353_658_941e-2 * 1e6, 5e-9);
    close(psat(500.0).unwrap(), 0.263_889_776e1 * 1e6, 5e-9);
    close(psat(600.0).unwrap(), 0.123_443_146e2 * 1e6, 5e-9);
    close(tsat(0.1e6).unwrap(), 0.372_755_919e3, 5e-9);
    close(tsat(1.0e6).unwrap(), 0.453_035_632e3, 5e-9);
    close(tsat(10.0e6).unwrap(), 0.584_149_488e3, 5e-9);
    // TSATP is the inverse of PSATT.
    for t in [280.0, 373.15, 453.15, 600.0, 640.0] {
        close(tsat(psat(t).unwrap()).unwrap(), t, 1e-12);
    }
}

#[test]
fn saturation_slope_is_the_derivative_of_the_pressure() {
    for t in [275.0, 300.0, 373.15, 500.0, 640.0] {
        let h = 1e-3;
        let fd = (psat(t + h).unwrap() - psat(t - h).unwrap()) / (2.0 * h);
        close(dpsat_dt(t).unwrap(), fd, 1e-7);
    }
    // Clausius-Clapeyron at 100 °C: dp/dT = L / (T (v'' - v')), with
    // L = 2256.4 kJ/kg, v'' = 1.6718 m³/kg (steam tables) → 3.62 kPa/K.
    close(dpsat_dt(373.124).unwrap(), 2256.4e3 / (373.124 * (1.6718 - 0.001_043)), 2e-3);
}

#[test]
fn liquid_matches_if97_table_5() {
    close(1.0 / rho_liquid(3e6, 300.0).unwrap(), 0.100_215_168e-2, 1e-8);
    close(h_liquid(3e6, 300.0).unwrap(), 0.115_331_273e3 * 1e3, 1e-8);
    close(cp_liquid(3e6, 300.0).unwrap(), 0.417_301_218e1 * 1e3, 1e-8);
    close(1.0 / rho_liquid(80e6, 300.0).unwrap(), 0.971_180_894e-3, 1e-8);
    close(h_liquid(80e6, 300.0).unwrap(), 0.184_142_828e3 * 1e3, 1e-8);
    close(h_liquid(3e6, 500.0).unwrap(), 0.975_542_239e3 * 1e3, 1e-8);
    close(cp_liquid(3e6, 500.0).unwrap(), 0.465_580_682e1 * 1e3, 1e-8);
}

#[test]
fn steam_matches_if97_table_15() {
    close(1.0 / rho_steam(0.0035e6, 300.0).unwrap(), 0.394_913_866e2, 1e-8);
    close(h_steam(0.0035e6, 300.0).unwrap(), 0.254_991_145e4 * 1e3, 1e-8);
    close(cp_steam(0.0035e6, 300.0).unwrap(), 0.191_300_162e1 * 1e3, 1e-8);
    close(1.0 / rho_steam(0.0035e6, 700.0).unwrap(), 0.923_015_898e2, 1e-8);
    close(h_steam(0.0035e6, 700.0).unwrap(), 0.333_568_375e4 * 1e3, 1e-8);
    close(1.0 / rho_steam(30e6, 700.0).unwrap(), 0.542_946_619e-2, 1e-8);
    close(h_steam(30e6, 700.0).unwrap(), 0.263_149_474e4 * 1e3, 1e-8);
    close(cp_steam(30e6, 700.0).unwrap(), 0.103_505_092e2 * 1e3, 1e-8);
}

#[test]
fn inverses_agree_with_the_forward_laws() {
    for (p, t) in [(1e5, 300.0), (1e6, 453.0), (10e6, 600.0), (2e5, 273.2)] {
        let h = h_liquid(p, t).unwrap();
        close(t_liquid(p, h).unwrap(), t, 1e-12);
    }
    for (p, t) in [(1e3, 300.0), (1e5, 400.0), (1e6, 460.0), (20e6, 900.0)] {
        let rho = rho_steam(p, t).unwrap();
        close(p_steam(rho, t).unwrap(), p, 1e-11);
        close(z_steam(rho, t).unwrap(), p / (rho * R * t), 1e-11);
    }
    // A dilute steam is an ideal gas.
    close(z_steam(1e-6, 500.0).unwrap(), 1.0, 1e-6);
}

/// Central differences of a law against its derivative.
fn fd(f: impl Fn(f64) -> f64, x: f64, h: f64) -> f64 {
    (f(x + h) - f(x - h)) / (2.0 * h)
}

#[test]
fn derivatives_are_those_of_the_laws() {
    for (p, t) in [(1.0133e5, 373.15), (5.021e5, 425.15), (10.027e5, 453.15), (1e5, 500.0)] {
        close(cp_steam(p, t).unwrap(), fd(|t| h_steam(p, t).unwrap(), t, 1e-3), 1e-6);
        close(dh_steam_dp(p, t).unwrap(), fd(|p| h_steam(p, t).unwrap(), p, 1.0), 1e-5);
        close(drho_steam_dp(p, t).unwrap(), fd(|p| rho_steam(p, t).unwrap(), p, 1.0), 1e-6);
        close(drho_steam_dt(p, t).unwrap(), fd(|t| rho_steam(p, t).unwrap(), t, 1e-3), 1e-6);
        let z = |p: f64, t: f64| p / (rho_steam(p, t).unwrap() * R * t);
        close(dz_steam_dp(p, t).unwrap(), fd(|p| z(p, t), p, 10.0), 1e-4);
        close(dz_steam_dt(p, t).unwrap(), fd(|t| z(p, t), t, 1e-2), 1e-4);
    }
    for (p, t) in [(1e5, 300.0), (1e6, 453.15), (10e6, 550.0)] {
        close(dh_liquid_dp(p, t).unwrap(), fd(|p| h_liquid(p, t).unwrap(), p, 100.0), 1e-5);
        close(cp_liquid(p, t).unwrap(), fd(|t| h_liquid(p, t).unwrap(), t, 1e-3), 1e-6);
    }
}

#[test]
fn transport_properties_match_iapws() {
    // IAPWS 2008 viscosity, 2011 conductivity: liquid at 25 °C, 0.1 MPa
    // (verification values 890.0 µPa·s and 0.6065 W/(m·K)).
    close(mu_liquid(298.15).unwrap(), 890.0e-6, 1e-3);
    close(lambda_liquid(0.1e6, 298.15).unwrap(), 0.6065, 1e-3);
    // Hotter water is more fluid: 100 °C, 281.8 µPa·s on the saturation line.
    close(mu_liquid(373.15).unwrap(), 281.8e-6, 2e-3);
}

#[test]
fn out_of_domain_is_an_error_never_a_number() {
    assert!(psat(250.0).unwrap_err().0.contains("saturation line"));
    assert!(psat(700.0).is_err());
    assert!(psat(f64::NAN).unwrap_err().0.contains("not a finite number"));
    assert!(tsat(100.0).is_err());
    assert!(tsat(30e6).is_err());
    assert!(h_liquid(1e5, 700.0).is_err());
    assert!(h_liquid(-1.0, 300.0).is_err());
    // Steam at 1 MPa and 300 K would be deep in the liquid.
    assert!(h_steam(1e6, 300.0).unwrap_err().0.contains("liquid water"));
    assert!(p_steam(1000.0, 373.15).unwrap_err().0.contains("liquid water"));
    assert!(p_steam(-1.0, 373.15).is_err());
    assert!(t_liquid(1e5, 1e8).is_err());
    assert!(mu_liquid(200.0).is_err());
}
