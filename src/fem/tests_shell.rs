//! Thin shells (COQ3/DKT, COQ4): rigid motions, patch tests in a tilted
//! plane, and the Navier plate deflection.

use super::element::{self, Formulation, Material, Mode};
use super::mesh::ElemType;
use super::shell;
use super::test_support::{assemble, solve_prescribed, Model};
use std::collections::BTreeMap;

fn mat() -> Material {
    Material { youn: Some(210e3), nu: Some(0.3), epai: Some(0.1), ..Default::default() }
}

/// A plane through `o` spanned by the orthonormal a, b (normal a × b).
fn tilted() -> ([f64; 3], [f64; 3], [f64; 3]) {
    let a = [0.6, 0.0, -0.8];
    let b = [0.64, -0.6, 0.48];
    ([1.0, -2.0, 0.5], a, b)
}

fn place(p: [f64; 2]) -> [f64; 3] {
    let (o, a, b) = tilted();
    std::array::from_fn(|k| o[k] + p[0] * a[k] + p[1] * b[k])
}

fn matvec(k: &[f64], u: &[f64]) -> Vec<f64> {
    let n = u.len();
    (0..n).map(|i| (0..n).map(|j| k[i * n + j] * u[j]).sum()).collect()
}

/// Six independent rigid motions of the nodes x: UX UY UZ RX RY RZ per node.
fn rigid(x: &[[f64; 3]]) -> Vec<Vec<f64>> {
    let mut out = Vec::new();
    for m in 0..6 {
        let mut u = Vec::new();
        for p in x {
            let (t, w) = if m < 3 {
                let mut t = [0.0; 3];
                t[m] = 1.0;
                (t, [0.0; 3])
            } else {
                let mut w = [0.0; 3];
                w[m - 3] = 1.0;
                ([w[1] * p[2] - w[2] * p[1], w[2] * p[0] - w[0] * p[2], w[0] * p[1] - w[1] * p[0]], w)
            };
            u.extend(t);
            u.extend(w);
        }
        out.push(u);
    }
    out
}

#[test]
fn rigid_motions_cost_nothing() {
    let tri = [[0.1, 0.2, 0.3], [1.3, 0.1, 0.5], [0.4, 1.1, 0.9]];
    let qua = [place([0.0, 0.0]), place([1.2, 0.1]), place([1.0, 0.9]), place([-0.1, 1.1])];
    for (f, x) in [(Formulation::Coq3, &tri[..]), (Formulation::Dkt, &tri[..]), (Formulation::Coq4, &qua[..])] {
        let ty = shell::geometry(f);
        let k = element::stiffness(f, ty, Mode::Trid, x, &mat()).unwrap();
        let scale = k.k.iter().fold(0.0f64, |a, v| a.max(v.abs()));
        for u in rigid(x) {
            let r = matvec(&k.k, &u);
            let worst = r.iter().fold(0.0f64, |a, v| a.max(v.abs()));
            assert!(worst < 1e-10 * scale, "{:?}: {worst} vs {scale}", f);
        }
        // Symmetric, and positive on a pure drilling rotation.
        let n = 6 * x.len();
        for i in 0..n {
            for j in 0..n {
                assert!((k.k[i * n + j] - k.k[j * n + i]).abs() < 1e-9 * scale);
            }
        }
    }
}

/// Exact displacement of a uniform membrane strain plus a uniform
/// curvature, in the tilted plane's coordinates (s, t): u_s = εs·s + γ/2·t,
/// u_t = γ/2·s + εt·t, w = −½(κs s² + κt t² + κst s t).
fn patch_field(p: [f64; 2]) -> [f64; 6] {
    let (es, et, g) = (1e-3, -4e-4, 6e-4);
    let (ks, kt, kst) = (2e-3, -1e-3, 5e-4);
    let [s, t] = p;
    let (us, ut) = (es * s + 0.5 * g * t, 0.5 * g * s + et * t);
    let w = -0.5 * (ks * s * s + kt * t * t + kst * s * t);
    // Rotation vector: θs = w,t, θt = −w,s, θn = 0 (no in-plane rotation).
    let (ws, wt) = (-(ks * s + 0.5 * kst * t), -(kt * t + 0.5 * kst * s));
    let (th_s, th_t) = (wt, -ws);
    let (_, a, b) = tilted();
    let n = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    let mut out = [0.0; 6];
    for k in 0..3 {
        out[k] = us * a[k] + ut * b[k] + w * n[k];
        out[3 + k] = th_s * a[k] + th_t * b[k];
    }
    out
}

