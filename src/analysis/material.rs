//! The constitutive seam of the step driver.
//!
//! The driver asks a [`Material`] two things: whether its law is linear
//! with constant moduli (then a step is one solve with a stiffness
//! factorised once, and stresses follow from the displacements), and the
//! stresses of one element for its strains. Elasticity is the only law
//! today; a plastic law will implement the same trait with internal
//! variables and a tangent, and the driver will iterate on equilibrium
//! for it (the `is_linear` branch is where that loop goes).

use crate::fem::constitutive;
use crate::fem::element::{self, FemError, Formulation, GaussField, Mode};
use crate::fem::mesh::ElemType;

/// What an element is, for a material: its formulation and geometry.
#[derive(Debug, Clone, Copy)]
pub struct ElemKind {
    pub form: Formulation,
    pub ty: ElemType,
    pub mode: Mode,
}

/// A constitutive law, as the step driver sees it.
pub trait Material: std::fmt::Debug {
    /// The law's name, for messages ("ELASTIQUE").
    fn name(&self) -> &str;
    /// Linear elastic with constant moduli.
    fn is_linear(&self) -> bool;
    /// The element data the element routines read (moduli, sections).
    fn props(&self) -> &element::Material;
    /// The data of element `e` of its set (materials evaluated element by
    /// element, from a field of a parameter, differ between elements).
    fn props_of(&self, _e: usize) -> &element::Material {
        self.props()
    }
    /// Strains and stresses at the element points of one element, for its
    /// coordinates `x`, displacements `u` (element dof order) and, when the
    /// structure is heated, its nodal temperatures minus the reference;
    /// `e` is the element's number in its set.
    fn respond(
        &self,
        e: usize,
        k: ElemKind,
        x: &[[f64; 3]],
        u: &[f64],
        heat: Option<&[f64]>,
    ) -> Result<(GaussField, GaussField), FemError>;
}

/// Isotropic linear elasticity (MATE 'YOUN' 'NU', and 'ALPH' for thermal
/// strains), with one data set, or one per element (`by_elem`, empty when
/// the data are the same for all).
#[derive(Debug, Clone)]
pub struct Elastic {
    pub props: element::Material,
    pub by_elem: Vec<element::Material>,
}

impl Material for Elastic {
    fn name(&self) -> &str {
        "ELASTIQUE"
    }

    fn is_linear(&self) -> bool {
        true
    }

    fn props(&self) -> &element::Material {
        &self.props
    }

    fn props_of(&self, e: usize) -> &element::Material {
        self.by_elem.get(e).unwrap_or(&self.props)
    }

    fn respond(
        &self,
        e: usize,
        k: ElemKind,
        x: &[[f64; 3]],
        u: &[f64],
        heat: Option<&[f64]>,
    ) -> Result<(GaussField, GaussField), FemError> {
        let m = self.props_of(e);
        let eps = element::strain(k.form, k.ty, k.mode, x, m, u)?;
        let Some(dt) = heat else {
            let sig = element::stress(k.form, k.ty, k.mode, x, m, u)?;
            return Ok((eps, sig));
        };
        // σ = D (ε − εth), εth = α ΔT with ΔT measured from the reference
        // temperature of the run (the material's TREF is not used: PASAPAS
        // measures thermal strains from the initial temperature).
        let mut m0 = m.clone();
        m0.tref = Some(0.0);
        let th = constitutive::thermal_strain(k.form, k.ty, k.mode, &m0, dt)?;
        let mut mech = eps.clone();
        for (row, trow) in mech.values.iter_mut().zip(&th.values) {
            for (c, v) in mech.comps.iter().zip(row.iter_mut()) {
                if let Some(i) = th.comps.iter().position(|t| t == c) {
                    *v -= trow[i];
                }
            }
        }
        let sig = constitutive::hooke(k.form, k.ty, k.mode, m, &mech)?;
        Ok((eps, sig))
    }
}
