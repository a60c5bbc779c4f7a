//! FOFI: nodal forces of a stress field S through the gradient of a field
//! U, whose work in any V is ∫ S : (∇V·∇U) (fofi.notice), on massive
//! models. The numerics, and why this pairing, are in `fem::fofi`.

use super::model::{formulation, material_for, zone_mode};
use super::post::{to_gauss, zone_of};
use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::element::{self, Formulation, GaussField};
use crate::fem::solid::gradient_comps;
use crate::value::model::MchamlZone;
use crate::value::{Chpoint, Mchaml, Model, Nature, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "FOFI",
    signature: "FOFI MMODEL MCHAML_STRESS MCHAML_GRADIENT (MCHAML_CARA)",
    doc: "Nodal forces F of a stress field S through the gradient field of a displacement U (GRAD): the forces whose work in any V is ∫ S : (∇V·∇U) = ∫ S_ij V_i,k U_k,j, the analogue of BSIG for terms quadratic in the gradients (with the hoop term S_θθ U_r V_r / r² in AXIS); G_THETA's DJ/DA uses it for the stiffness derivative of a moving mesh. Massive elements only.",
    example: "f = fofi mo sig (grad mo u) ;",
    f: fofi,
}];

fn fofi(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let model = a.req::<Rc<Model>>()?;
    let mut fields = Vec::new();
    while let Some(f) = a.opt::<Rc<Mchaml>>() {
        fields.push(f);
    }
    let is_grad = |f: &Mchaml| f.zones.iter().any(|z| z.comps.iter().any(|c| c == "UX,X" || c == "UR,R"));
    let is_sig = |f: &Mchaml| f.zones.iter().any(|z| z.comps.iter().any(|c| c == "SMXX" || c == "SMRR"));
    let sig = fields.iter().find(|f| is_sig(f)).cloned().ok_or_else(|| a.missing("MCHAML of stresses (SIGM)"))?;
    let grad = fields
        .iter()
        .find(|f| is_grad(f))
        .cloned()
        .ok_or_else(|| a.missing("MCHAML of displacement gradients (GRAD)"))?;
    let mut out = Chpoint::new(Nature::Discret);
    for z in &sig.zones {
        let mz = zone_of(&model, z).ok_or_else(|| a.err("the stress field does not belong to this model"))?;
        let (form, mode) = (formulation(mz), zone_mode(mz)?);
        if !matches!(form, Formulation::Solid | Formulation::Q4ri | Formulation::Q8ri | Formulation::Incomp) {
            return Err(a.err(format!("only massive elements are handled; the model has {} elements", mz.element)));
        }
        let g = grad
            .zones
            .iter()
            .find(|g| g.mesh == z.mesh && g.values.len() == z.values.len())
            .ok_or_else(|| a.err("the stress and gradient fields are not on the same zones and elements"))?;
        if g.at_nodes != z.at_nodes || z.at_nodes {
            return Err(a.err("the fields must be at the stress points, not at the nodes (CHAN 'NOEUD')"));
        }
        let mat = material_for(mz, &fields);
        let duals = element::node_duals(form, mode).map_err(|e| a.err(e.to_string()))?;
        super::integrate::scatter_forces(it, a, z, duals, &mut out, |ty, x, e| {
            crate::fem::fofi::quadratic_forces(form, ty, mode, x, &mat, &to_gauss(z, e), &gradient_of(g, e, mode))
        })?;
    }
    Ok(vec![Value::Chpo(Rc::new(out))])
}

/// The gradient values of element `e` under GRAD's nine names, in their
/// order; a term the field lacks is left out (the element reports it).
fn gradient_of(g: &MchamlZone, e: usize, mode: crate::fem::element::Mode) -> GaussField {
    let names = gradient_comps(mode);
    let cols: Vec<Option<usize>> = names.iter().map(|n| g.comps.iter().position(|c| c == n)).collect();
    let comps = names.iter().zip(&cols).filter(|(_, c)| c.is_some()).map(|(n, _)| *n).collect();
    let values = g.values[e]
        .iter()
        .map(|pt| cols.iter().flatten().map(|c| pt.get(*c).copied().unwrap_or(0.0)).collect())
        .collect();
    GaussField { comps, values }
}
