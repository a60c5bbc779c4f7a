//! PASAPAS, from the table to the numerical structure: the stiffness of the
//! mechanical zones, the conditions (BLOCAGES_MECANIQUES and one
//! unilateral condition per contact element), the numbering, the element
//! sets of `analysis::body`, and the loads of the CHARGEMENT as functions
//! of time (`analysis::history`).

use super::assemble::Assembled;
use super::bc::mult_node;
use super::model::{formulation, material_for, stiffness_block, zone_mode};
use super::{dofs, Args};
use crate::analysis::body::{Body, ElementSet};
use crate::analysis::history::{LoadHistory, Term, TimeFunction};
use crate::analysis::material::{Elastic, ElemKind};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::contact::project;
use crate::fem::contact_weak;
use crate::fem::element;
use crate::fem::mesh::{ElemType, Part};
use crate::solve::{Kind, Load};
use crate::value::chargement::Timing;
use crate::value::model::ModelZone;
use crate::value::rigidity::{CondRow, Subtype};
use crate::value::{Chargement, Chpoint, Mchaml, Model, Rigidite, Value};
use rustc_hash::FxHashMap as HashMap;
use std::rc::Rc;

/// Everything numerical a run needs, built once per PASAPAS call.
pub(crate) struct Structure {
    /// Stiffness blocks and every condition, in the numbering's order.
    pub rig: Rigidite,
    pub asm: Assembled,
    pub body: Body,
    /// The model zone and mesh part of each element set (for the MCHAML
    /// of the results).
    pub parts: Vec<(ModelZone, Part)>,
    /// Contact conditions (numbers in `rig.conds`), the limits they take
    /// (the gap allowed minus the initial gap), and each contact node's
    /// share of the contact facets (for pressures).
    pub contact: Vec<usize>,
    pub contact_limits: Vec<(usize, f64)>,
    pub contact_measure: HashMap<usize, f64>,
    /// The tension each condition holds before it opens (MATE 'ADHE'
    /// times the condition's share of the contact surface), by condition.
    pub adhesion: Vec<f64>,
    /// The whole model and its fields: 'PRES' loads are pressure fields on
    /// its CHARGEMENT zones, turned into forces as BSIG does.
    pub model: Model,
    pub cara: Vec<Rc<Mchaml>>,
}

/// What a contact element gives: the node its multiplier sits on, the
/// condition's terms (node, translation, coefficient), its initial gap and
/// the facets it holds.
type ElementRow = (usize, Vec<(usize, usize, f64)>, f64, Vec<Vec<usize>>);

/// The zones of a model: mechanical ones, and contact ones. Pressure
/// loading zones (formulation CHARGEMENT) are in neither: they carry no
/// stiffness, only the support of the 'PRES' loads.
pub(crate) fn split(model: &Model) -> (Vec<&ModelZone>, Vec<&ModelZone>) {
    let (c, m): (Vec<&ModelZone>, Vec<&ModelZone>) = model
        .zones
        .iter()
        .filter(|z| z.formulation != super::pres_model::FORMULATION)
        .partition(|z| z.formulation == "CONTACT");
    (m, c)
}

