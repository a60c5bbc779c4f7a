//! Q8RI (QUA8 at 2×2) and GRAD: a linear displacement field is reproduced
//! exactly (patch test on a distorted element) and its gradient is the
//! field's constant matrix.

use super::element::{gauss_points, gradient, stiffness, stress, Formulation, Mode};
use super::mesh::ElemType;
use super::test_support::*;

/// A QUA8 with distorted straight edges (midside nodes at
/// the middle, so the map is bilinear).
fn qua8() -> Vec<[f64; 3]> {
    let c = [[0.0, 0.0], [2.0, 0.3], [2.4, 1.9], [-0.2, 1.5]];
    let mut x = Vec::new();
    for i in 0..4 {
        let (a, b) = (c[i], c[(i + 1) % 4]);
        x.push([a[0], a[1], 0.0]);
        x.push([(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0, 0.0]);
    }
    x
}

fn linear(x: &[[f64; 3]]) -> Vec<f64> {
    x.iter().flat_map(|p| [0.1 + 2e-3 * p[0] - 1e-3 * p[1], -0.2 + 3e-3 * p[0] + 4e-3 * p[1]]).collect()
}

#[test]
fn q8ri_uses_four_points_and_passes_the_patch_test() {
    assert_eq!(gauss_points(Formulation::Q8ri, ElemType::Qua8).len(), 4);
    let (x, m) = (qua8(), mat(1000.0, 0.25));
    let u = linear(&x);
    let s = stress(Formulation::Q8ri, ElemType::Qua8, Mode::PlanCont, &x, &m, &u).unwrap();
    // Plane stress, E = 1000, ν = 0.25: σxx = E/(1−ν²)(εxx + ν εyy).
    let c = 1000.0 / (1.0 - 0.0625);
    let (exx, eyy, gxy) = (2e-3, 4e-3, 2e-3);
    for p in &s.values {
        assert!((p[0] - c * (exx + 0.25 * eyy)).abs() < 1e-9, "{p:?}");
        assert!((p[1] - c * (eyy + 0.25 * exx)).abs() < 1e-9);
        assert!((p[3] - 1000.0 / 2.5 * gxy).abs() < 1e-9);
    }
    // A rigid motion costs nothing; the reduced matrix is symmetric.
    let k = stiffness(Formulation::Q8ri, ElemType::Qua8, Mode::PlanCont, &x, &m).unwrap();
    let rot: Vec<f64> = x.iter().flat_map(|p| [-p[1], p[0]]).collect();
    for i in 0..16 {
        let f: f64 = (0..16).map(|j| k.k[i * 16 + j] * rot[j]).sum();
        assert!(f.abs() < 1e-9);
        for j in 0..16 {
            assert!((k.k[i * 16 + j] - k.k[j * 16 + i]).abs() < 1e-9);
        }
    }
}

#[test]
fn gradient_of_a_linear_field_is_constant() {
    let (x, m) = (qua8(), mat(1000.0, 0.25));
    let g = gradient(Formulation::Solid, ElemType::Qua8, Mode::PlanDefo, &x, &m, &linear(&x)).unwrap();
    assert_eq!(g.comps, vec!["UX,X", "UX,Y", "UX,Z", "UY,X", "UY,Y", "UY,Z", "UZ,X", "UZ,Y", "UZ,Z"]);
    for p in &g.values {
        for (v, w) in p.iter().zip([2e-3, -1e-3, 0.0, 3e-3, 4e-3, 0.0, 0.0, 0.0, 0.0]) {
            assert!((v - w).abs() < 1e-12, "{p:?}");
        }
    }
    // AXIS adds the hoop term UT,T = u_r / r, the ninth.
    let shifted: Vec<[f64; 3]> = x.iter().map(|p| [p[0] + 1.0, p[1], 0.0]).collect();
    let u: Vec<f64> = shifted.iter().flat_map(|p| [0.5 * p[0], 0.0]).collect();
    let g = gradient(Formulation::Solid, ElemType::Qua8, Mode::Axis, &shifted, &m, &u).unwrap();
    for p in &g.values {
        assert!((p[0] - 0.5).abs() < 1e-12 && (p[8] - 0.5).abs() < 1e-12, "{p:?}");
    }
    assert!(gradient(Formulation::Barr, ElemType::Seg2, Mode::PlanCont, &x[..2], &m, &[0.0; 4]).is_err());
}
