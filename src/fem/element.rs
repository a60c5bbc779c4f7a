//! The element library's public face: what the language glue calls per
//! element. Everything here is language-free: coordinates, a merged
//! material, element dofs in, matrices and Gauss-point fields out.
//!
//! Conventions:
//! * Element dofs are node-major: node 0's components in [`node_dofs`]
//!   order, then node 1's, ... `ElemMatrix::dofs` spells them out.
//! * Coordinates are always given in 3D; the plane modes ignore z. In
//!   AXIS, x is the radius r (> 0) and y is the axial coordinate z.
//! * AXIS quantities are **per radian** (stiffness, mass and pressure loads
//!   integrate r·dr·dz, without 2π), as Cast3M does: a nodal force FR on a
//!   ring is the force per radian of circumference.
//! * PLAN CONT matrices include the thickness DIM3 (default 1); PLAN DEFO
//!   is per unit thickness.

use super::mesh::ElemType;
use super::{bar, beam, coq2, joint, shell, solid};
use thiserror::Error;

pub use super::material::Material;

/// Cast3M analysis modes (`OPTI MODE`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Mode {
    PlanCont,
    PlanDefo,
    Axis,
    Trid,
    /// Fourier harmonic n of an axisymmetric geometry (`OPTI MODE FOUR n`,
    /// see [`super::fourier`]): n ≥ 0 symmetric, n < 0 antisymmetric.
    Fourier(i32),
}

impl Mode {
    pub fn name(self) -> &'static str {
        match self {
            Mode::PlanCont => "PLAN CONT",
            Mode::PlanDefo => "PLAN DEFO",
            Mode::Axis => "AXIS",
            Mode::Trid => "TRID",
            Mode::Fourier(_) => "FOUR",
        }
    }

    /// AXIS or a Fourier harmonic: x is the radius and the weights carry r.
    pub fn is_axisymmetric(self) -> bool {
        matches!(self, Mode::Axis | Mode::Fourier(_))
    }

    /// The factor of r in the weights of the axisymmetric modes: the whole
    /// turn 2π in AXIS, ∫cos²nθ dθ for a Fourier harmonic; None otherwise.
    pub fn turn(self) -> Option<f64> {
        match self {
            Mode::Axis => Some(std::f64::consts::TAU),
            Mode::Fourier(n) => Some(super::fourier::ring(n)),
            _ => None,
        }
    }
}

/// Element formulation: structural ones named in MODE, or a massive element
/// following the mesh geometry. `Q4ri` is QUA4 with one Gauss point, `Q8ri`
/// QUA8 with 2×2.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Formulation {
    Barr,
    /// A bar offset from its nodes (see [`super::eccentric_bar`]).
    Baex,
    Pout,
    Timo,
    Solid,
    Q4ri,
    Q8ri,
    /// Mixed displacement/pressure massive elements (ICT3, ICQ4, ...; see
    /// [`super::incomp`]).
    Incomp,
    /// Thin flat shells (see [`shell`]).
    Coq3,
    Dkt,
    /// Shell with transverse shear on TRI3 (see [`super::dst`]).
    Dst,
    Coq4,
    /// Thick curved shells on TRI6 and QUA8 (see [`super::thick_shell`]).
    Coq6,
    Coq8,
    /// Thin conical (AXIS) or cylindrical (plane modes) shell on SEG2
    /// (see [`coq2`]).
    Coq2,
    /// Linear elastic joint (JOI2, JOI3, JOI4) on RAC2, RAC3, LIA3, LIA4
    /// (see [`joint`]).
    Joint,
    /// Generalised plane strain: massive plane elements plus a point
    /// carrying the out-of-plane strain (see [`super::gen_plane_strain`]).
    Dpge,
    /// Heat conduction on the massive geometries (see [`super::thermal`]).
    Thermal,
}

