//! BSIG is the transpose of SIGM: the internal forces of the stresses of
//! any displacement are K u, for every element family and mode.

use super::element::{internal_forces, stiffness, stress, Formulation, Material, Mode};
use super::mesh::ElemType;
use super::shape::ref_nodes;
use super::test_support::wobble;

fn check(f: Formulation, ty: ElemType, mode: Mode, x: &[[f64; 3]], m: &Material) {
    let em = stiffness(f, ty, mode, x, m).unwrap();
    let nd = em.dofs.len();
    let u: Vec<f64> = (0..nd).map(|i| 1e-3 * wobble(i as f64, nd as f64)).collect();
    let sig = stress(f, ty, mode, x, m, &u).unwrap();
    let fi = internal_forces(f, ty, mode, x, m, &sig).unwrap();
    let scale = em.k.iter().fold(0.0f64, |a, v| a.max(v.abs())) * 1e-3;
    for (i, fi) in fi.iter().enumerate() {
        let ku: f64 = (0..nd).map(|j| em.k[i * nd + j] * u[j]).sum();
        assert!((fi - ku).abs() <= 1e-11 * scale, "{:?} {:?} {:?} dof {}: {} vs {}", f, ty, mode, i, fi, ku);
    }
}

/// A distorted copy of the reference element, off the axis for AXIS.
fn distorted(ty: ElemType) -> Vec<[f64; 3]> {
    ref_nodes(ty)
        .iter()
        .enumerate()
        .map(|(k, p)| {
            let d = |c: usize| 0.1 * wobble(k as f64, c as f64);
            let z = if ty.dim() == 3 { p[2] + d(2) } else { 0.0 };
            [p[0] + 3.0 + d(0), p[1] + d(1), z]
        })
        .collect()
}

#[test]
fn massive_elements_in_every_mode() {
    let m = Material { youn: Some(200.0), nu: Some(0.3), dim3: Some(0.2), ..Default::default() };
    for ty in [ElemType::Tri3, ElemType::Tri6, ElemType::Qua4, ElemType::Qua8] {
        for mode in [Mode::PlanCont, Mode::PlanDefo, Mode::Axis] {
            check(Formulation::Solid, ty, mode, &distorted(ty), &m);
        }
    }
    check(Formulation::Q4ri, ElemType::Qua4, Mode::PlanDefo, &distorted(ElemType::Qua4), &m);
    for ty in [ElemType::Cub8, ElemType::Tet4, ElemType::Pri6] {
        check(Formulation::Solid, ty, Mode::Trid, &distorted(ty), &m);
    }
}

#[test]
fn bars_and_beams_in_2d_and_3d() {
    let m = Material {
        youn: Some(200.0),
        nu: Some(0.3),
        sect: Some(2.0),
        inry: Some(0.5),
        inrz: Some(0.7),
        tors: Some(0.4),
        secy: Some(1.5),
        secz: Some(1.2),
        vect: Some([0.0, 0.0, 1.0]),
        ..Default::default()
    };
    let x2 = [[0.5, 0.2, 0.0], [2.0, 1.1, 0.0]];
    let x3 = [[0.5, 0.2, 0.1], [2.0, 1.1, 0.7]];
    for f in [Formulation::Barr, Formulation::Pout, Formulation::Timo] {
        check(f, ElemType::Seg2, Mode::PlanCont, &x2, &m);
        check(f, ElemType::Seg2, Mode::Trid, &x3, &m);
    }
}
