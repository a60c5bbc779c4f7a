//! Small measurements used by the tests: lengths, signed areas, volumes.

use crate::fem::mesh::{ElemType, Mesh, Nodes};

pub fn pt(nodes: &mut Nodes, x: f64, y: f64) -> usize {
    nodes.push([x, y, 0.0], 0.0)
}

pub fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * (1.0 + a.abs().max(b.abs()))
}

/// Signed area (xy plane) of each surface element, corners only.
pub fn areas(nodes: &Nodes, mesh: &Mesh) -> Vec<f64> {
    let mut out = Vec::new();
    for p in &mesh.parts {
        let corners: &[usize] = match p.ty {
            ElemType::Tri3 => &[0, 1, 2],
            ElemType::Qua4 => &[0, 1, 2, 3],
            ElemType::Tri6 => &[0, 2, 4],
            ElemType::Qua8 => &[0, 2, 4, 6],
            _ => continue,
        };
        for e in p.elems() {
            let x: Vec<[f64; 3]> = corners.iter().map(|&k| nodes.get(e[k])).collect();
            let mut a = 0.0;
            for i in 0..x.len() {
                let (p, q) = (x[i], x[(i + 1) % x.len()]);
                a += p[0] * q[1] - q[0] * p[1];
            }
            out.push(0.5 * a);
        }
    }
    out
}

/// Lengths of the line elements (end to end).
pub fn lengths(nodes: &Nodes, mesh: &Mesh) -> Vec<f64> {
    let mut out = Vec::new();
    for p in mesh.parts.iter().filter(|p| p.ty.dim() == 1) {
        for e in p.elems() {
            let (a, b) = (nodes.get(e[0]), nodes.get(e[e.len() - 1]));
            out.push(((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt());
        }
    }
    out
}

/// Volume of a CUB8 / PRI6 by splitting into tetrahedra from its
/// centroid over triangulated faces (exact for planar faces; positive when
/// the element is positively oriented).
pub fn volume(nodes: &Nodes, ty: ElemType, e: &[usize]) -> f64 {
    let faces: &[&[usize]] = match ty {
        ElemType::Cub8 => &[&[0, 3, 2, 1], &[4, 5, 6, 7], &[0, 1, 5, 4], &[1, 2, 6, 5], &[2, 3, 7, 6], &[3, 0, 4, 7]],
        ElemType::Pri6 => &[&[0, 2, 1], &[3, 4, 5], &[0, 1, 4, 3], &[1, 2, 5, 4], &[2, 0, 3, 5]],
        _ => return 0.0,
    };
    let x: Vec<[f64; 3]> = e.iter().map(|&n| nodes.get(n)).collect();
    let mut c = [0.0; 3];
    for p in &x {
        for k in 0..3 {
            c[k] += p[k] / x.len() as f64;
        }
    }
    let tet = |a: [f64; 3], b: [f64; 3], d: [f64; 3]| {
        let u = [a[0] - c[0], a[1] - c[1], a[2] - c[2]];
        let v = [b[0] - c[0], b[1] - c[1], b[2] - c[2]];
        let w = [d[0] - c[0], d[1] - c[1], d[2] - c[2]];
        (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]))
            / 6.0
    };
    let mut vol = 0.0;
    for f in faces {
        for i in 1..f.len() - 1 {
            vol += tet(x[f[0]], x[f[i]], x[f[i + 1]]);
        }
    }
    vol
}