impl Formulation {
    pub fn name(self) -> &'static str {
        match self {
            Formulation::Barr => "BARR",
            Formulation::Baex => "BAEX",
            Formulation::Pout => "POUT",
            Formulation::Timo => "TIMO",
            Formulation::Solid => "massive",
            Formulation::Q4ri => "Q4RI",
            Formulation::Q8ri => "Q8RI",
            Formulation::Incomp => "incompressible",
            Formulation::Coq3 => "COQ3",
            Formulation::Dkt => "DKT",
            Formulation::Dst => "DST",
            Formulation::Coq4 => "COQ4",
            Formulation::Coq6 => "COQ6",
            Formulation::Coq8 => "COQ8",
            Formulation::Coq2 => "COQ2",
            Formulation::Joint => "JOI2",
            Formulation::Thermal => "THERMIQUE",
            Formulation::Dpge => "DPGE",
        }
    }

    /// COQ3, DKT, DST, COQ4, COQ6, COQ8 or COQ2.
    pub fn is_shell(self) -> bool {
        matches!(
            self,
            Formulation::Coq3
                | Formulation::Dkt
                | Formulation::Dst
                | Formulation::Coq4
                | Formulation::Coq6
                | Formulation::Coq8
                | Formulation::Coq2
        )
    }
}

