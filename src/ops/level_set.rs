//! PSIP (psip.notice): the level sets of a crack at the nodes of a mesh,
//! as CHPOINTs. Numerics in `fem::level_set`.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::args::PointId;
use crate::eval::Interp;
use crate::fem::level_set::{inf_distance, tip_level, Crack, Tip};
use crate::fem::mesh::{ElemType, Mesh};
use crate::value::{Chpoint, Nature, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "PSIP",
    signature: "PSIP MAIL1 CRACK (CRIT) ('DEUX'|'TROI' TIP1 (TIP2) | FRONT)",
    doc: "Level sets of a crack at the nodes of MAIL1: PHI, the distance to the crack (SEG2 lines in 2D, TRI3/QUA4 surfaces in 3D) signed by its orientation (positive on the left of a 2D line, on the side of a facet's normal in 3D), extended past the tips along the crack. With 'DEUX': first PSI, the signed distance to the line through the nearest tip perpendicular to the crack (2D, positive ahead), or to the plane through the front perpendicular to the crack (3D), then PHI; 'TROI' (3D) adds TAU, the coordinate along the front. With CRIT, only the nodes nearer the crack than CRIT (in the infinity norm) get values.",
    example: "c = (0. 0.) droi 2 (1. 0.) ; s = ((-1. -1.) droi 2 (2. -1.)) tran 2 (0. 2.) ; psi phi = psip s c 'DEUX' (1. 0.) ;",
    f: psip,
}];

fn mesh_or_point(v: &Value) -> Option<Rc<Mesh>> {
    match v {
        Value::Mesh(m) => Some(m.clone()),
        Value::Point(p) => Some(Rc::new(Mesh::points(&[*p]))),
        _ => None,
    }
}

/// The crack's facets: segments in 2D (a SEG3 as its two halves),
/// triangles in 3D (a QUA4 as two, quadratic faces by their corners).
fn crack_of(it: &Interp, a: &Args, m: &Mesh, dim: usize) -> Result<Crack> {
    let x = |n: usize| it.nodes.get(n);
    let (mut segs, mut tris) = (Vec::new(), Vec::new());
    for p in &m.parts {
        for e in p.elems() {
            match (dim, p.ty) {
                (2, ElemType::Seg2) => segs.push([x(e[0]), x(e[1])]),
                (2, ElemType::Seg3) => segs.extend([[x(e[0]), x(e[1])], [x(e[1]), x(e[2])]]),
                (3, ElemType::Tri3) => tris.push([x(e[0]), x(e[1]), x(e[2])]),
                (3, ElemType::Tri6) => tris.push([x(e[0]), x(e[2]), x(e[4])]),
                (3, ElemType::Qua4) => tris.extend([[x(e[0]), x(e[1]), x(e[2])], [x(e[0]), x(e[2]), x(e[3])]]),
                (3, ElemType::Qua8) => tris.extend([[x(e[0]), x(e[2]), x(e[4])], [x(e[0]), x(e[4]), x(e[6])]]),
                _ => {
                    return Err(a.err(format!(
                        "the crack must be made of {} in dimension {}, not {}",
                        if dim == 2 { "SEG2 lines" } else { "TRI3 or QUA4 faces" },
                        dim,
                        p.ty.name()
                    )))
                }
            }
        }
    }
    let c = if dim == 2 { Crack::from_segments(&segs) } else { Crack::from_triangles(&tris) };
    c.map_err(|e| a.err(e))
}

/// The crack front of a 3D crack: its segments (SEG2, or SEG3 halves).
fn front_of(it: &Interp, a: &Args, m: &Mesh) -> Result<Vec<[[f64; 3]; 2]>> {
    let x = |n: usize| it.nodes.get(n);
    let mut segs = Vec::new();
    for p in &m.parts {
        for e in p.elems() {
            match p.ty {
                ElemType::Seg2 => segs.push([x(e[0]), x(e[1])]),
                ElemType::Seg3 => segs.extend([[x(e[0]), x(e[1])], [x(e[1]), x(e[2])]]),
                t => return Err(a.err(format!("the crack front must be a line of SEG2, not {}", t.name()))),
            }
        }
    }
    if segs.is_empty() {
        return Err(a.err("the crack front has no segment"));
    }
    Ok(segs)
}

fn psip(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let dim = it.opts.dime.max(2);
    let target = a.opt_with(mesh_or_point).ok_or_else(|| a.missing("MAILLAGE"))?;
    let crack_mesh = a.req::<Rc<Mesh>>()?;
    let crit = a.opt_num();
    if let Some(c) = crit {
        if !(c >= 0.0 && c.is_finite()) {
            return Err(a.err(format!("the distance criterion must be a positive number, not {}", c)));
        }
    }
    let crack = crack_of(it, a, &crack_mesh, dim)?;
    let fields = a.keyword(&["DEUX", "TROI"]);
    if fields == Some("TROI") && dim != 3 {
        return Err(a.err("'TROI' needs dimension 3"));
    }
    // The second level set: from the tips in 2D, from the front in 3D.
    let mut tips: Vec<Tip> = Vec::new();
    let mut front = Vec::new();
    if fields.is_some() {
        if dim == 2 {
            let p1 = a.req::<PointId>()?;
            tips.push(crack.tip(it.nodes.get(p1.0)));
            if let Some(p2) = a.opt::<PointId>() {
                tips.push(crack.tip(it.nodes.get(p2.0)));
            }
        } else {
            let m = a.req::<Rc<Mesh>>()?;
            front = front_of(it, a, &m)?;
        }
    }
    let (mut phi, mut psi, mut tau) =
        (Chpoint::new(Nature::Diffus), Chpoint::new(Nature::Diffus), Chpoint::new(Nature::Diffus));
    for n in target.node_list() {
        let x = it.nodes.get(n);
        let near = crack.nearest(x);
        if crit.is_some_and(|c| inf_distance(x, near.point) > c) {
            continue;
        }
        phi.add(n, "PHI", near.phi, false);
        if fields.is_some() {
            if dim == 2 {
                psi.add(n, "PSI", tip_level(&tips, x), false);
            } else {
                let (p, t) = crack.front_levels(&front, x);
                psi.add(n, "PSI", p, false);
                tau.add(n, "TAU", t, false);
            }
        }
    }
    let chpo = |c: Chpoint| Value::Chpo(Rc::new(c));
    Ok(match fields {
        None => vec![chpo(phi)],
        Some("DEUX") => vec![chpo(psi), chpo(phi)],
        _ => vec![chpo(psi), chpo(phi), chpo(tau)],
    })
}
