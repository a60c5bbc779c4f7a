//! Integrals over meshes and models: MESU (length, area, volume), INTG
//! (integral of a field over a model) and BSIG (nodal forces of a stress
//! field). The quadrature lives in `fem::integrate` and the element files.

use super::mesh::req_geo;
use super::model::{formulation, material_for, zone_mode};
use super::post::{to_gauss, zone_of};
use super::{Args, OpDef};
use crate::error::{Error, Result};
use crate::eval::Interp;
use crate::fem::element::{self, FemError};
use crate::fem::integrate;
use crate::fem::mesh::Mesh;
use crate::value::model::MchamlZone;
use crate::value::{Chpoint, Mchaml, Model, Nature, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "MESU",
        signature: "MESU GEO ('LONG'|'SURF'|'VOLU')",
        doc: "Measure of a mesh: the length of a line, the area of a surface, the volume of a volume (of its elements of highest dimension, geometric in every mode). 'LONG', 'SURF', 'VOLU' measure the elements of that dimension; 'SURF' of a closed line is the area it encloses (projected on its mean plane in 3D), 'VOLU' of a closed surface the volume it encloses.",
        example: "a = mesu s ;",
        f: mesu,
    },
    OpDef {
        name: "INTG",
        signature: "INTG ('ELEM') MMODEL MCHAML|CHPOINT (COMP) (MCHAML_CARA) | INTG EVOLUTIO ('ABS') (I1 I2 | LISTENTI1 LISTENTI2)",
        doc: "Integral of one component of a field over a model (thickness DIM3 in PLAN CONT, over the whole ring (2πr) in AXIS, along the length of bars and beams); 'ELEM' gives one value per element. Of an EVOLUTIO: the integral of its curve N (1 by default) by the trapezoidal rule.",
        example: "f = intg mo sig 'SMXX' ;",
        f: intg,
    },
    OpDef {
        name: "BSIG",
        signature: "BSIG MMODEL MCHAML_STRESS (MCHAML)",
        doc: "Nodal forces equivalent to a stress field (∫ Bᵀσ): the internal forces, K u for the stresses of u.",
        example: "fi = bsig mo sig ma ;",
        f: bsig,
    },
];

fn fem_err(a: &Args, e: FemError) -> Error {
    a.err(e.to_string())
}

fn coords(it: &Interp, nodes: &[usize]) -> Vec<[f64; 3]> {
    nodes.iter().map(|n| it.nodes.get(*n)).collect()
}

fn mesu(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    // The keyword may come before the mesh (`MESU 'SURF' CONTOUR`).
    let before = a.keyword(&["LONG", "SURF", "VOLU"]);
    let m = req_geo(a)?;
    let highest = m.parts.iter().filter(|p| !p.is_empty()).map(|p| p.ty.dim()).max().unwrap_or(0);
    // 'LONG' / 'SURF' / 'VOLU' name the measure; one dimension below it,
    // the mesh is a closed boundary and the measure is what it encloses.
    let want = match before.or_else(|| a.keyword(&["LONG", "SURF", "VOLU"])) {
        Some("LONG") => 1,
        Some("SURF") => 2,
        Some(_) => 3,
        None => highest,
    };
    let pieces = |d: usize| -> Vec<Vec<[f64; 3]>> {
        m.parts.iter().filter(|p| p.ty.dim() == d).flat_map(|p| p.elems().map(|e| coords(it, e))).collect()
    };
    let total = if highest >= want {
        let mut total = 0.0;
        for p in m.parts.iter().filter(|p| p.ty.dim() == want) {
            for e in p.elems() {
                total += integrate::measure(p.ty, &coords(it, e));
            }
        }
        total
    } else if want == 2 && highest == 1 {
        crate::fem::enclosed::area_inside(&pieces(1))
    } else if want == 3 && highest == 2 {
        crate::fem::enclosed::volume_inside(&pieces(2))
    } else {
        return Err(a.err(format!(
            "a mesh of dimension {} has no {} measure",
            highest,
            ["", "LONG", "SURF", "VOLU"][want]
        )));
    };
    Ok(vec![Value::Float(total)])
}

/// The component to integrate: the one named, else the field's only one.
fn component(a: &mut Args, available: Vec<String>) -> Result<String> {
    // A blank word (`TEXT '        '`, no characteristics) names nothing.
    if let Some(c) = a.word_not_operator().filter(|c| !c.is_empty()) {
        if !available.contains(&c) {
            return Err(a.err(format!("the field has no component {} (it has {})", c, available.join(" "))));
        }
        return Ok(c);
    }
    match available.as_slice() {
        [only] => Ok(only.clone()),
        _ => Err(a.err(format!("the field has components {}: name the one to integrate", available.join(" ")))),
    }
}

