//! Massive elements: rigid modes, Q4RI hourglass, mass, pressure, the
//! Lamé thick cylinder in AXIS, post-processing and error reporting.

use super::element::{gauss_points, mass, stiffness, stress, FemError, Formulation, GaussField, Mode};
use super::loads::pressure_load;
use super::mesh::ElemType;
use super::stress::{to_nodes, von_mises};
use super::test_support::*;
use super::tests_patch::{plane_mesh, solid_mesh};
use std::collections::BTreeMap;

const PLANE: [ElemType; 4] = [ElemType::Tri3, ElemType::Tri6, ElemType::Qua4, ElemType::Qua8];
const SOLID3: [ElemType; 3] = [ElemType::Cub8, ElemType::Tet4, ElemType::Pri6];

/// A single distorted element of type `ty` (reference nodes, moved).
fn distorted(ty: ElemType) -> Vec<[f64; 3]> {
    let d3 = ty.dim() == 3;
    super::shape::ref_nodes(ty)
        .into_iter()
        .enumerate()
        .map(|(i, p)| {
            let w = |c: usize| 0.1 * wobble(i as f64, c as f64 + 0.5);
            [2.0 + 0.8 * p[0] + w(0), 1.0 + 0.6 * p[1] + 0.2 * p[0] + w(1), if d3 { 0.7 * p[2] + w(2) } else { 0.0 }]
        })
        .collect()
}

type RigidMode = Box<dyn Fn([f64; 3]) -> [f64; 3]>;

fn matvec(k: &[f64], u: &[f64]) -> Vec<f64> {
    let n = u.len();
    (0..n).map(|i| (0..n).map(|j| k[i * n + j] * u[j]).sum()).collect()
}

#[test]
fn rigid_modes_have_zero_energy() {
    let m = mat(1000.0, 0.3);
    let cases = PLANE
        .iter()
        .flat_map(|&t| [(t, Mode::PlanCont), (t, Mode::PlanDefo), (t, Mode::Axis)])
        .chain(SOLID3.iter().map(|&t| (t, Mode::Trid)));
    for (ty, mode) in cases {
        let x = distorted(ty);
        let k = stiffness(Formulation::Solid, ty, mode, &x, &m).unwrap();
        let kmax = k.k.iter().fold(0.0f64, |a, v| a.max(v.abs()));
        let modes: Vec<RigidMode> = match mode {
            Mode::Axis => vec![Box::new(|_| [0.0, 1.0, 0.0])],
            Mode::Trid => vec![
                Box::new(|_| [1.0, 0.0, 0.0]),
                Box::new(|_| [0.0, 1.0, 0.0]),
                Box::new(|_| [0.0, 0.0, 1.0]),
                Box::new(|p| [-p[1], p[0], 0.0]),
                Box::new(|p| [p[2], 0.0, -p[0]]),
                Box::new(|p| [0.0, -p[2], p[1]]),
            ],
            _ => vec![Box::new(|_| [1.0, 0.0, 0.0]), Box::new(|_| [0.0, 1.0, 0.0]), Box::new(|p| [-p[1], p[0], 0.0])],
        };
        let nc = if mode == Mode::Trid { 3 } else { 2 };
        for r in modes {
            let u: Vec<f64> = x.iter().flat_map(|&p| r(p)[..nc].to_vec()).collect();
            let f = matvec(&k.k, &u);
            assert!(f.iter().all(|v| v.abs() < 1e-10 * kmax), "{} {:?}: {f:?}", ty.name(), mode);
        }
        // And a non-rigid field does cost energy: K is not identically 0.
        let u: Vec<f64> = x.iter().flat_map(|&p| [p[0], 0.0, 0.0][..nc].to_vec()).collect();
        assert!(matvec(&k.k, &u).iter().any(|v| v.abs() > 1e-3 * kmax));
    }
}

