//! CMCT (cmct.notice): the multipliers of `[M Cᵀ; C 0]` condensed, M
//! diagonal and given inverted as a field: C M⁻¹ Cᵀ over the LX unknowns.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::rigidity::Rigidite;
use crate::value::{Chpoint, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "CMCT",
    signature: "CMCT RIGIDITE CHPOINT",
    doc: "C M⁻¹ Cᵀ: the conditions C of the RIGIDITE condensed through the diagonal M⁻¹ given as a CHPOINT on their unknowns (INVE of a lumped mass; a node absent from the field counts as held, M⁻¹ = 0); a RIGIDITE over the multiplier unknowns LX.",
    example: "h = cmct (bloq p1 'UX') (manu chpo p1 1 'UX' 0.5) ;",
    f: cmct,
}];

fn cmct(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let r: Rc<Rigidite> = a.req()?;
    let minv: Rc<Chpoint> = a.req()?;
    if r.conds.is_empty() {
        return Err(a.err("the RIGIDITE holds no condition"));
    }
    // A node the field does not hold at all has no mass to invert: it is
    // held (a rigid obstacle outside the model, as IMPO 'IMPA' links the
    // moving nodes to), so it counts for 0; a node that the field holds
    // without that component is still an error.
    let held: std::collections::HashSet<usize> = minv.nodes.iter().copied().collect();
    let h = r.cmct(|n, c| if held.contains(&n) { minv.get(n, c) } else { Some(0.0) }).map_err(|e| a.err(e))?;
    Ok(vec![Value::Rigi(Rc::new(h))])
}
