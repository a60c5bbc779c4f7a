//! Bars and beams against closed-form answers.

use super::element::{mass, stiffness, strain, stress, ElemMatrix, Formulation, GaussField, Material, Mode};
use super::mesh::ElemType;
use super::stress::von_mises;
use super::test_support::*;
use std::collections::BTreeMap;

fn beam_mat(e: f64, nu: f64) -> Material {
    Material {
        youn: Some(e),
        nu: Some(nu),
        sect: Some(1.0),
        inrz: Some(1.0),
        inry: Some(2.0),
        tors: Some(0.5),
        ..Default::default()
    }
}

/// A straight line of `n` SEG2 from `a` to `b`; node 0 clamped (all dofs),
/// `loads` at the last node as (dof, value). Returns (u by (node, dof), model, map).
fn line(
    f: Formulation,
    mode: Mode,
    mat: Material,
    a: [f64; 3],
    b: [f64; 3],
    n: usize,
    loads: &[(&'static str, f64)],
) -> (Model, super::test_support::DofMap, Vec<f64>, Vec<f64>) {
    let coords: Vec<[f64; 3]> = (0..=n)
        .map(|i| {
            let t = i as f64 / n as f64;
            [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])]
        })
        .collect();
    let elems = (0..n).map(|i| (ElemType::Seg2, vec![i, i + 1])).collect();
    let model = Model { mode, f, coords, elems, mat };
    let (map, k) = assemble(&model);
    let mut rhs = vec![0.0; map.len()];
    for &(d, v) in loads {
        rhs[map[&(n, d)]] += v;
    }
    let fixed: BTreeMap<usize, f64> = map.iter().filter(|((nd, _), _)| *nd == 0).map(|(_, &r)| (r, 0.0)).collect();
    let u = solve_prescribed(&k, &rhs, &fixed);
    // Reactions K u − f at the clamp.
    let reac: Vec<f64> = (0..map.len()).map(|i| (0..map.len()).map(|j| k[i][j] * u[j]).sum::<f64>() - rhs[i]).collect();
    (model, map, u, reac)
}

fn close(a: f64, b: f64, what: &str) {
    assert!((a - b).abs() < 1e-10 * (1.0 + b.abs()), "{what}: {a} vs {b}");
}

#[test]
fn pout_2d_cantilever() {
    // Deck 10: L = 10 in ten elements, EI = 1000, tip load −3.
    let m = Material { youn: Some(1000.0), nu: Some(0.3), sect: Some(1.0), inrz: Some(1.0), ..Default::default() };
    let (model, map, u, reac) =
        line(Formulation::Pout, Mode::PlanCont, m.clone(), [0.0; 3], [10.0, 0.0, 0.0], 10, &[("UY", -3.0)]);
    close(u[map[&(10, "UY")]], -1.0, "tip deflection PL³/3EI");
    close(u[map[&(10, "RZ")]], -0.15, "tip rotation PL²/2EI");
    close(u[map[&(10, "UX")]], 0.0, "no axial motion");
    close(reac[map[&(0, "UY")]], 3.0, "clamp force");
    close(reac[map[&(0, "RZ")]], 30.0, "clamp moment");
    // Section resultants of the first element: M(x) = P(L − x), V = P.
    let x = [model.coords[0], model.coords[1]];
    let ue = gather(&model, &map, &[0, 1], ElemType::Seg2, &u);
    let s = stress(Formulation::Pout, ElemType::Seg2, Mode::PlanCont, &x, &m, &ue).unwrap();
    assert_eq!(s.comps, vec!["EFFX", "EFFY", "MOMZ"]);
    close(s.get("MOMZ", 0).unwrap(), -30.0, "M at the clamp");
    close(s.get("MOMZ", 1).unwrap(), -27.0, "M at x = 1");
    close(s.get("EFFY", 0).unwrap(), -3.0, "shear");
    close(s.get("EFFY", 1).unwrap(), -3.0, "shear");
    let e = strain(Formulation::Pout, ElemType::Seg2, Mode::PlanCont, &x, &m, &ue).unwrap();
    close(e.get("CURZ", 0).unwrap(), -0.03, "curvature M/EI");
    // The same cantilever at 30°, loaded across and along its axis.
    let (c, sn) = (30f64.to_radians().cos(), 30f64.to_radians().sin());
    let (_, map, u, _) = line(
        Formulation::Pout,
        Mode::PlanDefo,
        m.clone(),
        [1.0, 2.0, 0.0],
        [1.0 + 10.0 * c, 2.0 + 10.0 * sn, 0.0],
        3,
        &[("UX", 3.0 * sn + 2.0 * c), ("UY", -3.0 * c + 2.0 * sn)],
    );
    let (ux, uy) = (u[map[&(3, "UX")]], u[map[&(3, "UY")]]);
    close(-ux * sn + uy * c, -1.0, "inclined tip deflection");
    close(ux * c + uy * sn, 2.0 * 10.0 / 1000.0, "axial PL/EA");
    close(u[map[&(3, "RZ")]], -0.15, "inclined tip rotation");
}

