//! VERSENS: the identity on a mesh, after checking that neighbouring
//! elements run the same way.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::fem::meshing::orient_check::opposed_neighbours;
use crate::value::Value;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "VERSENS",
    signature: "VERSENS MAILLAGE",
    doc: "The mesh itself; an error if two neighbouring elements are oriented in opposite directions (lines meeting end to end or start to start, surfaces running their shared edge the same way; ORIE makes them agree).",
    example: "l2 = versens (droi 2 (0. 0.) (1. 0.)) ;",
    f: versens,
}];

fn versens(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let m = a.req::<Rc<Mesh>>()?;
    if let Some((e1, e2)) = opposed_neighbours(&m) {
        return Err(a.err(format!(
            "elements {} and {} are neighbours oriented in opposite directions (ORIE orients a mesh)",
            e1 + 1,
            e2 + 1
        )));
    }
    Ok(vec![Value::Mesh(m)])
}
