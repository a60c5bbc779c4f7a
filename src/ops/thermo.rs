//! Thermal loading and stress post-processing on element fields: EPTH
//! (thermal strains of a temperature field), ELAS (Hooke's law on a strain
//! field), ENER (strain energy density), INVA (stress invariants) and TRES
//! (Tresca stress). The point-wise laws live in `fem::constitutive`.
//!
//! The Cast3M idiom for a thermal load in linear statics:
//! `EPT = EPTH mo ma t ; U = RESO k (BSIG mo (ELAS mo ma EPT)) ;` then the
//! stresses `SIGM mo ma u - ELAS mo ma EPT`.

use super::model::{formulation, material_for, zone_mode};
use super::post::{model_args, to_gauss, zone_of};
use super::thermo_field::ElementTemps;
use super::{Args, OpDef};
use crate::error::{Error, Result};
use crate::eval::Interp;
use crate::fem::constitutive;
use crate::fem::element::{FemError, GaussField};
use crate::fem::mesh::{ElemType, Mesh};
use crate::value::model::{MchamlZone, ModelZone};
use crate::value::{Chpoint, Mchaml, Model, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef { name: "EPTH", signature: "EPTH MMODEL MCHAML (CHPOINT_T | MCHAML_T)", doc: "Thermal strains α(T − TREF) at the element points, from a temperature CHPOINT (component T) and the material's ALPH (TREF 0 by default). EPZZ = αΔT in the plane modes; bars and beams: EPSS of the element's mean temperature.", example: "ept = epth mo ma t ;", f: epth },
    OpDef { name: "ELAS", signature: "ELAS MMODEL MCHAML MCHAML_STRAIN|MCHAML_STRESS", doc: "Hooke's law on a strain field: the stresses (SMXX …, or EFFX … for bars and beams) of strains such as those of EPSI or EPTH; on a stress field of massive elements, the strains (EPXX …).", example: "sth = elas mo ma (epth mo ma t) ;", f: elas },
    OpDef { name: "THET", signature: "THET MMODEL MCHAML (CHPOINT_T | MCHAML_T)", doc: "Stresses of the thermal strains of a temperature CHPOINT (component T): ELAS mo ma (EPTH mo ma t) in one step.", example: "sth = thet mo ma t ;", f: thet },
    OpDef { name: "ENER", signature: "ENER (MMODEL) MCHAML_STRESS MCHAML_STRAIN", doc: "Contracted product σ:ε of a stress and a strain field (component SCAL, as Cast3M names a SCALAIRE field; per unit length for bars and beams): twice the strain energy density, so INTG of 0.5 * ENER is the strain energy.", example: "w = 0.5 * (intg mo (ener mo sig eps)) ;", f: ener },
    OpDef { name: "INVA", signature: "INVA MMODEL MCHAML_STRESS", doc: "Stress invariants of massive elements: I1 = tr σ, J2 = ½ s:s and J3 = det s of the deviator s (σzz, σθθ included); √(3 J2) is the von Mises stress.", example: "inv = inva mo sig ;", f: inva },
    OpDef { name: "TRES", signature: "TRES MMODEL MCHAML_STRESS (MCHAML)", doc: "Tresca equivalent stress σ1 − σ3 (component TRES) of massive elements, the out-of-plane stress included.", example: "tr = tres mo sig ;", f: tres },
];

fn fem_err(a: &Args, e: usize, err: FemError) -> Error {
    a.err(format!("element {}: {}", e + 1, err))
}

fn put(z: &mut MchamlZone, g: GaussField) {
    if z.comps.is_empty() {
        z.comps = g.comps.iter().map(|c| c.to_string()).collect();
    }
    z.values.push(g.values);
}

fn epth(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let (model, fields, t) = model_args(a)?;
    let temps = temperatures(a, &fields, t)?;
    Ok(vec![Value::Mchaml(Rc::new(thermal_strains(a, &model, &fields, &temps)?))])
}

/// Where the temperatures come from: a CHPOINT (component T), or an element
/// field among the MCHAMLs that holds T (the others stay material fields).
enum Temps {
    Nodes(Rc<Chpoint>),
    Elements(ElementTemps),
}

fn temperatures(a: &Args, fields: &[Rc<Mchaml>], t: Option<Rc<Chpoint>>) -> Result<Temps> {
    if let Some(t) = t {
        let have = t.components();
        if !have.iter().any(|c| c == "T") {
            return Err(a.err(format!(
                "the temperature CHPOINT needs the component T, it has {} (rename it with NOMC 'T')",
                if have.is_empty() { "none".to_string() } else { have.join(" ") }
            )));
        }
        return Ok(Temps::Nodes(t));
    }
    match ElementTemps::find(fields) {
        Some((_, e)) => Ok(Temps::Elements(e)),
        None => Err(a.missing("CHPOINT or MCHAML (the temperatures, component T)")),
    }
}

