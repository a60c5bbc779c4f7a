//! XC8R: reduction to CUB8, zero-energy modes of the enrichment, the tip
//! functions' gradients, and blocks cut right through by a plane crack
//! where the Heaviside enrichment alone gives the exact solution.

use super::element::{Formulation, Mode};
use super::mesh::ElemType;
use super::quadrature::hexa;
use super::test_support::{dense_solve, mat, solve_prescribed};
use super::xfem_c8r::{displacement_at, field, internal_forces, mass, stiffness, Crack, Field};
use std::collections::{BTreeMap, HashMap};

/// The 8 nodes of the box [lo, hi] in CUB8 order (bottom face
/// counter-clockwise, then the top one).
fn boxel(lo: [f64; 3], hi: [f64; 3]) -> Vec<[f64; 3]> {
    let mut v = Vec::new();
    for z in [lo[2], hi[2]] {
        for (x, y) in [(lo[0], lo[1]), (hi[0], lo[1]), (hi[0], hi[1]), (lo[0], hi[1])] {
            v.push([x, y, z]);
        }
    }
    v
}

fn distorted() -> Vec<[f64; 3]> {
    let mut x = boxel([0.0; 3], [1.0, 0.8, 1.2]);
    x[2] = [1.1, 0.9, -0.05];
    x[5] = [0.95, 0.1, 1.3];
    x
}

fn kv(k: &[f64], v: &[f64]) -> Vec<f64> {
    let n = v.len();
    (0..n).map(|i| (0..n).map(|j| k[i * n + j] * v[j]).sum()).collect()
}

fn norm(v: &[f64]) -> f64 {
    v.iter().map(|a| a * a).sum::<f64>().sqrt()
}

#[test]
fn unenriched_element_is_a_cub8() {
    let x = distorted();
    let m = mat(2e5, 0.3);
    let k = stiffness(&x, &Crack::none(), &m).unwrap();
    let c = super::solid::stiffness(Formulation::Solid, ElemType::Cub8, Mode::Trid, &x, &m).unwrap();
    assert_eq!(k.dofs, c.dofs);
    let scale = c.k.iter().fold(0.0f64, |a, b| a.max(b.abs()));
    for (a, b) in k.k.iter().zip(&c.k) {
        assert!((a - b).abs() < 1e-12 * scale);
    }
}

/// A cut element with every node enriched: rigid motions of the whole,
/// and a rigid slip of one side against the other, cost no energy; a
/// stretch does.
#[test]
fn rigid_and_sliding_modes_have_no_energy() {
    let x = distorted();
    let mut c = Crack::none();
    for (i, p) in x.iter().enumerate() {
        c.normal[i] = p[0] + 0.4 * p[1] - 0.2 * p[2] - 0.55;
        c.tangent[i] = -1.0;
        c.heaviside[i] = true;
    }
    let m = mat(2e5, 0.3);
    let k = stiffness(&x, &c, &m).unwrap();
    let dofs = &k.dofs;
    let scale = k.k.iter().fold(0.0f64, |a, b| a.max(b.abs()));
    let mode = |f: &dyn Fn(usize, &str) -> f64| -> Vec<f64> { dofs.iter().map(|&(i, d)| f(i, d)).collect() };
    let comp = |d: &str| "XYZ".find(&d[d.len() - 1..]).unwrap();
    for d in 0..3 {
        let t = mode(&|_, n| if n.starts_with('U') && comp(n) == d { 1.0 } else { 0.0 });
        assert!(norm(&kv(&k.k, &t)) < 1e-10 * scale);
        let s = mode(&|_, n| if n.starts_with('A') && comp(n) == d { 1.0 } else { 0.0 });
        assert!(norm(&kv(&k.k, &s)) < 1e-10 * scale);
    }
    // Rotation about z of both sides, and of one side only (U = A = ω×x/2).
    let rot = |i: usize, n: &str| match comp(n) {
        0 => -x[i][1],
        1 => x[i][0],
        _ => 0.0,
    };
    let r = mode(&|i, n| if n.starts_with('U') { rot(i, n) } else { 0.0 });
    assert!(norm(&kv(&k.k, &r)) < 1e-10 * scale);
    let half = mode(&|i, n| rot(i, n) / 2.0);
    assert!(norm(&kv(&k.k, &half)) < 1e-10 * scale);
    let stretch = mode(&|i, n| if n == "UX" { x[i][0] } else { 0.0 });
    assert!(norm(&kv(&k.k, &stretch)) > 1e-3 * scale);
    // Symmetric, and the mass of a translation is ρ·volume on both sides.
    let n = dofs.len();
    for i in 0..n {
        for j in 0..n {
            assert!((k.k[i * n + j] - k.k[j * n + i]).abs() < 1e-10 * scale);
        }
    }
    let mut mm = m.clone();
    mm.rho = Some(2.0);
    let ms = mass(&boxel([0.0; 3], [1.0, 0.8, 1.2]), &c, &mm).unwrap();
    let t = mode(&|_, n| if n == "UY" { 1.0 } else { 0.0 });
    let mt: f64 = kv(&ms.k, &t).iter().zip(&t).map(|(a, b)| a * b).sum();
    assert!((mt - 2.0 * 0.96).abs() < 1e-12);
}

