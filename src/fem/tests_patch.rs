//! Patch tests: distorted meshes, a linear displacement imposed on the
//! boundary, the interior solved; interior displacements and the stress at
//! every Gauss point must be exact. A wrong B matrix, Jacobian, weight or
//! elasticity matrix fails here.

use super::element::{strain, stress, Formulation, Mode};
use super::mesh::ElemType;
use super::test_support::*;
use std::collections::{BTreeMap, HashMap};

/// Node coordinates and (geometry, connectivity) of each element.
pub type PatchMesh = (Vec<[f64; 3]>, Vec<(ElemType, Vec<usize>)>);

/// Structured (n×n) patch of `ty` on [0.5, 2.5] × [0, 2] with the interior
/// nodes moved; with `curved`, the interior mid-side nodes move off their
/// chord too.
pub fn plane_mesh(ty: ElemType, n: usize, curved: bool) -> PatchMesh {
    let h = 2.0 / n as f64;
    let mut coords = Vec::new();
    let id = |i: usize, j: usize| i + (n + 1) * j;
    for j in 0..=n {
        for i in 0..=n {
            let mut p = [0.5 + h * i as f64, h * j as f64, 0.0];
            if i > 0 && i < n && j > 0 && j < n {
                p[0] += 0.2 * h * wobble(i as f64, j as f64);
                p[1] += 0.2 * h * wobble(j as f64 + 0.3, i as f64 + 1.7);
            }
            coords.push(p);
        }
    }
    let mut mids: HashMap<(usize, usize), usize> = HashMap::new();
    let mut mid = |a: usize, b: usize, coords: &mut Vec<[f64; 3]>| -> usize {
        let key = (a.min(b), a.max(b));
        *mids.entry(key).or_insert_with(|| {
            let (pa, pb) = (coords[a], coords[b]);
            let mut m = [(pa[0] + pb[0]) / 2.0, (pa[1] + pb[1]) / 2.0, 0.0];
            let on_boundary =
                |p: [f64; 3]| p[0] < 0.5 + 1e-12 || p[0] > 2.5 - 1e-12 || p[1] < 1e-12 || p[1] > 2.0 - 1e-12;
            let boundary_edge = on_boundary(pa) && on_boundary(pb) && (pa[0] == pb[0] || pa[1] == pb[1]);
            if curved && !boundary_edge {
                m[0] += 0.05 * h * wobble(m[0], m[1]);
                m[1] += 0.05 * h * wobble(m[1], m[0] + 0.5);
            }
            coords.push(m);
            coords.len() - 1
        })
    };
    let mut elems = Vec::new();
    for j in 0..n {
        for i in 0..n {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            match ty {
                ElemType::Qua4 => elems.push((ty, vec![a, b, c, d])),
                ElemType::Tri3 => {
                    elems.push((ty, vec![a, b, c]));
                    elems.push((ty, vec![a, c, d]));
                }
                ElemType::Qua8 => {
                    let (m1, m2, m3, m4) = (
                        mid(a, b, &mut coords),
                        mid(b, c, &mut coords),
                        mid(c, d, &mut coords),
                        mid(d, a, &mut coords),
                    );
                    elems.push((ty, vec![a, m1, b, m2, c, m3, d, m4]));
                }
                ElemType::Tri6 => {
                    for [p, q, r] in [[a, b, c], [a, c, d]] {
                        let (m1, m2, m3) = (mid(p, q, &mut coords), mid(q, r, &mut coords), mid(r, p, &mut coords));
                        elems.push((ty, vec![p, m1, q, m2, r, m3]));
                    }
                }
                _ => unreachable!(),
            }
        }
    }
    (coords, elems)
}