/// THET: the stresses of the thermal strains, ELAS of EPTH in one step.
fn thet(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let (model, fields, t) = model_args(a)?;
    let temps = temperatures(a, &fields, t)?;
    let eps = thermal_strains(a, &model, &fields, &temps)?;
    Ok(vec![Value::Mchaml(Rc::new(hooke_field(a, &model, &fields, &eps)?))])
}

fn thermal_strains(a: &Args, model: &Model, fields: &[Rc<Mchaml>], t: &Temps) -> Result<Mchaml> {
    let mut out = Mchaml { subtype: "DEFORMATIONS".into(), zones: vec![] };
    for zone in &model.zones {
        let (form, mode) = (formulation(zone), zone_mode(zone)?);
        let mat = material_for(zone, fields);
        for part in &zone.mesh.parts {
            let mut z =
                MchamlZone { mesh: Mesh::single(part.clone()), element: zone.element.clone(), ..Default::default() };
            for (e, nodes) in part.elems().enumerate() {
                let temps = match t {
                    Temps::Nodes(t) => nodes
                        .iter()
                        .map(|n| t.get(*n, "T").ok_or_else(|| a.err(format!("node {} has no temperature T", n + 1))))
                        .collect::<Result<Vec<f64>>>()?,
                    Temps::Elements(t) => t.at(nodes).ok_or_else(|| {
                        a.err(format!("element {} of the model has no temperature T in the field", e + 1))
                    })?,
                };
                let g = constitutive::thermal_strain(form, part.ty, mode, &mat, &temps)
                    .map_err(|err| fem_err(a, e, err))?;
                put(&mut z, g);
            }
            out.zones.push(z);
        }
    }
    Ok(out)
}

/// Whether a field holds point values (a strain or stress field) rather
/// than the constants of MATE and CARA.
fn has_points(f: &Mchaml) -> bool {
    f.zones.iter().any(|z| !z.values.is_empty())
}

const STRESS_NAMES: &[&str] = &[
    "SMXX", "SMYY", "SMZZ", "SMXY", "SMXZ", "SMYZ", "SMRR", "SMTT", "SMRZ", "EFFX", "EFFY", "EFFZ", "MOMX", "MOMY",
    "MOMZ", "N11", "N22", "N12", "M11", "M22", "M12", "V1", "V2",
];
const STRAIN_NAMES: &[&str] = &[
    "EPXX", "EPYY", "EPZZ", "GAXY", "GAXZ", "GAYZ", "EPRR", "EPTT", "GARZ", "EPSS", "CURX", "CURY", "CURZ", "GAST",
    "RTSS", "RTTT", "RTST",
];

pub(crate) fn holds(f: &Mchaml, names: &[&str]) -> bool {
    f.zones.iter().any(|z| z.comps.iter().any(|c| names.contains(&c.as_str())))
}

pub(crate) fn comps_of(f: &Mchaml) -> String {
    let mut v: Vec<&str> = Vec::new();
    for c in f.zones.iter().flat_map(|z| z.comps.iter()) {
        if !v.contains(&c.as_str()) {
            v.push(c);
        }
    }
    if v.is_empty() {
        "no point values".into()
    } else {
        v.join(" ")
    }
}

/// Apply a point-wise law zone by zone to the one point-valued field
/// among `fields`, with the model's formulation, mode and material.
fn map_zones(
    a: &Args,
    model: &Model,
    field: &Mchaml,
    subtype: &str,
    law: impl Fn(&ModelZone, ElemType, &GaussField) -> std::result::Result<GaussField, FemError>,
) -> Result<Mchaml> {
    let mut out = Mchaml { subtype: subtype.into(), zones: vec![] };
    for z in &field.zones {
        let mz = zone_of(model, z).ok_or_else(|| a.err("the field does not belong to this model"))?;
        let mut nz = MchamlZone { mesh: z.mesh.clone(), element: z.element.clone(), ..Default::default() };
        let mut e = 0;
        for p in &z.mesh.parts {
            for _ in p.elems() {
                if e >= z.values.len() {
                    return Err(a.err(format!("the field has no values on element {}", e + 1)));
                }
                let g = law(mz, p.ty, &to_gauss(z, e)).map_err(|err| fem_err(a, e, err))?;
                put(&mut nz, g);
                e += 1;
            }
        }
        out.zones.push(nz);
    }
    Ok(out)
}

