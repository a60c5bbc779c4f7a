//! Massive elements in Fourier mode (`OPTI MODE FOUR n`): an axisymmetric
//! geometry (x = r, y = z) loaded and displaced as one harmonic n of the
//! angle θ. The unknowns are the amplitudes UR UZ UT of
//!
//! * n ≥ 0 (symmetric):      u_r = UR cos nθ, u_z = UZ cos nθ, u_θ = UT sin nθ;
//! * n = -m < 0 (antisymmetric): u_r = UR sin mθ, u_z = UZ sin mθ, u_θ = UT cos mθ.
//!
//! Both give the same strain amplitudes with the signed n, so one B matrix
//! serves: with ( ),r and ( ),z the derivatives in the meridian plane,
//!
//! ```text
//! EPRR = UR,r            EPZZ = UZ,z          EPTT = (UR + n UT) / r
//! GARZ = UR,z + UZ,r     GART = UT,r - (UT + n UR) / r
//! GAZT = UT,z - n UZ / r
//! ```
//!
//! (the rigid translation along x is n = 1, UR = -UT = const: no strain).
//! The strain order is TRID's with r → x, z → y, θ → z, so the 3D
//! elasticity matrix applies unchanged. Matrices integrate over the whole
//! turn like AXIS: the weight r dr dz is multiplied by ∫cos²nθ dθ, 2π for
//! n = 0 (where FOUR 0 is AXIS plus the uncoupled torsion UT) and π for
//! n ≠ 0.

use std::f64::consts::{PI, TAU};

pub const DOFS: &[&str] = &["UR", "UZ", "UT"];
pub const STRESSES: [&str; 6] = ["SMRR", "SMZZ", "SMTT", "SMRZ", "SMRT", "SMZT"];
pub const STRAINS: [&str; 6] = ["EPRR", "EPZZ", "EPTT", "GARZ", "GART", "GAZT"];

/// ∫ cos²(nθ) dθ over a turn (∫ sin² for the antisymmetric harmonics).
pub fn ring(n: i32) -> f64 {
    if n == 0 {
        TAU
    } else {
        PI
    }
}

/// Strain-displacement matrix at a point: 6 rows (the order of
/// [`STRAINS`]), 3 columns per node (UR UZ UT), node-major.
pub(super) fn bmat(n: i32, shape: &[f64], dndx: &[[f64; 3]], r: f64) -> Vec<Vec<f64>> {
    let nf = f64::from(n);
    let mut b = vec![vec![0.0; 3 * shape.len()]; 6];
    for (i, (g, ni)) in dndx.iter().zip(shape).enumerate() {
        let (cr, cz, ct) = (3 * i, 3 * i + 1, 3 * i + 2);
        let nr = ni / r;
        b[0][cr] = g[0];
        b[1][cz] = g[1];
        b[2][cr] = nr;
        b[2][ct] = nf * nr;
        b[3][cr] = g[1];
        b[3][cz] = g[0];
        b[4][cr] = -nf * nr;
        b[4][ct] = g[0] - nr;
        b[5][cz] = -nf * nr;
        b[5][ct] = g[1];
    }
    b
}
