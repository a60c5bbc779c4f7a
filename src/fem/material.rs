//! Material and section data (MATE and CARA merged), and elasticity
//! matrices for each analysis mode.

use super::element::{FemError, Mode};

/// Everything MATE and CARA can give an element, merged. Absent values are
/// `None`; each element asks for what it needs and reports what is missing.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Material {
    pub youn: Option<f64>,
    pub nu: Option<f64>,
    pub rho: Option<f64>,
    /// Thermal expansion coefficient, and the temperature at which the
    /// thermal strain is zero (MATE 'TREF', 0 by default as in Cast3M).
    pub alph: Option<f64>,
    pub tref: Option<f64>,
    /// Cross-section area (BARR, POUT, TIMO).
    pub sect: Option<f64>,
    /// Second moments about the local y and z axes.
    pub inry: Option<f64>,
    pub inrz: Option<f64>,
    /// Torsion constant J.
    pub tors: Option<f64>,
    /// Shear areas along local y and z (TIMO).
    pub secy: Option<f64>,
    pub secz: Option<f64>,
    pub epai: Option<f64>,
    /// Offset of a shell's mid-surface from its nodes, along the normal.
    pub exce: Option<f64>,
    /// Thickness of plane-stress solids (default 1).
    pub dim3: Option<f64>,
    /// Fibre distances used by the beam VMIS formula.
    pub dx: Option<f64>,
    pub dy: Option<f64>,
    pub dz: Option<f64>,
    /// Local y axis of 3D beams (CARA 'VECT', or MATE 'VX' 'VY' 'VZ').
    pub vect: Option<[f64; 3]>,
    /// Offsets of an eccentric bar's fibre (BAEX) along local y and z.
    pub excy: Option<f64>,
    pub excz: Option<f64>,
    /// Tangential and normal stiffnesses of joints, per unit area.
    pub ks: Option<f64>,
    pub kn: Option<f64>,
    /// Thermal conductivity (MATE 'K') and specific heat (MATE 'C') of a
    /// THERMIQUE model.
    pub cond: Option<f64>,
    pub capa: Option<f64>,
    /// A Hooke matrix given in place of the elastic constants (RIGI of a
    /// HOOKE field): entries named "STRESS/STRAIN" (SMXX/EPXX …). When
    /// present it is the elasticity matrix, whatever YOUN and NU say.
    pub hooke: Vec<(String, f64)>,
}

impl Material {
    /// Set the property Cast3M names `name` (YOUN, NU, …); false for a name
    /// that is not a scalar property of this material.
    pub fn set(&mut self, name: &str, v: f64) -> bool {
        // MATE 'VX' 'VY' 'VZ': the components of the local y vector.
        if let Some(i) = ["VX", "VY", "VZ"].iter().position(|c| *c == name) {
            let mut w = self.vect.unwrap_or([0.0; 3]);
            w[i] = v;
            self.vect = Some(w);
            return true;
        }
        let v = Some(v);
        match name {
            "YOUN" => self.youn = v,
            "NU" => self.nu = v,
            "RHO" => self.rho = v,
            "ALPH" => self.alph = v,
            "TREF" => self.tref = v,
            "SECT" => self.sect = v,
            "INRY" => self.inry = v,
            "INRZ" => self.inrz = v,
            "TORS" => self.tors = v,
            "SECY" => self.secy = v,
            "SECZ" => self.secz = v,
            "EPAI" => self.epai = v,
            "DIM3" => self.dim3 = v,
            "EXCE" => self.exce = v,
            "DX" => self.dx = v,
            "DY" => self.dy = v,
            "DZ" => self.dz = v,
            "KS" => self.ks = v,
            "EXCY" => self.excy = v,
            "EXCZ" => self.excz = v,
            "KN" => self.kn = v,
            "K" => self.cond = v,
            "C" => self.capa = v,
            _ => return false,
        }
        true
    }

    /// A required, strictly positive property.
    pub(crate) fn positive(&self, v: Option<f64>, prop: &'static str, elem: &'static str) -> Result<f64, FemError> {
        let x = v.ok_or(FemError::MissingProperty { prop, elem })?;
        if x.is_finite() && x > 0.0 {
            Ok(x)
        } else {
            Err(FemError::InvalidProperty { prop, value: x, elem, why: "must be positive" })
        }
    }

    pub(crate) fn young(&self, elem: &'static str) -> Result<f64, FemError> {
        self.positive(self.youn, "YOUN", elem)
    }

