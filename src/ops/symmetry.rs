//! SYMT and ANTI: symmetry and antisymmetry conditions on the nodes of a
//! mesh that lie on an axis (2D) or a plane (3D).
//!
//! With n the unit normal of the plane (in 2D, the plane holds the axis and
//! the out-of-plane direction), a symmetric structure has no displacement
//! across the plane and no rotation about an axis lying in it; an
//! antisymmetric one the converse:
//!
//! | | displacements | rotations |
//! |---|---|---|
//! | SYMT | u·n = 0 | θ·t = 0 for t in the plane |
//! | ANTI | u·t = 0 for t in the plane | θ·n = 0 |
//!
//! Each is one equality row per node and direction, in the basis of the
//! plane; a direction along an axis gives a one-term row (a BLOQ).

use super::bc::mult_node;
use super::mesh::req_geo;
use super::{dofs, Args, OpDef, PointId};
use crate::error::Result;
use crate::eval::Interp;
use crate::solve::Kind;
use crate::value::rigidity::{CondRow, Subtype};
use crate::value::{Rigidite, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "SYMT",
        signature: "SYMT ('DEPL') ('ROTA') P1 P2 (P3 in 3D) GEO (FLOT)",
        doc: "Symmetry conditions on the nodes of GEO within FLOT (default: a tenth of the current density) of the axis P1 P2 (2D) or the plane P1 P2 P3 (3D): no displacement across it ('DEPL'), no rotation about a line in it ('ROTA').",
        example: "opti dime 2 elem qua4 ; l = droi 2 (0 0) (0 1) ; cl = symt 'DEPL' (0 0) (0 1) l 1.e-3 ;",
        f: symt,
    },
    OpDef {
        name: "ANTI",
        signature: "ANTI ('DEPL') ('ROTA') P1 P2 (P3 in 3D) GEO (FLOT)",
        doc: "Antisymmetry conditions on the nodes of GEO within FLOT (default: a tenth of the current density) of the axis P1 P2 (2D) or the plane P1 P2 P3 (3D): no displacement along it ('DEPL'), no rotation about its normal ('ROTA').",
        example: "opti dime 2 elem qua4 ; l = droi 2 (0 0) (0 1) ; cl = anti 'DEPL' (0 0) (0 1) l 1.e-3 ;",
        f: anti,
    },
];

fn symt(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    conditions(it, a, true)
}

fn anti(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    conditions(it, a, false)
}

fn conditions(it: &mut Interp, a: &mut Args, symmetric: bool) -> Result<Vec<Value>> {
    let (mut depl, mut rota) = (false, false);
    while let Some(k) = a.keyword(&["DEPL", "ROTA"]) {
        match k {
            "DEPL" => depl = true,
            _ => rota = true,
        }
    }
    if !depl && !rota {
        return Err(a.err("give 'DEPL', 'ROTA' or both: which unknowns the conditions hold"));
    }
    let dim = if it.opts.dime == 3 || it.opts.mode == "TRID" { 3 } else { it.opts.dime };
    if dim < 2 {
        return Err(a.err("needs a 2D or 3D space (OPTI DIME): in 1D, BLOQ is enough"));
    }
    let mut pts = Vec::new();
    for _ in 0..dim {
        let p = a.req::<PointId>()?;
        pts.push(it.nodes.get(p.0));
    }
    let geo = req_geo(a)?;
    let tol = match a.opt_num() {
        Some(t) => t,
        None if it.opts.dens > 0.0 => it.opts.dens / 10.0,
        None => {
            return Err(
                a.err("no density is set (DENS): give the distance within which a node lies on the axis or plane")
            )
        }
    };
    let n = normal(&pts, dim)
        .ok_or_else(|| a.err("the points do not define an axis or a plane (they coincide or are aligned)"))?;
    let (t1, t2) = in_plane(n);
    // Directions held, as (unknowns, direction) pairs.
    let mut held: Vec<(&[&str], [f64; 3])> = Vec::new();
    if depl {
        let tr = dofs::translations(it);
        if symmetric {
            held.push((tr, n));
        } else {
            held.push((tr, t1));
            if dim == 3 {
                held.push((tr, t2));
            }
        }
    }
    if rota {
        let ro = dofs::rotations(it);
        if dim == 2 {
            // The one rotation of a 2D mode turns about the out-of-plane
            // axis, which lies in the symmetry plane: held by symmetry,
            // free under antisymmetry.
            if symmetric {
                held.push((ro, [1.0, 0.0, 0.0]));
            }
        } else if symmetric {
            held.push((ro, t1));
            held.push((ro, t2));
        } else {
            held.push((ro, n));
        }
    }
    let mut rig = Rigidite::new(Subtype::Blocage);
    let mut on_plane = 0;
    for node in geo.node_list() {
        let x = it.nodes.get(node);
        let d: f64 = (0..3).map(|k| (x[k] - pts[0][k]) * n[k]).sum();
        if d.abs() > tol {
            continue;
        }
        on_plane += 1;
        for (names, v) in &held {
            let terms: Vec<(usize, String, f64)> = names
                .iter()
                .zip(v.iter())
                .filter(|(_, c)| c.abs() > 1e-12)
                .map(|(name, c)| (node, name.to_string(), *c))
                .collect();
            let m = mult_node(it, node);
            rig.conds.push(CondRow::new(m, terms, Kind::Equal));
        }
    }
    if on_plane == 0 {
        return Err(
            a.err(format!("no node of the mesh lies within {} of the axis or plane", crate::value::fmt_float(tol)))
        );
    }
    Ok(vec![Value::Rigi(Rc::new(rig))])
}

