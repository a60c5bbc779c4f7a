//! Plate kinematics in an element's own plane, for the thin shells of
//! [`super::shell`]: the discrete Kirchhoff bending of Batoz (DKT on the
//! triangle, DKQ on the quadrangle) and the membrane (constant-strain
//! triangle, bilinear quadrangle).
//!
//! Local frame: x1, x2 in the plane, x3 along the normal. Per corner the
//! membrane dofs are (u1, u2) and the bending dofs (w, θ1, θ2), θ being the
//! rotation vector (right-hand rule), so that a Kirchhoff normal has slopes
//! w,1 = −θ2 and w,2 = θ1.
//!
//! The discrete Kirchhoff idea, written so each step can be checked: the
//! normal slopes β = (β1, β2) are interpolated *quadratically* (TRI6/QUA8
//! shape functions, corners and mid-sides); at the corners β is the
//! Kirchhoff slope of the nodal rotations; at a mid-side the component
//! along the side is the slope of the cubic w along that side
//! (3/(2l)(w_j − w_i) − (β_s,i + β_s,j)/4) and the normal component is the
//! mean of the corners'. Curvatures are κ = −∇β (κ12 doubled, engineering),
//! so that with M = D κ, M11 = ∫ σ11 x3 dx3: positive M11 stretches the face
//! on the +x3 side. This is exactly Batoz's DKT (and DKQ with the 8-node
//! interpolation).

use super::mesh::ElemType;
use super::shape::eval;

/// Strain-displacement rows at one point, and the area Jacobian there.
pub(crate) struct PlatePoint {
    /// Membrane strains (ε11, ε22, γ12) over the corner (u1, u2) dofs.
    pub bm: [Vec<f64>; 3],
    /// Curvatures (κ11, κ22, 2κ12) over the corner (w, θ1, θ2) dofs.
    pub bb: [Vec<f64>; 3],
    pub det: f64,
    /// Inverse Jacobian: physical gradient = `inv` · reference gradient.
    pub inv: [[f64; 2]; 2],
}

/// The linear (TRI3/QUA4) and quadratic (TRI6/QUA8) geometries of a
/// corner count.
fn types(n: usize) -> (ElemType, ElemType) {
    if n == 3 {
        (ElemType::Tri3, ElemType::Tri6)
    } else {
        (ElemType::Qua4, ElemType::Qua8)
    }
}

/// Corner slopes β_i = C q_i: β1 = −θ2, β2 = θ1, over (w, θ1, θ2).
const C: [[f64; 3]; 2] = [[0.0, 0.0, -1.0], [0.0, 1.0, 0.0]];

/// β at the quadratic nodes as linear maps of the bending dofs: `h[k][a]`
/// is the row of β_a at node k (TRI6/QUA8 order: corner, mid-side, ...).
pub(crate) fn slopes(xl: &[[f64; 2]]) -> Vec<[Vec<f64>; 2]> {
    let n = xl.len();
    let mut h = Vec::with_capacity(2 * n);
    for i in 0..n {
        let mut corner = [vec![0.0; 3 * n], vec![0.0; 3 * n]];
        for a in 0..2 {
            corner[a][3 * i..3 * i + 3].copy_from_slice(&C[a]);
        }
        h.push(corner);
        let j = (i + 1) % n;
        let d = [xl[j][0] - xl[i][0], xl[j][1] - xl[i][1]];
        let l = (d[0] * d[0] + d[1] * d[1]).sqrt();
        let s = [d[0] / l, d[1] / l];
        let nn = [s[1], -s[0]];
        // P = −¼ s sᵀ + ½ n nᵀ acts on β_i + β_j.
        let p = |a: usize, b: usize| -0.25 * s[a] * s[b] + 0.5 * nn[a] * nn[b];
        let mut mid = [vec![0.0; 3 * n], vec![0.0; 3 * n]];
        for a in 0..2 {
            mid[a][3 * i] = -1.5 / l * s[a];
            mid[a][3 * j] = 1.5 / l * s[a];
            for node in [i, j] {
                for q in 1..3 {
                    mid[a][3 * node + q] += p(a, 0) * C[0][q] + p(a, 1) * C[1][q];
                }
            }
        }
        h.push(mid);
    }
    h
}

/// The strain rows at reference point `p` of a flat element with corners
/// `xl` (3 or 4, counter-clockwise in the local plane).
pub(crate) fn at(xl: &[[f64; 2]], p: [f64; 3]) -> PlatePoint {
    let n = xl.len();
    let (lin, quad) = types(n);
    let s = eval(lin, p);
    let mut j = [[0.0; 2]; 2];
    for (d, x) in s.dn.iter().zip(xl) {
        for a in 0..2 {
            for b in 0..2 {
                j[a][b] += d[a] * x[b];
            }
        }
    }
    let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
    let inv = [[j[1][1] / det, -j[0][1] / det], [-j[1][0] / det, j[0][0] / det]];
    // Physical gradient of a function with reference gradient d.
    let grad = |d: &[f64; 3]| [inv[0][0] * d[0] + inv[0][1] * d[1], inv[1][0] * d[0] + inv[1][1] * d[1]];
    let mut bm = [vec![0.0; 2 * n], vec![0.0; 2 * n], vec![0.0; 2 * n]];
    for (i, d) in s.dn.iter().enumerate() {
        let g = grad(d);
        bm[0][2 * i] = g[0];
        bm[1][2 * i + 1] = g[1];
        bm[2][2 * i] = g[1];
        bm[2][2 * i + 1] = g[0];
    }
    let h = slopes(xl);
    let q = eval(quad, p);
    let mut bb = [vec![0.0; 3 * n], vec![0.0; 3 * n], vec![0.0; 3 * n]];
    for (d, hk) in q.dn.iter().zip(&h) {
        let g = grad(d);
        for c in 0..3 * n {
            bb[0][c] -= g[0] * hk[0][c];
            bb[1][c] -= g[1] * hk[1][c];
            bb[2][c] -= g[1] * hk[0][c] + g[0] * hk[1][c];
        }
    }
    PlatePoint { bm, bb, det, inv }
}

/// Plane-stress elasticity [[1, ν, 0], [ν, 1, 0], [0, 0, (1 − ν)/2]]·c.
pub(crate) fn plane_stress(c: f64, nu: f64) -> [[f64; 3]; 3] {
    [[c, c * nu, 0.0], [c * nu, c, 0.0], [0.0, 0.0, c * (1.0 - nu) / 2.0]]
}
