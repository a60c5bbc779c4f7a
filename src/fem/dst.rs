//! DST (Batoz and Lardeur's Discrete Shear Triangle): the DKT of
//! [`super::plate`] with transverse shear, for thick plates and shells on
//! TRI3. Used by [`super::shell`] for the bending part; the membrane is
//! the DKT's.
//!
//! The rotations β (slopes of the normal, β = ∇w in Kirchhoff's limit)
//! keep the DKT's quadratic interpolation, but the Kirchhoff condition
//! on each side becomes Timoshenko's, ∫ (w,s − β_s − γ_s) ds = 0 with a
//! shear strain γ constant over the element. The side's mid-node
//! tangential slope then gets a correction δ_k = −(3/2) s_k·γ on top of
//! the DKT's value. The shear is the one that balances the bending
//! moments, γ = T / (k G t) with T = div M (T1 = M11,1 + M12,2, T2 =
//! M12,1 + M22,2) and M = D κ(β) (κ = −∇β, linear, so T is constant):
//! a 3×3 linear system gives δ = A q over the corner dofs q = (w, θ1,
//! θ2). The energy is ½∫κᵀDκ + ½∫γᵀ(kGt)γ, k = 5/6. When kGt → ∞, δ
//! → 0 and the element is the DKT.
//!
//! Known limit: the shear γ is the element's own (not shared along a
//! side), so a uniform moment M11 does work on the side corrections of
//! a slanted side, and the constant-moment patch test holds only on
//! meshes where those terms cancel (a rectangle cut in four by its
//! centre). On right triangles all cut the same way (DALL), a thick strip
//! (L/t = 5) comes out about 9 % too flexible; thin plates are unaffected.

use super::element::FemError;
use super::mesh::ElemType;
use super::plate::{self, PlatePoint};
use super::shape::eval;

/// Shear correction factor of a homogeneous section.
pub const SHEAR_FACTOR: f64 = 5.0 / 6.0;

/// The element's condensed shear: mid-side corrections and shear strains
/// as linear maps of the 9 corner bending dofs.
pub(crate) struct Dst {
    /// δ_k over q, one row per side k (from corner k to k+1).
    a: [[f64; 9]; 3],
    /// γ1, γ2 over q.
    pub gamma: [[f64; 9]; 2],
    /// Shear stiffness k G t.
    pub ds: f64,
    tangents: [[f64; 2]; 3],
}

/// Curvature rows (κ11, κ22, 2κ12) over the 12 nodal slope values
/// (β1, β2 at the 6 TRI6 nodes: corner, mid-side, corner, ...) at `p`.
fn kappa(inv: &[[f64; 2]; 2], p: [f64; 3]) -> [[f64; 12]; 3] {
    let q = eval(ElemType::Tri6, p);
    let mut k = [[0.0; 12]; 3];
    for (n, d) in q.dn.iter().enumerate() {
        let g = [inv[0][0] * d[0] + inv[0][1] * d[1], inv[1][0] * d[0] + inv[1][1] * d[1]];
        k[0][2 * n] -= g[0];
        k[1][2 * n + 1] -= g[1];
        k[2][2 * n] -= g[1];
        k[2][2 * n + 1] -= g[0];
    }
    k
}

/// The curvature rows over the 3 mid-side corrections at `p` (each δ_k
/// moves mid-node k's slope along its side's tangent).
fn kappa_delta(inv: &[[f64; 2]; 2], p: [f64; 3], t: &[[f64; 2]; 3]) -> [[f64; 3]; 3] {
    let k = kappa(inv, p);
    std::array::from_fn(|r| {
        std::array::from_fn(|s| k[r][2 * (2 * s + 1)] * t[s][0] + k[r][2 * (2 * s + 1) + 1] * t[s][1])
    })
}

