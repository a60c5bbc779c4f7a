//! KSIGMA: the geometric stiffness of a stress field (for buckling with
//! VIBR, or to stiffen a prestressed structure). The numerics are in
//! `fem::geometric`.

use super::model::{formulation, material_for, zone_mode};
use super::post::{to_gauss, zone_of};
use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::geometric;
use crate::value::rigidity::{Subtype, Symmetry};
use crate::value::{Mchaml, Model, Rigidite, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "KSIGMA",
    signature: "KSIGMA MMODEL MCHAML_STRESS (MCHAML_CARA) ('FLAM')",
    doc: "Geometric (initial stress) stiffness of a stress field on bars, beams (POUT, TIMO) and COQ2 in the plane modes: K = ∫ N d'ᵀd' along each element, N the normal force (EFFX, or N11 for COQ2). K u + λ KSIGMA(σ) u = 0 gives the buckling multipliers λ of σ (VIBR on K and −KSIGMA). 'FLAM' is accepted (the matrix is always the one for buckling).",
    example: "opti dime 2 elem seg2 mode plan cont ; l = (0. 0.) droi 2 (0. 1.) ; mo = mode l mecanique elastique pout ; ma = mate mo youn 1. nu 0.3 sect 1. inrz 1. ; u = manu chpo l 3 'UX' 0. 'UY' -1. 'RZ' 0. ; s = sigm mo ma u ; k = ksigma mo s ma 'FLAM' ;",
    f: ksigma,
}];

fn ksigma(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let model = a.req::<Rc<Model>>()?;
    let mut fields = Vec::new();
    loop {
        if let Some(f) = a.opt::<Rc<Mchaml>>() {
            fields.push(f);
        } else if a.keyword(&["FLAM"]).is_some() {
        } else if a.peek_word().is_some_and(|w| w.trim().is_empty()) {
            // A blank MOT stands for "no characteristics" (procedures pass
            // one when they have no CARA field).
            a.word();
        } else {
            break;
        }
    }
    let sig = fields
        .iter()
        .find(|f| f.zones.iter().any(|z| !z.values.is_empty()))
        .cloned()
        .ok_or_else(|| a.missing("MCHAML of stresses (from SIGM)"))?;
    let mut rig = Rigidite::new(Subtype::Rigidite);
    for z in &sig.zones {
        let mz = zone_of(&model, z).ok_or_else(|| a.err("the stress field does not belong to this model"))?;
        let (form, mode) = (formulation(mz), zone_mode(mz)?);
        let mat = material_for(mz, &fields);
        let mut first = 0;
        for part in &z.mesh.parts {
            let block = super::element_block::part_block(it, part, None, Symmetry::Symmetric, |e, x| {
                let k = first + e;
                if k >= z.values.len() {
                    return Err(a.err(format!("the stress field has no values on element {}", k + 1)));
                }
                geometric::stiffness(form, mode, x, &mat, &to_gauss(z, k))
                    .map_err(|err| a.err(format!("element {}: {}", k + 1, err)))
            })?;
            first += part.len();
            if let Some(b) = block {
                rig.blocks.push(b);
            }
        }
    }
    if rig.blocks.is_empty() {
        return Err(a.err("the stress field has no element"));
    }
    Ok(vec![Value::Rigi(Rc::new(rig))])
}
