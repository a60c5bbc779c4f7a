//! COQ2: rigid motions, a thin cylinder under internal pressure (hoop
//! stress pR/t), a plane-strain cantilever (tip deflection PL³/3EI) and
//! BSIG of SIGM = K u.

use super::coq2;
use super::element::{GaussField, Mode};
use super::material::Material;
use super::test_support::dense_solve;

fn mat(t: f64) -> Material {
    Material { youn: Some(2.0e11), nu: Some(0.3), epai: Some(t), rho: Some(7800.0), ..Default::default() }
}

fn k_times(k: &[f64], u: &[f64]) -> Vec<f64> {
    (0..6).map(|i| (0..6).map(|j| k[i * 6 + j] * u[j]).sum()).collect()
}

#[test]
fn rigid_motions_cost_nothing() {
    let x = [[1.0, 0.2, 0.0], [1.7, 0.9, 0.0]];
    let m = mat(0.01);
    let k = coq2::stiffness(Mode::Axis, &x, &m).unwrap().k;
    let scale = k.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    // Axial translation (UZ) is the one rigid motion of a ring.
    for f in k_times(&k, &[0.0, 1.0, 0.0, 0.0, 1.0, 0.0]) {
        assert!(f.abs() < 1e-10 * scale, "{}", f);
    }
    let kp = coq2::stiffness(Mode::PlanDefo, &x, &m).unwrap().k;
    let sp = kp.iter().fold(0.0f64, |a, v| a.max(v.abs()));
    // Plane: two translations and the rotation about z through the origin.
    let rot = [-x[0][1], x[0][0], 1.0, -x[1][1], x[1][0], 1.0];
    for u in [[1.0, 0.0, 0.0, 1.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0, 1.0, 0.0], rot] {
        for f in k_times(&kp, &u) {
            assert!(f.abs() < 1e-9 * sp, "{}", f);
        }
    }
}

/// A cylinder R = 2, t = 0.02 of 4 elements along z, internal pressure p,
/// one end held axially: N22 = pR (hoop stress pR/t), N11 = 0, no bending,
/// radial displacement pR²/(E t).
#[test]
fn thin_cylinder_under_internal_pressure() {
    let (r, t, p, e) = (2.0, 0.02, 1.0e5, 2.0e11);
    let m = mat(t);
    let n = 4;
    let x: Vec<[f64; 3]> = (0..=n).map(|i| [r, i as f64 * 0.25, 0.0]).collect();
    let nd = 3 * (n + 1);
    let mut k = vec![vec![0.0; nd]; nd];
    let mut f = vec![0.0; nd];
    for el in 0..n {
        // Going up the wall, the left normal points to the axis: the
        // internal pressure pushes along −n, i.e. it is −p on this line.
        let xe = [x[el], x[el + 1]];
        let ke = coq2::stiffness(Mode::Axis, &xe, &m).unwrap().k;
        let fe = coq2::pressure_load(Mode::Axis, &xe, [-p, -p], 1.0, true).unwrap();
        for i in 0..6 {
            f[3 * el + i] += fe[i];
            for j in 0..6 {
                k[3 * el + i][3 * el + j] += ke[i * 6 + j];
            }
        }
    }
    // Hold UZ of the first node: zero the row and column, unit diagonal.
    k[1].iter_mut().for_each(|v| *v = 0.0);
    k.iter_mut().for_each(|row| row[1] = 0.0);
    k[1][1] = 1.0;
    f[1] = 0.0;
    let u = dense_solve(&mut k, &mut f);
    let ur = p * r * r / (e * t);
    for i in 0..=n {
        assert!((u[3 * i] - ur).abs() < 1e-9 * ur, "node {}: {} vs {}", i, u[3 * i], ur);
    }
    let ue: Vec<f64> = u[0..6].to_vec();
    let s = coq2::stress(Mode::Axis, &[x[0], x[1]], &m, &ue).unwrap();
    for v in &s.values {
        assert!((v[1] - p * r).abs() < 1e-6 * p * r, "N22 {}", v[1]);
        assert!(v[0].abs() < 1e-6 * p * r && v[2].abs() < 1e-6 * p * r * t, "{:?}", v);
    }
}

