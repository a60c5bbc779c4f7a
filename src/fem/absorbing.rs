//! Viscous absorbing boundary of Lysmer and Kuhlemeyer (1969), AMOR's
//! second form.
//!
//! A boundary face of an elastic medium radiates waves away when it
//! carries the traction `-ρ c_p (v·n) n - ρ c_s (v - (v·n) n)`: dashpots of
//! the compression wave speed along the normal and of the shear wave speed
//! in the tangent plane. The damping matrix of a face is therefore
//! `∫ Nᵢ Nⱼ ρ [c_p n nᵀ + c_s (I - n nᵀ)] dS`, consistent (the same shape
//! functions as the displacement).
//!
//! Edges (SEG2, SEG3) in the 2D modes: per unit thickness in plane strain
//! or stress; in AXIS the ring, weighted by the radius as the stiffness
//! is (`Mode::turn`). Faces (TRI3, TRI6, QUA4, QUA8) in TRID.

use super::element::{ElemMatrix, FemError, Mode};
use super::mesh::ElemType;
use super::quadrature::{quad, seg, tri, QPoint};
use super::shape::eval;

/// The wave speeds (c_p, c_s) of an isotropic elastic medium.
pub fn wave_speeds(young: f64, nu: f64, rho: f64) -> Result<(f64, f64), FemError> {
    const ELEM: &str = "absorbing boundary";
    if !(rho > 0.0 && rho.is_finite()) {
        return Err(FemError::InvalidProperty { prop: "RHO", value: rho, elem: ELEM, why: "must be positive" });
    }
    if !(young > 0.0 && young.is_finite()) {
        return Err(FemError::InvalidProperty { prop: "YOUN", value: young, elem: ELEM, why: "must be positive" });
    }
    if !(nu > -1.0 && nu < 0.5) {
        return Err(FemError::InvalidProperty { prop: "NU", value: nu, elem: ELEM, why: "must lie in ]-1, 0.5[" });
    }
    let mu = young / (2.0 * (1.0 + nu));
    let lambda = young * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    Ok((((lambda + 2.0 * mu) / rho).sqrt(), (mu / rho).sqrt()))
}

/// The damping matrix of one boundary face, over its nodes' displacements
/// (UX UY (UZ), or UR UZ in AXIS).
pub fn lysmer_damping(
    face: ElemType,
    mode: Mode,
    x: &[[f64; 3]],
    rho: f64,
    cp: f64,
    cs: f64,
) -> Result<ElemMatrix, FemError> {
    let edge = matches!(face, ElemType::Seg2 | ElemType::Seg3);
    let surf = matches!(face, ElemType::Tri3 | ElemType::Tri6 | ElemType::Qua4 | ElemType::Qua8);
    let supported = match mode {
        Mode::Trid => surf,
        Mode::PlanCont | Mode::PlanDefo | Mode::Axis => edge,
        _ => false,
    };
    if !supported {
        return Err(FemError::Unsupported { form: "absorbing boundary", elem: face.name(), mode: mode.name() });
    }
    if x.len() != face.nodes() {
        return Err(FemError::WrongNodeCount { elem: face.name(), expected: face.nodes(), got: x.len() });
    }
    let dims = if edge { 2 } else { 3 };
    let comps: &[&'static str] = match mode {
        Mode::Trid => &["UX", "UY", "UZ"],
        Mode::Axis => &["UR", "UZ"],
        _ => &["UX", "UY"],
    };
    // Exact for straight edges and flat faces (N N r is of degree 5 at
    // most on a SEG3 in AXIS); warped quadrangles get the same rule.
    let rule: Vec<QPoint> = match face {
        ElemType::Seg2 | ElemType::Seg3 => seg(3),
        ElemType::Tri3 | ElemType::Tri6 => tri(7),
        _ => quad(3),
    };
    let nn = face.nodes();
    let nd = nn * dims;
    let mut k = vec![0.0; nd * nd];
    for (pt, w) in rule {
        let s = eval(face, pt);
        let area_n = super::loads::normal(edge, &s, x);
        let jac = area_n.iter().map(|v| v * v).sum::<f64>().sqrt();
        if !(jac > 0.0 && jac.is_finite()) {
            return Err(FemError::Degenerate { elem: face.name(), why: "face of zero length or area".into() });
        }
        let n: Vec<f64> = area_n[..dims].iter().map(|v| v / jac).collect();
        let mut wt = w * jac * rho;
        if let Some(turn) = mode.turn() {
            let r: f64 = s.n.iter().zip(x).map(|(a, b)| a * b[0]).sum();
            if r < 0.0 {
                return Err(FemError::Degenerate {
                    elem: face.name(),
                    why: format!("AXIS face reaches r = {r:e} < 0"),
                });
            }
            wt *= turn * r;
        }
        // The dashpot tensor ρ-free: c_s I + (c_p - c_s) n nᵀ.
        let mut d = [[0.0; 3]; 3];
        for a in 0..dims {
            for b in 0..dims {
                d[a][b] = (cp - cs) * n[a] * n[b] + if a == b { cs } else { 0.0 };
            }
        }
        for i in 0..nn {
            for j in 0..nn {
                let nij = wt * s.n[i] * s.n[j];
                for a in 0..dims {
                    for b in 0..dims {
                        k[(i * dims + a) * nd + j * dims + b] += nij * d[a][b];
                    }
                }
            }
        }
    }
    let dofs = (0..nn).flat_map(|i| comps.iter().map(move |c| (i, *c))).collect();
    Ok(ElemMatrix { dofs, k })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unit_square_radiates_its_normal_velocity() {
        // A unit square face in the plane z = 0: a uniform velocity along
        // z meets the dashpot ρ c_p over the whole area.
        let x = [[0., 0., 0.], [1., 0., 0.], [1., 1., 0.], [0., 1., 0.]];
        let m = lysmer_damping(ElemType::Qua4, Mode::Trid, &x, 2.0, 3.0, 1.0).unwrap();
        let nd = 12;
        let (mut fz, mut fx) = (0.0, 0.0);
        for i in 0..nd {
            for j in 0..4 {
                fz += if i % 3 == 2 { m.k[i * nd + j * 3 + 2] } else { 0.0 };
                fx += if i % 3 == 0 { m.k[i * nd + j * 3] } else { 0.0 };
            }
        }
        assert!((fz - 6.0).abs() < 1e-12, "{fz}");
        assert!((fx - 2.0).abs() < 1e-12, "{fx}");
    }

    #[test]
    fn speeds_of_a_medium_without_poisson_effect() {
        let (cp, cs) = wave_speeds(2.0, 0.0, 1.0).unwrap();
        assert!((cp - 2f64.sqrt()).abs() < 1e-15 && (cs - 1.0).abs() < 1e-15);
    }
}
