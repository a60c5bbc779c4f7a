//! KP: the stiffness of pressure loads that follow the structure. Only the
//! form with a pressure gradient (`KP MODL RG (VEC1)`) on the flat shells
//! is here; the numerics are in `fem::kp`.

use super::model::formulation;
use super::{Args, OpDef, PointId};
use crate::error::{Error, Result};
use crate::eval::Interp;
use crate::fem::kp;
use crate::value::rigidity::{Subtype, Symmetry};
use crate::value::{Model, Rigidite, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "KP",
    signature: "KP MMODEL RG (POINT_DIRECTION) ('FLAM') ('ASYM')",
    doc: "Stiffness of a pressure with a linear gradient of modulus RG along the direction VEC1 (default: each element's normal, then a Winkler soil of stiffness RG), seen by a moving shell (COQ3, DKT, DST, COQ4): K[(i,c),(j,d)] = RG ∫N_i N_j dA n_c g_d, so K u is the change of the pressure forces (along the normal n) when the structure moves by u. Non-symmetric when a direction is given.",
    example: "opti dime 3 elem tri3 ; s = (0. 0. 0.) (1. 0. 0.) (0. 1. 0.) mani 'TRI3' ; mo = mode s mecanique elastique dkt ; k = kp mo 1000. ;",
    f: kp_op,
}];

fn kp_op(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let model = a.req::<Rc<Model>>()?;
    let rg = a.opt::<f64>().ok_or_else(|| {
        a.err("KP needs the modulus RG of the pressure gradient (KP with a pressure field is not available)")
    })?;
    if !rg.is_finite() {
        return Err(a.err("KP: RG is not a finite number"));
    }
    let dir = a.opt::<PointId>().map(|p| it.nodes.get(p.0));
    let _ = a.keyword(&["FLAM"]);
    let _ = a.keyword(&["ASYM"]);
    let mut rig = Rigidite::new(Subtype::Rigidite);
    for zone in &model.zones {
        let form = formulation(zone);
        for part in &zone.mesh.parts {
            let symmetry = if dir.is_some() { Symmetry::General } else { Symmetry::Symmetric };
            let block = super::element_block::part_block(it, part, None, symmetry, |e, x| {
                kp::gradient_stiffness(form, x, rg, dir).map_err(|err| a.err(format!("KP: element {}: {}", e + 1, err)))
            })?;
            rig.blocks.push(block.ok_or_else(|| Error::runtime("KP: the model has no element"))?);
        }
    }
    Ok(vec![Value::Rigi(Rc::new(rig))])
}
