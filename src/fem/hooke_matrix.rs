//! The Hooke matrix of an element's material (HOOKE), and the reverse
//! way: a Hooke matrix given in place of the elastic constants.
//!
//! A matrix is named entry by entry, "STRESS/STRAIN" (SMXX/EPXX, SIGN/EPSN
//! …), with the component names of SIGM and EPSI, so a field of Hooke
//! matrices says by itself which strain each column multiplies and which
//! stress each row gives: the product with a strain field needs no model.

use super::element::{FemError, Formulation, Mode};
use super::material::{elasticity, Material};
use super::mesh::ElemType;
use super::{joint, solid};

/// Rows (stresses), columns (strains) and the matrix.
#[derive(Debug, Clone, PartialEq)]
pub struct HookeMatrix {
    pub stresses: Vec<&'static str>,
    pub strains: Vec<&'static str>,
    pub d: Vec<Vec<f64>>,
}

impl HookeMatrix {
    /// Every entry with its "STRESS/STRAIN" name, row by row.
    pub fn entries(&self) -> Vec<(String, f64)> {
        let mut out = Vec::new();
        for (s, row) in self.stresses.iter().zip(&self.d) {
            for (e, v) in self.strains.iter().zip(row) {
                out.push((format!("{s}/{e}"), *v));
            }
        }
        out
    }
}

/// The elastic Hooke matrix of a formulation in a mode. Massive elements:
/// the mode's elasticity matrix (engineering shears; plane stress has a
/// zero zz row). Joints: the diagonal KS…KN in the local frame. Bars: E·S.
pub fn of_material(f: Formulation, ty: ElemType, mode: Mode, m: &Material) -> Result<HookeMatrix, FemError> {
    match f {
        Formulation::Solid | Formulation::Q4ri | Formulation::Q8ri | Formulation::Incomp => Ok(HookeMatrix {
            stresses: solid::stress_comps(mode),
            strains: solid::strain_comps(mode),
            d: elasticity(mode, m, ty.name())?,
        }),
        Formulation::Joint => {
            let stresses = joint::comp_names(mode, true);
            let n = stresses.len();
            let ks = m.positive(m.ks, "KS", "JOI2")?;
            let kn = m.positive(m.kn, "KN", "JOI2")?;
            let mut d = vec![vec![0.0; n]; n];
            for (i, row) in d.iter_mut().enumerate() {
                row[i] = if i + 1 == n { kn } else { ks };
            }
            Ok(HookeMatrix { stresses, strains: joint::comp_names(mode, false), d })
        }
        Formulation::Barr | Formulation::Baex => {
            let ea = m.young("BARR")? * m.positive(m.sect, "SECT", "BARR")?;
            Ok(HookeMatrix { stresses: vec!["EFFX"], strains: vec!["EPSS"], d: vec![vec![ea]] })
        }
        _ => Err(FemError::NotFor { what: "the Hooke matrix (HOOKE)", form: f.name() }),
    }
}

/// The matrix of a material given by its Hooke entries, in the order of
/// `rows` and `cols`; None when the material has no Hooke entries. An
/// entry the matrix lacks counts as 0, but a matrix with none of the
/// element's entries belongs to another element.
pub(crate) fn given(m: &Material, rows: &[&str], cols: &[&str]) -> Option<Result<Vec<Vec<f64>>, FemError>> {
    if m.hooke.is_empty() {
        return None;
    }
    let mut found = false;
    let d = rows
        .iter()
        .map(|r| {
            cols.iter()
                .map(|c| {
                    let key = format!("{r}/{c}");
                    m.hooke.iter().find(|(k, _)| *k == key).map_or(0.0, |(_, v)| {
                        found = true;
                        *v
                    })
                })
                .collect()
        })
        .collect();
    Some(if found {
        Ok(d)
    } else {
        Err(FemError::MissingProperty { prop: "the Hooke matrix of this element", elem: "HOOKE" })
    })
}

/// σ = D ε at one point: the strain components come by name (absent ones
/// count as 0); the result has the matrix's stress components.
pub fn apply(h: &[(String, f64)], strain_names: &[String], eps: &[f64]) -> (Vec<String>, Vec<f64>) {
    let mut rows: Vec<String> = Vec::new();
    let mut out: Vec<f64> = Vec::new();
    for (key, v) in h {
        let Some((s, e)) = key.split_once('/') else { continue };
        let i = match rows.iter().position(|r| r == s) {
            Some(i) => i,
            None => {
                rows.push(s.to_string());
                out.push(0.0);
                rows.len() - 1
            }
        };
        if let Some(j) = strain_names.iter().position(|n| n == e) {
            out[i] += v * eps[j];
        }
    }
    (rows, out)
}