pub(crate) fn build(
    it: &mut Interp,
    a: &Args,
    model: &Model,
    cara: &[Rc<Mchaml>],
    blocks: Option<&Rigidite>,
) -> Result<Structure> {
    let (mech, cont) = split(model);
    let mut rig = Rigidite::new(Subtype::Rigidite);
    let mut parts = Vec::new();
    for zone in &mech {
        let form = formulation(zone);
        let mode = zone_mode(zone).map_err(|e| a.err(e.message))?;
        // Properties that are curves were evaluated by the caller (at the
        // step's parameters); values by element enter element by element.
        super::variable_fields::no_unevaluated_law(a, zone, cara)?;
        let base = material_for(zone, cara);
        for part in &zone.mesh.parts {
            let mats = super::variable_fields::element_materials(a, &base, part, cara)?;
            let b = stiffness_block(it, form, mode, part, &mats, zone.dpge)
                .map_err(|e| a.err(format!("stiffness: {}", e.message)))?;
            rig.blocks.push(b);
            parts.push(((*zone).clone(), part.clone()));
        }
    }
    if let Some(b) = blocks {
        rig.blocks.extend(b.blocks.iter().cloned());
        rig.conds.extend(b.conds.iter().cloned());
    }
    let mut contact = Vec::new();
    let mut contact_limits = Vec::new();
    let mut facets_seen: HashMap<Vec<usize>, Vec<usize>> = HashMap::default();
    // (condition, ADHE, the node whose share it holds, or the overlap).
    let mut adhe: Vec<(usize, f64, Option<usize>, f64)> = Vec::new();
    for zone in &cont {
        let jeu = zone_values(a, zone, cara, "JEU")?;
        let adh = zone_values(a, zone, cara, "ADHE")?;
        let names = dofs::translations(it);
        let mut e_global = 0;
        for part in &zone.mesh.parts {
            for el in part.elems() {
                let jeu_e = jeu.get(e_global).copied().unwrap_or(0.0);
                let adh_e = adh.get(e_global).copied().unwrap_or(0.0).max(0.0);
                e_global += 1;
                let coords = &it.nodes.coords;
                let mut overlap = 0.0;
                let (anchor, terms, gap, facets): ElementRow = match part.ty {
                    ElemType::Qua4 => match contact_weak::facing(coords, [el[0], el[1], el[2], el[3]]) {
                        Some(p) => {
                            overlap = p.length;
                            (el[0], p.terms(), p.gap, vec![vec![el[0], el[1]], vec![el[2], el[3]]])
                        }
                        None => continue,
                    },
                    _ => {
                        let p = project(coords, el[0], &el[1..], false).map_err(|_| {
                            a.err(format!("contact element {}: its facet has no length or area", e_global))
                        })?;
                        let ndim = el.len() - 1;
                        (el[0], p.terms(ndim), p.gap, vec![el[1..].to_vec()])
                    }
                };
                for f in facets {
                    let mut key = f.clone();
                    key.sort_unstable();
                    facets_seen.entry(key).or_insert(f);
                }
                let m = mult_node(it, anchor);
                let terms = terms.into_iter().map(|(n, k, c)| (n, names[k].to_string(), c)).collect();
                if adh_e > 0.0 {
                    let node = (part.ty != ElemType::Qua4).then_some(anchor);
                    adhe.push((rig.conds.len(), adh_e, node, overlap));
                }
                contact.push(rig.conds.len());
                contact_limits.push((rig.conds.len(), jeu_e - gap));
                rig.conds.push(CondRow::new(m, terms, Kind::Mini));
            }
        }
    }
    let measure = contact_measures(&it.nodes.coords, &parts, &rig, &contact, facets_seen.values());
    // A node-to-facet condition holds for the smallest share of the nodes
    // it ties (a support longer than the body it meets has nodes whose
    // share reaches past the contact zone); a weak one for its overlap.
    let mut adhesion = vec![0.0; rig.conds.len()];
    for (k, v, node, overlap) in adhe {
        let share = match node {
            None => overlap,
            Some(_) => {
                let c = &rig.conds[k];
                let big = c.terms.iter().fold(0.0_f64, |m, t| m.max(t.2.abs()));
                c.terms
                    .iter()
                    .filter(|t| t.2.abs() > 1e-9 * big)
                    .filter_map(|t| measure.get(&t.0).copied())
                    .fold(f64::INFINITY, f64::min)
            }
        };
        adhesion[k] = if share.is_finite() { v * share } else { 0.0 };
    }
    let mut asm = rig.number();
    // A condition written twice (the same BLOQ in two blocks) is one
    // condition, as RESO takes it: the conditions (and the numbers that
    // refer to them) follow the merged numbering.
    asm.merge_twins();
    let m = asm.problem.conditions.len();
    if m != rig.conds.len() {
        let back: HashMap<usize, usize> = (0..m).map(|k| (asm.origin(k), k)).collect();
        rig.conds = (0..m).map(|k| rig.conds[asm.origin(k)].clone()).collect();
        adhesion = (0..m).map(|k| adhesion[asm.origin(k)]).collect();
        contact = contact.iter().filter_map(|c| back.get(c).copied()).collect();
        contact_limits = contact_limits.iter().filter_map(|(c, d)| back.get(c).map(|k| (*k, *d))).collect();
    }
    let mut index = HashMap::default();
    for (i, (n, c)) in asm.dofs.iter().enumerate() {
        index.insert((*n, c.clone()), i);
    }
    let mut body = Body { coords: it.nodes.coords.clone(), sets: Vec::new() };
    for (zone, part) in &parts {
        let form = formulation(zone);
        let mode = zone_mode(zone).map_err(|e| a.err(e.message))?;
        let names = element::node_dofs(form, mode).map_err(|e| a.err(e.to_string()))?;
        let mut d = Vec::with_capacity(part.conn.len() * names.len());
        for n in &part.conn {
            for c in names {
                d.push(index.get(&(*n, c.to_string())).copied());
            }
        }
        body.sets.push(ElementSet::new(
            ElemKind { form, ty: part.ty, mode },
            part.conn.clone(),
            d,
            Box::new(Elastic { props: material_for(zone, cara), by_elem: per_elem(a, zone, part, cara)? }),
        ));
    }
    Ok(Structure {
        rig,
        asm,
        body,
        parts,
        contact,
        contact_limits,
        contact_measure: measure,
        adhesion,
        model: model.clone(),
        cara: cara.to_vec(),
    })
}

