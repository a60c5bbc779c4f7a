//! Consistent nodal forces of a pressure on a face (PRES 'MASS').
//!
//! Positive pressure pushes towards the solid. A face alone does not know
//! which side the solid is on, so the caller passes a point `inside` the
//! solid (typically the centroid of the adjacent element, see
//! [`super::shape::faces`]); the normal is turned towards it.
//!
//! Edges (SEG2, SEG3) in the 2D modes: PLAN CONT/DEFO forces are per unit
//! thickness (the caller scales p by DIM3 when it has one); AXIS forces are per radian, i.e. the
//! integral of p·N·n·r along the edge (no 2π), matching the per-radian
//! stiffness. Faces (TRI3, TRI6, QUA4, QUA8) in TRID.

use super::element::{FemError, Mode};
use super::mesh::ElemType;
use super::quadrature::{quad, seg, tri, QPoint};
use super::shape::eval;

/// Nodal forces [fx, fy, fz] (or [fr, fz, 0] in AXIS), one per face node.
pub fn pressure_load(
    face: ElemType,
    mode: Mode,
    x: &[[f64; 3]],
    p: f64,
    inside: [f64; 3],
) -> Result<Vec<[f64; 3]>, FemError> {
    pressure_load_nodal(face, mode, x, &vec![p; x.len()], inside)
}

/// As [`pressure_load`] for a pressure given at the face nodes and
/// interpolated with the face's shape functions.
pub fn pressure_load_nodal(
    face: ElemType,
    mode: Mode,
    x: &[[f64; 3]],
    p: &[f64],
    inside: [f64; 3],
) -> Result<Vec<[f64; 3]>, FemError> {
    let edge = check(face, mode, x, p)?;
    let centre = match face {
        ElemType::Tri3 | ElemType::Tri6 => [1.0 / 3.0, 1.0 / 3.0, 0.0],
        _ => [0.0; 3],
    };
    let sc = eval(face, centre);
    let nc = normal(edge, &sc, x);
    let mut xc = [0.0; 3];
    for (n, xi) in sc.n.iter().zip(x) {
        for c in 0..3 {
            xc[c] += n * xi[c];
        }
    }
    let dims = if edge { 2 } else { 3 };
    let side: f64 = (0..dims).map(|c| nc[c] * (inside[c] - xc[c])).sum();
    let len2: f64 = nc.iter().map(|v| v * v).sum();
    let dist2: f64 = (0..dims).map(|c| (inside[c] - xc[c]).powi(2)).sum();
    if len2 <= 0.0 || !len2.is_finite() {
        return Err(FemError::Degenerate { elem: face.name(), why: "face of zero length or area".into() });
    }
    if side.abs() <= 1e-10 * (len2 * dist2).sqrt() || !side.is_finite() {
        return Err(FemError::Degenerate {
            elem: face.name(),
            why: "the point given inside the solid lies on the face plane; the pressure side is undefined".into(),
        });
    }
    pressure_load_signed(face, mode, x, p, side.signum())
}

/// As [`pressure_load_nodal`], the side given by the face's own orientation
/// rather than by a point inside the solid (pressure models, whose faces
/// must be oriented): the forces are ∫ p · sign · n, n the face's normal,
/// for an edge (i, j) its direction turned by -90°, for a surface
/// x_ξ × x_η (right-handed with the node order).
pub fn pressure_load_signed(
    face: ElemType,
    mode: Mode,
    x: &[[f64; 3]],
    p: &[f64],
    sign: f64,
) -> Result<Vec<[f64; 3]>, FemError> {
    let edge = check(face, mode, x, p)?;
    let dims = if edge { 2 } else { 3 };
    // Exact for the polynomial integrands of straight/flat faces, including
    // the extra factor r in AXIS.
    let rule: Vec<QPoint> = match face {
        ElemType::Seg2 | ElemType::Seg3 => seg(3),
        ElemType::Tri3 | ElemType::Tri6 => tri(7),
        _ => quad(3),
    };
    let mut f = vec![[0.0; 3]; face.nodes()];
    for (pt, w) in rule {
        let s = eval(face, pt);
        let n = normal(edge, &s, x);
        if n.iter().all(|v| *v == 0.0) || n.iter().any(|v| !v.is_finite()) {
            return Err(FemError::Degenerate { elem: face.name(), why: "face of zero length or area".into() });
        }
        let pt_p: f64 = s.n.iter().zip(p).map(|(a, b)| a * b).sum();
        let mut wt = w * pt_p * sign;
        if let Some(turn) = mode.turn() {
            let r: f64 = s.n.iter().zip(x).map(|(a, b)| a * b[0]).sum();
            if r < 0.0 {
                return Err(FemError::Degenerate {
                    elem: face.name(),
                    why: format!("{} face reaches r = {r:e} < 0", mode.name()),
                });
            }
            // The whole ring, as the stiffness (solid::points).
            wt *= turn * r;
        }
        for (fi, ni) in f.iter_mut().zip(&s.n) {
            for c in 0..dims {
                fi[c] += wt * ni * n[c];
            }
        }
    }
    Ok(f)
}

/// Edges in the 2D modes, surfaces in TRID; one value per node. Whether
/// the face is an edge.
fn check(face: ElemType, mode: Mode, x: &[[f64; 3]], p: &[f64]) -> Result<bool, FemError> {
    let edge = matches!(face, ElemType::Seg2 | ElemType::Seg3);
    let surf = matches!(face, ElemType::Tri3 | ElemType::Tri6 | ElemType::Qua4 | ElemType::Qua8);
    if !((edge && mode != Mode::Trid) || (surf && mode == Mode::Trid)) {
        return Err(FemError::Unsupported { form: "pressure", elem: face.name(), mode: mode.name() });
    }
    if x.len() != face.nodes() || p.len() != x.len() {
        return Err(FemError::WrongNodeCount { elem: face.name(), expected: face.nodes(), got: x.len().min(p.len()) });
    }
    Ok(edge)
}

/// Area-scaled normal at a reference point, before orientation.
pub(crate) fn normal(edge: bool, s: &super::shape::Shape, x: &[[f64; 3]]) -> [f64; 3] {
    let mut t = [[0.0; 3]; 2];
    for (d, xi) in s.dn.iter().zip(x) {
        for a in 0..2 {
            for c in 0..3 {
                t[a][c] += d[a] * xi[c];
            }
        }
    }
    if edge {
        [t[0][1], -t[0][0], 0.0]
    } else {
        let (a, b) = (t[0], t[1]);
        [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    }
}
