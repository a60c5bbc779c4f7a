//! Small dense assembly and solve used by the element tests.

use super::element::{stiffness, Formulation, Material, Mode};
use super::mesh::ElemType;
use std::collections::BTreeMap;

pub struct Model {
    pub mode: Mode,
    pub f: Formulation,
    pub coords: Vec<[f64; 3]>,
    pub elems: Vec<(ElemType, Vec<usize>)>,
    pub mat: Material,
}

pub type DofMap = BTreeMap<(usize, &'static str), usize>;

/// Global dense stiffness and the (node, name) → row map.
pub fn assemble(m: &Model) -> (DofMap, Vec<Vec<f64>>) {
    let mut map = DofMap::new();
    let mut mats = Vec::new();
    for (ty, conn) in &m.elems {
        let x: Vec<[f64; 3]> = conn.iter().map(|&n| m.coords[n]).collect();
        let em = stiffness(m.f, *ty, m.mode, &x, &m.mat).unwrap();
        for &(ln, d) in &em.dofs {
            let next = map.len();
            map.entry((conn[ln], d)).or_insert(next);
        }
        mats.push((conn.clone(), em));
    }
    let n = map.len();
    let mut k = vec![vec![0.0; n]; n];
    for (conn, em) in mats {
        let idx: Vec<usize> = em.dofs.iter().map(|&(ln, d)| map[&(conn[ln], d)]).collect();
        let nd = idx.len();
        for i in 0..nd {
            for j in 0..nd {
                k[idx[i]][idx[j]] += em.k[i * nd + j];
            }
        }
    }
    (map, k)
}

/// Solve K u = f with some rows prescribed (value known). Returns u.
pub fn solve_prescribed(k: &[Vec<f64>], f: &[f64], fixed: &BTreeMap<usize, f64>) -> Vec<f64> {
    let n = f.len();
    let free: Vec<usize> = (0..n).filter(|i| !fixed.contains_key(i)).collect();
    let mut a: Vec<Vec<f64>> = free.iter().map(|&i| free.iter().map(|&j| k[i][j]).collect()).collect();
    let mut b: Vec<f64> = free.iter().map(|&i| f[i] - fixed.iter().map(|(&j, &v)| k[i][j] * v).sum::<f64>()).collect();
    let x = dense_solve(&mut a, &mut b);
    let mut u = vec![0.0; n];
    for (&j, &v) in fixed {
        u[j] = v;
    }
    for (p, &i) in free.iter().enumerate() {
        u[i] = x[p];
    }
    u
}

// Index loops read best for elimination on rows k and i of one matrix.
#[allow(clippy::needless_range_loop)]
pub fn dense_solve(a: &mut [Vec<f64>], b: &mut [f64]) -> Vec<f64> {
    let n = b.len();
    for k in 0..n {
        let p = (k..n).max_by(|&i, &j| a[i][k].abs().total_cmp(&a[j][k].abs())).unwrap();
        assert!(a[p][k].abs() > 1e-300, "singular test system");
        a.swap(k, p);
        b.swap(k, p);
        for i in k + 1..n {
            let r = a[i][k] / a[k][k];
            if r != 0.0 {
                for j in k..n {
                    a[i][j] -= r * a[k][j];
                }
                b[i] -= r * b[k];
            }
        }
    }
    let mut x = vec![0.0; n];
    for k in (0..n).rev() {
        x[k] = (b[k] - (k + 1..n).map(|j| a[k][j] * x[j]).sum::<f64>()) / a[k][k];
    }
    x
}

/// Element dof values of a global vector.
pub fn gather(m: &Model, map: &DofMap, conn: &[usize], ty: ElemType, u: &[f64]) -> Vec<f64> {
    let names = super::element::node_dofs(m.f, m.mode).unwrap();
    let _ = ty;
    conn.iter().flat_map(|&n| names.iter().map(move |&d| u[map[&(n, d)]])).collect()
}

pub fn mat(e: f64, nu: f64) -> Material {
    Material { youn: Some(e), nu: Some(nu), ..Default::default() }
}

/// Deterministic "random" perturbation in [-1, 1].
pub fn wobble(a: f64, b: f64) -> f64 {
    (12.9898 * a + 78.233 * b).sin()
}