#[test]
fn q4ri_has_exactly_two_hourglass_modes() {
    let m = mat(1000.0, 0.25);
    let x = vec![[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [2.0, 1.0, 0.0], [0.0, 1.0, 0.0]];
    let kr = stiffness(Formulation::Q4ri, ElemType::Qua4, Mode::PlanDefo, &x, &m).unwrap();
    let kf = stiffness(Formulation::Solid, ElemType::Qua4, Mode::PlanDefo, &x, &m).unwrap();
    // ξη at the nodes: +1, -1, +1, -1.
    let h = [1.0, -1.0, 1.0, -1.0];
    for c in 0..2 {
        let mut u = vec![0.0; 8];
        for i in 0..4 {
            u[2 * i + c] = h[i];
        }
        assert!(matvec(&kr.k, &u).iter().all(|v| v.abs() < 1e-9));
        assert!(matvec(&kf.k, &u).iter().any(|v| v.abs() > 1.0));
    }
    // Rank 3: the 8×8 matrix has 5 zero pivots in elimination.
    let mut a: Vec<Vec<f64>> = (0..8).map(|i| kr.k[i * 8..(i + 1) * 8].to_vec()).collect();
    let mut rank = 0;
    for col in 0..8 {
        let p = (rank..8).max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs())).unwrap();
        if a[p][col].abs() < 1e-9 {
            continue;
        }
        a.swap(rank, p);
        let pivot = a[rank].clone();
        for row in a.iter_mut().skip(rank + 1) {
            let r = row[col] / pivot[col];
            for (v, pv) in row.iter_mut().zip(&pivot) {
                *v -= r * pv;
            }
        }
        rank += 1;
    }
    assert_eq!(rank, 3);
    assert_eq!(gauss_points(Formulation::Q4ri, ElemType::Qua4).len(), 1);
}

#[test]
fn total_mass_is_density_times_volume() {
    let rho = 7.5;
    let mut m = mat(1.0, 0.3);
    m.rho = Some(rho);
    m.dim3 = Some(0.3);
    let mut cases: Vec<(ElemType, Mode, f64)> = Vec::new();
    for &t in &PLANE {
        // Domain [0.5, 2.5] × [0, 2]: area 4; AXIS ∫ 2πr dA = 2π·2·(2.5² − 0.5²)/2.
        cases.push((t, Mode::PlanCont, 4.0 * 0.3));
        cases.push((t, Mode::PlanDefo, 4.0));
        cases.push((t, Mode::Axis, std::f64::consts::TAU * 6.0));
    }
    for &t in &SOLID3 {
        cases.push((t, Mode::Trid, 8.0));
    }
    for (ty, mode, vol) in cases {
        let (coords, elems) = if ty.dim() == 3 { solid_mesh(ty, 2) } else { plane_mesh(ty, 2, mode != Mode::Axis) };
        for lumped in [false, true] {
            let mut total = 0.0;
            for (t, conn) in &elems {
                let x: Vec<[f64; 3]> = conn.iter().map(|&n| coords[n]).collect();
                let em = mass(Formulation::Solid, *t, mode, &x, &m, lumped).unwrap();
                let nd = em.dofs.len();
                for i in 0..nd {
                    for j in 0..nd {
                        if em.dofs[i].1 == em.dofs[j].1 && em.dofs[i].1 == if mode == Mode::Axis { "UR" } else { "UX" }
                        {
                            total += em.k[i * nd + j];
                        }
                        if lumped && i != j {
                            assert_eq!(em.k[i * nd + j], 0.0);
                        }
                    }
                    assert!(em.k[i * nd + i] > 0.0);
                }
            }
            assert!(
                (total - rho * vol).abs() < 1e-10 * vol,
                "{} {:?} lumped={lumped}: {total} vs {}",
                ty.name(),
                mode,
                rho * vol
            );
        }
    }
}

fn sum(f: &[[f64; 3]]) -> [f64; 3] {
    f.iter().fold([0.0; 3], |a, v| [a[0] + v[0], a[1] + v[1], a[2] + v[2]])
}