fn elas(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let (model, fields, _) = model_args(a)?;
    let eps = fields
        .iter()
        .find(|f| has_points(f))
        .cloned()
        .ok_or_else(|| a.missing("MCHAML of strains (from EPSI or EPTH)"))?;
    if holds(&eps, STRESS_NAMES) && !holds(&eps, STRAIN_NAMES) {
        // Stresses to strains: the law inverted.
        let out = map_zones(a, &model, &eps, "DEFORMATIONS", |mz, ty, g| {
            let mode = zone_mode(mz).map_err(|_| FemError::Unsupported { form: "ELAS", elem: ty.name(), mode: "?" })?;
            constitutive::inverse_hooke(formulation(mz), ty, mode, &material_for(mz, &fields), g)
        })?;
        return Ok(vec![Value::Mchaml(Rc::new(out))]);
    }
    if !holds(&eps, STRAIN_NAMES) {
        return Err(a.err(format!(
            "Hooke's law applies to a strain field (EPXX …, EPSS …); this field has {}",
            comps_of(&eps)
        )));
    }
    Ok(vec![Value::Mchaml(Rc::new(hooke_field(a, &model, &fields, &eps)?))])
}

fn hooke_field(a: &Args, model: &Model, fields: &[Rc<Mchaml>], eps: &Mchaml) -> Result<Mchaml> {
    map_zones(a, model, eps, "CONTRAINTES", |mz, ty, g| {
        let mode = zone_mode(mz).map_err(|_| FemError::Unsupported { form: "ELAS", elem: ty.name(), mode: "?" })?;
        constitutive::hooke(formulation(mz), ty, mode, &material_for(mz, fields), g)
    })
}

fn ener(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    // The model adds nothing: the two fields pair point by point.
    let _ = a.opt::<Rc<Model>>();
    let f1 = a.req::<Rc<Mchaml>>()?;
    let f2 = a.req::<Rc<Mchaml>>()?;
    let _ = a.opt::<Rc<Model>>();
    let (sig, eps) = match (holds(&f1, STRESS_NAMES), holds(&f2, STRESS_NAMES)) {
        (true, false) => (f1, f2),
        (false, true) => (f2, f1),
        _ => {
            return Err(a.err(format!(
                "one stress field and one strain field are needed; the fields have {} and {}",
                comps_of(&f1),
                comps_of(&f2)
            )))
        }
    };
    if !holds(&eps, STRAIN_NAMES) {
        return Err(a.err(format!("the second field of ENER must hold strains (EPXX …); it has {}", comps_of(&eps))));
    }
    let mut out = Mchaml { subtype: "SCALAIRE".into(), zones: vec![] };
    for z in &sig.zones {
        let w = eps
            .zones
            .iter()
            .find(|w| w.mesh == z.mesh)
            .ok_or_else(|| a.err("the stress and strain fields are not on the same zones"))?;
        if w.values.len() != z.values.len() {
            return Err(a.err("the stress and strain fields do not have the same elements"));
        }
        let mut nz = MchamlZone { mesh: z.mesh.clone(), element: z.element.clone(), ..Default::default() };
        nz.at_nodes = z.at_nodes;
        let elem = ElemType::from_name(&z.element).map_or("element", |t| t.name());
        for e in 0..z.values.len() {
            let g = constitutive::energy(&to_gauss(z, e), &to_gauss(w, e), elem).map_err(|err| fem_err(a, e, err))?;
            put(&mut nz, g);
        }
        out.zones.push(nz);
    }
    Ok(vec![Value::Mchaml(Rc::new(out))])
}

type StressLaw = fn(
    crate::fem::element::Formulation,
    crate::fem::element::Mode,
    &GaussField,
) -> std::result::Result<GaussField, FemError>;

fn stress_measure(a: &mut Args, law: StressLaw) -> Result<Vec<Value>> {
    let (model, fields, _) = model_args(a)?;
    let sig =
        fields.iter().find(|f| has_points(f)).cloned().ok_or_else(|| a.missing("MCHAML of stresses (from SIGM)"))?;
    if !holds(&sig, STRESS_NAMES) {
        return Err(a.err(format!("expected a stress field (SMXX …), this field has {}", comps_of(&sig))));
    }
    let out = map_zones(a, &model, &sig, "SCALAIRE", |mz, ty, g| {
        let mode = zone_mode(mz).map_err(|_| FemError::Unsupported { form: "massive", elem: ty.name(), mode: "?" })?;
        law(formulation(mz), mode, g)
    })?;
    Ok(vec![Value::Mchaml(Rc::new(out))])
}

fn inva(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    stress_measure(a, constitutive::invariants)
}

fn tres(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    stress_measure(a, constitutive::tresca)
}
