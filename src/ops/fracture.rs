//! Operators the fracture procedures (G_THETA, CH_THETA) call on their
//! own fields.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::{Chpoint, Model, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "CFND",
    signature: "CFND CHPOINT MMODEL",
    doc: "Make a node field satisfy the conformity relations of a model's elements (between the nodes of incompatible or mixed elements). gibi's elements are all conforming, with no such relation: the field comes back as it is.",
    example: "p = 0. 0. ; t = manu 'CHPO' p 1 'UX' 1. ; s = (p droi 1 (1. 0.)) tran 1 (0. 1.) ; mo = mode s mecanique ; t2 = cfnd t mo ;",
    f: cfnd,
}];

fn cfnd(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let f = a.req::<Rc<Chpoint>>()?;
    a.req::<Rc<Model>>()?;
    Ok(vec![Value::Chpo(f)])
}