/// Each contact node's share of the contact surface, for pressures: the
/// consistent lumping ∫Nᵢ of the faces of the bodies' skin whose nodes
/// all take part in contact (what the forces of a uniform pressure
/// follow); for nodes on no such face (a rigid support meshed as a line,
/// a beam), an equal share of the contact facets that hold them.
fn contact_measures<'a>(
    x: &[[f64; 3]],
    parts: &[(ModelZone, Part)],
    rig: &Rigidite,
    contact: &[usize],
    facets: impl Iterator<Item = &'a Vec<usize>>,
) -> HashMap<usize, f64> {
    let mut nodes: std::collections::HashSet<usize> = Default::default();
    for &k in contact {
        let c = &rig.conds[k];
        let big = c.terms.iter().fold(0.0_f64, |m, t| m.max(t.2.abs()));
        nodes.extend(c.terms.iter().filter(|t| t.2.abs() > 1e-9 * big).map(|t| t.0));
    }
    let mut out: HashMap<usize, f64> = HashMap::default();
    // Skin faces: used by one element only.
    let mut count: HashMap<Vec<usize>, (ElemType, Vec<usize>, usize)> = HashMap::default();
    for (_, p) in parts {
        for e in p.elems() {
            for (fty, loc) in crate::fem::shape::faces(p.ty) {
                if fty.dim() + 1 != p.ty.dim() {
                    continue;
                }
                let f: Vec<usize> = loc.iter().map(|&k| e[k]).collect();
                let mut key = f.clone();
                key.sort_unstable();
                count.entry(key).or_insert((fty, f, 0)).2 += 1;
            }
        }
    }
    for (fty, f, n) in count.values() {
        if *n != 1 || !f.iter().all(|v| nodes.contains(v)) {
            continue;
        }
        let xf: Vec<[f64; 3]> = f.iter().map(|&v| x[v]).collect();
        for (v, w) in f.iter().zip(lumped(*fty, &xf)) {
            *out.entry(*v).or_insert(0.0) += w;
        }
    }
    let mut fallback: HashMap<usize, f64> = HashMap::default();
    for f in facets {
        let share = facet_measure(x, f) / f.len() as f64;
        for v in f {
            *fallback.entry(*v).or_insert(0.0) += share;
        }
    }
    for (v, m) in fallback {
        out.entry(v).or_insert(m);
    }
    out
}

/// ∫Nᵢ over a face (SEG2, TRI3, QUA4; other faces share their measure
/// equally).
fn lumped(ty: ElemType, x: &[[f64; 3]]) -> Vec<f64> {
    match ty {
        ElemType::Qua4 => {
            let g = 1.0 / 3f64.sqrt();
            let mut w = vec![0.0; 4];
            for (a, b) in [(-g, -g), (g, -g), (g, g), (-g, g)] {
                let p = [a, b, 0.0];
                let j = crate::fem::integrate::jacobian(ty, x, p);
                for (wi, ni) in w.iter_mut().zip(crate::fem::shape::eval(ty, p).n) {
                    *wi += ni * j;
                }
            }
            w
        }
        _ => {
            let idx: Vec<usize> = (0..x.len()).collect();
            vec![facet_measure(x, &idx) / x.len() as f64; x.len()]
        }
    }
}

/// Length of a segment, area of a triangle (of the nodes `f` of `x`).
fn facet_measure(x: &[[f64; 3]], f: &[usize]) -> f64 {
    use crate::fem::vec3::{cross, dot, sub};
    match f {
        [a, b] => {
            let d = sub(x[*b], x[*a]);
            dot(d, d).sqrt()
        }
        [a, b, c] => {
            let n = cross(sub(x[*b], x[*a]), sub(x[*c], x[*a]));
            0.5 * dot(n, n).sqrt()
        }
        [a, b, c, d] => facet_measure(x, &[*a, *b, *c]) + facet_measure(x, &[*a, *c, *d]),
        _ => 0.0,
    }
}

