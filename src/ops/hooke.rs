//! HOOKE (alias HOOK): the field of Hooke matrices of a model and its
//! material, and the product of such a field with a strain field, σ = D ε
//! point by point (`HOO * EPS`, `HOO * MODL EPS`, `MODL HOO * EPS`).
//!
//! A Hooke field is a constant field by element of subtype MATRICE DE
//! HOOKE whose constants are the matrix entries named "STRESS/STRAIN"
//! (`fem::hooke_matrix`). Given to RIGI, SIGM or ELAS in place of the
//! material, those entries become the elasticity matrix (`material_for`).

use super::model::{formulation, material_for, zone_mode};
use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::hooke_matrix;
use crate::value::model::MchamlZone;
use crate::value::{Mchaml, Model, Value};
use std::rc::Rc;

/// The subtype that marks a field of Hooke matrices.
pub(crate) const SUBTYPE: &str = "MATRICE DE HOOKE";

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "HOOK",
    signature: "HOOK MMODEL MCHAML.. (MCHAML_VARINTER) ('REFE')",
    doc: "The field of Hooke matrices (subtype MATRICE DE HOOKE) of a model's elastic material: the mode's elasticity matrix for massive elements, KS…KN for joints, E·S for bars. Its product with a strain field (`hoo * eps`) gives the stresses; RIGI, SIGM and ELAS accept it in place of the material.",
    example: "opti dime 2 elem qua4 mode plan cont ; p1 = 0 0 ; p2 = 1 0 ; p3 = 1 1 ; p4 = 0 1 ; s = dall (d 1 p1 p2) (d 1 p2 p3) (d 1 p3 p4) (d 1 p4 p1) ; mo = mode s mecanique elastique ; ma = mate mo youn 1.0 nu 0.25 ; hoo = hook mo ma ;",
    f: hook,
}];

fn hook(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let model = a.req::<Rc<Model>>()?;
    let mut fields = Vec::new();
    while let Some(f) = a.opt::<Rc<Mchaml>>() {
        fields.push(f);
    }
    // 'REFE' matters only for offset thin shells, which have no Hooke
    // matrix here; internal variables only for damage models.
    a.keyword(&["REFE"]);
    let mut out = Mchaml { subtype: SUBTYPE.into(), zones: vec![] };
    for mz in &model.zones {
        let mode = zone_mode(mz)?;
        let m = material_for(mz, &fields);
        let mut zone = MchamlZone { mesh: mz.mesh.clone(), element: mz.element.clone(), ..Default::default() };
        for p in &mz.mesh.parts {
            let h = hooke_matrix::of_material(formulation(mz), p.ty, mode, &m)
                .map_err(|e| a.err(format!("zone of {} elements: {e}", mz.element)))?;
            for (k, v) in h.entries() {
                zone.constants.insert(k, v);
            }
        }
        out.zones.push(zone);
    }
    Ok(vec![Value::Mchaml(Rc::new(out))])
}

/// Whether a field holds Hooke matrices.
pub(crate) fn is_hooke(v: &Value) -> bool {
    matches!(v, Value::Mchaml(m) if m.subtype == SUBTYPE)
}

/// `HOO * EPS`: the stresses D ε at every point of the strain field, each
/// zone with the matrix of the Hooke zone on the same mesh. None when the
/// left operand is not a Hooke field (the ordinary product applies).
pub(crate) fn product(a: &Args, x: &Value, y: &Value) -> Result<Option<Value>> {
    let (Value::Mchaml(h), Value::Mchaml(eps)) = (x, y) else { return Ok(None) };
    if h.subtype != SUBTYPE || eps.subtype == SUBTYPE {
        return Ok(None);
    }
    let mut out = Mchaml { subtype: "CONTRAINTES".into(), zones: vec![] };
    for z in &eps.zones {
        let hz = h
            .zones
            .iter()
            .find(|w| w.mesh == z.mesh)
            .ok_or_else(|| a.err("the strain field has a zone where the Hooke field has no matrix"))?;
        let entries: Vec<(String, f64)> = hz.constants.iter().map(|(k, v)| (k.clone(), *v)).collect();
        let mut nz =
            MchamlZone { mesh: z.mesh.clone(), element: z.element.clone(), at_nodes: z.at_nodes, ..Default::default() };
        for elem in &z.values {
            let mut pts = Vec::with_capacity(elem.len());
            for point in elem {
                let (names, sig) = hooke_matrix::apply(&entries, &z.comps, point);
                if nz.comps.is_empty() {
                    nz.comps = names;
                }
                pts.push(sig);
            }
            nz.values.push(pts);
        }
        if !z.values.is_empty() && nz.comps.is_empty() {
            return Err(a.err("the Hooke field's matrices have no stress component"));
        }
        if z.values.is_empty() && !z.constants.is_empty() {
            // A uniform strain field: one point per zone, its constants.
            let names: Vec<String> = z.constants.keys().cloned().collect();
            let vals: Vec<f64> = z.constants.values().copied().collect();
            let (rows, sig) = hooke_matrix::apply(&entries, &names, &vals);
            nz.constants = rows.into_iter().zip(sig).collect();
        }
        out.zones.push(nz);
    }
    Ok(Some(Value::Mchaml(Rc::new(out))))
}
