//! CHPOINT (chpo.notice): a field on the primal unknowns of a RIGIDITE,
//! random ('ALEATOIRE', from the interpreter's generator, the one BRUI
//! uses, so a deck's values are reproducible) or uniform.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::rigidity::Rigidite;
use crate::value::signal::noise::Law;
use crate::value::{Chpoint, Nature, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "CHPO",
    signature: "CHPO 'ALEATOIRE' RIGIDITE | CHPO 'UNIFORME' FLOT1 RIGIDITE",
    doc: "A CHPOINT over the primal unknowns of the RIGIDITE (their nodes and component names): 'ALEATOIRE' draws each value uniformly in [0, 1] from the generator BRUI uses; 'UNIFORME' gives every unknown FLOT1.",
    example: "f = chpo 'ALEATOIRE' (k et cl) ;",
    f: chpo,
}];

fn chpo(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let kind = a.req_keyword(&["ALEATOIRE", "UNIFORME"])?;
    let uniform = if kind == "UNIFORME" { Some(a.req_num()?) } else { None };
    let rigi: Rc<Rigidite> = a.req()?;
    let unknowns = rigi.primal_unknowns();
    let values = match uniform {
        Some(v) => vec![v; unknowns.len()],
        None => it.noise.draw(Law::Uniform { mean: 0.5, half_width: 0.5 }, unknowns.len()).map_err(|e| a.err(e))?,
    };
    Ok(vec![Value::Chpo(Rc::new(Chpoint::from_entries(
        Nature::Diffus,
        unknowns.iter().zip(values).map(|((n, c), v)| (*n, c.as_str(), v)),
    )))])
}
