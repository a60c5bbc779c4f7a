//! Surfaces between lines: REGLER (a ruled surface) and COUTURE (a strip
//! of triangles). The algorithms are in `fem::meshing::{sweep, couture}`.

use super::mesh::{mesh_val, more_spacing, spacing, swept_surface};
use super::{Args, OpDef, PointId};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::fem::meshing as mg;
use crate::fem::meshing::couture::{couture, Other};
use crate::value::Value;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef { name: "REGL", signature: "LINE1 REGL (n) ('DINI' d1) ('DFIN' d2) LINE2", doc: "The ruled surface between two lines of the same type, element count and direction (QUA4, QUA8 from SEG3, TRI3 under OPTI ELEM TRI3). A surface in place of LINE1 is prolonged from its side 3, in place of LINE2 from its side 1.", example: "s = l1 regl 4 l2 ;", f: regl },
    OpDef { name: "COUT", signature: "COUT LINE1 LINE2|POINT", doc: "A strip of triangles stitching two lines running the same way (each triangle across the shorter diagonal), or a fan from a line to a point.", example: "s = cout l1 l2 ;", f: cout },
];

fn regl(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mut sp = spacing(a)?;
    let g1 = a.req::<Rc<Mesh>>()?;
    more_spacing(a, &mut sp)?;
    let g2 = a.req::<Rc<Mesh>>()?;
    more_spacing(a, &mut sp)?;
    // A surface stands for its side 3 (first) or side 1 (second), run
    // along side 1, and the result includes it.
    let is_surface = |m: &Mesh| m.parts.iter().any(|p| p.ty.dim() == 2);
    let l1 = if is_surface(&g1) { mg::inve(&mg::cote(&g1, 3)?)? } else { (*g1).clone() };
    let l2 = if is_surface(&g2) { mg::cote(&g2, 1)? } else { (*g2).clone() };
    if let Some(p) = l1.parts.iter().chain(&l2.parts).find(|p| p.ty.dim() != 1 && !p.is_empty()) {
        return Err(a.err(format!("expected two lines (SEG2 or SEG3), got {} elements", p.ty.name())));
    }
    let s = mg::sweep::between("REGL", &mut it.nodes, &l1, &l2, &sp)?;
    let mut s = swept_surface(it, s);
    if is_surface(&g1) {
        s = g1.union(&s);
    }
    if is_surface(&g2) {
        s = s.union(&g2);
    }
    Ok(mesh_val(s))
}

fn cout(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let l1 = a.req::<Rc<Mesh>>()?;
    let m = match a.opt::<Rc<Mesh>>() {
        Some(l2) => couture(&mut it.nodes, &l1, Other::Line(&l2))?,
        None => {
            let p = a.req::<PointId>()?;
            couture(&mut it.nodes, &l1, Other::Point(p.0))?
        }
    };
    Ok(mesh_val(m))
}