/// Condense the shear of a triangle with corners `xl` (counter-clockwise
/// in its plane), bending matrix `db` and shear stiffness `ds`.
pub(crate) fn condense(xl: &[[f64; 2]], db: &[[f64; 3]; 3], ds: f64) -> Result<Dst, FemError> {
    let centre = [1.0 / 3.0, 1.0 / 3.0, 0.0];
    let inv = plate::at(xl, centre).inv;
    let tangents: [[f64; 2]; 3] = std::array::from_fn(|i| {
        let j = (i + 1) % 3;
        let d = [xl[j][0] - xl[i][0], xl[j][1] - xl[i][1]];
        let l = (d[0] * d[0] + d[1] * d[1]).sqrt();
        [d[0] / l, d[1] / l]
    });
    // κ is linear: its reference derivatives are exact differences.
    let k0 = kappa(&inv, centre);
    let kx = kappa(&inv, [centre[0] + 1.0, centre[1], 0.0]);
    let ky = kappa(&inv, [centre[0], centre[1] + 1.0, 0.0]);
    let dref = |r: usize, c: usize| [kx[r][c] - k0[r][c], ky[r][c] - k0[r][c]];
    // Physical derivative along x_a of κ row r, column c.
    let dk = |a: usize, r: usize, c: usize| {
        let d = dref(r, c);
        inv[a][0] * d[0] + inv[a][1] * d[1]
    };
    let dm = |a: usize, r: usize, c: usize| (0..3).map(|s| db[r][s] * dk(a, s, c)).sum::<f64>();
    // T over the 12 nodal slopes.
    let gb: [[f64; 12]; 2] =
        [std::array::from_fn(|c| dm(0, 0, c) + dm(1, 2, c)), std::array::from_fn(|c| dm(0, 2, c) + dm(1, 1, c))];
    // Nodal slopes over q (the DKT's), and T over q and over δ.
    let h = plate::slopes(xl);
    let gq: [[f64; 9]; 2] = std::array::from_fn(|r| {
        std::array::from_fn(|c| (0..6).map(|n| gb[r][2 * n] * h[n][0][c] + gb[r][2 * n + 1] * h[n][1][c]).sum())
    });
    let gd: [[f64; 3]; 2] = std::array::from_fn(|r| {
        std::array::from_fn(|k| gb[r][2 * (2 * k + 1)] * tangents[k][0] + gb[r][2 * (2 * k + 1) + 1] * tangents[k][1])
    });
    // (I + 3/2 S Gδ / ds) δ = −3/2 S Gq / ds · q.
    let mut lhs = [[0.0; 3]; 3];
    let mut rhs = [[0.0; 9]; 3];
    for k in 0..3 {
        let s = tangents[k];
        for j in 0..3 {
            lhs[k][j] = if k == j { 1.0 } else { 0.0 } + 1.5 / ds * (s[0] * gd[0][j] + s[1] * gd[1][j]);
        }
        for c in 0..9 {
            rhs[k][c] = -1.5 / ds * (s[0] * gq[0][c] + s[1] * gq[1][c]);
        }
    }
    let a = solve3(lhs, rhs)
        .ok_or_else(|| FemError::Degenerate { elem: "DST", why: "singular shear condensation".into() })?;
    let gamma = std::array::from_fn(|r| {
        std::array::from_fn(|c| (gq[r][c] + (0..3).map(|k| gd[r][k] * a[k][c]).sum::<f64>()) / ds)
    });
    Ok(Dst { a, gamma, ds, tangents })
}

/// The DKT's point `p` with the shear corrections added to its curvature
/// rows.
pub(crate) fn at(xl: &[[f64; 2]], p: [f64; 3], d: &Dst) -> PlatePoint {
    let mut pp = plate::at(xl, p);
    let kd = kappa_delta(&pp.inv, p, &d.tangents);
    for (r, row) in pp.bb.iter_mut().enumerate() {
        for (c, v) in row.iter_mut().enumerate() {
            *v += (0..3).map(|k| kd[r][k] * d.a[k][c]).sum::<f64>();
        }
    }
    pp
}

/// Gaussian elimination with partial pivoting on a 3×3 system with 9
/// right-hand sides.
fn solve3(mut m: [[f64; 3]; 3], mut b: [[f64; 9]; 3]) -> Option<[[f64; 9]; 3]> {
    for c in 0..3 {
        let p = (c..3).max_by(|&i, &j| m[i][c].abs().total_cmp(&m[j][c].abs()))?;
        if m[p][c].abs() < 1e-300 || !m[p][c].is_finite() {
            return None;
        }
        m.swap(c, p);
        b.swap(c, p);
        let (mc, bc) = (m[c], b[c]);
        for r in c + 1..3 {
            let f = m[r][c] / mc[c];
            for (v, w) in m[r].iter_mut().zip(mc).skip(c) {
                *v -= f * w;
            }
            for (v, w) in b[r].iter_mut().zip(bc) {
                *v -= f * w;
            }
        }
    }
    let mut x = [[0.0; 9]; 3];
    for r in (0..3).rev() {
        for k in 0..9 {
            let s: f64 = (r + 1..3).map(|j| m[r][j] * x[j][k]).sum();
            x[r][k] = (b[r][k] - s) / m[r][r];
        }
    }
    Some(x)
}