/// The value of a contact datum on each element of a contact zone (0 when
/// the material does not give it).
/// The data of each element of `part` when a field gives them element by
/// element (empty when they are the same for all).
fn per_elem(
    a: &Args,
    zone: &ModelZone,
    part: &Part,
    cara: &[Rc<Mchaml>],
) -> Result<Vec<crate::fem::material::Material>> {
    let mats = super::variable_fields::element_materials(a, &material_for(zone, cara), part, cara)?;
    Ok(if mats.len() == part.len() { mats } else { Vec::new() })
}

fn zone_values(a: &Args, zone: &ModelZone, cara: &[Rc<Mchaml>], name: &str) -> Result<Vec<f64>> {
    let n = zone.mesh.n_elements();
    for f in cara {
        for z in f.zones.iter().filter(|z| z.belongs_to(zone)) {
            if let Some(v) = z.constants.get(name) {
                return Ok(vec![*v; n]);
            }
            if let Some(ci) = z.comps.iter().position(|c| c == name) {
                return z
                    .values
                    .iter()
                    .map(|pts| {
                        pts.first().map(|p| p[ci]).ok_or_else(|| a.err(format!("the {} field has no value", name)))
                    })
                    .collect();
            }
        }
    }
    Ok(vec![0.0; n])
}

/// The loads of a CHARGEMENT on the numbering of `s`, as functions of
/// time, and the temperatures it gives (by node).
pub(crate) struct Loads {
    pub history: LoadHistory,
    /// The temperature parts: time function and temperature by node.
    pub heat: Vec<(TimeFunction, Vec<f64>)>,
    /// The reference temperature by node (thermal strains are measured
    /// from it).
    pub tref: Vec<f64>,
}

impl Loads {
    /// ΔT by node at time t, None without temperature loads.
    pub fn heat_at(&self, t: f64) -> std::result::Result<Option<Vec<f64>>, String> {
        if self.heat.is_empty() {
            return Ok(None);
        }
        let mut h: Vec<f64> = self.tref.iter().map(|v| -v).collect();
        for (f, temp) in &self.heat {
            let c = f.at(t).map_err(|e| e.to_string())?;
            for (hi, ti) in h.iter_mut().zip(temp) {
                *hi += c * ti;
            }
        }
        Ok(Some(h))
    }
}

/// Names of the loads PASAPAS applies; others are variables the material
/// may depend on (ignored by elastic materials), except the loads of the
/// physics gibi does not run, which are refused by name.
const UNSUPPORTED: &[(&str, &str)] = &[
    ("DEFI", "imposed strains"),
    ("TIMP", "imposed temperatures need a thermal model, which gibi's PASAPAS does not solve"),
    ("Q", "heat fluxes need a thermal model, which gibi's PASAPAS does not solve"),
    ("TECO", "convection needs a thermal model, which gibi's PASAPAS does not solve"),
    ("TERA", "radiation needs a thermal model, which gibi's PASAPAS does not solve"),
    ("CIMP", "diffusion is not solved by gibi's PASAPAS"),
    ("QCO", "diffusion is not solved by gibi's PASAPAS"),
    ("FLUX", "consolidation is not solved by gibi's PASAPAS"),
];

/// Refuses what PASAPAS cannot apply, before anything is computed.
pub(crate) fn check_loads(a: &Args, ch: &Chargement) -> Result<()> {
    for p in &ch.parts {
        if p.name.is_empty() {
            return Err(a.err("a CHARGEMENT part has no name: PASAPAS reads 'MECA', 'DIMP', 'T' … (CHAR 'MECA' f ev)"));
        }
        if let Some((_, why)) = UNSUPPORTED.iter().find(|(n, _)| *n == p.name) {
            return Err(a.err(format!("the load '{}' is not supported: {}", p.name, why)));
        }
    }
    Ok(())
}

/// Each field of a part with the time function that weighs it.
fn weighted(p: &Timing) -> Vec<(TimeFunction, Value)> {
    match p {
        Timing::Scaled { field, function } => vec![(function.clone(), field.clone())],
        Timing::Table(steps) => {
            // Hat functions over the whole range: 1 at t_i, 0 at its
            // neighbours and beyond.
            let (t0, tn) = (steps[0].0, steps[steps.len() - 1].0);
            (0..steps.len())
                .map(|i| {
                    let mut pts = Vec::new();
                    if i > 0 {
                        pts.push((t0, 0.0));
                        pts.push((steps[i - 1].0, 0.0));
                    }
                    pts.push((steps[i].0, 1.0));
                    if i + 1 < steps.len() {
                        pts.push((steps[i + 1].0, 0.0));
                        pts.push((tn, 0.0));
                    }
                    pts.dedup_by(|b, a| a.0 == b.0 && a.1 == b.1);
                    let (x, y): (Vec<f64>, Vec<f64>) = pts.into_iter().unzip();
                    let f = TimeFunction::new(x, y).unwrap_or_else(|_| TimeFunction::constant(0.0));
                    (f, steps[i].1.clone())
                })
                .collect()
        }
    }
}

