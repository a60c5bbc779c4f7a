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
    if m.starts_with("AXIS") || m.starts_with("FOUR") {
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

/// The dual (force) name of a primal unknown (one table for the elements
/// and the language: `fem::element::dual_name`).
pub use crate::fem::element::dual_name as dual_of;

/// The primal names gibi knows (the mechanical ones, then the other pairs
/// of `fem::element::dual_name`), for VALE 'INCO'.
pub fn known_primals() -> Vec<&'static str> {
    let mut v = vec!["UX", "UY", "UZ", "UR", "RX", "RY", "RZ"];
    v.extend(crate::fem::element::OTHER_DUALS.iter().map(|(p, _)| *p));
    v
}
