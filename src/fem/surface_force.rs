//! Nodal forces equivalent to a surface force density (FSUR): the density
//! is given at the nodes of a face (an edge in the 2D modes, a surface in
//! TRID, a shell or beam element itself) and interpolated with the face's
//! shape functions, so `F_i = ∫ N_i Σ_j N_j f_j dS` — consistent, exact for
//! straight edges and flat faces. In AXIS the face is the whole ring (the
//! factor 2πr, as the stiffness), in the plane modes per unit thickness
//! (times `width`).

use super::element::{FemError, Mode};
use super::mesh::ElemType;
use super::quadrature::{quad, seg, tri, QPoint};
use super::shape::eval;

/// The nodal forces of the density `f` (one vector per face node).
pub fn surface_force(
    face: ElemType,
    mode: Mode,
    x: &[[f64; 3]],
    f: &[[f64; 3]],
    width: f64,
) -> Result<Vec<[f64; 3]>, FemError> {
    let edge = matches!(face, ElemType::Seg2 | ElemType::Seg3);
    let surf = matches!(face, ElemType::Tri3 | ElemType::Tri6 | ElemType::Qua4 | ElemType::Qua8);
    if !(edge || (surf && mode == Mode::Trid)) {
        return Err(FemError::Unsupported { form: "surface force", elem: face.name(), mode: mode.name() });
    }
    if x.len() != face.nodes() || f.len() != x.len() {
        return Err(FemError::WrongNodeCount { elem: face.name(), expected: face.nodes(), got: x.len().min(f.len()) });
    }
    let rule: Vec<QPoint> = match face {
        ElemType::Seg2 | ElemType::Seg3 => seg(3),
        ElemType::Tri3 | ElemType::Tri6 => tri(7),
        _ => quad(3),
    };
    // A line in 3D (a beam) has no normal: its jacobian is its tangent.
    let line_3d = edge && mode == Mode::Trid;
    let mut out = vec![[0.0; 3]; face.nodes()];
    for (pt, w) in rule {
        let s = eval(face, pt);
        let jac = if line_3d {
            let mut t = [0.0; 3];
            for (d, xi) in s.dn.iter().zip(x) {
                for c in 0..3 {
                    t[c] += d[0] * xi[c];
                }
            }
            t.iter().map(|v| v * v).sum::<f64>().sqrt()
        } else {
            super::loads::normal(edge, &s, x).iter().map(|v| v * v).sum::<f64>().sqrt()
        };
        if !(jac > 0.0 && jac.is_finite()) {
            return Err(FemError::Degenerate { elem: face.name(), why: "face of zero length or area".into() });
        }
        let mut wt = w * jac;
        match mode.turn() {
            Some(turn) => {
                let r: f64 = s.n.iter().zip(x).map(|(a, b)| a * b[0]).sum();
                wt *= turn * r;
            }
            None if edge && !line_3d => wt *= width,
            None => {}
        }
        let mut fp = [0.0; 3];
        for (nj, fj) in s.n.iter().zip(f) {
            for c in 0..3 {
                fp[c] += nj * fj[c];
            }
        }
        for (oi, ni) in out.iter_mut().zip(&s.n) {
            for c in 0..3 {
                oi[c] += wt * ni * fp[c];
            }
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uniform_density_on_a_square_gives_a_quarter_each() {
        let x = [[0., 0., 0.], [2., 0., 0.], [2., 2., 0.], [0., 2., 0.]];
        let f = surface_force(ElemType::Qua4, Mode::Trid, &x, &[[0., 0., 1.]; 4], 1.0).unwrap();
        assert!(f.iter().all(|v| (v[2] - 1.0).abs() < 1e-14));
    }
}
