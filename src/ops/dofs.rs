//! Unknown names per analysis mode and their duals (UX ↔ FX, LX ↔ FLX).

use crate::eval::Interp;

/// Translations of the current mode (BLOQ DEPL, FORC vectors).
pub fn translations(it: &Interp) -> &'static [&'static str] {
    let m = it.opts.mode.as_str();
    if m.starts_with("AXIS") {
        &["UR", "UZ"]
    } else if m.starts_with("FOUR") {
        &["UR", "UZ", "UT"]
    } else if it.opts.dime == 3 || m == "TRID" {
        &["UX", "UY", "UZ"]
    } else if it.opts.dime == 1 {
        &["UX"]
    } else {
        &["UX", "UY"]
    }
}

/// Rotations of the current mode (BLOQ ROTA).
pub fn rotations(it: &Interp) -> &'static [&'static str] {
    let m = it.opts.mode.as_str();
    if m.starts_with("AXIS") || m.starts_with("FOUR") {
        &["RT"]
    } else if it.opts.dime == 3 || m == "TRID" {
        &["RX", "RY", "RZ"]
    } else {
        &["RZ"]
    }
}

/// Force and moment names of the current mode (FORC/MOME with a vector).
pub fn forces(it: &Interp) -> &'static [&'static str] {
    let m = it.opts.mode.as_str();
    if m.starts_with("AXIS") {
        &["FR", "FZ"]
    } else if it.opts.dime == 3 || m == "TRID" {
        &["FX", "FY", "FZ"]
    } else {
        &["FX", "FY"]
    }
}

pub fn moments(it: &Interp) -> &'static [&'static str] {
    if it.opts.dime == 3 {
        &["MX", "MY", "MZ"]
    } else {
        &["MZ"]
    }
}

/// Pairs the element library does not know: multipliers, thermal and
/// Fourier unknowns. Mechanical pairs (UX ↔ FX …) come from
/// `fem::element::dual_of`, the one table the elements use too.
const EXTRA: &[(&str, &str)] =
    &[("UT", "FT"), ("RT", "MT"), ("LX", "FLX"), ("T", "Q"), ("TH", "QH"), ("P", "FP"), ("PI", "FPI")];

/// The primal names gibi knows (mechanical, then EXTRA), for VALE 'INCO'.
pub fn known_primals() -> Vec<&'static str> {
    let mut v = vec!["UX", "UY", "UZ", "UR", "RX", "RY", "RZ"];
    v.extend(EXTRA.iter().map(|(p, _)| *p));
    v
}

/// The dual (force) name of a primal unknown.
pub fn dual_of(primal: &str) -> String {
    if let Some(d) = crate::fem::element::dual_of(primal) {
        return d.to_string();
    }
    EXTRA.iter().find(|(p, _)| *p == primal).map_or_else(|| format!("F{}", primal), |(_, d)| d.to_string())
}