/// The unit normal of the axis P1 P2 in the (x, y) plane, or of the plane
/// P1 P2 P3.
fn normal(p: &[[f64; 3]], dim: usize) -> Option<[f64; 3]> {
    let d1 = sub(p[1], p[0]);
    let n = if dim == 2 { [-d1[1], d1[0], 0.0] } else { cross(d1, sub(p[2], p[0])) };
    let len = dot(n, n).sqrt();
    let scale = dot(d1, d1).sqrt();
    (len > 1e-12 * scale * scale.max(1.0) && len > 0.0).then(|| [n[0] / len, n[1] / len, n[2] / len])
}

/// Two unit vectors that span the plane of normal n. In 2D (n in the
/// (x, y) plane) the first is the axis itself. Built from the coordinate
/// axis least aligned with n, so that a plane normal to an axis gets
/// coordinate directions (one-term rows).
fn in_plane(n: [f64; 3]) -> ([f64; 3], [f64; 3]) {
    if n[2] == 0.0 {
        return ([-n[1], n[0], 0.0], [0.0, 0.0, 1.0]);
    }
    let k = (0..3).min_by(|&i, &j| n[i].abs().total_cmp(&n[j].abs())).unwrap_or(0);
    let mut e = [0.0; 3];
    e[k] = 1.0;
    let t1 = cross(n, e);
    let l = dot(t1, t1).sqrt();
    let t1 = [t1[0] / l, t1[1] / l, t1[2] / l];
    (t1, cross(n, t1))
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plane_normal_to_an_axis_gives_coordinate_directions() {
        let (t1, t2) = in_plane([0.0, 0.0, 1.0]);
        assert_eq!(t1.iter().filter(|c| c.abs() > 1e-15).count(), 1);
        assert_eq!(t2.iter().filter(|c| c.abs() > 1e-15).count(), 1);
        assert!(dot(t1, t2).abs() < 1e-15);
    }

    #[test]
    fn tilted_plane_basis_is_orthonormal() {
        let n = normal(&[[0.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 0.0, 2.0]], 3).unwrap();
        assert!((n[0] - std::f64::consts::FRAC_1_SQRT_2).abs() < 1e-15 && (n[1] + n[0]).abs() < 1e-15);
        let (t1, t2) = in_plane(n);
        for v in [t1, t2] {
            assert!(dot(v, n).abs() < 1e-15 && (dot(v, v) - 1.0).abs() < 1e-15);
        }
        assert!(dot(t1, t2).abs() < 1e-15);
    }

    #[test]
    fn aligned_points_have_no_plane() {
        assert!(normal(&[[0.0; 3], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0]], 3).is_none());
        assert!(normal(&[[1.0, 1.0, 0.0], [1.0, 1.0, 0.0]], 2).is_none());
    }
}
