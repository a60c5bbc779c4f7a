//! `CHAN 'RIGIDITE'|'MASSE'|'STRESSES' MMODEL MCHAML (subtype)`: an element
//! field moved to the integration points of its model's elements.

use super::model::formulation;
use super::post::zone_of;
use super::Args;
use crate::error::Result;
use crate::fem::element::gauss_points;
use crate::value::{Mchaml, Model, Value};
use std::rc::Rc;

/// Values at one point per element (a centre) hold at every integration
/// point; values at the nodes are interpolated there; values already at
/// those points stay. Zones of constants only (material data) are kept.
pub(crate) fn to_integration_points(a: &mut Args) -> Result<Vec<Value>> {
    let model = a.req::<Rc<Model>>()?;
    let m = a.req::<Rc<Mchaml>>()?;
    to_points(a, &model, &m)
}

/// The same once the model and field are read (also `CHAN 'CHAM' MCHAML
/// MMODEL 'STRESSES'`); an optional subtype word may follow.
pub(crate) fn to_points(a: &mut Args, model: &Model, m: &Mchaml) -> Result<Vec<Value>> {
    let mut out = m.clone();
    if let Some(sub) = a.opt::<String>() {
        if !sub.trim().is_empty() {
            out.subtype = sub.trim().to_uppercase();
        }
    }
    for z in out.zones.iter_mut() {
        if z.values.is_empty() {
            continue;
        }
        let mz = zone_of(model, z).ok_or_else(|| a.err("the field does not belong to this model"))?;
        let form = formulation(mz);
        let mut e = 0;
        let mut values = Vec::with_capacity(z.values.len());
        for part in &z.mesh.parts {
            let gauss = gauss_points(form, part.ty);
            for _ in part.elems() {
                let Some(v) = z.values.get(e) else { break };
                e += 1;
                let moved = if v.len() == gauss.len() && !z.at_nodes {
                    v.clone()
                } else if v.len() == 1 {
                    vec![v[0].clone(); gauss.len()]
                } else if z.at_nodes && v.len() == part.ty.nodes() {
                    gauss
                        .iter()
                        .map(|(p, _)| {
                            let n = crate::fem::shape::eval(part.ty, *p).n;
                            (0..z.comps.len()).map(|c| n.iter().zip(v).map(|(w, row)| w * row[c]).sum()).collect()
                        })
                        .collect()
                } else {
                    return Err(a.err(format!(
                        "cannot move the {} values of a {} element to its {} integration points",
                        v.len(),
                        part.ty.name(),
                        gauss.len()
                    )));
                };
                values.push(moved);
            }
        }
        z.values = values;
        z.at_nodes = false;
    }
    Ok(vec![Value::Mchaml(Rc::new(out))])
}
