//! Jacobians and surface vectors at an element's output points (JACO,
//! VSUR): what the reference element's measure is multiplied by there,
//! and for shells and beams the direction of the normal (or tangent).
//!
//! The jacobian is the measure of the map from the reference element:
//! |dX/dξ| on a line, |dX/dξ × dX/dη| on a surface, |det| in a volume
//! (the geometric one; AXIS weights r are not part of it). Points are
//! those of [`super::element::gauss_points`].

use super::element::{gauss_points, FemError, Formulation, Mode};
use super::mesh::ElemType;
use super::shape::eval;
use super::vec3::{cross, dot};

/// The tangents dX/dξ_a (a < the element's dimension) at reference `p`.
fn tangents(ty: ElemType, x: &[[f64; 3]], p: [f64; 3]) -> Vec<[f64; 3]> {
    let s = eval(ty, p);
    (0..ty.dim())
        .map(|a| std::array::from_fn(|c| s.dn.iter().zip(x).map(|(d, xi)| d[a] * xi[c]).sum::<f64>()))
        .collect()
}

fn det3(t: &[[f64; 3]]) -> f64 {
    dot(t[0], cross(t[1], t[2]))
}

/// |J| at each output point.
pub fn jacobians(f: Formulation, ty: ElemType, x: &[[f64; 3]]) -> Result<Vec<f64>, FemError> {
    if x.len() != ty.nodes() {
        return Err(FemError::WrongNodeCount { elem: ty.name(), expected: ty.nodes(), got: x.len() });
    }
    Ok(gauss_points(f, ty)
        .into_iter()
        .map(|(p, _)| {
            let t = tangents(ty, x, p);
            match t.len() {
                1 => dot(t[0], t[0]).sqrt(),
                2 => {
                    let n = cross(t[0], t[1]);
                    dot(n, n).sqrt()
                }
                3 => det3(&t).abs(),
                _ => 0.0,
            }
        })
        .collect())
}

/// Surface vectors of a shell (the normal, of length |J|, on the side
/// given by the node order: dX/dξ × dX/dη on a surface, the generator
/// turned by +90° in the plane for COQ2) or tangent vectors of a beam
/// (dX/dξ); `None` for the other elements. Unit vectors if `unit`.
pub fn surface_vectors(
    f: Formulation,
    ty: ElemType,
    mode: Mode,
    x: &[[f64; 3]],
    unit: bool,
) -> Result<Option<Vec<[f64; 3]>>, FemError> {
    let beam = matches!(f, Formulation::Barr | Formulation::Baex | Formulation::Pout | Formulation::Timo);
    if !(f.is_shell() || beam) {
        return Ok(None);
    }
    if x.len() != ty.nodes() {
        return Err(FemError::WrongNodeCount { elem: ty.name(), expected: ty.nodes(), got: x.len() });
    }
    let mut out = Vec::new();
    for (p, _) in gauss_points(f, ty) {
        let t = tangents(ty, x, p);
        let v = match (t.len(), beam) {
            (1, true) => t[0],
            (1, false) if mode != Mode::Trid => [-t[0][1], t[0][0], 0.0],
            (2, false) => cross(t[0], t[1]),
            _ => return Err(FemError::NotFor { what: "surface vectors in this mode", form: f.name() }),
        };
        let n = dot(v, v).sqrt();
        if n <= 0.0 || !n.is_finite() {
            return Err(FemError::Degenerate { elem: f.name(), why: "zero jacobian".into() });
        }
        out.push(if unit { v.map(|c| c / n) } else { v });
    }
    Ok(Some(out))
}
