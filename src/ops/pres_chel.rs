//! `PRES mop CHEL1` (pres.notice, 2nd syntax): a pressure model's field
//! from an element field of one component, whatever its name. Values at
//! the nodes are kept; values at the element's points are carried to its
//! nodes as CHAN 'NOEUD' does, since the pressure forces interpolate the
//! pressure from the nodes.

use super::Args;
use crate::error::Result;
use crate::fem::element::GaussField;
use crate::fem::mesh::ElemType;
use crate::fem::stress::to_nodes;
use crate::value::model::MchamlZone;
use crate::value::{Mchaml, Model, Value};
use std::collections::HashMap;
use std::rc::Rc;

fn key(ty: ElemType, nodes: &[usize]) -> (ElemType, Vec<usize>) {
    let mut k = nodes.to_vec();
    k.sort_unstable();
    (ty, k)
}

pub(crate) fn field(a: &Args, model: &Model, chel: &Mchaml) -> Result<Vec<Value>> {
    let mut out = Mchaml { subtype: "CONTRAINTES".into(), zones: vec![] };
    // The values of each element, found by its nodes: the field's zones
    // need not cut the mesh as the model's do.
    let mut at: HashMap<(ElemType, Vec<usize>), (&MchamlZone, usize)> = HashMap::new();
    for c in &chel.zones {
        if c.comps.len() != 1 || c.values.is_empty() {
            return Err(a.err(format!(
                "the element field must have one component of point values, a zone has {}",
                c.comps.len()
            )));
        }
        let mut e = 0;
        for part in &c.mesh.parts {
            for nodes in part.elems() {
                at.entry(key(part.ty, nodes)).or_insert((c, e));
                e += 1;
            }
        }
    }
    for z in &model.zones {
        let form = super::model::formulation(z);
        let mut mz = MchamlZone { mesh: z.mesh.clone(), element: z.element.clone(), ..Default::default() };
        mz.comps = vec!["PRES".into()];
        mz.at_nodes = true;
        let mut e = 0;
        for part in &z.mesh.parts {
            for nodes in part.elems() {
                let (src, k) = at
                    .get(&key(part.ty, nodes))
                    .ok_or_else(|| a.err(format!("the element field has no values on element {}", e + 1)))?;
                let v = &src.values[*k];
                let vals = if src.at_nodes || v.len() == 1 {
                    (0..nodes.len()).map(|k| vec![v[if v.len() == 1 { 0 } else { k }][0]]).collect()
                } else {
                    let g = GaussField { comps: vec!["PRES"], values: v.clone() };
                    to_nodes(form, part.ty, &g).map_err(|err| a.err(format!("element {}: {}", e + 1, err)))?.values
                };
                mz.values.push(vals);
                e += 1;
            }
        }
        out.zones.push(mz);
    }
    Ok(vec![Value::Mchaml(Rc::new(out))])
}
