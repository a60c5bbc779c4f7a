//! Integrals over elements: the measure of an element (MESU), and the
//! weights that turn values at an element's points into its integral
//! (INTG). Internal forces (BSIG) are per element family, in
//! [`super::element::internal_forces`].
//!
//! The measure is geometric: length, area or volume by the element's own
//! dimension, whatever the analysis mode. Integration weights follow the
//! element library instead (see [`super::element`]): thickness DIM3 in
//! PLAN CONT, r (per radian) in AXIS, the length along bars and beams.

use super::element::{FemError, Formulation, Mode};
use super::material::Material;
use super::mesh::ElemType;
use super::quadrature::{hexa, prism, quad, seg, tet, tri, QPoint};
use super::shape::eval;
use super::solid;

/// The Jacobian of the map from the reference element at `p`, measured in
/// the element's own dimension (|dx/dξ| on a line, the area ratio on a
/// surface, even one in 3D space, |det J| in a volume).
pub fn jacobian(ty: ElemType, x: &[[f64; 3]], p: [f64; 3]) -> f64 {
    let s = eval(ty, p);
    let dim = ty.dim();
    let mut t = [[0.0; 3]; 3];
    for (d, xi) in s.dn.iter().zip(x) {
        for (a, ta) in t.iter_mut().enumerate().take(dim) {
            for c in 0..3 {
                ta[c] += d[a] * xi[c];
            }
        }
    }
    let cross =
        |a: [f64; 3], b: [f64; 3]| [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    let norm = |a: [f64; 3]| (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
    match dim {
        0 => 1.0,
        1 => norm(t[0]),
        2 => norm(cross(t[0], t[1])),
        _ => {
            let c = cross(t[1], t[2]);
            (t[0][0] * c[0] + t[0][1] * c[1] + t[0][2] * c[2]).abs()
        }
    }
}

/// A rule exact for the measure of straight-sided elements and accurate
/// for curved quadratic ones.
fn measure_rule(ty: ElemType) -> Vec<QPoint> {
    match ty {
        ElemType::Poi1 | ElemType::Mult3 | ElemType::Mult4 | ElemType::Mult5 => vec![],
        ElemType::Seg2 => seg(3),
        // |dx/dξ| of a curved SEG3 is a square root, not a polynomial:
        // 3 Gauss points on each quarter keep the length to about 1e-6.
        ElemType::Seg3 => (0..4)
            .flat_map(|q| {
                let c = -0.75 + 0.5 * q as f64;
                seg(3).into_iter().map(move |([x, _, _], w)| ([c + 0.25 * x, 0.0, 0.0], 0.25 * w))
            })
            .collect(),
        ElemType::Tri3 | ElemType::Tri6 => tri(7),
        ElemType::Qua4 | ElemType::Qua8 => quad(3),
        ElemType::Cub8 => hexa(3),
        ElemType::Tet4 => tet(4),
        ElemType::Pri6 => prism(7, 3),
        // The pyramid is a cube with its top face shrunk to the apex: its
        // Jacobian is a polynomial of degree 2 in each direction.
        ElemType::Pyr5 => hexa(3),
        // Degree 5 in each direction covers curved quadratic volumes well.
        ElemType::Cu20 => hexa(3),
        ElemType::Pr15 => prism(7, 3),
        // The face's measure, on the mid-surface (t = 0).
        ElemType::Rac2 => seg(3),
        ElemType::Rac3 => measure_rule(ElemType::Seg3),
        ElemType::Lia3 => tri(7),
        ElemType::Lia4 => quad(3),
    }
}

/// Length, area or volume of one element (0 for a point).
pub fn measure(ty: ElemType, x: &[[f64; 3]]) -> f64 {
    measure_rule(ty).into_iter().map(|(p, w)| w * jacobian(ty, x, p)).sum()
}

/// Weights of the points where [`super::element::stress`] gives values: the
/// integral of a field over the element is `Σ w_k v_k`.
pub fn point_weights(
    f: Formulation,
    ty: ElemType,
    mode: Mode,
    x: &[[f64; 3]],
    m: &Material,
) -> Result<Vec<f64>, FemError> {
    match f {
        Formulation::Barr | Formulation::Baex | Formulation::Pout | Formulation::Timo => line_weights(x),
        Formulation::Solid | Formulation::Q4ri | Formulation::Q8ri | Formulation::Incomp | Formulation::Thermal => {
            if let Some(w) = surface_in_space(ty, mode, x, &solid::rule(f, ty), false)? {
                return Ok(w);
            }
            solid::point_weights(f, ty, mode, x, m)
        }
        Formulation::Coq3 | Formulation::Dkt | Formulation::Dst | Formulation::Coq4 => {
            super::shell::point_weights(f, x)
        }
        Formulation::Coq6 | Formulation::Coq8 => super::thick_shell::point_weights(f, x),
        Formulation::Coq2 => super::coq2::point_weights(mode, x),
        Formulation::Joint => super::joint::point_weights(ty, mode, x),
        // The nodes, without the point that carries the out-of-plane strain.
        Formulation::Dpge => solid::point_weights(Formulation::Solid, ty, mode, &x[..ty.nodes().min(x.len())], m),
    }
}

/// Weights of the nodes for a field given at the nodes and interpolated
/// by the shape functions: `∫ Σ N_i v_i = Σ_i v_i ∫ N_i`.
pub fn node_weights(
    f: Formulation,
    ty: ElemType,
    mode: Mode,
    x: &[[f64; 3]],
    m: &Material,
) -> Result<Vec<f64>, FemError> {
    match f {
        Formulation::Barr | Formulation::Baex | Formulation::Pout | Formulation::Timo => line_weights(x),
        Formulation::Solid | Formulation::Q4ri | Formulation::Q8ri | Formulation::Incomp | Formulation::Thermal => {
            if let Some(w) = surface_in_space(ty, mode, x, &measure_rule(ty), true)? {
                return Ok(w);
            }
            solid::node_weights(ty, mode, x, m)
        }
        Formulation::Coq3 | Formulation::Dkt | Formulation::Dst | Formulation::Coq4 => super::shell::node_weights(f, x),
        Formulation::Coq6 | Formulation::Coq8 => super::thick_shell::node_weights(f, x),
        Formulation::Coq2 => super::coq2::node_weights(mode, x),
        Formulation::Joint => Err(FemError::NotFor { what: "integrating a nodal field", form: f.name() }),
        Formulation::Dpge => solid::node_weights(ty, mode, &x[..ty.nodes().min(x.len())], m),
    }
}

/// A massive model on surface elements in 3D (a crack face) only
/// measures: its weights are those of the area, without thickness. `None`
/// when the element is not a surface in space.
fn surface_in_space(
    ty: ElemType,
    mode: Mode,
    x: &[[f64; 3]],
    rule: &[QPoint],
    at_nodes: bool,
) -> Result<Option<Vec<f64>>, FemError> {
    // Lines in the plane modes too (the edges of a pressure model): per
    // unit thickness, over the whole ring in AXIS as the massive weights.
    let on_line = mode != Mode::Trid && ty.dim() == 1;
    if !on_line && (mode != Mode::Trid || ty.dim() != 2) {
        return Ok(None);
    }
    if x.len() != ty.nodes() {
        return Err(FemError::WrongNodeCount { elem: ty.name(), expected: ty.nodes(), got: x.len() });
    }
    let ring = |p: [f64; 3]| -> Result<f64, FemError> {
        let Some(turn) = mode.turn() else {
            return Ok(1.0);
        };
        let r: f64 = eval(ty, p).n.iter().zip(x).map(|(n, q)| n * q[0]).sum();
        if r < 0.0 {
            return Err(FemError::Degenerate {
                elem: ty.name(),
                why: format!("{} element reaches r = {r:e} < 0", mode.name()),
            });
        }
        Ok(turn * r)
    };
    if !at_nodes {
        return Ok(Some(rule.iter().map(|&(p, w)| Ok(w * jacobian(ty, x, p) * ring(p)?)).collect::<Result<_, _>>()?));
    }
    let mut w = vec![0.0; ty.nodes()];
    for &(p, wp) in rule {
        let j = wp * jacobian(ty, x, p) * ring(p)?;
        for (wi, ni) in w.iter_mut().zip(eval(ty, p).n) {
            *wi += ni * j;
        }
    }
    Ok(Some(w))
}

/// Bars and beams carry values at both ends: the trapezoidal rule along
/// the length, which is also ∫ N_i for the linear shape functions.
fn line_weights(x: &[[f64; 3]]) -> Result<Vec<f64>, FemError> {
    Ok(vec![0.5 * line_length(x)?; 2])
}

fn line_length(x: &[[f64; 3]]) -> Result<f64, FemError> {
    if x.len() != 2 {
        return Err(FemError::WrongNodeCount { elem: "SEG2", expected: 2, got: x.len() });
    }
    Ok(measure(ElemType::Seg2, x))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn measures_of_unit_shapes_and_a_curved_edge() {
        let sq = [[0., 0., 0.], [2., 0., 0.], [2., 1., 0.], [0., 1., 0.]];
        assert!((measure(ElemType::Qua4, &sq) - 2.0).abs() < 1e-14);
        let tri = [[0., 0., 5.], [1., 0., 5.], [0., 1., 6.]];
        assert!((measure(ElemType::Tri3, &tri) - 0.5 * 2f64.sqrt()).abs() < 1e-14);
        let mut cube: Vec<[f64; 3]> = sq.to_vec();
        cube.extend(sq.iter().map(|p| [p[0], p[1], 3.0]));
        assert!((measure(ElemType::Cub8, &cube) - 6.0).abs() < 1e-13);
        let tet = [[0., 0., 0.], [1., 0., 0.], [0., 1., 0.], [0., 0., 1.]];
        assert!((measure(ElemType::Tet4, &tet) - 1.0 / 6.0).abs() < 1e-15);
        // A parabolic SEG3 y = x² - 1 on [-1, 1]: length 2.9578857...
        let arc = [[-1., 0., 0.], [0., -1., 0.], [1., 0., 0.]];
        let exact = 5f64.sqrt() + 0.5 * (2.0 + 5f64.sqrt()).ln();
        assert!((measure(ElemType::Seg3, &arc) - exact).abs() < 1e-5, "{}", measure(ElemType::Seg3, &arc) - exact);
    }
}
