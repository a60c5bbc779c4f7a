//! Linear heat conduction on the massive elements (MODE 'THERMIQUE'):
//! one unknown T per node (dual Q), the conductivity matrix
//! `∫ k ∇Nᵢ·∇Nⱼ`, the capacity matrix `∫ ρ c Nᵢ Nⱼ` and the temperature
//! gradient at the stress points.
//!
//! The geometry, Gauss rules and measure are those of the mechanical
//! solids ([`super::solid`]): the same thickness in PLAN CONT, the same
//! whole-ring (2πr) weight in AXIS, so a thermal and a mechanical model of
//! one mesh integrate alike.

use super::element::{ElemMatrix, FemError, Formulation, GaussField, Mode};
use super::material::Material;
use super::mesh::ElemType;
use super::solid::{mass_rule, points, rule};

/// The one unknown of a node, and its dual.
pub const DOFS: &[&str] = &["T"];
pub const DUALS: &[&str] = &["Q"];

fn dof_list(ty: ElemType) -> Vec<(usize, &'static str)> {
    (0..ty.nodes()).map(|i| (i, "T")).collect()
}

/// The conductivity K of the material: required, positive.
fn conductivity_of(m: &Material, ty: ElemType) -> Result<f64, FemError> {
    m.positive(m.cond, "K", ty.name())
}

/// Conductivity matrix `∫ k ∇Nᵢ·∇Nⱼ dV` (the stiffness of CONDUCTIVITE).
pub fn conductivity(ty: ElemType, mode: Mode, x: &[[f64; 3]], m: &Material) -> Result<ElemMatrix, FemError> {
    let k = conductivity_of(m, ty)?;
    let t = m.thickness(mode, ty.name())?;
    let pts = points(ty, mode, x, &rule(Formulation::Solid, ty), t)?;
    let nn = ty.nodes();
    let mut out = vec![0.0; nn * nn];
    for p in &pts {
        for i in 0..nn {
            for j in i..nn {
                let g: f64 = (0..3).map(|c| p.dndx[i][c] * p.dndx[j][c]).sum();
                out[i * nn + j] += k * g * p.w;
            }
        }
    }
    mirror(&mut out, nn);
    Ok(ElemMatrix { dofs: dof_list(ty), k: out })
}

/// Capacity matrix `∫ ρ c Nᵢ Nⱼ dV` (CAPACITE), or its lumping when
/// `lumped`: the diagonal scaled to keep the total (as the mechanical mass).
pub fn capacity(ty: ElemType, mode: Mode, x: &[[f64; 3]], m: &Material, lumped: bool) -> Result<ElemMatrix, FemError> {
    let rho = m.positive(m.rho, "RHO", ty.name())?;
    let c = m.positive(m.capa, "C", ty.name())?;
    let t = m.thickness(mode, ty.name())?;
    let pts = points(ty, mode, x, &mass_rule(ty), t)?;
    let nn = ty.nodes();
    let mut out = vec![0.0; nn * nn];
    for p in &pts {
        for i in 0..nn {
            for j in i..nn {
                out[i * nn + j] += rho * c * p.n[i] * p.n[j] * p.w;
            }
        }
    }
    mirror(&mut out, nn);
    if lumped {
        let total: f64 = out.iter().sum();
        let diag: f64 = (0..nn).map(|i| out[i * nn + i]).sum();
        let d: Vec<f64> = (0..nn).map(|i| out[i * nn + i] * total / diag).collect();
        out.fill(0.0);
        for (i, v) in d.into_iter().enumerate() {
            out[i * nn + i] = v;
        }
    }
    Ok(ElemMatrix { dofs: dof_list(ty), k: out })
}

/// Names of the gradient components: T,X T,Y (T,Z in TRID), T,R T,Z in AXIS.
pub fn gradient_comps(mode: Mode) -> Vec<&'static str> {
    match mode {
        Mode::Axis | Mode::Fourier(_) => vec!["T,R", "T,Z"],
        Mode::Trid => vec!["T,X", "T,Y", "T,Z"],
        Mode::PlanCont | Mode::PlanDefo => vec!["T,X", "T,Y"],
    }
}

/// Temperature gradient ∇T at the points of [`super::solid::rule`]; `t`
/// holds the nodal temperatures.
pub fn gradient(ty: ElemType, mode: Mode, x: &[[f64; 3]], t: &[f64]) -> Result<GaussField, FemError> {
    if t.len() != ty.nodes() {
        return Err(FemError::WrongDofCount { elem: ty.name(), expected: ty.nodes(), got: t.len() });
    }
    let comps = gradient_comps(mode);
    let pts = points(ty, mode, x, &rule(Formulation::Solid, ty), 1.0)?;
    let values = pts
        .iter()
        .map(|p| (0..comps.len()).map(|c| p.dndx.iter().zip(t).map(|(d, v)| d[c] * v).sum()).collect())
        .collect();
    Ok(GaussField { comps, values })
}

/// Copy the upper triangle onto the lower one.
fn mirror(k: &mut [f64], n: usize) {
    for r in 0..n {
        for c in 0..r {
            k[r * n + c] = k[c * n + r];
        }
    }
}