/// The loads of `ch`; `tref` is the reference temperature field, if any.
pub(crate) fn loads(
    it: &Interp,
    a: &Args,
    s: &Structure,
    ch: Option<&Chargement>,
    tref: Option<&Chpoint>,
) -> Result<Loads> {
    let (n, m) = (s.asm.problem.k.n, s.asm.problem.conditions.len());
    let mut history = LoadHistory::new(n, m);
    for (k, d) in &s.contact_limits {
        history.base.d[*k] = *d;
    }
    let nn = it.nodes.len();
    let temps = |c: &Chpoint| -> Vec<f64> {
        let mut v = vec![0.0; nn];
        for (node, comp, x) in c.entries() {
            if comp == "T" && node < nn {
                v[node] = x;
            }
        }
        v
    };
    let tref = tref.map(temps).unwrap_or_else(|| vec![0.0; nn]);
    let mut heat = Vec::new();
    for p in ch.iter().flat_map(|c| c.parts.iter()) {
        for (f, field) in weighted(&p.time) {
            let chpo = match &field {
                Value::Chpo(c) => c.clone(),
                Value::Mchaml(pres) if p.name == "PRES" => pressure_forces(it, a, s, pres)?,
                other => {
                    if matches!(p.name.as_str(), "MECA" | "FORC" | "DIMP" | "T") {
                        return Err(a.err(format!(
                            "the load '{}' must be a CHPOINT, not an {}",
                            p.name,
                            other.type_name()
                        )));
                    }
                    continue;
                }
            };
            match p.name.as_str() {
                // 'FORC' is read like 'MECA' by Cast3M's step (unpas);
                // 'PRES' is its forces.
                "MECA" | "FORC" | "DIMP" | "PRES" => {
                    let load = super::assemble::load(it, &s.asm, &[&chpo]).map_err(|e| {
                        let err = a.err(format!("load '{}': {}", p.name, e.message));
                        if e.message.contains("carries no condition") {
                            err.note("give DEPI the very conditions of 'BLOCAGES_MECANIQUES' (cl = BLOQ … ; DEPI cl v): a new BLOQ makes new conditions")
                        } else {
                            err
                        }
                    })?;
                    history.terms.push(Term { load, time: f });
                }
                "T" => {
                    let t = temps(&chpo);
                    let fth = s.body.thermal_forces(n, &t).map_err(|e| a.err(body_error(s, &e)))?;
                    heat.push((f.clone(), t));
                    history.terms.push(Term { load: Load { f: fth, d: vec![0.0; m] }, time: f });
                }
                _ => {}
            }
        }
    }
    if !heat.is_empty() && tref.iter().any(|v| *v != 0.0) {
        let f0 = s.body.thermal_forces(n, &tref).map_err(|e| a.err(body_error(s, &e)))?;
        for (b, v) in history.base.f.iter_mut().zip(f0) {
            *b -= v;
        }
    }
    Ok(Loads { history, heat, tref })
}

/// The nodal forces of a pressure field of the model's CHARGEMENT zones
/// (PRES mop 'PRES' p), as BSIG mop gives them.
fn pressure_forces(it: &Interp, a: &Args, s: &Structure, pres: &Rc<Mchaml>) -> Result<Rc<Chpoint>> {
    let mut fields = vec![pres.clone()];
    fields.extend(s.cara.iter().cloned());
    match super::pres_model::forces(it, a, &s.model, &fields)
        .map_err(|e| a.err(format!("load 'PRES': {}", e.message)))?
        .pop()
    {
        Some(Value::Chpo(c)) => Ok(c),
        _ => Err(a.err("load 'PRES': the pressure field gives no forces")),
    }
}

/// An element failure in words: the zone's element type and its number.
pub(crate) fn body_error(s: &Structure, e: &crate::analysis::body::BodyError) -> String {
    let ty = s.parts.get(e.set).map_or("?", |(z, _)| z.element.as_str());
    format!("{} element {}: {}", ty, e.elem + 1, e.error)
}
