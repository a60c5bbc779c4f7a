//! Stresses and strains at a fibre of a beam section from its generalised
//! ones (CALP on POUT/TIMO): at the point (y, z) = (DY, DZ) of the local
//! section, σxx = N/A + My·z/Iy − Mz·y/Iz and εxx = e + κy·z − κz·y (the
//! signs follow MOMY = EIy·CURY, MOMZ = EIz·CURZ). Shear stresses from the
//! shear forces and the twisting moment are not computed (as Cast3M's
//! notice says for the twist), so only the axial component is produced.

use super::element::{FemError, GaussField};
use super::material::Material;

/// The axial stress SMXX (from EFFX …) or strain EPXX (from EPSS …) at the
/// fibre (DY, DZ); a missing DY or DZ is the section's centroid line.
pub fn at_fibre(elem: &'static str, g: &GaussField, m: &Material) -> Result<GaussField, FemError> {
    let has = |c: &str| g.comps.contains(&c);
    let at = |v: &[f64], c: &str| g.comps.iter().position(|n| *n == c).map_or(0.0, |i| v[i]);
    let (y, z) = (m.dy.unwrap_or(0.0), m.dz.unwrap_or(0.0));
    if has("EFFX") {
        let a = m.positive(m.sect, "SECT", elem)?;
        let iz = if has("MOMZ") { m.positive(m.inrz, "INRZ", elem)? } else { 1.0 };
        let iy = if has("MOMY") { m.positive(m.inry, "INRY", elem)? } else { 1.0 };
        let values = g
            .values
            .iter()
            .map(|v| vec![at(v, "EFFX") / a + at(v, "MOMY") * z / iy - at(v, "MOMZ") * y / iz])
            .collect();
        Ok(GaussField { comps: vec!["SMXX"], values })
    } else if has("EPSS") {
        let values = g.values.iter().map(|v| vec![at(v, "EPSS") + at(v, "CURY") * z - at(v, "CURZ") * y]).collect();
        Ok(GaussField { comps: vec!["EPXX"], values })
    } else {
        Err(FemError::NotFor { what: "this field in CALP (a beam's EFFX … or EPSS …)", form: elem })
    }
}