/// Plane strain strip as a cantilever: one element holds the cubic
/// deflection exactly, w = P L³ / (3 D) with D = E t³/(12(1 − ν²)).
#[test]
fn plane_strain_cantilever() {
    let (l, t, pf) = (2.0, 0.1, 100.0);
    let m = mat(t);
    let x = [[0.0, 0.0, 0.0], [l, 0.0, 0.0]];
    let k = coq2::stiffness(Mode::PlanDefo, &x, &m).unwrap().k;
    let mut kr: Vec<Vec<f64>> = (3..6).map(|i| (3..6).map(|j| k[i * 6 + j]).collect()).collect();
    let mut f = vec![0.0, pf, 0.0];
    let u = dense_solve(&mut kr, &mut f);
    let d = 2.0e11 * t.powi(3) / (12.0 * (1.0 - 0.09));
    let w = pf * l.powi(3) / (3.0 * d);
    assert!((u[1] - w).abs() < 1e-9 * w, "{} vs {}", u[1], w);
    assert!((u[2] - pf * l * l / (2.0 * d)).abs() < 1e-9 * w);
    // PLAN CONT: the strip of width DIM3 with E t³/12, no Poisson factor.
    let mut mc = m.clone();
    mc.dim3 = Some(0.5);
    let kc = coq2::stiffness(Mode::PlanCont, &x, &mc).unwrap().k;
    let mut kr: Vec<Vec<f64>> = (3..6).map(|i| (3..6).map(|j| kc[i * 6 + j]).collect()).collect();
    let mut f = vec![0.0, pf, 0.0];
    let u = dense_solve(&mut kr, &mut f);
    let w = pf * l.powi(3) / (3.0 * 2.0e11 * 0.5 * t.powi(3) / 12.0);
    assert!((u[1] - w).abs() < 1e-9 * w, "{} vs {}", u[1], w);
}

#[test]
fn internal_forces_of_the_stresses_are_k_u() {
    let x = [[0.5, 0.0, 0.0], [0.9, 0.6, 0.0]];
    let m = mat(0.05);
    let u = [1e-3, -2e-3, 0.01, 3e-3, 1e-3, -0.02];
    for mode in [Mode::Axis, Mode::PlanDefo, Mode::PlanCont] {
        let k = coq2::stiffness(mode, &x, &m).unwrap().k;
        let s: GaussField = coq2::stress(mode, &x, &m, &u).unwrap();
        let f = coq2::internal_forces(mode, &x, &m, &s).unwrap();
        let ku = k_times(&k, &u);
        let scale = ku.iter().fold(0.0f64, |a, v| a.max(v.abs()));
        for (a, b) in f.iter().zip(&ku) {
            assert!((a - b).abs() < 1e-9 * scale, "{:?}: {} vs {}", mode, a, b);
        }
    }
}

#[test]
fn mass_of_a_ring_and_the_axis_is_refused() {
    let (r, h, t) = (1.5, 0.4, 0.01);
    let x = [[r, 0.0, 0.0], [r, h, 0.0]];
    let m = mat(t);
    let total = 7800.0 * t * 2.0 * std::f64::consts::PI * r * h;
    for lumped in [true, false] {
        let mm = coq2::mass(Mode::Axis, &x, &m, lumped).unwrap().k;
        // Mass seen by a uniform radial motion.
        let u = [1.0, 0.0, 0.0, 1.0, 0.0, 0.0];
        let mu: f64 = (0..6).map(|i| (0..6).map(|j| u[i] * mm[i * 6 + j] * u[j]).sum::<f64>()).sum();
        assert!((mu - total).abs() < 1e-9 * total, "lumped {}: {} vs {}", lumped, mu, total);
    }
    let on_axis = [[0.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    assert!(coq2::stiffness(Mode::Axis, &on_axis, &m).is_err());
    assert!(coq2::stiffness(Mode::Trid, &x, &m).is_err());
}