/// Structured n×n×n patch on [0.5, 2.5] × [0, 2] × [0, 2], interior nodes
/// moved, hexahedra split into Kuhn tetrahedra (mixed orientations) or two
/// prisms as asked.
pub fn solid_mesh(ty: ElemType, n: usize) -> PatchMesh {
    let h = 2.0 / n as f64;
    let id = |i: usize, j: usize, k: usize| i + (n + 1) * (j + (n + 1) * k);
    let mut coords = Vec::new();
    for k in 0..=n {
        for j in 0..=n {
            for i in 0..=n {
                let mut p = [0.5 + h * i as f64, h * j as f64, h * k as f64];
                if [i, j, k].iter().all(|&v| v > 0 && v < n) {
                    for (c, pc) in p.iter_mut().enumerate() {
                        *pc += 0.2 * h * wobble(i as f64 + c as f64, j as f64 * 1.3 + k as f64);
                    }
                }
                coords.push(p);
            }
        }
    }
    let mut elems = Vec::new();
    for k in 0..n {
        for j in 0..n {
            for i in 0..n {
                let c = |dx: usize, dy: usize, dz: usize| id(i + dx, j + dy, k + dz);
                let hex = vec![
                    c(0, 0, 0),
                    c(1, 0, 0),
                    c(1, 1, 0),
                    c(0, 1, 0),
                    c(0, 0, 1),
                    c(1, 0, 1),
                    c(1, 1, 1),
                    c(0, 1, 1),
                ];
                match ty {
                    ElemType::Cub8 => elems.push((ty, hex)),
                    ElemType::Pri6 => {
                        elems.push((ty, vec![hex[0], hex[1], hex[2], hex[4], hex[5], hex[6]]));
                        elems.push((ty, vec![hex[0], hex[2], hex[3], hex[4], hex[6], hex[7]]));
                    }
                    ElemType::Tet4 => {
                        for perm in [[0, 1, 2], [0, 2, 1], [1, 0, 2], [1, 2, 0], [2, 0, 1], [2, 1, 0]] {
                            let mut v = [0usize; 3];
                            let mut tet = vec![c(0, 0, 0)];
                            for &ax in &perm {
                                v[ax] = 1;
                                tet.push(c(v[0], v[1], v[2]));
                            }
                            elems.push((ty, tet));
                        }
                    }
                    _ => unreachable!(),
                }
            }
        }
    }
    (coords, elems)
}

/// Linear fields used by the tests: u(x) and its constant strain in the
/// mode's order.
fn field(mode: Mode, p: [f64; 3]) -> Vec<f64> {
    let [x, y, z] = p;
    match mode {
        Mode::PlanCont | Mode::PlanDefo => {
            vec![0.1 + 0.02 * x - 0.03 * y, -0.05 + 0.04 * x + 0.01 * y]
        }
        // Axisymmetric fields with constant strain: u_r ∝ r, u_z affine in z.
        Mode::Axis => vec![0.02 * x, 0.1 - 0.03 * y],
        Mode::Trid => vec![
            0.1 + 0.02 * x - 0.03 * y + 0.015 * z,
            -0.05 + 0.04 * x + 0.01 * y - 0.02 * z,
            0.03 - 0.01 * x + 0.025 * y + 0.005 * z,
        ],
        // Fourier harmonics have their own deck (elements/fourier_solid).
        Mode::Fourier(_) => unreachable!("the patch tests run in the plane, axisymmetric and 3D modes"),
    }
}

/// Exact stresses, written out independently of `material::elasticity`.
fn exact_stress(mode: Mode, e: f64, nu: f64) -> Vec<f64> {
    let g = e / (2.0 * (1.0 + nu));
    let lam = e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    let iso = |eps: [f64; 3]| -> [f64; 3] {
        let tr = eps[0] + eps[1] + eps[2];
        [lam * tr + 2.0 * g * eps[0], lam * tr + 2.0 * g * eps[1], lam * tr + 2.0 * g * eps[2]]
    };
    match mode {
        Mode::PlanCont => {
            let (exx, eyy, gxy) = (0.02, 0.01, 0.01);
            let c = e / (1.0 - nu * nu);
            vec![c * (exx + nu * eyy), c * (eyy + nu * exx), 0.0, g * gxy]
        }
        Mode::PlanDefo => {
            let s = iso([0.02, 0.01, 0.0]);
            vec![s[0], s[1], s[2], g * 0.01]
        }
        Mode::Axis => {
            // rr, zz, θθ
            let s = iso([0.02, -0.03, 0.02]);
            vec![s[0], s[1], s[2], 0.0]
        }
        Mode::Trid => {
            let s = iso([0.02, 0.01, 0.005]);
            vec![s[0], s[1], s[2], g * (-0.03 + 0.04), g * (0.015 - 0.01), g * (-0.02 + 0.025)]
        }
        Mode::Fourier(_) => unreachable!("the patch tests run in the plane, axisymmetric and 3D modes"),
    }
}