#[test]
fn pressure_resultants() {
    let p = 3.0;
    // Plane edge from (1,0) to (1,2), solid on the +x side: total p·L along +x.
    for (ty, x) in [
        (ElemType::Seg2, vec![[1.0, 0.0, 0.0], [1.0, 2.0, 0.0]]),
        (ElemType::Seg3, vec![[1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [1.0, 2.0, 0.0]]),
    ] {
        let f = pressure_load(ty, Mode::PlanCont, &x, p, [2.0, 1.0, 0.0]).unwrap();
        let s = sum(&f);
        assert!((s[0] - 6.0).abs() < 1e-12 && s[1].abs() < 1e-12);
        // Same edge in AXIS at r = 1: the whole ring, 2π·p·r·h; solid inside (r < 1) flips it.
        let f = pressure_load(ty, Mode::Axis, &x, p, [0.5, 1.0, 0.0]).unwrap();
        assert!((sum(&f)[0] + std::f64::consts::TAU * 6.0).abs() < 1e-11);
    }
    // SEG2 on a slanted AXIS edge (1,0)-(3,1): ∫ r ds along it, times p, along the normal.
    let x = vec![[1.0, 0.0, 0.0], [3.0, 1.0, 0.0]];
    let f = pressure_load(ElemType::Seg2, Mode::Axis, &x, p, [3.0, 0.0, 0.0]).unwrap();
    let (len, rmean) = (5f64.sqrt(), 2.0);
    let n = [1.0 / len, -2.0 / len];
    let s = sum(&f);
    for c in 0..2 {
        assert!((s[c] - std::f64::consts::TAU * p * len * rmean * n[c]).abs() < 1e-11);
    }
    // The ring load splits 5:7 between the r = 1 and r = 3 ends (∫N_i r ds).
    assert!((f[0][0] / f[1][0] - 5.0 / 7.0).abs() < 1e-12);
    // 3D faces in the plane z = 1, solid below: total p·A along −z.
    let q4 = vec![[0.0, 0.0, 1.0], [2.0, 0.0, 1.0], [2.5, 1.5, 1.0], [0.0, 1.0, 1.0]];
    let area_q4 = 0.5 * (2.0 * 1.5 + 2.5 * 1.0); // shoelace
    let mid = |a: [f64; 3], b: [f64; 3]| [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0, (a[2] + b[2]) / 2.0];
    let q8 = (0..4).flat_map(|i| [q4[i], mid(q4[i], q4[(i + 1) % 4])]).collect::<Vec<_>>();
    let t3 = vec![q4[0], q4[1], q4[2]];
    let t6 = (0..3).flat_map(|i| [t3[i], mid(t3[i], t3[(i + 1) % 3])]).collect::<Vec<_>>();
    let area_t3 = 0.5 * (2.0 * 1.5 - 0.0 * 2.5);
    for (ty, x, a) in [
        (ElemType::Qua4, q4.clone(), area_q4),
        (ElemType::Qua8, q8, area_q4),
        (ElemType::Tri3, t3, area_t3),
        (ElemType::Tri6, t6, area_t3),
    ] {
        let f = pressure_load(ty, Mode::Trid, &x, p, [1.0, 0.5, -3.0]).unwrap();
        let s = sum(&f);
        assert!((s[2] + p * a).abs() < 1e-12 && s[0].abs() < 1e-12 && s[1].abs() < 1e-12, "{}: {s:?}", ty.name());
    }
    // Wrong face/mode pairs and an ambiguous side are errors.
    assert!(pressure_load(ElemType::Seg2, Mode::Trid, &[[0.0; 3], [1.0, 0.0, 0.0]], p, [0.0, 1.0, 0.0]).is_err());
    assert!(pressure_load(ElemType::Qua4, Mode::Trid, &q4, p, [1.0, 0.5, 1.0]).is_err());
}

/// Thick cylinder a = 1, b = 2 under internal pressure, ε_z = 0, meshed with
/// 8 × 2 QUA8 in AXIS; compared with Lamé (plane strain).
#[test]
fn lame_thick_cylinder_axis_qua8() {
    let (a, b, h, p, e, nu) = (1.0, 2.0, 0.4, 10.0, 1000.0, 0.3);
    let (nr, nz) = (8, 2);
    // Nodes on a (2nr+1) × (2nz+1) grid; QUA8 skips the cell centres.
    let id = |i: usize, j: usize| i + (2 * nr + 1) * j;
    let coords: Vec<[f64; 3]> = (0..=2 * nz)
        .flat_map(|j| {
            (0..=2 * nr).map(move |i| [a + (b - a) * i as f64 / (2 * nr) as f64, h * j as f64 / (2 * nz) as f64, 0.0])
        })
        .collect();
    let mut elems = Vec::new();
    for j in 0..nz {
        for i in 0..nr {
            let (i0, j0) = (2 * i, 2 * j);
            elems.push((
                ElemType::Qua8,
                vec![
                    id(i0, j0),
                    id(i0 + 1, j0),
                    id(i0 + 2, j0),
                    id(i0 + 2, j0 + 1),
                    id(i0 + 2, j0 + 2),
                    id(i0 + 1, j0 + 2),
                    id(i0, j0 + 2),
                    id(i0, j0 + 1),
                ],
            ));
        }
    }
    let model = Model { mode: Mode::Axis, f: Formulation::Solid, coords, elems, mat: mat(e, nu) };
    let (map, k) = assemble(&model);
    let mut rhs = vec![0.0; map.len()];
    for j in 0..nz {
        let edge = [id(0, 2 * j), id(0, 2 * j + 1), id(0, 2 * j + 2)];
        let x: Vec<[f64; 3]> = edge.iter().map(|&n| model.coords[n]).collect();
        let f = pressure_load(ElemType::Seg3, Mode::Axis, &x, p, [1.5, x[1][1], 0.0]).unwrap();
        for (n, fv) in edge.iter().zip(&f) {
            rhs[map[&(*n, "UR")]] += fv[0];
            rhs[map[&(*n, "UZ")]] += fv[1];
        }
    }
    let total: f64 = map.iter().filter(|((_, d), _)| *d == "UR").map(|(_, &r)| rhs[r]).sum();
    assert!((total - std::f64::consts::TAU * p * a * h).abs() < 1e-10, "whole-ring load {total}");
    let mut fixed = BTreeMap::new();
    for (&(n, d), &r) in &map {
        let z = model.coords[n][1];
        if d == "UZ" && (z.abs() < 1e-12 || (z - h).abs() < 1e-12) {
            fixed.insert(r, 0.0);
        }
    }
    let u = solve_prescribed(&k, &rhs, &fixed);
    let c = p * a * a / (b * b - a * a);
    let ur = |r: f64| (1.0 + nu) * c / e * ((1.0 - 2.0 * nu) * r + b * b / r);
    for (&(n, d), &row) in &map {
        if d == "UR" {
            let r = model.coords[n][0];
            assert!((u[row] - ur(r)).abs() < 1e-3 * ur(a), "u_r({r}) = {} vs {}", u[row], ur(r));
        } else {
            assert!(u[row].abs() < 1e-12);
        }
    }
    // Stresses converge one order slower than displacements: 1 % of p
    // at the Gauss points (the worst is next to the bore).
    for (ty, conn) in &model.elems {
        let x: Vec<[f64; 3]> = conn.iter().map(|&n| model.coords[n]).collect();
        let ue = gather(&model, &map, conn, *ty, &u);
        let s = stress(Formulation::Solid, *ty, Mode::Axis, &x, &model.mat, &ue).unwrap();
        for (g, pos) in super::element::gauss_positions(Formulation::Solid, *ty, &x).iter().enumerate() {
            let r = pos[0];
            let (srr, stt) = (c * (1.0 - b * b / (r * r)), c * (1.0 + b * b / (r * r)));
            let got = s.get("SMRR", g).unwrap();
            assert!((got - srr).abs() < 1e-2 * p, "SMRR({r}) = {got} vs {srr}");
            assert!((s.get("SMTT", g).unwrap() - stt).abs() < 1e-2 * p);
            assert!((s.get("SMZZ", g).unwrap() - nu * (srr + stt)).abs() < 1e-2 * p);
        }
    }
}

#[test]
fn von_mises_and_node_transfer() {
    let m = mat(1.0, 0.3);
    let sig = GaussField {
        comps: vec!["SMXX", "SMYY", "SMZZ", "SMXY"],
        values: vec![vec![3.0, 0.0, 0.0, 0.0], vec![0.0, 0.0, 0.0, 2.0]],
    };
    let vm = von_mises(Formulation::Solid, Mode::PlanDefo, &m, &sig).unwrap();
    assert!((vm.values[0][0] - 3.0).abs() < 1e-14 && (vm.values[1][0] - 2.0 * 3f64.sqrt()).abs() < 1e-14);
    // Bilinear/trilinear (or, for TRI6, linear) fields are recovered exactly at the nodes.
    let lin = |p: [f64; 3]| 1.0 + 2.0 * p[0] - 3.0 * p[1] + 0.5 * p[2];
    for (ty, f) in [
        (ElemType::Qua4, Formulation::Solid),
        (ElemType::Qua8, Formulation::Solid),
        (ElemType::Tri6, Formulation::Solid),
        (ElemType::Cub8, Formulation::Solid),
        (ElemType::Pri6, Formulation::Solid),
    ] {
        let g =
            GaussField { comps: vec!["S"], values: gauss_points(f, ty).iter().map(|(p, _)| vec![lin(*p)]).collect() };
        let n = to_nodes(f, ty, &g).unwrap();
        for (k, xn) in super::shape::ref_nodes(ty).into_iter().enumerate() {
            assert!((n.values[k][0] - lin(xn)).abs() < 1e-12, "{} node {k}", ty.name());
        }
    }
}

#[test]
fn bad_input_is_reported_not_panicked() {
    let good = vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]];
    let m = mat(100.0, 0.25);
    // Bow-tie: the Jacobian changes sign.
    let bow = vec![good[0], good[1], good[3], good[2]];
    assert!(matches!(
        stiffness(Formulation::Solid, ElemType::Qua4, Mode::PlanCont, &bow, &m),
        Err(FemError::Degenerate { .. })
    ));
    // Clockwise numbering is the same element, accepted.
    let cw = vec![good[0], good[3], good[2], good[1]];
    let (k1, k2) = (
        stiffness(Formulation::Solid, ElemType::Qua4, Mode::PlanCont, &good, &m).unwrap(),
        stiffness(Formulation::Solid, ElemType::Qua4, Mode::PlanCont, &cw, &m).unwrap(),
    );
    let perm = [0, 3, 2, 1];
    for i in 0..8 {
        for j in 0..8 {
            let (a, b) = (k2.k[i * 8 + j], k1.k[(2 * perm[i / 2] + i % 2) * 8 + 2 * perm[j / 2] + j % 2]);
            assert!((a - b).abs() < 1e-12);
        }
    }
    let flat = vec![good[0], good[1], [2.0, 0.0, 0.0]];
    assert!(matches!(
        stiffness(Formulation::Solid, ElemType::Tri3, Mode::PlanCont, &flat, &m),
        Err(FemError::Degenerate { .. })
    ));
    let e = stiffness(Formulation::Solid, ElemType::Qua4, Mode::PlanCont, &good, &Default::default()).unwrap_err();
    assert_eq!(e.to_string(), "material property YOUN missing for QUA4");
    let e = stiffness(Formulation::Solid, ElemType::Qua4, Mode::PlanDefo, &good, &mat(1.0, 0.5)).unwrap_err();
    assert!(matches!(e, FemError::InvalidProperty { prop: "NU", .. }));
    // AXIS with negative radius, 3D element in a plane mode, too few nodes, no RHO.
    let left: Vec<[f64; 3]> = good.iter().map(|p| [p[0] - 2.0, p[1], 0.0]).collect();
    assert!(stiffness(Formulation::Solid, ElemType::Qua4, Mode::Axis, &left, &m).is_err());
    assert!(stiffness(Formulation::Solid, ElemType::Cub8, Mode::PlanCont, &good, &m).is_err());
    assert!(stiffness(Formulation::Solid, ElemType::Qua4, Mode::PlanCont, &good[..3], &m).is_err());
    let e = mass(Formulation::Solid, ElemType::Qua4, Mode::PlanCont, &good, &m, false).unwrap_err();
    assert_eq!(e.to_string(), "material property RHO missing for QUA4");
    assert!(stress(Formulation::Solid, ElemType::Qua4, Mode::PlanCont, &good, &m, &[0.0; 3]).is_err());
}
