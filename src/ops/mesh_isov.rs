//! ISOV (ISOVALEUR): the mesh where an element field given at the nodes
//! equals a value ('EGAL'), or the parts of its elements where it is at
//! most ('EGINFE') or at least ('EGSUPE') that value. The cutting is
//! `fem::meshing::isovalue`; this file reads the Gibiane arguments.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::meshing::isovalue::{isovalue, IsoElement, IsoMode};
use crate::value::{Mchaml, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "ISOV",
    signature: "ISOV MCHAML ('EGAL' | 'EGINFE' | 'EGSUPE') value",
    doc: "Isovalue of a one-component element field at the nodes of linear elements (CHAN 'NOEUD'): points of SEG2, SEG2 of TRI3/QUA4, TRI3/QUA4 of TET4/CUB8 where it equals the value; with 'EGINFE' / 'EGSUPE' the parts of the elements where it is at most / at least the value.",
    example: "iso1 = isov (chan 'CHAM' t mo 'NOEUD') 0.5 ;",
    f: isov,
}];

fn isov(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let field = a.req::<Rc<Mchaml>>()?;
    let mode = match a.keyword(&["EGAL", "EGINFE", "EGSUPE"]) {
        Some("EGINFE") => IsoMode::AtMost,
        Some("EGSUPE") => IsoMode::AtLeast,
        _ => IsoMode::Equal,
    };
    let v = a.req_num()?;
    if !v.is_finite() {
        return Err(a.err(format!("the value must be finite (got {v})")));
    }
    let mut elems = Vec::new();
    let mut buf: Vec<Vec<f64>> = Vec::new();
    for z in &field.zones {
        if z.comps.len() != 1 {
            return Err(a.err(format!(
                "the field must have one component, not {} ({})",
                z.comps.len(),
                z.comps.join(", ")
            )));
        }
        let mut e = 0;
        for p in &z.mesh.parts {
            for nodes in p.elems() {
                let pts = z.values.get(e).ok_or_else(|| a.err("the field has fewer values than elements"))?;
                if pts.len() != nodes.len() {
                    return Err(a.err(format!(
                        "the field must be given at the nodes of its elements (CHAN 'NOEUD'): a {} element has {} values for {} nodes",
                        p.ty.name(),
                        pts.len(),
                        nodes.len()
                    )));
                }
                buf.push(pts.iter().map(|c| c[0]).collect());
                e += 1;
            }
        }
    }
    let mut k = 0;
    for z in &field.zones {
        for p in &z.mesh.parts {
            for nodes in p.elems() {
                elems.push(IsoElement { ty: p.ty, nodes, values: &buf[k] });
                k += 1;
            }
        }
    }
    let mesh = isovalue(&mut it.nodes, &elems, v, mode)?;
    Ok(vec![Value::Mesh(Rc::new(mesh))])
}
