//! Force-driven tests. Patch tests with imposed displacements cannot see a
//! stiffness that is right up to a factor; here a uniform traction (given
//! through `pressure_load` on the boundary faces found with `shape::faces`)
//! must produce the exact uniaxial displacement field at every node.

use super::element::{node_duals, stiffness, Formulation, Mode};
use super::loads::pressure_load;
use super::mesh::ElemType;
use super::shape::faces;
use super::test_support::*;
use super::tests_patch::{plane_mesh, solid_mesh, PatchMesh};
use std::collections::BTreeMap;

/// Pull with traction `s` on the face at the top of coordinate `axis`,
/// hold the symmetry planes, compare every nodal displacement.
fn uniaxial(f: Formulation, mode: Mode, (coords, elems): PatchMesh, axis: usize) {
    let (e, nu, s) = (250.0, 0.3, 2.0);
    let model = Model { mode, f, coords, elems, mat: mat(e, nu) };
    let (map, k) = assemble(&model);
    let dims = if mode == Mode::Trid { 3 } else { 2 };
    let hi = model.coords.iter().fold(f64::MIN, |a, p| a.max(p[axis]));
    let lo = model.coords.iter().fold(f64::MAX, |a, p| a.min(p[axis]));
    let mut rhs = vec![0.0; map.len()];
    let mut nfaces = 0;
    for (ty, conn) in &model.elems {
        let centroid = conn.iter().fold([0.0; 3], |a, &n| {
            let p = model.coords[n];
            [a[0] + p[0], a[1] + p[1], a[2] + p[2]]
        });
        let inside = centroid.map(|v| v / conn.len() as f64);
        for (fty, local) in faces(*ty) {
            let nodes: Vec<usize> = local.iter().map(|&l| conn[l]).collect();
            if nodes.iter().all(|&n| (model.coords[n][axis] - hi).abs() < 1e-12) {
                nfaces += 1;
                let x: Vec<[f64; 3]> = nodes.iter().map(|&n| model.coords[n]).collect();
                // A traction pulling outwards is a negative pressure.
                let fv = pressure_load(fty, mode, &x, -s, inside).unwrap();
                let names = super::element::node_dofs(f, mode).unwrap();
                for (n, v) in nodes.iter().zip(&fv) {
                    for c in 0..dims {
                        rhs[map[&(*n, names[c])]] += v[c];
                    }
                }
            }
        }
    }
    assert!(nfaces > 0);
    // Uniaxial strains: along `axis`, and across it.
    let (ea, et) = match mode {
        Mode::PlanDefo => ((1.0 - nu * nu) * s / e, -nu * (1.0 + nu) * s / e),
        _ => (s / e, -nu * s / e),
    };
    let exact = |p: [f64; 3], c: usize| {
        if c == axis {
            ea * (p[c] - lo)
        } else if mode == Mode::Axis {
            et * p[c]
        } else {
            et * p[c] - et * model.coords.iter().fold(f64::MAX, |a, q| a.min(q[c]))
        }
    };
    let names = super::element::node_dofs(f, mode).unwrap();
    let mut fixed = BTreeMap::new();
    for (&(n, d), &row) in &map {
        let c = names.iter().position(|x| *x == d).unwrap();
        let p = model.coords[n];
        let low = model.coords.iter().fold(f64::MAX, |a, q| a.min(q[c]));
        // Symmetry planes; in AXIS the radial motion is free (no rigid mode).
        if (p[c] - low).abs() < 1e-12 && !(mode == Mode::Axis && c == 0) {
            fixed.insert(row, 0.0);
        }
    }
    let u = solve_prescribed(&k, &rhs, &fixed);
    for (&(n, d), &row) in &map {
        let c = names.iter().position(|x| *x == d).unwrap();
        let want = exact(model.coords[n], c);
        assert!((u[row] - want).abs() < 1e-10, "{:?} {:?} node {n} {d}: {} vs {want}", f, mode, u[row]);
    }
}

#[test]
fn uniform_traction_gives_the_exact_uniaxial_field() {
    for ty in [ElemType::Tri3, ElemType::Tri6, ElemType::Qua4, ElemType::Qua8] {
        for mode in [Mode::PlanCont, Mode::PlanDefo] {
            uniaxial(Formulation::Solid, mode, plane_mesh(ty, 2, true), 0);
        }
        // AXIS: pull along z (the second coordinate) on the top edge.
        uniaxial(Formulation::Solid, Mode::Axis, plane_mesh(ty, 2, false), 1);
    }
    uniaxial(Formulation::Q4ri, Mode::PlanCont, plane_mesh(ElemType::Qua4, 2, false), 0);
    for ty in [ElemType::Cub8, ElemType::Tet4, ElemType::Pri6] {
        uniaxial(Formulation::Solid, Mode::Trid, solid_mesh(ty, 2), 0);
        uniaxial(Formulation::Solid, Mode::Trid, solid_mesh(ty, 2), 2);
    }
}