/// Component names of an element field, point values and constants alike.
fn mchaml_comps(m: &Mchaml) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    for z in &m.zones {
        for c in z.comps.iter().chain(z.constants.keys()) {
            if !out.contains(c) {
                out.push(c.clone());
            }
        }
    }
    out
}

/// Integrals per element, zone by zone (the meshes of the zones).
type PerElement = Vec<(Mesh, String, Vec<f64>)>;

fn intg(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if let Some(e) = a.opt::<Rc<crate::value::Evolution>>() {
        return super::curves::intg_curve(a, e);
    }
    let per_elem = a.keyword(&["ELEM"]).is_some();
    let model = a.req::<Rc<Model>>()?;
    // The field is an MCHAML or a CHPOINT, read in one go: looking for an
    // MCHAML first would reach past the CHPOINT to the CARA field.
    let (field, chpo) = match a.opt_with(|v| match v {
        Value::Mchaml(m) => Some((Some(m.clone()), None)),
        Value::Chpo(c) => Some((None, Some(c.clone()))),
        _ => None,
    }) {
        Some(f) => f,
        None => return Err(a.missing("MCHAML or CHPOINT (the field to integrate)")),
    };
    let comp = match (&field, &chpo) {
        (Some(f), _) => component(a, mchaml_comps(f))?,
        (_, Some(c)) => component(a, c.components())?,
        _ => unreachable!("one of them was read"),
    };
    let mut mats: Vec<Rc<Mchaml>> = field.iter().cloned().collect();
    while let Some(f) = a.opt::<Rc<Mchaml>>() {
        mats.push(f);
    }
    let parts = match (&field, &chpo) {
        (Some(f), _) => intg_mchaml(it, a, &model, &on_model(a, &model, f, &comp), &comp, &mats)?,
        (_, Some(c)) => intg_chpoint(it, a, &model, c, &comp, &mats)?,
        _ => unreachable!("one of them was read"),
    };
    if !per_elem {
        return Ok(vec![Value::Float(parts.iter().flat_map(|(_, _, v)| v.iter()).sum())]);
    }
    let zones = parts
        .into_iter()
        .map(|(mesh, element, v)| MchamlZone {
            mesh,
            element,
            comps: vec![comp.clone()],
            values: v.into_iter().map(|x| vec![vec![x]]).collect(),
            ..Default::default()
        })
        .collect();
    Ok(vec![Value::Mchaml(Rc::new(Mchaml { subtype: "SCALAIRE".into(), zones }))])
}

/// The field as the model's zones hold it: a field made on a mesh (CHAN
/// 'CHAM' of a CHPOINT on the whole geometry) whose zones are not those of
/// the model (a part of it, REDU) is first carried onto the model's
/// elements, as REDU MCHAML MMODEL does; a field made on the model is kept.
fn on_model(a: &Args, model: &Model, f: &Rc<Mchaml>, comp: &str) -> Rc<Mchaml> {
    let carrying = |z: &&MchamlZone| z.comps.iter().any(|c| c == comp);
    let foreign = f.zones.iter().filter(carrying).any(|z| zone_of(model, z).is_none());
    if !foreign {
        return f.clone();
    }
    match super::restrict::mchaml_to_model(a, f, model) {
        Ok(m) if m.zones.iter().any(|z| z.comps.iter().any(|c| c == comp)) => Rc::new(m),
        _ => f.clone(),
    }
}

fn intg_mchaml(
    it: &Interp,
    a: &Args,
    model: &Model,
    field: &Mchaml,
    comp: &str,
    mats: &[Rc<Mchaml>],
) -> Result<PerElement> {
    let mut out = Vec::new();
    for z in field.zones.iter().filter(|z| z.comps.iter().any(|c| c == comp) || z.constants.contains_key(comp)) {
        let Some(mz) = zone_of(model, z) else { continue };
        let (form, mode) = (formulation(mz), zone_mode(mz)?);
        let mat = material_for(mz, mats);
        let c = z.comps.iter().position(|x| x == comp);
        let mut vals = Vec::new();
        for p in &z.mesh.parts {
            for nodes in p.elems() {
                let e = vals.len();
                let x = coords(it, nodes);
                let w = if z.at_nodes && c.is_some() {
                    integrate::node_weights(form, p.ty, mode, &x, &mat)
                } else {
                    integrate::point_weights(form, p.ty, mode, &x, &mat)
                }
                .map_err(|err| fem_err(a, err))?;
                let v = match c {
                    Some(c) => {
                        let pts = z
                            .values
                            .get(e)
                            .ok_or_else(|| a.err(format!("the field has no values on element {}", e + 1)))?;
                        // One value per element (a field at the centres,
                        // CHAN 'GRAVITE'): constant over the element.
                        if pts.len() == 1 && w.len() > 1 && !z.at_nodes {
                            vals.push(pts[0][c] * w.iter().sum::<f64>());
                            continue;
                        }
                        if pts.len() != w.len() {
                            return Err(a.err(format!(
                                "element {}: the field has values at {} points, the model's elements at {}",
                                e + 1,
                                pts.len(),
                                w.len()
                            )));
                        }
                        pts.iter().zip(&w).map(|(p, w)| p[c] * w).sum()
                    }
                    None => z.constants[comp] * w.iter().sum::<f64>(),
                };
                vals.push(v);
            }
        }
        out.push((z.mesh.clone(), z.element.clone(), vals));
    }
    // An empty model (REDU on an empty mesh) integrates to zero.
    if out.is_empty() && !model.zones.is_empty() {
        return Err(a.err(format!("the field has no zone of this model carrying {}", comp)));
    }
    Ok(out)
}