/// With B1 = 1 (resp. B2 = 1) at every node of an element around a
/// straight front, u_x is √r sin θ/2 (resp. √r cos θ/2) exactly: the
/// computed strain EPXX is its analytic x-derivative.
#[test]
fn tip_enrichment_reproduces_the_tip_functions() {
    let x = boxel([-0.5, -0.5, 0.0], [0.5, 0.5, 1.0]);
    let (x0, y0) = (0.13, 0.07);
    let mut c = Crack::none();
    for (i, p) in x.iter().enumerate() {
        c.tangent[i] = p[0] - x0;
        c.normal[i] = p[1] - y0;
        c.tip[i] = true;
    }
    let m = mat(1.0, 0.0);
    for (name, dfdx) in [("B1X", -1.0), ("C1X", 1.0)] {
        let u: Vec<f64> = c.dofs().iter().map(|&(_, d)| if d == name { 1.0 } else { 0.0 }).collect();
        let eps = field(&x, &c, &m, &u, Field::Strain).unwrap();
        let pts = hexa(2);
        assert_eq!(eps.values.len(), pts.len());
        for (e, (xi, _)) in eps.values.iter().zip(&pts) {
            let (px, py) = (xi[0] / 2.0 - x0, xi[1] / 2.0 - y0);
            let r = (px * px + py * py).sqrt();
            let th = py.atan2(px);
            let exact =
                if name == "B1X" { dfdx * (th / 2.0).sin() } else { dfdx * (th / 2.0).cos() } / (2.0 * r.sqrt());
            assert!((e[0] - exact).abs() < 1e-9 * (1.0 + exact.abs()), "{name}: {} vs {exact}", e[0]);
        }
        // The opening across the crack behind the front is 2√r for B1.
        let xi = [-0.8, 2.0 * y0, 0.0];
        let up = displacement_at(&x, &c, &u, xi, Some(1.0)).unwrap();
        let dn = displacement_at(&x, &c, &u, xi, Some(-1.0)).unwrap();
        let r: f64 = x0 + 0.4;
        let jump = if name == "B1X" { 2.0 * r.sqrt() } else { 0.0 };
        assert!((up[0] - dn[0] - jump).abs() < 1e-9, "{name}: {up:?} {dn:?} {jump}");
    }
}

/// An nx×ny×nz mesh of the box [0, l]; returns nodes and elements.
fn block(l: [f64; 3], n: [usize; 3]) -> (Vec<[f64; 3]>, Vec<[usize; 8]>) {
    let id = |i: usize, j: usize, k: usize| i + (n[0] + 1) * (j + (n[1] + 1) * k);
    let mut nodes = Vec::new();
    for k in 0..=n[2] {
        for j in 0..=n[1] {
            for i in 0..=n[0] {
                let f = |a: usize, b: usize, c: f64| c * a as f64 / b as f64;
                nodes.push([f(i, n[0], l[0]), f(j, n[1], l[1]), f(k, n[2], l[2])]);
            }
        }
    }
    let mut elems = Vec::new();
    for k in 0..n[2] {
        for j in 0..n[1] {
            for i in 0..n[0] {
                let q = |k| [id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k)];
                let (b, t) = (q(k), q(k + 1));
                elems.push([b[0], b[1], b[2], b[3], t[0], t[1], t[2], t[3]]);
            }
        }
    }
    (nodes, elems)
}

