//! RACCORD and LIAISON: the joint elements (RAC2, RAC3, LIA3, LIA4)
//! between two facing lines or surfaces; the pairing is in
//! `fem::meshing::joints`.

use super::mesh::mesh_val;
use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::fem::meshing::joints::joints;
use crate::value::Value;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef { name: "RACC", signature: "RACC (CRIT) LINE1 LINE2", doc: "Joint elements (RAC2 from SEG2, RAC3 from SEG3) between the elements of LINE1 and those of LINE2 whose nodes lie within CRIT of theirs (default: a tenth of the density). Nodes: LINE1's element, then the facing nodes of LINE2 in the same order; model them with JOI2 or JOI3.", example: "l1 = (0. 0.) d 1 (1. 0.) ; l2 = (0. 0.) d 1 (1. 0.) ; j = racc 1.e-5 l1 l2 ;", f: racc },
    OpDef { name: "LIAI", signature: "LIAI (CRIT) SURF1 SURF2", doc: "Joint elements (LIA4 from QUA4, LIA3 from TRI3) between the elements of SURF1 and those of SURF2 whose nodes lie within CRIT of theirs (default: a tenth of the density). Nodes: SURF1's element, then the facing nodes of SURF2 in the same order; model them with JOI4.", example: "opti dime 3 elem qua4 ; s1 = ((0. 0. 0.) d 1 (1. 0. 0.)) tran 1 (0. 1. 0.) ; s2 = ((0. 0. 0.) d 1 (1. 0. 0.)) tran 1 (0. 1. 0.) ; j = liai 1.e-5 s1 s2 ;", f: liai },
];

fn racc(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    pair(it, a, "RACC", true)
}

fn liai(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    pair(it, a, "LIAI", false)
}

fn pair(it: &mut Interp, a: &mut Args, op: &'static str, lines: bool) -> Result<Vec<Value>> {
    let crit = a.opt::<f64>();
    let g1 = a.req::<Rc<Mesh>>()?;
    let crit = crit.or_else(|| a.opt::<f64>()).unwrap_or(it.opts.dens / 10.0);
    let g2 = a.req::<Rc<Mesh>>()?;
    Ok(mesh_val(joints(op, &it.nodes, &g1, &g2, crit, lines)?))
}