fn intg_chpoint(
    it: &Interp,
    a: &Args,
    model: &Model,
    field: &Chpoint,
    comp: &str,
    mats: &[Rc<Mchaml>],
) -> Result<PerElement> {
    let mut out = Vec::new();
    for mz in &model.zones {
        let (form, mode) = (formulation(mz), zone_mode(mz)?);
        let mat = material_for(mz, mats);
        for p in &mz.mesh.parts {
            let mut vals = Vec::new();
            for nodes in p.elems() {
                let w = integrate::node_weights(form, p.ty, mode, &coords(it, nodes), &mat)
                    .map_err(|err| fem_err(a, err))?;
                let mut v = 0.0;
                for (n, w) in nodes.iter().zip(w) {
                    let f = field
                        .get(*n, comp)
                        .ok_or_else(|| a.err(format!("the CHPOINT has no {} at node {}", comp, n + 1)))?;
                    v += f * w;
                }
                vals.push(v);
            }
            out.push((Mesh::single(p.clone()), mz.element.clone(), vals));
        }
    }
    Ok(out)
}

fn bsig(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let model = a.req::<Rc<Model>>()?;
    let mut fields = Vec::new();
    while let Some(f) = a.opt::<Rc<Mchaml>>() {
        fields.push(f);
    }
    if super::pres_model::is_pressure_model(&model) {
        return super::pres_model::forces(it, a, &model, &fields);
    }
    let sig = fields
        .iter()
        .find(|f| f.zones.iter().any(|z| !z.values.is_empty()))
        .cloned()
        .ok_or_else(|| a.missing("MCHAML of stresses (from SIGM)"))?;
    let mut out = Chpoint::new(Nature::Discret);
    for z in &sig.zones {
        let mz = zone_of(&model, z).ok_or_else(|| a.err("the stress field does not belong to this model"))?;
        if let Some(x) = &mz.xfem {
            super::xfem_model::bsig_zone(it, a, mz, x, z, &fields, &mut out)?;
            continue;
        }
        let (form, mode) = (formulation(mz), zone_mode(mz)?);
        let mat = material_for(mz, &fields);
        let duals = element::node_duals(form, mode).map_err(|e| fem_err(a, e))?;
        scatter_forces(it, a, z, duals, &mut out, |ty, x, e| {
            element::internal_forces(form, ty, mode, x, &mat, &to_gauss(z, e))
        })?;
    }
    Ok(vec![Value::Chpo(Rc::new(out))])
}

/// Add to `out` the nodal forces that `forces(type, coordinates, element)`
/// gives for each element of a stress zone (in ElemMatrix dof order, with
/// the node duals `duals`): BSIG's and FOFI's common assembly.
pub(crate) fn scatter_forces<E: std::fmt::Display>(
    it: &Interp,
    a: &Args,
    z: &crate::value::model::MchamlZone,
    duals: &[&str],
    out: &mut Chpoint,
    mut forces: impl FnMut(crate::fem::mesh::ElemType, &[[f64; 3]], usize) -> std::result::Result<Vec<f64>, E>,
) -> Result<()> {
    let mut e = 0;
    for p in &z.mesh.parts {
        for nodes in p.elems() {
            if e >= z.values.len() {
                return Err(a.err(format!("the stress field has no values on element {}", e + 1)));
            }
            let f = forces(p.ty, &coords(it, nodes), e).map_err(|err| a.err(format!("element {}: {}", e + 1, err)))?;
            for (k, n) in nodes.iter().enumerate() {
                for (c, d) in duals.iter().enumerate() {
                    out.add(*n, d, f[k * duals.len() + c], true);
                }
            }
            e += 1;
        }
    }
    Ok(())
}