#[test]
fn pout_3d_cantilever_both_planes_and_torsion() {
    let m = Material { vect: Some([0.0, 1.0, 0.0]), ..beam_mat(1000.0, 0.25) };
    // G = 400, GJ = 200, EIz = 1000, EIy = 2000, L = 10.
    for n in [1, 4] {
        let (_, map, u, _) = line(
            Formulation::Pout,
            Mode::Trid,
            m.clone(),
            [0.0; 3],
            [10.0, 0.0, 0.0],
            n,
            &[("UY", -3.0), ("UZ", -3.0), ("RX", 2.0)],
        );
        close(u[map[&(n, "UY")]], -1.0, "UY = PL³/3EIz");
        close(u[map[&(n, "RZ")]], -0.15, "RZ = PL²/2EIz");
        close(u[map[&(n, "UZ")]], -0.5, "UZ = PL³/3EIy");
        close(u[map[&(n, "RY")]], 0.075, "RY = −PL²/2EIy");
        close(u[map[&(n, "RX")]], 0.1, "RX = TL/GJ");
    }
    // A skewed beam along (1, 2, 2), local y from VECT = z: loads along the
    // local axes give the same answers in the local frame.
    let d: [f64; 3] = [1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0];
    let v = [0.0, 0.0, 1.0];
    let p = d[2];
    let ey = {
        let y = [v[0] - p * d[0], v[1] - p * d[1], v[2] - p * d[2]];
        let n = (y[0] * y[0] + y[1] * y[1] + y[2] * y[2]).sqrt();
        [y[0] / n, y[1] / n, y[2] / n]
    };
    let ez = [d[1] * ey[2] - d[2] * ey[1], d[2] * ey[0] - d[0] * ey[2], d[0] * ey[1] - d[1] * ey[0]];
    let m = Material { vect: Some(v), ..m };
    let (py, pz, t) = (-3.0, 1.5, 2.0);
    let load: Vec<(&'static str, f64)> = (0..3)
        .flat_map(|c| [(["UX", "UY", "UZ"][c], py * ey[c] + pz * ez[c]), (["RX", "RY", "RZ"][c], t * d[c])])
        .collect();
    let (_, map, u, _) = line(Formulation::Pout, Mode::Trid, m, [1.0, -1.0, 0.5], [4.0, 5.0, 6.5], 3, &load);
    let at = |names: [&'static str; 3], e: [f64; 3]| (0..3).map(|c| u[map[&(3, names[c])]] * e[c]).sum::<f64>();
    let tr = ["UX", "UY", "UZ"];
    let ro = ["RX", "RY", "RZ"];
    let l: f64 = 9.0;
    close(at(tr, ey), py * l.powi(3) / 3000.0, "local y deflection");
    close(at(tr, ez), pz * l.powi(3) / 6000.0, "local z deflection");
    close(at(tr, d), 0.0, "no axial motion");
    close(at(ro, ez), py * l * l / 2000.0, "rotation about local z");
    close(at(ro, ey), -pz * l * l / 4000.0, "rotation about local y");
    close(at(ro, d), t * l / 200.0, "twist");
}

#[test]
fn beam_rigid_modes_in_3d() {
    let m = Material { vect: Some([0.3, 1.0, 0.2]), secy: Some(0.8), secz: Some(0.6), ..beam_mat(1000.0, 0.25) };
    let x = [[0.5, -1.0, 2.0], [2.0, 1.5, 0.7]];
    for f in [Formulation::Pout, Formulation::Timo] {
        let k = stiffness(f, ElemType::Seg2, Mode::Trid, &x, &m).unwrap();
        for mode in 0..6 {
            // Translation e_c, or rotation θ = e_c: u = θ × x.
            let mut u = [0.0; 12];
            for (i, p) in x.iter().enumerate() {
                if mode < 3 {
                    u[6 * i + mode] = 1.0;
                } else {
                    let th = [(mode == 3) as u8 as f64, (mode == 4) as u8 as f64, (mode == 5) as u8 as f64];
                    let t = [th[1] * p[2] - th[2] * p[1], th[2] * p[0] - th[0] * p[2], th[0] * p[1] - th[1] * p[0]];
                    u[6 * i..6 * i + 3].copy_from_slice(&t);
                    u[6 * i + 3..6 * i + 6].copy_from_slice(&th);
                }
            }
            for r in 0..12 {
                let v: f64 = (0..12).map(|c| k.k[r * 12 + c] * u[c]).sum();
                assert!(v.abs() < 1e-9, "{:?} mode {mode}: {v}", f);
            }
        }
    }
}

#[test]
fn timo_one_point_elements_under_a_tip_load() {
    // E = 1000, ν = 0.25 → G = 400; L = 2, P = 1, EIz = 1000, SECY = 0.5.
    // n one-point elements: the bending part is PL³/3EI·(1 − 1/4n²), the
    // shear part and the tip rotation are exact.
    let m = Material { secy: Some(0.5), secz: Some(0.25), vect: Some([0.0, 1.0, 0.0]), ..beam_mat(1000.0, 0.25) };
    for n in [1, 5] {
        let b = 1.0 - 1.0 / (4.0 * (n * n) as f64);
        let (_, map, u, _) =
            line(Formulation::Timo, Mode::PlanCont, m.clone(), [0.0; 3], [2.0, 0.0, 0.0], n, &[("UY", 1.0)]);
        close(u[map[&(n, "UY")]], b * 8.0 / 3000.0 + 2.0 / 200.0, "PL³/3EI + PL/GAs");
        close(u[map[&(n, "RZ")]], 4.0 / 2000.0, "PL²/2EI");
        // 3D, both planes: EIy = 2000 with SECZ = 0.25.
        let (_, map, u, _) =
            line(Formulation::Timo, Mode::Trid, m.clone(), [0.0; 3], [2.0, 0.0, 0.0], n, &[("UY", 1.0), ("UZ", 1.0)]);
        close(u[map[&(n, "UY")]], b * 8.0 / 3000.0 + 2.0 / 200.0, "3D y");
        close(u[map[&(n, "UZ")]], b * 8.0 / 6000.0 + 2.0 / 100.0, "3D z");
        close(u[map[&(n, "RY")]], -4.0 / 4000.0, "3D RY");
    }
    // Generalised shear strain V/(G·As) on TIMO, zero on POUT.
    let x = [[0.0; 3], [2.0, 0.0, 0.0]];
    let u = [0.0, 0.0, 0.0, 0.0, 8.0 / 4000.0 + 0.01, 0.002];
    let e = strain(Formulation::Timo, ElemType::Seg2, Mode::PlanCont, &x, &m, &u).unwrap();
    close(e.get("GAXY", 0).unwrap(), 1.0 / 200.0, "shear strain");
    let e = stress(Formulation::Timo, ElemType::Seg2, Mode::PlanCont, &x, &m, &u).unwrap();
    close(e.get("EFFY", 1).unwrap(), 1.0, "tip shear");
    close(e.get("MOMZ", 0).unwrap(), 2.0, "clamp moment");
    // Without SECY the shear area is the section SECT (here 1).
    let k0 = stiffness(Formulation::Timo, ElemType::Seg2, Mode::PlanCont, &x, &beam_mat(1.0, 0.3)).unwrap();
    let m1 = Material { secy: Some(1.0), ..beam_mat(1.0, 0.3) };
    let k1 = stiffness(Formulation::Timo, ElemType::Seg2, Mode::PlanCont, &x, &m1).unwrap();
    assert_eq!(k0.k, k1.k);
}

#[test]
fn barr_three_bar_truss() {
    // Free node D = (0, 0) held by bars to A (0, 1), B (1, 1), C (1, 0);
    // EA = 1, load (0, −2) at D. With c = 1/(2√2): K_D = [[1+c, c], [c, 1+c]],
    // so u = 2c/(1+2c), v = −2(1+c)/(1+2c).
    let m = Material { youn: Some(4.0), sect: Some(0.25), ..Default::default() };
    let c = 1.0 / (2.0 * 2f64.sqrt());
    for mode in [Mode::PlanCont, Mode::Trid] {
        let coords = vec![[0.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 1.0, 0.0], [1.0, 0.0, 0.0]];
        let elems = (1..4).map(|i| (ElemType::Seg2, vec![0, i])).collect();
        let model = Model { mode, f: Formulation::Barr, coords, elems, mat: m.clone() };
        let (map, k) = assemble(&model);
        let mut rhs = vec![0.0; map.len()];
        rhs[map[&(0, "UY")]] = -2.0;
        let fixed: BTreeMap<usize, f64> =
            map.iter().filter(|((n, d), _)| *n > 0 || *d == "UZ").map(|(_, &r)| (r, 0.0)).collect();
        let u = solve_prescribed(&k, &rhs, &fixed);
        let (ux, uy) = (u[map[&(0, "UX")]], u[map[&(0, "UY")]]);
        close(ux, 2.0 * c / (1.0 + 2.0 * c), "truss u");
        close(uy, -2.0 * (1.0 + c) / (1.0 + 2.0 * c), "truss v");
        // Bar DC shortens by u: EFFX = −EA·u at both ends; DA (A above D) by v.
        let nodal = |n: usize| gather(&model, &map, &[0, n], ElemType::Seg2, &u);
        let x = |n: usize| [model.coords[0], model.coords[n]];
        let s = stress(Formulation::Barr, ElemType::Seg2, mode, &x(3), &m, &nodal(3)).unwrap();
        close(s.values[0][0], -ux, "N in DC");
        close(s.values[1][0], -ux, "N in DC, end 2");
        let s = stress(Formulation::Barr, ElemType::Seg2, mode, &x(1), &m, &nodal(1)).unwrap();
        close(s.values[0][0], -uy, "N in DA");
        let e = strain(Formulation::Barr, ElemType::Seg2, mode, &x(2), &m, &nodal(2)).unwrap();
        close(e.values[0][0], -(ux + uy) / 2.0, "EPSS in DB: (u_B − u_D)·e / L");
    }
}

fn total_translational(em: &ElemMatrix, dof: &str) -> f64 {
    let n = em.dofs.len();
    let mut s = 0.0;
    for i in 0..n {
        for j in 0..n {
            if em.dofs[i].1 == dof && em.dofs[j].1 == dof {
                s += em.k[i * n + j];
            }
        }
    }
    s
}

#[test]
fn bar_and_beam_mass() {
    let m = Material { rho: Some(2.0), sect: Some(0.5), vect: Some([0.0, 0.0, 1.0]), ..beam_mat(1.0, 0.3) };
    let x = [[1.0, 1.0, 0.0], [4.0, 5.0, 0.0]]; // L = 5, ρAL = 5
    for (f, mode) in [
        (Formulation::Barr, Mode::PlanCont),
        (Formulation::Barr, Mode::Trid),
        (Formulation::Pout, Mode::PlanCont),
        (Formulation::Timo, Mode::Trid),
    ] {
        for lumped in [false, true] {
            let em = mass(f, ElemType::Seg2, mode, &x, &m, lumped).unwrap();
            for d in ["UX", "UY"] {
                close(total_translational(&em, d), 5.0, "ρAL");
            }
            let n = em.dofs.len();
            assert!((0..n).all(|i| em.k[i * n + i] > 0.0));
        }
    }
    // Lumped 2D beam rotation: HRZ value ρAL³/78.
    let em = mass(Formulation::Pout, ElemType::Seg2, Mode::PlanCont, &x, &m, true).unwrap();
    close(em.k[2 * 6 + 2], 5.0 * 25.0 / 78.0, "rotary lumped mass");
}

#[test]
fn beam_von_mises_and_errors() {
    let m = Material { dx: Some(0.5), dy: Some(0.2), dz: Some(0.3), ..beam_mat(1.0, 0.3) };
    let sig = GaussField {
        comps: vec!["EFFX", "EFFY", "EFFZ", "MOMX", "MOMY", "MOMZ"],
        values: vec![vec![2.0, 9.0, 9.0, 1.0, 4.0, 5.0]],
    };
    let vm = von_mises(Formulation::Pout, Mode::Trid, &m, &sig).unwrap();
    let want =
        (2.0f64.powi(2) + (1.0 * 0.5 / 0.5f64).powi(2) + (4.0 * 0.3 / 2.0f64).powi(2) + (5.0 * 0.2f64).powi(2)).sqrt();
    close(vm.values[0][0], want, "beam VMIS");
    let x = [[0.0; 3], [1.0, 0.0, 0.0]];
    let no_i = Material { inrz: None, ..beam_mat(1.0, 0.3) };
    let msg = stiffness(Formulation::Pout, ElemType::Seg2, Mode::PlanCont, &x, &no_i).unwrap_err().to_string();
    assert_eq!(msg, "material property INRZ missing for POUT");
    // Without VECT, Cast3M's default local y: the same stiffness as with
    // VECT = (0 1 0) for a beam along x.
    let default = stiffness(Formulation::Pout, ElemType::Seg2, Mode::Trid, &x, &beam_mat(1.0, 0.3)).unwrap();
    let y = Material { vect: Some([0.0, 1.0, 0.0]), ..beam_mat(1.0, 0.3) };
    let given = stiffness(Formulation::Pout, ElemType::Seg2, Mode::Trid, &x, &y).unwrap();
    assert_eq!(default.k, given.k);
    let par = Material { vect: Some([2.0, 0.0, 0.0]), ..beam_mat(1.0, 0.3) };
    assert!(stiffness(Formulation::Pout, ElemType::Seg2, Mode::Trid, &x, &par).is_err());
    assert!(stiffness(Formulation::Pout, ElemType::Seg2, Mode::PlanCont, &[[1.0; 3], [1.0; 3]], &beam_mat(1.0, 0.3))
        .is_err());
    assert!(stiffness(Formulation::Pout, ElemType::Seg2, Mode::Axis, &x, &beam_mat(1.0, 0.3)).is_err());
    assert!(stiffness(Formulation::Barr, ElemType::Seg3, Mode::PlanCont, &x, &beam_mat(1.0, 0.3)).is_err());
    let no_s = Material { youn: Some(1.0), ..Default::default() };
    assert_eq!(
        stiffness(Formulation::Barr, ElemType::Seg2, Mode::Trid, &x, &no_s).unwrap_err().to_string(),
        "material property SECT missing for BARR"
    );
}