    /// Poisson's ratio of a 3D state of stress (solids in TRID, plane
    /// strain, AXIS), kept inside (-1, 1/2) where the elasticity matrix is
    /// positive definite: at 1/2 the material is incompressible and
    /// λ = Eν/((1+ν)(1−2ν)) is infinite.
    pub(crate) fn poisson(&self, elem: &'static str) -> Result<f64, FemError> {
        let nu = self.nu.ok_or(FemError::MissingProperty { prop: "NU", elem })?;
        if nu.is_finite() && nu > -1.0 && nu < 0.5 {
            Ok(nu)
        } else {
            Err(FemError::InvalidProperty { prop: "NU", value: nu, elem, why: "must lie in (-1, 0.5)" })
        }
    }

    /// Poisson's ratio where σzz = 0 (plane stress, shells) or only the
    /// shear modulus uses it (beams): E/(1 − ν²) and E/(2(1 + ν)) stay
    /// positive and finite on (-1, 1), so an incompressible material
    /// (ν = 1/2, rubber) is valid there.
    pub(crate) fn poisson_plane_stress(&self, elem: &'static str) -> Result<f64, FemError> {
        let nu = self.nu.ok_or(FemError::MissingProperty { prop: "NU", elem })?;
        if nu.is_finite() && nu > -1.0 && nu < 1.0 {
            Ok(nu)
        } else {
            Err(FemError::InvalidProperty { prop: "NU", value: nu, elem, why: "must lie in (-1, 1) in plane stress" })
        }
    }

    /// Shear modulus E / (2(1 + ν)).
    pub(crate) fn shear_modulus(&self, elem: &'static str) -> Result<f64, FemError> {
        Ok(self.young(elem)? / (2.0 * (1.0 + self.poisson_plane_stress(elem)?)))
    }

    /// Thermal expansion coefficient: any finite value (a negative α is a
    /// material that shrinks when heated, not an input error).
    pub(crate) fn expansion(&self, elem: &'static str) -> Result<f64, FemError> {
        let a = self.alph.ok_or(FemError::MissingProperty { prop: "ALPH", elem })?;
        if a.is_finite() {
            Ok(a)
        } else {
            Err(FemError::InvalidProperty { prop: "ALPH", value: a, elem, why: "must be finite" })
        }
    }

    pub(crate) fn density(&self, elem: &'static str) -> Result<f64, FemError> {
        self.positive(self.rho, "RHO", elem)
    }

    /// Plane-stress thickness; the other modes have none (unit thickness for
    /// plane strain, per radian for AXIS).
    pub(crate) fn thickness(&self, mode: Mode, elem: &'static str) -> Result<f64, FemError> {
        match (mode, self.dim3) {
            (Mode::PlanCont, Some(_)) => self.positive(self.dim3, "DIM3", elem),
            _ => Ok(1.0),
        }
    }
}

/// Elasticity matrix of a massive element, in the strain order of the mode:
/// 2D modes `[xx, yy, zz, xy]` (zz is θθ in AXIS, r ↔ x and z ↔ y), TRID
/// `[xx, yy, zz, xy, xz, yz]`, engineering shears.
///
/// Plane stress keeps a zero zz row and column, so the same 4-strain B
/// matrix serves every 2D mode and σzz comes out 0 by construction.
pub(crate) fn elasticity(mode: Mode, m: &Material, elem: &'static str) -> Result<Vec<Vec<f64>>, FemError> {
    if let Some(d) = super::hooke_matrix::given(m, &super::solid::stress_comps(mode), &super::solid::strain_comps(mode))
    {
        return d;
    }
    let e = m.young(elem)?;
    let nu = match mode {
        Mode::PlanCont => m.poisson_plane_stress(elem)?,
        _ => m.poisson(elem)?,
    };
    let g = e / (2.0 * (1.0 + nu));
    let lam = e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    Ok(match mode {
        Mode::PlanCont => {
            let c = e / (1.0 - nu * nu);
            vec![vec![c, c * nu, 0.0, 0.0], vec![c * nu, c, 0.0, 0.0], vec![0.0; 4], vec![0.0, 0.0, 0.0, g]]
        }
        Mode::PlanDefo | Mode::Axis => {
            let d = lam + 2.0 * g;
            vec![vec![d, lam, lam, 0.0], vec![lam, d, lam, 0.0], vec![lam, lam, d, 0.0], vec![0.0, 0.0, 0.0, g]]
        }
        // FOUR's strains are TRID's with r, z, θ for x, y, z.
        Mode::Trid | Mode::Fourier(_) => {
            let d = lam + 2.0 * g;
            let mut k = vec![vec![0.0; 6]; 6];
            for i in 0..3 {
                k[i][..3].copy_from_slice(&[lam; 3]);
                k[i][i] = d;
                k[i + 3][i + 3] = g;
            }
            k
        }
    })
}
