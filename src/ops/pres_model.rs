//! Pressure loading models (mode.notice, formulation CHARGEMENT):
//! `mop = MODE line 'CHARGEMENT' 'PRESSION' (COQ2)`, `chp = PRES mop 'PRES'
//! p|CHPOINT` (the pressure at the element nodes, an MCHAML) and
//! `BSIG mop chp` (the nodal forces it makes).
//!
//! The line must be oriented: a positive pressure pushes along the left
//! normal of each segment (its direction turned by +90°), the side of the
//! solid for a contour run counter-clockwise, and the normal of COQ2.
//! Lines (SEG2, SEG3) in the 2D modes, surfaces (TRI3, QUA4, TRI6, QUA8) in
//! TRID, where a positive pressure pushes along x_ξ × x_η (the normal
//! right-handed with the node order). The forces are the consistent ones
//! (∫ p N n over the face, p interpolated from the nodes); in AXIS for the
//! whole ring, as the stiffness; per unit thickness in the plane modes
//! (times DIM3 when the fields give one).

use super::model::{material_for, zone_mode};
use super::Args;
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::element::Mode;
use crate::fem::loads;
use crate::fem::mesh::Mesh;
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
    while let Some(w) = a.keyword_next(&["PRESSION", "CONS"]).map(String::from).or_else(|| a.word_not_operator()) {
        let w = w.trim().to_uppercase();
        // The constituent's name labels the zone; gibi's zones do not keep
        // one (REDU and EXTR select by mesh, formulation or behaviour).
        if w == "CONS" {
            a.word().ok_or_else(|| a.missing("the constituent's name after 'CONS'"))?;
            continue;
        }
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
        .map(|p| ModelZone::on_part(p, FORMULATION, &behaviour, element.as_deref(), &it.opts.mode))
        .collect();
    Ok(vec![Value::Model(Rc::new(Model { zones, ties: Vec::new() }))])
}

/// PRES mop 'PRES' p|CHPOINT: the pressure at every element node.
pub(crate) fn field(a: &mut Args, model: &Model) -> Result<Vec<Value>> {
    if let Some(chel) = a.opt::<Rc<Mchaml>>() {
        return super::pres_chel::field(a, model, &chel);
    }
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
        let form = super::model::formulation(mz);
        if form.is_shell() && form != crate::fem::element::Formulation::Coq2 {
            super::pres_shell::forces(it, a, form, z, c, &mut out)?;
            continue;
        }
        let mode = zone_mode(mz)?;
        let width = material_for(mz, fields).dim3.unwrap_or(1.0);
        let names: &[&str] = match mode {
            Mode::Axis | Mode::Fourier(_) => &["FR", "FZ"],
            Mode::Trid => &["FX", "FY", "FZ"],
            _ => &["FX", "FY"],
        };
        // Edges push along their left normal, surfaces along x_ξ × x_η.
        let sign = if mode == Mode::Trid { 1.0 } else { -1.0 };
        let mut e = 0;
        for part in &z.mesh.parts {
            for nodes in part.elems() {
                let v =
                    z.values.get(e).ok_or_else(|| a.err(format!("the field has no values on element {}", e + 1)))?;
                let at =
                    |k: usize| v.get(if z.at_nodes { k } else { 0 }).and_then(|r| r.get(c)).copied().unwrap_or(0.0);
                let x: Vec<[f64; 3]> = nodes.iter().map(|n| it.nodes.get(*n)).collect();
                // Per unit thickness in the plane modes, or per DIM3.
                let scale = if matches!(mode, Mode::Axis | Mode::Fourier(_) | Mode::Trid) { 1.0 } else { width };
                let p: Vec<f64> = (0..nodes.len()).map(|k| scale * at(k)).collect();
                let f = loads::pressure_load_signed(part.ty, mode, &x, &p, sign).map_err(|err| {
                    a.err(format!(
                        "element {} ({}, pressure models take lines SEG2 SEG3 in the 2D modes, \
                         surfaces TRI3 QUA4 TRI6 QUA8 in TRID): {}",
                        e + 1,
                        part.ty.name(),
                        err
                    ))
                })?;
                for (k, n) in nodes.iter().enumerate() {
                    for (d, name) in names.iter().enumerate() {
                        out.add(*n, name, f[k][d], true);
                    }
                }
                e += 1;
            }
        }
    }
    Ok(vec![Value::Chpo(Rc::new(out))])
}