struct Cracked {
    k: Vec<Vec<f64>>,
    map: HashMap<(usize, &'static str), usize>,
    nodes: Vec<[f64; 3]>,
}

/// Assemble a block crossed right through by the crack whose normal level
/// set is `level`: the nodes of cut elements get the Heaviside enrichment.
fn cracked(level: impl Fn([f64; 3]) -> f64) -> Cracked {
    let (nodes, elems) = block([2.0, 1.0, 1.0], [5, 2, 2]);
    let m = mat(1000.0, 0.25);
    let phi: Vec<f64> = nodes.iter().map(|&p| level(p)).collect();
    let mut enriched = vec![false; nodes.len()];
    for e in &elems {
        if e.iter().any(|&i| phi[i] > 0.0) && e.iter().any(|&i| phi[i] < 0.0) {
            e.iter().for_each(|&i| enriched[i] = true);
        }
    }
    let mut map = HashMap::new();
    let mut crack_of = Vec::new();
    for e in &elems {
        let mut c = Crack::none();
        for (a, &i) in e.iter().enumerate() {
            c.normal[a] = phi[i];
            c.tangent[a] = -10.0;
            c.heaviside[a] = enriched[i];
        }
        for (a, d) in c.dofs() {
            let n = map.len();
            map.entry((e[a], d)).or_insert(n);
        }
        crack_of.push(c);
    }
    let n = map.len();
    let mut k = vec![vec![0.0; n]; n];
    for (e, c) in elems.iter().zip(&crack_of) {
        let x: Vec<[f64; 3]> = e.iter().map(|&i| nodes[i]).collect();
        let ke = stiffness(&x, c, &m).unwrap();
        let g: Vec<usize> = ke.dofs.iter().map(|&(a, d)| map[&(e[a], d)]).collect();
        let nd = g.len();
        for i in 0..nd {
            for j in 0..nd {
                k[g[i]][g[j]] += ke.k[i * nd + j];
            }
        }
    }
    Cracked { k, map, nodes }
}

fn inclined(p: [f64; 3]) -> f64 {
    p[0] + 0.3 * p[2] - 0.97
}

/// Pulled apart across the crack, the two halves separate rigidly: left
/// at rest, right translated by δ, i.e. U = A = δ/2 on the enriched nodes.
#[test]
fn block_cut_through_opens_rigidly() {
    let c = cracked(inclined);
    let delta = 0.01;
    let mut fixed = BTreeMap::new();
    for (&(i, d), &g) in &c.map {
        let x = c.nodes[i][0];
        if d.starts_with('U') && (x == 0.0 || x == 2.0) {
            fixed.insert(g, if d == "UX" && x == 2.0 { delta } else { 0.0 });
        }
    }
    let f = vec![0.0; c.map.len()];
    let u = solve_prescribed(&c.k, &f, &fixed);
    for (&(i, d), &g) in &c.map {
        let enriched = c.map.contains_key(&(i, "AX"));
        let side = if inclined(c.nodes[i]) > 0.0 { delta } else { 0.0 };
        let want = match (d, enriched) {
            ("UX" | "AX", true) => delta / 2.0,
            ("UX", false) => side,
            _ => 0.0,
        };
        assert!((u[g] - want).abs() < 1e-9, "node {i} {d}: {} vs {want}", u[g]);
    }
}

/// Uniaxial stress along y, parallel to the crack plane (whose normal has
/// no y part), leaves the crack closed and traction-free: imposing the
/// uncracked solution on the boundary gives it back inside, with no jump.
#[test]
fn stress_parallel_to_the_crack_is_undisturbed() {
    let c = cracked(inclined);
    let (e, nu, s) = (1000.0, 0.25, 2.0);
    let exact = |p: [f64; 3]| [-nu * s / e * p[0], s / e * p[1], -nu * s / e * p[2]];
    let on_boundary = |p: [f64; 3]| p.iter().zip([2.0, 1.0, 1.0]).any(|(&v, l)| v == 0.0 || v == l);
    let mut fixed = BTreeMap::new();
    for (&(i, d), &g) in &c.map {
        if on_boundary(c.nodes[i]) {
            let k = "XYZ".find(&d[d.len() - 1..]).unwrap();
            fixed.insert(g, if d.starts_with('U') { exact(c.nodes[i])[k] } else { 0.0 });
        }
    }
    let n = c.map.len();
    let u = solve_prescribed(&c.k, &vec![0.0; n], &fixed);
    for (&(i, d), &g) in &c.map {
        let k = "XYZ".find(&d[d.len() - 1..]).unwrap();
        let want = if d.starts_with('U') { exact(c.nodes[i])[k] } else { 0.0 };
        assert!((u[g] - want).abs() < 1e-10, "node {i} {d}: {} vs {want}", u[g]);
    }
    let _ = dense_solve;
}

/// On an element the crack does not cut, the sub-cell rule is the Gauss
/// rule, so BSIG of the stresses at the Gauss points is K u.
#[test]
fn internal_forces_match_the_stiffness_off_the_crack() {
    let x = distorted();
    let m = mat(2e5, 0.3);
    let mut c = Crack::none();
    c.heaviside = [true, false, true, false, false, true, true, false];
    c.normal = [-1.0; 8];
    let nd = c.dofs().len();
    let u: Vec<f64> = (0..nd).map(|i| super::test_support::wobble(i as f64, 0.3) * 1e-3).collect();
    let k = stiffness(&x, &c, &m).unwrap();
    let sig = field(&x, &c, &m, &u, Field::Stress).unwrap();
    let f = internal_forces(&x, &c, &sig).unwrap();
    let ku = kv(&k.k, &u);
    let scale = norm(&ku);
    for (a, b) in f.iter().zip(&ku) {
        assert!((a - b).abs() < 1e-10 * scale);
    }
}
