//! WORK: the trace Tr(σ·G) of a stress field with a displacement-gradient
//! field (as GRAD gives it), point by point on a massive model; the
//! G-theta procedures integrate it (INTG) into energy-release terms.
//! The numerics are in `fem::work`.

use super::model::{formulation, zone_mode};
use super::post::zone_of;
use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::element::Formulation;
use crate::fem::work::stress_gradient_trace;
use crate::value::model::MchamlZone;
use crate::value::{Mchaml, Model, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "WORK",
    signature: "WORK MMODEL MCHAML_STRESS MCHAML_GRADIENT (MCHAML_GRAF)",
    doc: "Trace of the product of a stress field with a displacement-gradient field (GRAD), Tr(σ·G) = Σ σij Gji, at the stress points of massive elements: one component SCAL; INTG of it is the work of σ in the gradient. The bending gradients GRAF are for thin shells, which gibi does not handle here.",
    example: "w = intg mo (work mo sig (grad mo u)) ;",
    f: work,
}];

const STRESS_FIRST: &[&str] = &["SMXX", "SMRR"];

fn is_stress(f: &Mchaml) -> bool {
    super::thermo::holds(f, STRESS_FIRST)
}

// One wording of "these are the components" for every field operator.
use super::thermo::comps_of;

fn work(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let model = a.req::<Rc<Model>>()?;
    let f1 = a.req::<Rc<Mchaml>>()?;
    let f2 = a.req::<Rc<Mchaml>>()?;
    if a.opt::<Rc<Mchaml>>().is_some() {
        return Err(a.err("the bending gradient field (GRAF) is for thin shells, which WORK does not handle in gibi"));
    }
    for mz in &model.zones {
        let form = formulation(mz);
        if !matches!(form, Formulation::Solid | Formulation::Q4ri | Formulation::Q8ri | Formulation::Incomp) {
            return Err(a.err(format!("only massive elements are handled; the model has {} elements", mz.element)));
        }
    }
    // Cast3M takes the stress and gradient fields in either order.
    let (sig, grad) = match (is_stress(&f1), is_stress(&f2)) {
        (true, false) => (f1, f2),
        (false, true) => (f2, f1),
        _ => {
            return Err(a.err(format!(
                "one stress field (SMXX …) and one gradient field (GRAD) are needed; the fields have {} and {}",
                comps_of(&f1),
                comps_of(&f2)
            )))
        }
    };
    let mut out = Mchaml { subtype: "SCALAIRE".into(), zones: vec![] };
    for z in &sig.zones {
        let mz = zone_of(&model, z).ok_or_else(|| a.err("the stress field does not belong to this model"))?;
        let mode = zone_mode(mz).map_err(|e| a.err(e.to_string()))?;
        let g = grad
            .zones
            .iter()
            .find(|g| g.mesh == z.mesh)
            .ok_or_else(|| a.err("the stress and gradient fields are not on the same zones"))?;
        if g.values.len() != z.values.len() {
            return Err(a.err("the stress and gradient fields do not have the same elements"));
        }
        if g.at_nodes != z.at_nodes {
            return Err(a.err("one field is at the nodes (CHAN 'NOEUD'), the other at the stress points"));
        }
        let mut nz = MchamlZone {
            mesh: z.mesh.clone(),
            element: z.element.clone(),
            comps: vec!["SCAL".into()],
            at_nodes: z.at_nodes,
            ..Default::default()
        };
        let types = z.mesh.parts.iter().flat_map(|p| p.elems().map(move |_| p.ty));
        for (e, ty) in types.enumerate().take(z.values.len()) {
            let w = stress_gradient_trace(mode, ty.name(), &z.comps, &z.values[e], &g.comps, &g.values[e])
                .map_err(|err| a.err(format!("element {}: {}", e + 1, err)))?;
            nz.values.push(w.into_iter().map(|v| vec![v]).collect());
        }
        if nz.values.len() != z.values.len() {
            return Err(a.err("the stress field has more elements than its mesh"));
        }
        out.zones.push(nz);
    }
    Ok(vec![Value::Mchaml(Rc::new(out))])
}

/// `G1 * MODL G2` of two gradient fields (aaa2.notice, remark 5): the
/// matrix product point by point, as the G-theta procedures chain
/// ∇u·∇θ. None when the fields are not both gradient fields, for the
/// component-wise product to apply.
pub(crate) fn gradient_product(a: &Args, x: &Value, y: &Value) -> Result<Option<Value>> {
    let (Value::Mchaml(x), Value::Mchaml(y)) = (x, y) else { return Ok(None) };
    let mode_of = |f: &Mchaml| f.zones.first().and_then(|z| crate::fem::work::gradient_mode(&z.comps));
    let Some(mode) = mode_of(x) else { return Ok(None) };
    if mode_of(y).is_none() {
        return Ok(None);
    }
    let mut out = Mchaml { subtype: x.subtype.clone(), zones: vec![] };
    for z in &x.zones {
        let w = y
            .zones
            .iter()
            .find(|w| w.mesh == z.mesh && w.values.len() == z.values.len())
            .ok_or_else(|| a.err("the two gradient fields are not on the same zones and elements"))?;
        let mut nz =
            MchamlZone { mesh: z.mesh.clone(), element: z.element.clone(), at_nodes: z.at_nodes, ..Default::default() };
        let types = z.mesh.parts.iter().flat_map(|p| p.elems().map(move |_| p.ty));
        for (e, ty) in types.enumerate().take(z.values.len()) {
            let (names, v) =
                crate::fem::work::gradient_product(mode, ty.name(), &z.comps, &z.values[e], &w.comps, &w.values[e])
                    .map_err(|err| a.err(format!("element {}: {}", e + 1, err)))?;
            if nz.comps.is_empty() {
                nz.comps = names.iter().map(|n| n.to_string()).collect();
            }
            nz.values.push(v);
        }
        out.zones.push(nz);
    }
    Ok(Some(Value::Mchaml(Rc::new(out))))
}