#[test]
fn deck_09_qua4_plane_stress_square() {
    // 2 × 2 QUA4 on the unit square, E = 100, ν = 0.25, nodal forces
    // 0.25 / 0.5 / 0.25 on the right edge: ux = x/100, uy = −0.25 y/100.
    let coords: Vec<[f64; 3]> = (0..9).map(|i| [0.5 * (i % 3) as f64, 0.5 * (i / 3) as f64, 0.0]).collect();
    let elems = [(0, 0), (1, 0), (0, 1), (1, 1)]
        .iter()
        .map(|&(i, j)| {
            let a = i + 3 * j;
            (ElemType::Qua4, vec![a, a + 1, a + 4, a + 3])
        })
        .collect();
    let model = Model { mode: Mode::PlanCont, f: Formulation::Solid, coords, elems, mat: mat(100.0, 0.25) };
    let (map, k) = assemble(&model);
    let mut rhs = vec![0.0; map.len()];
    for (n, v) in [(2, 0.25), (5, 0.5), (8, 0.25)] {
        rhs[map[&(n, "UX")]] = v;
    }
    let mut fixed: BTreeMap<usize, f64> = [0, 3, 6].iter().map(|&n| (map[&(n, "UX")], 0.0)).collect();
    fixed.insert(map[&(0, "UY")], 0.0);
    let u = solve_prescribed(&k, &rhs, &fixed);
    for (n, p) in model.coords.iter().enumerate() {
        assert!((u[map[&(n, "UX")]] - p[0] / 100.0).abs() < 1e-12);
        assert!((u[map[&(n, "UY")]] + 0.25 * p[1] / 100.0).abs() < 1e-12);
    }
    // DIM3 scales the plane-stress stiffness and nothing else.
    let x: Vec<[f64; 3]> = vec![[0.0; 3], [1.0, 0.0, 0.0], [1.2, 0.9, 0.0], [0.1, 1.0, 0.0]];
    let k1 = stiffness(Formulation::Solid, ElemType::Qua4, Mode::PlanCont, &x, &mat(100.0, 0.25)).unwrap();
    let thick = super::element::Material { dim3: Some(0.3), ..mat(100.0, 0.25) };
    let k3 = stiffness(Formulation::Solid, ElemType::Qua4, Mode::PlanCont, &x, &thick).unwrap();
    assert!(k1.k.iter().zip(&k3.k).all(|(a, b)| (0.3 * a - b).abs() < 1e-12));
    let kd = stiffness(Formulation::Solid, ElemType::Qua4, Mode::PlanDefo, &x, &thick).unwrap();
    let kd1 = stiffness(Formulation::Solid, ElemType::Qua4, Mode::PlanDefo, &x, &mat(100.0, 0.25)).unwrap();
    assert_eq!(kd.k, kd1.k);
}

#[test]
fn dof_and_dual_names() {
    use Formulation::*;
    let cases: [(Formulation, Mode, &[&str], &[&str]); 6] = [
        (Pout, Mode::PlanCont, &["UX", "UY", "RZ"], &["FX", "FY", "MZ"]),
        (Timo, Mode::Trid, &["UX", "UY", "UZ", "RX", "RY", "RZ"], &["FX", "FY", "FZ", "MX", "MY", "MZ"]),
        (Solid, Mode::Axis, &["UR", "UZ"], &["FR", "FZ"]),
        (Q4ri, Mode::PlanDefo, &["UX", "UY"], &["FX", "FY"]),
        (Barr, Mode::Trid, &["UX", "UY", "UZ"], &["FX", "FY", "FZ"]),
        (Solid, Mode::Trid, &["UX", "UY", "UZ"], &["FX", "FY", "FZ"]),
    ];
    for (f, m, d, du) in cases {
        assert_eq!(super::element::node_dofs(f, m).unwrap(), d);
        assert_eq!(node_duals(f, m).unwrap(), du);
    }
    assert!(node_duals(Barr, Mode::Axis).is_err());
}