/// A distorted patch of elements around interior nodes, in the tilted
/// plane: the boundary nodes take the exact field, the interior ones must
/// find it, and every point must give the uniform strains.
fn patch(f: Formulation, pts: &[[f64; 2]], elems: Vec<Vec<usize>>, interior: &[usize]) {
    let ty = shell::geometry(f);
    let model = Model {
        mode: Mode::Trid,
        f,
        coords: pts.iter().map(|p| place(*p)).collect(),
        elems: elems.iter().map(|e| (ty, e.clone())).collect(),
        mat: mat(),
    };
    let (map, k) = assemble(&model);
    let names = ["UX", "UY", "UZ", "RX", "RY", "RZ"];
    let mut fixed = BTreeMap::new();
    for (n, p) in pts.iter().enumerate() {
        if interior.contains(&n) {
            continue;
        }
        let v = patch_field(*p);
        for (c, d) in names.iter().enumerate() {
            fixed.insert(map[&(n, *d)], v[c]);
        }
    }
    let u = solve_prescribed(&k, &vec![0.0; map.len()], &fixed);
    for &n in interior {
        let v = patch_field(pts[n]);
        for (c, d) in names.iter().enumerate() {
            let got = u[map[&(n, *d)]];
            assert!((got - v[c]).abs() < 1e-10, "{:?} node {n} {d}: {got} vs {}", f, v[c]);
        }
    }
    for e in &elems {
        let x: Vec<[f64; 3]> = e.iter().map(|&n| model.coords[n]).collect();
        let ue: Vec<f64> = e.iter().flat_map(|&n| names.map(|d| u[map[&(n, d)]])).collect();
        let eps = element::strain(f, ty, Mode::Trid, &x, &model.mat, &ue).unwrap();
        // The element frame's x1 is global X projected: (s, t) differ from
        // (1, 2) by a rotation, so compare invariants of the two tensors.
        for v in &eps.values {
            let inv = |a: f64, b: f64, g: f64| (a + b, a * b - 0.25 * g * g);
            let (m1, m2) = inv(v[0], v[1], v[2]);
            assert!((m1 - 6e-4).abs() < 1e-12 && (m2 - (-4e-7 - 0.25 * 3.6e-7)).abs() < 1e-14, "{:?} {v:?}", f);
            let (b1, b2) = inv(v[3], v[4], v[5]);
            assert!((b1 - 1e-3).abs() < 1e-12 && (b2 - (-2e-6 - 0.25 * 2.5e-7)).abs() < 1e-14, "{:?} {v:?}", f);
        }
    }
}

#[test]
fn patch_tests_in_a_tilted_plane() {
    let pts = [[0.0, 0.0], [2.0, 0.0], [2.2, 1.8], [-0.1, 2.0], [0.9, 0.7], [1.4, 1.1]];
    let tris = vec![vec![0, 1, 4], vec![1, 5, 4], vec![1, 2, 5], vec![2, 3, 5], vec![3, 4, 5], vec![3, 0, 4]];
    patch(Formulation::Dkt, &pts, tris.clone(), &[4, 5]);
    patch(Formulation::Coq3, &pts, tris, &[4, 5]);
    let pts =
        [[0.0, 0.0], [1.1, -0.1], [2.0, 0.0], [2.1, 0.9], [2.0, 2.0], [0.8, 2.2], [0.0, 2.0], [-0.2, 1.1], [0.9, 1.2]];
    let quads = vec![vec![0, 1, 8, 7], vec![1, 2, 3, 8], vec![8, 3, 4, 5], vec![7, 8, 5, 6]];
    patch(Formulation::Coq4, &pts, quads, &[8]);
}

/// Simply supported square plate under uniform pressure: Navier's centre
/// deflection 0.00406 q a⁴/D, within 1% on a 16×16 mesh.
#[test]
fn navier_plate() {
    for f in [Formulation::Dkt, Formulation::Coq4] {
        let nd = 16;
        let (a, t, e, nu, q) = (1.0, 0.01, 1e6, 0.3, 1.0);
        let m = Material { youn: Some(e), nu: Some(nu), epai: Some(t), ..Default::default() };
        let id = |i: usize, j: usize| i * (nd + 1) + j;
        let coords: Vec<[f64; 3]> = (0..=nd)
            .flat_map(|i| (0..=nd).map(move |j| [a * j as f64 / nd as f64, a * i as f64 / nd as f64, 0.0]))
            .collect();
        let mut elems = Vec::new();
        for i in 0..nd {
            for j in 0..nd {
                let (p, r, s, w) = (id(i, j), id(i, j + 1), id(i + 1, j + 1), id(i + 1, j));
                if f == Formulation::Coq4 {
                    elems.push((ElemType::Qua4, vec![p, r, s, w]));
                } else {
                    elems.push((ElemType::Tri3, vec![p, r, s]));
                    elems.push((ElemType::Tri3, vec![p, s, w]));
                }
            }
        }
        let model = Model { mode: Mode::Trid, f, coords, elems, mat: m };
        let (map, k) = assemble(&model);
        let mut load = vec![0.0; map.len()];
        for (_, e) in &model.elems {
            let x: Vec<[f64; 3]> = e.iter().map(|&n| model.coords[n]).collect();
            for (n, fv) in e.iter().zip(shell::pressure_load(f, &x, -q).unwrap()) {
                load[map[&(*n, "UZ")]] += fv[2];
            }
        }
        let mut fixed = BTreeMap::new();
        for (n, p) in model.coords.iter().enumerate() {
            // Membrane and drilling held everywhere; UZ on the edges.
            for d in ["UX", "UY", "RZ"] {
                fixed.insert(map[&(n, d)], 0.0);
            }
            if p[0] == 0.0 || p[1] == 0.0 || p[0] == a || p[1] == a {
                fixed.insert(map[&(n, "UZ")], 0.0);
            }
        }
        let u = solve_prescribed(&k, &load, &fixed);
        let d = e * t.powi(3) / (12.0 * (1.0 - nu * nu));
        let exact = -0.00406235 * q * a.powi(4) / d;
        let w = u[map[&(id(nd / 2, nd / 2), "UZ")]];
        assert!(((w - exact) / exact).abs() < 0.01, "{:?}: {w} vs {exact}", f);
    }
}