#[derive(Debug, Clone, Error, PartialEq)]
pub enum FemError {
    #[error("material property {prop} missing for {elem}")]
    MissingProperty { prop: &'static str, elem: &'static str },
    #[error("material property {prop} = {value} is invalid for {elem}: it {why}")]
    InvalidProperty { prop: &'static str, value: f64, elem: &'static str, why: &'static str },
    #[error("{form} elements on {elem} are not available in mode {mode}")]
    Unsupported { form: &'static str, elem: &'static str, mode: &'static str },
    #[error("{what} is not available for {form} elements")]
    NotFor { what: &'static str, form: &'static str },
    #[error("degenerate {elem} element: {why}")]
    Degenerate { elem: &'static str, why: String },
    #[error("{elem} element needs {expected} nodes, got {got}")]
    WrongNodeCount { elem: &'static str, expected: usize, got: usize },
    #[error("{elem} element has {expected} dofs, got {got} values")]
    WrongDofCount { elem: &'static str, expected: usize, got: usize },
    #[error("{elem} element: the field has values at {got} points, the element's stresses at {expected}")]
    WrongPointCount { elem: &'static str, expected: usize, got: usize },
    #[error("{elem} element: the field has no component {comp}")]
    MissingComponent { comp: &'static str, elem: &'static str },
}

/// An elementary matrix over the element's dofs, row-major.
#[derive(Debug, Clone, PartialEq)]
pub struct ElemMatrix {
    pub dofs: Vec<(usize, &'static str)>,
    pub k: Vec<f64>,
}

/// Values of one element at its integration (or output) points:
/// `values[point][component]`.
#[derive(Debug, Clone, PartialEq)]
pub struct GaussField {
    pub comps: Vec<&'static str>,
    pub values: Vec<Vec<f64>>,
}

impl GaussField {
    /// Value of a named component at a point.
    pub fn get(&self, comp: &str, point: usize) -> Option<f64> {
        let c = self.comps.iter().position(|n| *n == comp)?;
        self.values.get(point)?.get(c).copied()
    }
}

/// Primal component names of one node.
pub fn node_dofs(f: Formulation, mode: Mode) -> Result<&'static [&'static str], FemError> {
    match f {
        Formulation::Barr => bar::dofs(mode),
        Formulation::Baex => super::eccentric_bar::dofs(mode),
        Formulation::Pout | Formulation::Timo => beam::dofs(mode),
        Formulation::Solid | Formulation::Q4ri | Formulation::Q8ri | Formulation::Incomp => Ok(solid::dofs(mode)),
        Formulation::Coq3 | Formulation::Dkt | Formulation::Dst | Formulation::Coq4 => shell::dofs(f, mode),
        Formulation::Coq6 | Formulation::Coq8 => super::thick_shell::dofs(f, mode),
        Formulation::Coq2 => coq2::dofs(mode),
        Formulation::Joint => joint::dofs(mode),
        Formulation::Thermal => Ok(super::thermal::DOFS),
        Formulation::Dpge => super::gen_plane_strain::dofs(mode),
    }
}

/// Dual (force) names matching [`node_dofs`] one for one.
pub fn node_duals(f: Formulation, mode: Mode) -> Result<&'static [&'static str], FemError> {
    let d = node_dofs(f, mode)?;
    Ok(match d.len() {
        _ if d[0] == "T" => super::thermal::DUALS,
        _ if d[0] == "UR" && d.len() == 3 && d[2] == "UT" => &["FR", "FZ", "FT"],
        _ if d[0] == "UR" && d.len() == 3 => &["FR", "FZ", "MT"],
        _ if d[0] == "UR" => &["FR", "FZ"],
        2 => &["FX", "FY"],
        3 if d[2] == "RZ" => &["FX", "FY", "MZ"],
        3 => &["FX", "FY", "FZ"],
        _ => &["FX", "FY", "FZ", "MX", "MY", "MZ"],
    })
}

/// The dual of one primal component name (UX → FX, RZ → MZ, UR → FR ...).
pub fn dual_of(dof: &str) -> Option<&'static str> {
    Some(match dof {
        "UX" => "FX",
        "UY" => "FY",
        "UZ" => "FZ",
        "UR" => "FR",
        "RX" => "MX",
        "RY" => "MY",
        "RZ" => "MZ",
        "RT" => "MT",
        _ => return None,
    })
}

/// Pairs the element library does not produce: multipliers, thermal and
/// Fourier unknowns.
pub const OTHER_DUALS: &[(&str, &str)] =
    &[("UT", "FT"), ("LX", "FLX"), ("T", "Q"), ("TH", "QH"), ("P", "FP"), ("PI", "FPI")];

/// The dual (force) name of any unknown: the element pairs of [`dual_of`],
/// the other known pairs, else `F` before the name.
pub fn dual_name(primal: &str) -> String {
    if let Some(d) = dual_of(primal) {
        return d.to_string();
    }
    OTHER_DUALS.iter().find(|(p, _)| *p == primal).map_or_else(|| format!("F{}", primal), |(_, d)| d.to_string())
}

/// Which geometries each formulation accepts.
fn check(f: Formulation, ty: ElemType, mode: Mode) -> Result<(), FemError> {
    let ok = match f {
        Formulation::Barr | Formulation::Baex | Formulation::Pout | Formulation::Timo => ty == ElemType::Seg2,
        Formulation::Q4ri => ty == ElemType::Qua4,
        Formulation::Q8ri => ty == ElemType::Qua8,
        Formulation::Solid | Formulation::Thermal => ty.dim() >= 2,
        Formulation::Incomp => super::incomp::geometry_ok(ty),
        Formulation::Coq3 | Formulation::Dkt | Formulation::Dst | Formulation::Coq4 => ty == shell::geometry(f),
        Formulation::Coq6 | Formulation::Coq8 => ty == super::thick_shell::geometry(f),
        Formulation::Coq2 => ty == ElemType::Seg2,
        Formulation::Joint => joint::accepts(ty, mode),
        Formulation::Dpge => super::gen_plane_strain::accepts(ty, mode),
    };
    if ok {
        Ok(())
    } else {
        Err(FemError::Unsupported { form: f.name(), elem: ty.name(), mode: mode.name() })
    }
}

pub fn stiffness(
    f: Formulation,
    ty: ElemType,
    mode: Mode,
    x: &[[f64; 3]],
    m: &Material,
) -> Result<ElemMatrix, FemError> {
    check(f, ty, mode)?;
    match f {
        Formulation::Barr => bar::stiffness(mode, x, m),
        Formulation::Baex => super::eccentric_bar::stiffness(mode, x, m),
        Formulation::Pout => beam::stiffness(false, mode, x, m),
        Formulation::Timo => beam::stiffness(true, mode, x, m),
        Formulation::Incomp => super::incomp::stiffness(ty, mode, x, m),
        Formulation::Solid | Formulation::Q4ri | Formulation::Q8ri => solid::stiffness(f, ty, mode, x, m),
        Formulation::Coq3 | Formulation::Dkt | Formulation::Dst | Formulation::Coq4 => shell::stiffness(f, mode, x, m),
        Formulation::Coq6 | Formulation::Coq8 => super::ahmad::stiffness(f, mode, x, m),
        Formulation::Coq2 => coq2::stiffness(mode, x, m),
        Formulation::Joint => joint::stiffness(ty, mode, x, m),
        Formulation::Thermal => super::thermal::conductivity(ty, mode, x, m),
        Formulation::Dpge => super::gen_plane_strain::stiffness(ty, x, m),
    }
}

/// Consistent mass, or lumped (diagonal) mass when `lumped`.
pub fn mass(
    f: Formulation,
    ty: ElemType,
    mode: Mode,
    x: &[[f64; 3]],
    m: &Material,
    lumped: bool,
) -> Result<ElemMatrix, FemError> {
    check(f, ty, mode)?;
    match f {
        Formulation::Barr => bar::mass(mode, x, m, lumped),
        Formulation::Baex => super::eccentric_bar::mass(mode, x, m, lumped),
        Formulation::Pout => beam::mass(false, mode, x, m, lumped),
        Formulation::Timo => beam::mass(true, mode, x, m, lumped),
        Formulation::Solid | Formulation::Q4ri | Formulation::Q8ri | Formulation::Incomp => {
            solid::mass(ty, mode, x, m, lumped)
        }
        Formulation::Coq3 | Formulation::Dkt | Formulation::Dst | Formulation::Coq4 => {
            shell::mass(f, mode, x, m, lumped)
        }
        Formulation::Coq6 | Formulation::Coq8 => super::ahmad::mass(f, mode, x, m, lumped),
        Formulation::Coq2 => coq2::mass(mode, x, m, lumped),
        // A joint has no thickness, hence no mass.
        Formulation::Joint => {
            let names = joint::dofs(mode)?;
            let n = x.len() * names.len();
            let dofs = (0..x.len()).flat_map(|i| names.iter().map(move |&d| (i, d))).collect();
            Ok(ElemMatrix { dofs, k: vec![0.0; n * n] })
        }
        Formulation::Thermal => super::thermal::capacity(ty, mode, x, m, lumped),
        Formulation::Dpge => Err(FemError::NotFor { what: "a mass matrix", form: f.name() }),
    }
}

/// Stresses (SIGM) at the points of [`gauss_points`]; `u` holds the
/// element dofs in [`ElemMatrix`] order.
pub fn stress(
    f: Formulation,
    ty: ElemType,
    mode: Mode,
    x: &[[f64; 3]],
    m: &Material,
    u: &[f64],
) -> Result<GaussField, FemError> {
    check(f, ty, mode)?;
    match f {
        Formulation::Barr => bar::stress(mode, x, m, u),
        Formulation::Baex => super::eccentric_bar::stress(mode, x, m, u),
        Formulation::Pout => beam::stress(false, mode, x, m, u),
        Formulation::Timo => beam::stress(true, mode, x, m, u),
        Formulation::Incomp => super::incomp::stress(ty, mode, x, m, u),
        Formulation::Solid | Formulation::Q4ri | Formulation::Q8ri => solid::field(f, ty, mode, x, m, u, true),
        Formulation::Coq3 | Formulation::Dkt | Formulation::Dst | Formulation::Coq4 => shell::stress(f, mode, x, m, u),
        Formulation::Coq6 | Formulation::Coq8 => super::thick_shell::unavailable("SIGM", f),
        Formulation::Coq2 => coq2::stress(mode, x, m, u),
        Formulation::Joint => joint::stress(ty, mode, x, m, u),
        Formulation::Thermal => Err(FemError::NotFor { what: "SIGM", form: f.name() }),
        Formulation::Dpge => super::gen_plane_strain::field(ty, x, m, u, true),
    }
}

/// Displacement gradients (GRAD) of massive elements at the points of
/// [`gauss_points`]; the material is not used.
pub fn gradient(
    f: Formulation,
    ty: ElemType,
    mode: Mode,
    x: &[[f64; 3]],
    _m: &Material,
    u: &[f64],
) -> Result<GaussField, FemError> {
    check(f, ty, mode)?;
    match f {
        Formulation::Solid | Formulation::Q4ri | Formulation::Q8ri | Formulation::Incomp => {
            solid::gradient(f, ty, mode, x, u)
        }
        Formulation::Thermal => super::thermal::gradient(ty, mode, x, u),
        _ => Err(FemError::NotFor { what: "GRAD", form: f.name() }),
    }
}

/// Strains (EPSI): EPXX EPYY EPZZ GAXY (GAXZ GAYZ) with engineering
/// shears for solids (EPRR EPZZ EPTT GARZ in AXIS); generalised strains
/// for bars, beams and shells.
pub fn strain(
    f: Formulation,
    ty: ElemType,
    mode: Mode,
    x: &[[f64; 3]],
    m: &Material,
    u: &[f64],
) -> Result<GaussField, FemError> {
    check(f, ty, mode)?;
    match f {
        Formulation::Barr => bar::strain(mode, x, u),
        Formulation::Baex => super::eccentric_bar::strain(mode, x, m, u),
        Formulation::Pout => beam::strain(false, mode, x, m, u),
        Formulation::Timo => beam::strain(true, mode, x, m, u),
        Formulation::Solid | Formulation::Q4ri | Formulation::Q8ri | Formulation::Incomp => {
            solid::field(f, ty, mode, x, m, u, false)
        }
        Formulation::Coq3 | Formulation::Dkt | Formulation::Dst | Formulation::Coq4 => shell::strain(f, mode, x, m, u),
        Formulation::Coq6 | Formulation::Coq8 => super::thick_shell::unavailable("EPSI", f),
        Formulation::Coq2 => coq2::strain(mode, x, u),
        Formulation::Joint => joint::strain(ty, mode, x, m, u),
        Formulation::Thermal => Err(FemError::NotFor { what: "EPSI", form: f.name() }),
        Formulation::Dpge => super::gen_plane_strain::field(ty, x, m, u, false),
    }
}

/// Nodal forces equivalent to a stress field given at the points of
/// [`gauss_points`] (BSIG), in [`ElemMatrix`] dof order: the internal
/// forces, K u for the stresses of a displacement u.
pub fn internal_forces(
    f: Formulation,
    ty: ElemType,
    mode: Mode,
    x: &[[f64; 3]],
    m: &Material,
    sig: &GaussField,
) -> Result<Vec<f64>, FemError> {
    check(f, ty, mode)?;
    match f {
        Formulation::Barr => bar::internal_forces(mode, x, sig),
        Formulation::Baex => super::eccentric_bar::internal_forces(mode, x, m, sig),
        Formulation::Pout | Formulation::Timo => beam::internal_forces(f == Formulation::Timo, mode, x, m, sig),
        Formulation::Solid | Formulation::Q4ri | Formulation::Q8ri | Formulation::Incomp => {
            solid::internal_forces(f, ty, mode, x, m, sig)
        }
        Formulation::Coq3 | Formulation::Dkt | Formulation::Dst | Formulation::Coq4 => {
            shell::internal_forces(f, mode, x, m, sig)
        }
        Formulation::Coq6 | Formulation::Coq8 => super::thick_shell::unavailable("BSIG", f),
        Formulation::Coq2 => coq2::internal_forces(mode, x, m, sig),
        Formulation::Joint => joint::internal_forces(ty, mode, x, m, sig),
        Formulation::Thermal => Err(FemError::NotFor { what: "BSIG", form: f.name() }),
        Formulation::Dpge => super::gen_plane_strain::internal_forces(ty, x, sig),
    }
}

/// Reference coordinates and weights of the points where [`stress`] and
/// [`strain`] give values. Bars and beams output at their two ends
/// (ξ = −1, +1). Ordering: see [`super::quadrature`].
pub fn gauss_points(f: Formulation, ty: ElemType) -> Vec<([f64; 3], f64)> {
    match f {
        Formulation::Barr | Formulation::Baex | Formulation::Pout | Formulation::Timo => {
            vec![([-1.0, 0.0, 0.0], 1.0), ([1.0, 0.0, 0.0], 1.0)]
        }
        Formulation::Solid | Formulation::Q4ri | Formulation::Q8ri | Formulation::Incomp => solid::rule(f, ty),
        Formulation::Thermal | Formulation::Dpge => solid::rule(Formulation::Solid, ty),
        Formulation::Coq3 | Formulation::Dkt | Formulation::Dst | Formulation::Coq4 => shell::rule(ty),
        Formulation::Coq6 | Formulation::Coq8 => super::thick_shell::rule(f),
        Formulation::Coq2 => coq2::rule(),
        // On the face; the joint's reference coordinate across is 0.
        Formulation::Joint => joint::rule(ty),
    }
}

/// Physical positions of the [`gauss_points`] of one element.
pub fn gauss_positions(f: Formulation, ty: ElemType, x: &[[f64; 3]]) -> Vec<[f64; 3]> {
    gauss_points(f, ty)
        .into_iter()
        .map(|(p, _)| {
            let s = super::shape::eval(ty, p);
            let mut y = [0.0; 3];
            for (n, xi) in s.n.iter().zip(x) {
                for c in 0..3 {
                    y[c] += n * xi[c];
                }
            }
            y
        })
        .collect()
}
