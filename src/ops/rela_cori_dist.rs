//! `RELA 'CORI' 'DEPL' GEO1` without rotations: the nodes of GEO1 move as
//! a rigid body because the distances between them stay constant, to first
//! order: `(u_i − u_j)·(x_i − x_j) = 0` (rela.notice).
//!
//! All the pairs would be a redundant set of conditions. A rigid body has 6
//! motions in 3D (3 in the plane), so n nodes need exactly 3n − 6 (2n − 3)
//! independent conditions: the edges of a reference tetrahedron (triangle)
//! of non-coplanar (non-aligned) nodes, then, for every other node, its
//! distances to the three (two) reference nodes that fix it best.

use super::bc::mult_node;
use super::mesh::req_geo;
use super::{dofs, Args};
use crate::error::Result;
use crate::eval::Interp;
use crate::solve::Kind;
use crate::value::rigidity::{CondRow, Subtype};
use crate::value::{Rigidite, Value};
use std::rc::Rc;

pub(super) fn rela_cori_distances(it: &mut Interp, a: &mut Args, kind: Kind) -> Result<Vec<Value>> {
    let nodes = req_geo(a)?.node_list();
    let tr: Vec<String> = dofs::translations(it).iter().map(|s| s.to_string()).collect();
    let dim = tr.len();
    if dim != 2 && dim != 3 {
        return Err(a.err("CORI: rigid links are available in 3D and in the plane modes"));
    }
    let x: Vec<[f64; 3]> = nodes.iter().map(|n| it.nodes.get(*n)).collect();
    let refs = reference_nodes(&x, dim).ok_or_else(|| {
        a.err(if dim == 3 {
            "CORI: a rigid link without rotations needs at least 4 non-coplanar nodes"
        } else {
            "CORI: a rigid link without rotations needs at least 3 non-aligned nodes"
        })
    })?;
    let mut rig = Rigidite::new(Subtype::Blocage);
    let mut link = |it: &mut Interp, i: usize, j: usize| {
        let d: Vec<f64> = (0..dim).map(|c| x[i][c] - x[j][c]).collect();
        let l = d.iter().map(|v| v * v).sum::<f64>().sqrt();
        let mut row = Vec::with_capacity(2 * dim);
        for c in 0..dim {
            if d[c] != 0.0 {
                row.push((nodes[i], tr[c].clone(), d[c] / l));
                row.push((nodes[j], tr[c].clone(), -d[c] / l));
            }
        }
        let m = mult_node(it, nodes[i]);
        rig.conds.push(CondRow::new(m, row, kind));
    };
    for (k, &i) in refs.iter().enumerate() {
        for &j in &refs[..k] {
            link(it, i, j);
        }
    }
    for i in 0..nodes.len() {
        if refs.contains(&i) {
            continue;
        }
        for j in best_fix(&x, i, &refs, dim) {
            link(it, i, j);
        }
    }
    Ok(vec![Value::Rigi(Rc::new(rig))])
}

fn diff(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

/// Reference nodes spanning the space: the first node, the farthest from
/// it, the farthest from their line, (in 3D) the farthest from their
/// plane. None when the nodes are aligned (coplanar in 3D).
fn reference_nodes(x: &[[f64; 3]], dim: usize) -> Option<Vec<usize>> {
    let far = |f: &dyn Fn([f64; 3]) -> f64| -> (usize, f64) {
        x.iter().enumerate().map(|(i, p)| (i, f(*p))).fold((0, -1.0), |b, c| if c.1 > b.1 { c } else { b })
    };
    let a = *x.first()?;
    let (b, dab) = far(&|p| dot(diff(p, a), diff(p, a)).sqrt());
    if dab <= 0.0 {
        return None;
    }
    let ab = diff(x[b], a);
    let (c, dc) = far(&|p| dot(cross(ab, diff(p, a)), cross(ab, diff(p, a))).sqrt() / dab);
    if dc <= 1e-10 * dab {
        return None;
    }
    if dim == 2 {
        return Some(vec![0, b, c]);
    }
    let n = cross(ab, diff(x[c], a));
    let nl = dot(n, n).sqrt();
    let (d, dd) = far(&|p| dot(n, diff(p, a)).abs() / nl);
    (dd > 1e-10 * dab).then(|| vec![0, b, c, d])
}

/// The `dim` reference nodes whose directions from node i are the most
/// independent (the largest determinant of the unit directions).
fn best_fix(x: &[[f64; 3]], i: usize, refs: &[usize], dim: usize) -> Vec<usize> {
    let unit = |j: usize| -> Option<[f64; 3]> {
        let d = diff(x[i], x[j]);
        let l = dot(d, d).sqrt();
        (l > 0.0).then(|| [d[0] / l, d[1] / l, d[2] / l])
    };
    let mut best = (Vec::new(), -1.0);
    for skip in 0..refs.len() {
        let pick: Vec<usize> = refs.iter().enumerate().filter(|(k, _)| *k != skip).map(|(_, r)| *r).collect();
        let dirs: Option<Vec<[f64; 3]>> = pick.iter().map(|&j| unit(j)).collect();
        let Some(u) = dirs else { continue };
        let det =
            if dim == 3 { dot(u[0], cross(u[1], u[2])).abs() } else { (u[0][0] * u[1][1] - u[0][1] * u[1][0]).abs() };
        if det > best.1 {
            best = (pick, det);
        }
    }
    best.0
}
