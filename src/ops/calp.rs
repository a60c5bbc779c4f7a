//! CALP on shells: the stresses (or strains) of a continuum in a skin or
//! on the mid-surface, from a shell model's generalised ones. The
//! numerics are in `fem::skin`.

use super::model::{formulation, material_for};
use super::post::{to_gauss, zone_of};
use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::element::Formulation;
use crate::fem::{beam_skin, skin};
use crate::value::model::MchamlZone;
use crate::value::{Mchaml, Model, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "CALP",
    signature: "CALP MCHAML_SIGM|MCHAML_EPSI MCHAML_CARA MMODEL ('SUPE'|'MOYE'|'INFE') (shells) | CALP MCHAML_SIGM|MCHAML_EPSI MCHAML_CARA MMODEL (beams)",
    doc: "Of a shell model (COQ2, COQ3, DKT, COQ4): the stresses SMXX SMYY SMZZ SMXY (σ = N/t + 12Mζ/t³), or the strains EPXX EPYY EPZZ GAXY, in the element axes, on the upper skin ζ = t/2 (side of the normal), the mid-surface (default) or the lower skin; the thickness EPAI comes from the characteristics. Of a beam (POUT, TIMO): the axial stress SMXX = N/A + My·DZ/INRY − Mz·DY/INRZ (or strain EPXX) at the section point (DY, DZ) of the characteristics.",
    example: "opti dime 2 elem seg2 mode axis ; l = (1. 0.) droi 2 (1. 1.) ; mo = mode l mecanique elastique coq2 ; ma = mate mo youn 1. nu 0. epai 0.1 ; u = manu chpo l 3 'UR' 0.001 'UZ' 0. 'RT' 0. ; s = calp (sigm mo ma u) ma mo 'SUPE' ;",
    f: calp,
}];

fn calp(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mut fields: Vec<Rc<Mchaml>> = Vec::new();
    while let Some(f) = a.opt::<Rc<Mchaml>>() {
        fields.push(f);
    }
    let model = a.req::<Rc<Model>>()?;
    while let Some(f) = a.opt::<Rc<Mchaml>>() {
        fields.push(f);
    }
    let side = a.keyword(&["SUPE", "MOYE", "INFE"]).unwrap_or("MOYE");
    let (pos, field) = fields
        .iter()
        .enumerate()
        .find(|(_, f)| f.subtype == "CONTRAINTES" || f.subtype == "DEFORMATIONS")
        .ok_or_else(|| a.missing("MCHAML of stresses or strains (SIGM, EPSI)"))?;
    let others: Vec<Rc<Mchaml>> =
        fields.iter().enumerate().filter(|(i, _)| *i != pos).map(|(_, f)| f.clone()).collect();
    let mut out = Mchaml { subtype: field.subtype.clone(), zones: vec![] };
    for z in &field.zones {
        let mz = zone_of(&model, z).ok_or_else(|| a.err("the field does not belong to this model"))?;
        let form = formulation(mz);
        let mat = material_for(mz, &others);
        let mut nz = MchamlZone { mesh: z.mesh.clone(), element: z.element.clone(), ..Default::default() };
        nz.at_nodes = z.at_nodes;
        let beam = matches!(form, Formulation::Pout | Formulation::Timo);
        let (t, zeta) = if beam {
            (0.0, 0.0)
        } else {
            let t = mat.epai.filter(|t| *t > 0.0 && t.is_finite()).ok_or_else(|| {
                a.err("CALP needs the shell thickness: give the characteristics (MATE/CARA … 'EPAI' t)")
            })?;
            let zeta = match side {
                "SUPE" => 0.5 * t,
                "INFE" => -0.5 * t,
                _ => 0.0,
            };
            (t, zeta)
        };
        for e in 0..z.values.len() {
            let g = if beam {
                beam_skin::at_fibre(form.name(), &to_gauss(z, e), &mat)
            } else {
                skin::at_fibre(form, &to_gauss(z, e), t, zeta)
            }
            .map_err(|err| a.err(err.to_string()))?;
            if nz.comps.is_empty() {
                nz.comps = g.comps.iter().map(|c| c.to_string()).collect();
            }
            nz.values.push(g.values);
        }
        out.zones.push(nz);
    }
    Ok(vec![Value::Mchaml(Rc::new(out))])
}
