//! Pressure loading models (mode.notice, formulation CHARGEMENT):
//! `mop = MODE line 'CHARGEMENT' 'PRESSION' (COQ2)`, `chp = PRES mop 'PRES'
//! p|CHPOINT` (the pressure at the element nodes, an MCHAML) and
//! `BSIG mop chp` (the nodal forces it makes).
//!
//! The line must be oriented: a positive pressure pushes along the left
//! normal of each segment (its direction turned by +90°), the side of the
//! solid for a contour run counter-clockwise, and the normal of COQ2.
//! Lines (SEG2) in the 2D modes only; in AXIS for the whole ring on COQ2
//! (as its stiffness, see `fem::coq2`), per radian on massive edges; per unit
//! thickness in the plane modes (times DIM3 when the fields give one).

use super::model::{material_for, zone_mode};
use super::Args;
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::coq2;
use crate::fem::mesh::{ElemType, Mesh};
use crate::value::model::{MchamlZone, ModelZone};
use crate::value::{Chpoint, Mchaml, Model, Nature, Value};
use std::rc::Rc;

/// The formulation name of these models.
pub(crate) const FORMULATION: &str = "CHARGEMENT";

pub(crate) fn is_pressure_model(m: &Model) -> bool {
    !m.zones.is_empty() && m.zones.iter().all(|z| z.formulation == FORMULATION)
}

/// MODE geo 'CHARGEMENT' 'PRESSION' (element): one zone per mesh part.
pub(crate) fn model(it: &Interp, a: &mut Args, geo: &Mesh) -> Result<Vec<Value>> {
    let mut behaviour = Vec::new();
    let mut element = None;
    while let Some(w) = a.keyword_next(&["PRESSION"]).map(String::from).or_else(|| a.word_not_operator()) {
        let w = w.trim().to_uppercase();
        if "PRESSION".starts_with(&w) && w.len() >= 4 {
            behaviour.push("PRESSION".to_string());
        } else {
            element = Some(w);
        }
    }
    if behaviour.is_empty() {
        return Err(a.err("a CHARGEMENT model names its load: MODE geo 'CHARGEMENT' 'PRESSION'"));
    }
    let zones = geo
        .parts
        .iter()
        .map(|p| ModelZone {
            mesh: Mesh::single(p.clone()),
            formulation: FORMULATION.into(),
            behaviour: behaviour.clone(),
            element: element.clone().unwrap_or_else(|| p.ty.name().into()),
            mode: it.opts.mode.clone(),
        })
        .collect();
    Ok(vec![Value::Model(Rc::new(Model { zones }))])
}

/// PRES mop 'PRES' p|CHPOINT: the pressure at every element node.
pub(crate) fn field(a: &mut Args, model: &Model) -> Result<Vec<Value>> {
    a.req_keyword(&["PRES"])?;
    let chpo = a.opt::<Rc<Chpoint>>();
    let p = match &chpo {
        Some(_) => None,
        None => Some(a.req_num()?),
    };
    let mut out = Mchaml { subtype: "CONTRAINTES".into(), zones: vec![] };
    for z in &model.zones {
        let mut mz = MchamlZone { mesh: z.mesh.clone(), element: z.element.clone(), ..Default::default() };
        mz.comps = vec!["PRES".into()];
        mz.at_nodes = true;
        for part in &z.mesh.parts {
            for nodes in part.elems() {
                let vals = nodes
                    .iter()
                    .map(|n| {
                        vec![p.unwrap_or_else(|| {
                            chpo.as_ref()
                                .and_then(|c| c.get(*n, "P"))
                                .or_else(|| chpo.as_ref().and_then(|c| c.get(*n, "PRES")))
                                .unwrap_or(0.0)
                        })]
                    })
                    .collect();
                mz.values.push(vals);
            }
        }
        out.zones.push(mz);
    }
    Ok(vec![Value::Mchaml(Rc::new(out))])
}

/// BSIG mop chp: nodal forces of the pressure field.
pub(crate) fn forces(it: &Interp, a: &Args, model: &Model, fields: &[Rc<Mchaml>]) -> Result<Vec<Value>> {
    let pres = fields
        .iter()
        .find(|f| f.zones.iter().any(|z| z.comps.iter().any(|c| c == "PRES")))
        .ok_or_else(|| a.missing("MCHAML of pressures (from PRES mop 'PRES' p)"))?;
    let mut out = Chpoint::new(Nature::Discret);
    for z in &pres.zones {
        let c = z.comps.iter().position(|c| c == "PRES").unwrap_or(0);
        let mz =
            super::post::zone_of(model, z).ok_or_else(|| a.err("the pressure field does not belong to this model"))?;
        let mode = zone_mode(mz)?;
        let width = material_for(mz, fields).dim3.unwrap_or(1.0);
        let names: [&str; 2] = if mode == crate::fem::element::Mode::Axis { ["FR", "FZ"] } else { ["FX", "FY"] };
        let mut e = 0;
        let trid = mode == crate::fem::element::Mode::Trid;
        for part in &z.mesh.parts {
            // SEG2 (and COQ2) keep their own integration; other lines of
            // the plane modes and surfaces in TRID use the face loads.
            let general = match part.ty {
                ElemType::Seg2 if !trid => false,
                ElemType::Seg3 if !trid && mode != crate::fem::element::Mode::Axis => true,
                t if trid && t.dim() == 2 && t.joint_face().is_none() => true,
                t => {
                    return Err(a.err(format!(
                        "pressure models are available on lines (SEG2, SEG3) in the plane modes, SEG2 in AXIS and surfaces in TRID, not on {} elements in mode {}",
                        t.name(),
                        mode.name()
                    )))
                }
            };
            for nodes in part.elems() {
                let v =
                    z.values.get(e).ok_or_else(|| a.err(format!("the field has no values on element {}", e + 1)))?;
                let at =
                    |k: usize| v.get(if z.at_nodes { k } else { 0 }).and_then(|r| r.get(c)).copied().unwrap_or(0.0);
                let x: Vec<[f64; 3]> = nodes.iter().map(|n| it.nodes.get(*n)).collect();
                if general {
                    let scale = if trid { 1.0 } else { width };
                    let p: Vec<f64> = (0..nodes.len()).map(|k| at(k) * scale).collect();
                    let f = crate::fem::loads::oriented_pressure_load(part.ty, mode, &x, &p)
                        .map_err(|err| a.err(format!("element {}: {}", e + 1, err)))?;
                    let names: &[&str] = if trid { &["FX", "FY", "FZ"] } else { &names };
                    for (n, fk) in nodes.iter().zip(&f) {
                        for (d, name) in names.iter().enumerate() {
                            out.add(*n, name, fk[d], true);
                        }
                    }
                    e += 1;
                    continue;
                }
                let f = coq2::pressure_load(mode, &x, [at(0), at(1)], width, mz.element == "COQ2")
                    .map_err(|err| a.err(format!("element {}: {}", e + 1, err)))?;
                for (k, n) in nodes.iter().enumerate() {
                    for (d, name) in names.iter().enumerate() {
                        out.add(*n, name, f[3 * k + d], true);
                    }
                }
                e += 1;
            }
        }
    }
    Ok(vec![Value::Chpo(Rc::new(out))])
}