fn patch(f: Formulation, ty: ElemType, mode: Mode, coords: Vec<[f64; 3]>, elems: Vec<(ElemType, Vec<usize>)>) {
    let (e, nu) = (200.0, 0.3);
    let mut mat = mat(e, nu);
    mat.dim3 = Some(0.7);
    let model = Model { mode, f, coords, elems, mat };
    let (map, k) = assemble(&model);
    let (lo, hi) = model.coords.iter().fold(([f64::MAX; 3], [f64::MIN; 3]), |(mut lo, mut hi), p| {
        for c in 0..3 {
            lo[c] = lo[c].min(p[c]);
            hi[c] = hi[c].max(p[c]);
        }
        (lo, hi)
    });
    let dims = if mode == Mode::Trid { 3 } else { 2 };
    let boundary = |p: [f64; 3]| (0..dims).any(|c| (p[c] - lo[c]).abs() < 1e-12 || (p[c] - hi[c]).abs() < 1e-12);
    let mut fixed = BTreeMap::new();
    let mut interior = Vec::new();
    for (&(node, d), &row) in &map {
        let ci = map.range((node, "")..(node, d)).count();
        let exact = field(mode, model.coords[node])[ci];
        if boundary(model.coords[node]) {
            fixed.insert(row, exact);
        } else {
            interior.push((row, exact));
        }
    }
    assert!(!interior.is_empty());
    let u = solve_prescribed(&k, &vec![0.0; map.len()], &fixed);
    for (row, exact) in interior {
        assert!(
            (u[row] - exact).abs() < 1e-10,
            "{} {:?} {}: interior dof {} vs {}",
            ty.name(),
            mode,
            f.name(),
            u[row],
            exact
        );
    }
    let want = exact_stress(mode, e, nu);
    for (ty, conn) in &model.elems {
        let x: Vec<[f64; 3]> = conn.iter().map(|&n| model.coords[n]).collect();
        let ue = gather(&model, &map, conn, *ty, &u);
        let s = stress(f, *ty, mode, &x, &model.mat, &ue).unwrap();
        assert_eq!(s.values.len(), super::element::gauss_points(f, *ty).len());
        for v in &s.values {
            for (c, (a, b)) in v.iter().zip(&want).enumerate() {
                assert!((a - b).abs() < 1e-10, "{} {:?}: {} = {a} vs {b}", ty.name(), mode, s.comps[c]);
            }
        }
        let eps = strain(f, *ty, mode, &x, &model.mat, &ue).unwrap();
        if mode == Mode::PlanCont {
            // Out-of-plane strain of plane stress: -ν/(1-ν)(εxx+εyy).
            assert!((eps.get("EPZZ", 0).unwrap() + nu / (1.0 - nu) * 0.03).abs() < 1e-12);
        }
    }
}

#[test]
fn patch_tests_plane_and_axisymmetric() {
    for mode in [Mode::PlanCont, Mode::PlanDefo, Mode::Axis] {
        for ty in [ElemType::Tri3, ElemType::Qua4, ElemType::Tri6, ElemType::Qua8] {
            // Curved interior edges only in the plane modes: the AXIS hoop
            // term N/r is not polynomial on a curved isoparametric element.
            let (c, e) = plane_mesh(ty, 3, mode != Mode::Axis);
            patch(Formulation::Solid, ty, mode, c, e);
        }
        let (c, e) = plane_mesh(ElemType::Qua4, 3, false);
        if mode != Mode::Axis {
            patch(Formulation::Q4ri, ElemType::Qua4, mode, c, e);
        }
    }
}

#[test]
fn patch_tests_3d() {
    for ty in [ElemType::Cub8, ElemType::Tet4, ElemType::Pri6] {
        let (c, e) = solid_mesh(ty, 3);
        patch(Formulation::Solid, ty, Mode::Trid, c, e);
    }
}
