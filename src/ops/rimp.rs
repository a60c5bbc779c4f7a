//! RIMP: a directive that switches a complex EVOLUTIO (a transform) between
//! its two forms, real and imaginary parts (PREE PIMA) and modulus and
//! phase (MODU PHAS), in place: every name bound to the object sees it.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::signal::complex::switch_form;
use crate::value::{Evolution, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "RIMP",
    signature: "RIMP EVOLUTIO",
    doc: "Directive: a complex EVOLUTIO of real and imaginary parts (PREE PIMA) becomes modulus and phase in degrees (MODU PHAS), and the reverse, in place.",
    example: "e = evol 'COMP' 'REIM' (prog 1. 2.) (prog 0. 1.) (prog 1. 0.) ; rimp e ;",
    f: rimp,
}];

fn rimp(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let e = a.req::<Rc<Evolution>>()?;
    let new = switch_form(&e).ok_or_else(|| {
        a.err("the EVOLUTIO is not complex: it must be two curves PREE PIMA or MODU PHAS (as TFR or EVOL 'COMP' give)")
    })?;
    super::replace::rebind(it, &Value::Evol(e), &Value::Evol(Rc::new(new)));
    Ok(vec![])
}
