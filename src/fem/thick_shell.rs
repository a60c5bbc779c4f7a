//! COQ6 (on TRI6) and COQ8 (on QUA8): Cast3M's curved thick shells with
//! six dofs per node: their geometry (models, their points, surface
//! vectors and jacobians, VSUR, JACO). The stiffness and mass are in
//! [`super::ahmad`]; stresses and strains are not implemented yet and are
//! refused by name.

use super::element::{FemError, Formulation, Mode};
use super::mesh::ElemType;
use super::quadrature::{quad, tri, QPoint};

pub fn geometry(f: Formulation) -> ElemType {
    if f == Formulation::Coq6 {
        ElemType::Tri6
    } else {
        ElemType::Qua8
    }
}

pub fn dofs(f: Formulation, mode: Mode) -> Result<&'static [&'static str], FemError> {
    match mode {
        Mode::Trid => Ok(&["UX", "UY", "UZ", "RX", "RY", "RZ"]),
        _ => Err(FemError::Unsupported { form: f.name(), elem: geometry(f).name(), mode: mode.name() }),
    }
}

/// Output points: 3 interior points on the triangle, 2×2 on the quadrangle.
pub fn rule(f: Formulation) -> Vec<QPoint> {
    if f == Formulation::Coq6 {
        tri(3)
    } else {
        quad(2)
    }
}

/// What is not implemented for these elements.
pub fn unavailable<T>(what: &'static str, f: Formulation) -> Result<T, FemError> {
    Err(FemError::NotFor { what, form: f.name() })
}

/// Area of each output point (INTG of a field given at the points).
pub fn point_weights(f: Formulation, x: &[[f64; 3]]) -> Result<Vec<f64>, FemError> {
    let j = super::surface_vectors::jacobians(f, geometry(f), x)?;
    Ok(rule(f).iter().zip(j).map(|((_, w), j)| w * j).collect())
}

/// ∫ N_i dA per node (with the quadratic shape functions).
pub fn node_weights(f: Formulation, x: &[[f64; 3]]) -> Result<Vec<f64>, FemError> {
    let ty = geometry(f);
    let mut out = vec![0.0; x.len()];
    for ((p, _), wj) in rule(f).iter().zip(point_weights(f, x)?) {
        for (o, n) in out.iter_mut().zip(super::shape::eval(ty, *p).n) {
            *o += wj * n;
        }
    }
    Ok(out)
}
