//! Models and stiffness: MODE, MATE, CARA, RIGI, APPU. Element matrices come
//! from `fem::element`; a RIGIDITE keeps them per mesh part (lazy assembly).

use super::mesh::req_geo;
use super::{dofs, Args, OpDef, PointId};
use crate::error::{Error, Result};
use crate::eval::Interp;
use crate::fem::element::{self, Formulation, Material, Mode};
use crate::fem::incomp;
use crate::fem::mesh::{ElemType, Mesh};
use crate::value::model::{MchamlZone, ModelZone};
use crate::value::rigidity::{Block, Subtype, Symmetry};
use crate::value::{Evolution, Mchaml, Model, Rigidite, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef { name: "MODE", signature: "MODE GEO 'MECANIQUE' ('ELASTIQUE' ('ISOTROPE')) (BARR|POUT|TIMO|Q4RI|COQ2|COQ3|DKT|COQ4|…) | MODE GEO 'CHARGEMENT' 'PRESSION' (COQ2) | MODE CONTACT_MESH 'CONTACT' ('UNILATERAL')", doc: "A model: a mesh tied to a formulation, a behaviour and an element type (COQ3, DKT on TRI3 and COQ4 on QUA4 are thin shells, DST on TRI3 a shell with transverse shear, in TRID; COQ2 on SEG2 the thin shell of AXIS and the plane modes; ICT3, ICQ4, ICT6, ICQ8 (ICT4, ICC8, ICP6 in TRID) the incompressible massive elements, with a pressure condensed per element). MODE GEO 'CHARGEMENT' 'PRESSION' ('CONS' name) makes a pressure model for PRES and BSIG, on lines (SEG2, SEG3) in 2D or surfaces (TRI3, QUA4, TRI6, QUA8) in TRID. 'CONTACT' on the elements of IMPO 'MAIL' makes a contact model for PASAPAS.", example: "mo = mode l mecanique elastique pout ;", f: mode },
    OpDef { name: "MATE", signature: "MATE MMODEL 'YOUN' E 'NU' nu ('RHO' r) ('ALPH' a ('TREF' t)) (SECT INRY INRZ TORS SECY SECZ EPAI EXCE DIM3 …); a value may be an EVOLUTIO of a parameter | MATE MMODEL_CONTACT ('JEU' j|MCHAML) ('ADHE' a|MCHAML)", doc: "Material (and section) data of a model. A property given as an EVOLUTIO depends on the parameter its abscissa names (VARI 'NUAG' evaluates it against a field). For a contact model, the distance the bodies keep ('JEU') and the tension the contact holds before it opens ('ADHE', per unit length or area).", example: "ma = mate mo youn 2.e11 nu 0.3 ;", f: mate },
    OpDef { name: "CARA", signature: "CARA MMODEL ('SECT' s) ('INRY' i) ('INRZ' i) ('TORS' j) ('SECY' a) ('SECZ' a) ('EPAI' e) ('DIM3' e) ('VECT' P)", doc: "Geometric characteristics of a model (merge with MATE using ET).", example: "ca = cara mo sect 1. inrz 1. ;", f: cara },
    OpDef { name: "RIGI", signature: "RIGI MMODEL MCHAML (MCHAML) | RIGI ('DEPL') ('ROTA') (comps) VALUE GEO", doc: "Stiffness of a model, or springs to ground.", example: "k = rigi mo ma ;", f: rigi },
    OpDef { name: "APPU", signature: "APPU ('DEPL') ('ROTA') (comps) ('DIRECTION' VEC) VALUE GEO", doc: "Springs to ground of stiffness VALUE on the listed unknowns of every node.", example: "ri = appu 'UX' 10. p1 ;", f: appu },
];

const FORMS: &[&str] = &[
    "BARR", "POUT", "TIMO", "Q4RI", "Q8RI", "COQ3", "DKT", "DST", "COQ4", "COQ6", "COQ8", "COQ2", "TRI3", "TRI6",
    "QUA4", "QUA8", "CUB8", "TET4", "PRI6", "CU20", "PR15", "SEG2", "JOI2", "JOI3", "JOI4", "ICT3", "ICQ4", "ICT6",
    "ICQ8", "ICT4", "ICC8", "ICP6", "BAEX", "QUAS", "TRIS", "TUYA", "XQ4R", "XC8R",
];

const BEHAVIOURS: &[&str] = &["ELASTIQUE", "ISOTROPE", "EPSILON", "SECTION"];

fn mode(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    // Relation elements (RAFF's MULT) carry no mechanics: the model keeps
    // them aside for RELA.
    let (geo, ties): (Vec<_>, Vec<_>) = req_geo(a)?.parts.into_iter().partition(|p| p.ty.tie_side().is_none());
    let mut out = mode_on(it, a, Mesh { parts: geo })?;
    if let Some(Value::Model(m)) = out.first_mut() {
        Rc::make_mut(m).ties = ties;
    }
    Ok(out)
}

fn mode_on(it: &mut Interp, a: &mut Args, geo: Mesh) -> Result<Vec<Value>> {
    // CONTACT is read as a word before any operator check: its first four
    // letters name the operator CONT.
    let formulation = match a.keyword_next(&["CONTACT"]) {
        Some(c) => c.to_string(),
        None => a.word_not_operator().unwrap_or_else(|| "MECANIQUE".into()).to_uppercase(),
    };
    if formulation.starts_with("CONT") {
        return contact_model(it, a, &geo);
    }
    if formulation.starts_with("CHAR") {
        return super::pres_model::model(it, a, &geo);
    }
    if formulation.starts_with("THER") {
        return super::heat::model(it, a, &geo);
    }
    if !formulation.starts_with("MECA") {
        return Err(a.err(format!("only the MECANIQUE formulation is available, not {}", formulation)));
    }
    let mut behaviour = Vec::new();
    let mut element = String::new();
    // Every element name given: with several shells, each element of the
    // mesh takes the one made for its geometry (MODE's notice).
    let mut names: Vec<String> = Vec::new();
    let mut dpge = None;
    let mut cons = String::new();
    // ELASTIQUE is matched before any operator check: its first four
    // letters name the operator ELAS, which must not stop `MODE s
    // MECANIQUE ELASTIQUE` (Cast3M reads MODE's words as words).
    while let Some(w) = a.keyword_next(BEHAVIOURS).map(String::from).or_else(|| a.word_not_operator()) {
        let w = w.to_uppercase();
        if w.starts_with("EPSI") {
            epsilon(a)?;
            continue;
        }
        if let Some(f) = FORMS.iter().find(|f| super::args::keyword_matches(&w, f)) {
            element = f.to_string();
            names.push(element.clone());
        } else if super::args::keyword_matches(&w, "DPGE") {
            dpge = Some(a.req::<PointId>()?.0);
        } else if super::args::keyword_matches(&w, "CONSTITUANT") {
            // Element fields go to model zones by mesh and constituent.
            cons = a.req::<String>()?.to_uppercase();
        } else if ["ELAS", "ISOT", "SECT"].iter().any(|k| w.starts_with(k)) {
            behaviour.push(w);
        } else if INELASTIC.iter().any(|k| w.starts_with(k)) || behaviour.iter().any(|b| inelastic(b)) {
            // A constitutive law gibi does not integrate: the model exists
            // (RIGI gives its elastic stiffness, as Cast3M does) and
            // PASAPAS refuses it by name.
            behaviour.push(w);
        } else {
            return Err(a.err(format!(
                "{} is not supported (elastic isotropic BARR, POUT, TIMO, COQ2, COQ3, DKT, COQ4, COQ6, COQ8 and massive elements are)",
                w
            )));
        }
    }
    let mode = it.opts.mode.clone();
    if (mode == "PLAN GENE") != dpge.is_some() {
        return Err(match dpge {
            Some(_) => {
                a.err(format!("'DPGE' P is the generalised plane strain of OPTI MODE PLAN GENE, not of mode {}", mode))
            }
            None => a.missing("the point carrying the out-of-plane strain ('DPGE' P) of mode PLAN GENE"),
        });
    }
    if names.len() > 1 && names.iter().all(|n| shell_geometry(n).is_some()) {
        return super::model_mixed::shells_by_geometry(a, geo, formulation, behaviour, &names, mode);
    }
    let shell = shell_geometry(&element);
    if let Some(ty) = shell {
        if let Some(p) = geo.parts.iter().find(|p| p.ty != ty) {
            return Err(a
                .err(format!(
                    "{} is a shell element on {} meshes; this mesh has {} elements",
                    element,
                    ty.name(),
                    p.ty.name()
                ))
                .note(if ty == ElemType::Seg2 {
                    "COQ2 is the axisymmetric (AXIS) or plane shell on lines: mesh a line with OPTI ELEM SEG2"
                } else if ty == ElemType::Tri3 {
                    "mesh the surface with triangles (OPTI ELEM TRI3, or CHAN 'TRI3'), or use COQ4 on QUA4"
                } else if ty == ElemType::Qua4 {
                    "mesh the surface with quadrangles (OPTI ELEM QUA4), or use COQ3/DKT on TRI3"
                } else {
                    "COQ6 is made for TRI6 meshes and COQ8 for QUA8 (OPTI ELEM TRI6 or QUA8)"
                }));
        }
        if ty == ElemType::Seg2 {
            if mode == "TRID" {
                return Err(a.err("COQ2 shells need OPTI DIME 2 and mode AXIS, PLAN CONT or PLAN DEFO, not TRID"));
            }
        } else if mode != "TRID" {
            return Err(a.err(format!("{} shells need OPTI DIME 3 MODE TRID, not mode {}", element, mode)));
        }
    }
    let mut model = Model { zones: vec![], ties: Vec::new() };
    if let Some(&(_, ty)) = incomp::NAMES.iter().find(|(n, _)| *n == element) {
        return incompressible_model(a, geo, formulation, behaviour, element, ty, mode);
    }
    if element == "XQ4R" || element == "XC8R" {
        return super::xfem_model::model(a, geo, formulation, behaviour, mode, &element);
    }
    // Massive elements follow the mesh: one zone per element type.
    if element.is_empty() || ElemType::from_name(&element).is_some() {
        for p in &geo.parts {
            model.zones.push(ModelZone { dpge, ..ModelZone::on_part(p, &formulation, &behaviour, None, &mode) });
        }
    } else {
        model.zones.push(ModelZone {
            mesh: geo,
            formulation,
            behaviour,
            element,
            mode,
            dpge: None,
            xfem: None,
            cons: String::new(),
        });
    }
    for z in &mut model.zones {
        z.cons.clone_from(&cons);
    }
    Ok(vec![Value::Model(Rc::new(model))])
}

/// A model of incompressible elements (ICT3 on TRI3, ICQ4 on QUA4, ...):
/// one zone per mesh part, each of the element's own geometry.
fn incompressible_model(
    a: &Args,
    geo: Mesh,
    formulation: String,
    behaviour: Vec<String>,
    element: String,
    ty: ElemType,
    mode: String,
) -> Result<Vec<Value>> {
    if let Some(p) = geo.parts.iter().find(|p| p.ty != ty) {
        return Err(a.err(format!(
            "{} is the incompressible element on {} meshes; this mesh has {} elements",
            element,
            ty.name(),
            p.ty.name()
        )));
    }
    if (ty.dim() == 3) != (mode == "TRID") {
        return Err(a.err(format!("{} elements are not available in mode {}", element, mode)));
    }
    let zones =
        geo.parts.iter().map(|p| ModelZone::on_part(p, &formulation, &behaviour, Some(&element), &mode)).collect();
    Ok(vec![Value::Model(Rc::new(Model { zones, ties: Vec::new() }))])
}

/// `'EPSI' MOT`: how strains are computed. gibi's elements use small
/// (linear) strains, which is what 'LINEAIRE' asks for; another measure
/// is refused rather than silently replaced.
fn epsilon(a: &mut Args) -> Result<()> {
    match a.word().map(|w| w.to_uppercase()) {
        Some(w) if w.starts_with("LINE") => Ok(()),
        Some(w) => Err(a.err(format!("EPSI {}: only linear strains (EPSI LINEAIRE) are available", w))),
        None => Err(a.missing("the strain measure after EPSI (LINEAIRE)")),
    }
}

/// Behaviour families beyond elasticity (mode.notice): accepted by MODE,
/// with whatever words follow them, so that PASAPAS can name what it lacks.
const INELASTIC: &[&str] = &["PLAS", "VISC", "ENDO", "FLUA", "NONL", "FISS", "UTIL"];

/// Whether a behaviour word belongs to a law beyond linear elasticity.
pub(crate) fn inelastic(word: &str) -> bool {
    INELASTIC.iter().any(|k| word.starts_with(k))
}

/// `MODE mesh 'CONTACT' ('UNILATERAL'|'FROTTANT' 'COULOMB' …)`: a contact
/// model on the elements of IMPO 'MAIL' (node against facet: TRI3 in 2D,
/// TET4 in 3D; segment against segment in 2D: QUA4). PASAPAS turns each
/// element into a unilateral condition; friction models are accepted here
/// and refused by PASAPAS by name.
fn contact_model(it: &mut Interp, a: &mut Args, geo: &Mesh) -> Result<Vec<Value>> {
    let mut behaviour = Vec::new();
    // UNILATERAL is read as a word before any operator check (UNIL).
    while let Some(w) = a.keyword_next(&["UNILATERAL"]).map(String::from).or_else(|| a.word_not_operator()) {
        behaviour.push(w.trim().to_uppercase());
    }
    if behaviour.is_empty() {
        behaviour.push("UNILATERAL".into());
    }
    let allowed: &[ElemType] = if it.opts.dime == 3 { &[ElemType::Tet4] } else { &[ElemType::Tri3, ElemType::Qua4] };
    if let Some(p) = geo.parts.iter().find(|p| !allowed.contains(&p.ty)) {
        return Err(a
            .err(format!("a contact model is made on contact elements, not on {} elements", p.ty.name()))
            .note("make them with IMPO 'MAIL' line1 line2 (surfaces in 3D)"));
    }
    let zones = geo.parts.iter().map(|p| ModelZone::on_part(p, "CONTACT", &behaviour, None, &it.opts.mode)).collect();
    Ok(vec![Value::Model(Rc::new(Model { zones, ties: Vec::new() }))])
}

const PROPS: &[&str] = &[
    "YOUN", "NU", "RHO", "ALPH", "TREF", "SECT", "INRY", "INRZ", "TORS", "SECY", "SECZ", "EPAI", "DIM3", "EXCE", "DX",
    "DY", "DZ", "VECT", "VX", "VY", "VZ", "EXCY", "EXCZ", "MODS", "MATS", "ALPY", "ALPZ", "JEU", "ADHE", "SIGY", "H",
    "KS", "KN", "ALPN", "K", "C", "RAYO", "RACO", "PRES",
];

fn props(it: &Interp, a: &mut Args, subtype: &str) -> Result<Vec<Value>> {
    let model = a.req::<Rc<Model>>()?;
    let mut consts = std::collections::BTreeMap::new();
    let mut vecs = std::collections::BTreeMap::new();
    let mut laws = std::collections::BTreeMap::new();
    // Properties given element by element (MANU 'CHML' mc 'JEU' j, or a
    // YOUN field REDU'ced onto the model).
    let mut fields: Vec<(&str, Rc<Mchaml>)> = Vec::new();
    let mut section = super::fibre_section::Given::default();
    while let Some(k) = a.keyword(PROPS) {
        if section.read(k, a)? {
            continue;
        }
        if k != "VECT" {
            if let Some(f) = a.opt::<Rc<Mchaml>>() {
                fields.push((k, f));
                continue;
            }
        }
        if k == "VECT" {
            let p = a.req::<PointId>()?;
            vecs.insert(k.to_string(), it.nodes.get(p.0));
        } else if let Some(ev) = a.opt_right::<Rc<Evolution>>() {
            // A property that depends on a parameter: VARI evaluates it.
            laws.insert(k.to_string(), super::variable::law_of(a, k, &ev)?);
        } else {
            consts.insert(k.to_string(), a.opt_num().ok_or_else(|| a.missing("FLOTTANT or EVOLUTIO"))?);
        }
    }
    if let Some(w) = a.word_not_operator() {
        return Err(a.err(format!("unknown property {}", w)));
    }
    for (k, v) in section.properties(it, a)? {
        consts.entry(k.to_string()).or_insert(v);
    }
    let mut zones = Vec::new();
    for z in &model.zones {
        let mut mz = MchamlZone {
            mesh: z.mesh.clone(),
            cons: z.cons.clone(),
            element: z.element.clone(),
            constants: consts.clone(),
            vectors: vecs.clone(),
            laws: laws.clone(),
            objects: section.objects().into_iter().map(|(k, v)| (k.to_string(), v)).collect(),
            ..Default::default()
        };
        if z.element == "TUYA" {
            tube_section(a, &mut mz.constants)?;
        }
        for (name, f) in &fields {
            let per = element_values(f, &z.mesh, name).map_err(|e| a.err(e))?;
            match per.iter().all(|v| *v == per[0]) {
                // One value everywhere: a constant like a number.
                true if !per.is_empty() => {
                    mz.constants.insert(name.to_string(), per[0]);
                }
                _ => {
                    mz.comps.push(name.to_string());
                    if mz.values.is_empty() {
                        mz.values = vec![vec![vec![]]; per.len()];
                    }
                    for (e, v) in per.iter().enumerate() {
                        mz.values[e][0].push(*v);
                    }
                }
            }
        }
        zones.push(mz);
    }
    Ok(vec![Value::Mchaml(Rc::new(Mchaml { subtype: subtype.into(), zones }))])
}

/// TUYA: the beam section of a tube (`fem::pipe`) from EPAI and RAYO
/// (and RACO, PRES for an elbow), when both are given in this call.
fn tube_section(a: &Args, c: &mut std::collections::BTreeMap<String, f64>) -> Result<()> {
    let (Some(&e), Some(&r)) = (c.get("EPAI"), c.get("RAYO")) else { return Ok(()) };
    let props = crate::fem::pipe::section(e, r, c.get("RACO").copied(), c.get("PRES").copied(), c.get("YOUN").copied())
        .map_err(|m| a.err(m))?;
    for (k, v) in props {
        c.entry(k.to_string()).or_insert(v);
    }
    Ok(())
}

/// The value of component `name` of `f` on each element of `mesh` (its
/// first point), the field being given on that mesh.
fn element_values(f: &Mchaml, mesh: &Mesh, name: &str) -> std::result::Result<Vec<f64>, String> {
    let mut out = Vec::new();
    for part in &mesh.parts {
        let z = f
            .zones
            .iter()
            .find(|z| z.mesh.parts.first() == Some(part) || z.mesh == Mesh::single(part.clone()))
            .ok_or_else(|| format!("the {} field is not given on the elements of the model", name))?;
        let ci = z.comps.iter().position(|c| c == name);
        for e in 0..part.len() {
            let v = match (ci, z.values.get(e).and_then(|pts| pts.first())) {
                (Some(ci), Some(pt)) => pt[ci],
                _ => *z.constants.get(name).ok_or_else(|| format!("the field has no component {}", name))?,
            };
            if !v.is_finite() {
                return Err(format!("the {} field holds a non-finite value", name));
            }
            out.push(v);
        }
    }
    Ok(out)
}

fn mate(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    props(it, a, "CARACTERISTIQUES")
}

fn cara(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    props(it, a, "CARACTERISTIQUES")
}

/// The material of one model zone, merged from every MCHAML given.
pub(crate) fn material_for(zone: &ModelZone, fields: &[Rc<Mchaml>]) -> Material {
    let mut m = Material::default();
    for f in fields {
        for z in f.zones.iter().filter(|z| z.belongs_to(zone)) {
            for (k, v) in &z.constants {
                // Entries "STRESS/STRAIN" of a HOOKE field (ops/hooke.rs).
                if !m.set(k, *v) && k.contains('/') {
                    m.hooke.push((k.clone(), *v));
                }
            }
            if let Some(v) = z.vectors.get("VECT") {
                m.vect = Some(*v);
            }
        }
    }
    m
}

/// The mesh geometry a shell element needs (None for other elements).
pub(crate) fn shell_geometry(element: &str) -> Option<ElemType> {
    match element {
        "COQ3" | "DKT" | "DST" => Some(ElemType::Tri3),
        "COQ4" => Some(ElemType::Qua4),
        "COQ6" => Some(ElemType::Tri6),
        "COQ8" => Some(ElemType::Qua8),
        "COQ2" => Some(ElemType::Seg2),
        _ => None,
    }
}

pub(crate) fn formulation(zone: &ModelZone) -> Formulation {
    if zone.formulation == super::heat::FORMULATION {
        return Formulation::Thermal;
    }
    if zone.dpge.is_some() {
        return Formulation::Dpge;
    }
    match zone.element.as_str() {
        "COQ3" => Formulation::Coq3,
        "DKT" => Formulation::Dkt,
        "DST" => Formulation::Dst,
        "COQ4" => Formulation::Coq4,
        "COQ6" => Formulation::Coq6,
        "COQ8" => Formulation::Coq8,
        "COQ2" => Formulation::Coq2,
        "BARR" => Formulation::Barr,
        "BAEX" => Formulation::Baex,
        "POUT" => Formulation::Pout,
        "TIMO" => Formulation::Timo,
        // A pipe is a beam with a tube's section (`tube_section`).
        "TUYA" => Formulation::Pout,
        "Q4RI" => Formulation::Q4ri,
        "Q8RI" => Formulation::Q8ri,
        "JOI2" | "JOI3" | "JOI4" => Formulation::Joint,
        e if incomp::NAMES.iter().any(|(n, _)| *n == e) => Formulation::Incomp,
        _ => Formulation::Solid,
    }
}

pub(crate) fn zone_mode(zone: &ModelZone) -> Result<Mode> {
    Ok(match zone.mode.as_str() {
        "PLAN CONT" => Mode::PlanCont,
        // Generalised plane strain: the plane-strain elements plus the
        // extra point of their zone (Formulation::Dpge).
        "PLAN DEFO" | "PLAN GENE" => Mode::PlanDefo,
        "AXIS" => Mode::Axis,
        "TRID" => Mode::Trid,
        m if m.strip_prefix("FOUR ").is_some_and(|n| n.parse::<i32>().is_ok()) => {
            Mode::Fourier(m[5..].parse().unwrap_or(0))
        }
        m => return Err(Error::runtime(format!("analysis mode {} is not supported by the element library", m))),
    })
}

fn fem_err(e: element::FemError) -> Error {
    Error::runtime(e.to_string())
}

fn rigi(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let Some(model) = a.opt::<Rc<Model>>() else {
        return springs(it, a, Subtype::Rigidite);
    };
    let mut fields = Vec::new();
    while let Some(f) = a.opt::<Rc<Mchaml>>() {
        fields.push(f);
    }
    let mut rig = Rigidite::new(Subtype::Rigidite);
    for zone in model.zones.iter().filter(|z| z.formulation != super::pres_model::FORMULATION) {
        if matches!(zone.element.as_str(), "QUAS" | "TRIS") {
            return Err(a
                .err(format!("a {} model describes a beam section and has no stiffness of its own", zone.element))
                .note("give it to a TIMO beam: MATE beam_model 'MODS' section_model 'MATS' section_material"));
        }
        if let Some(x) = &zone.xfem {
            rig.blocks.extend(super::xfem_model::stiffness_blocks(it, a, zone, x, &fields)?);
            continue;
        }
        let form = formulation(zone);
        let mode = zone_mode(zone)?;
        let mat = material_for(zone, &fields);
        super::variable::no_unevaluated_law(a, zone, &fields)?;
        for part in &zone.mesh.parts {
            let mats = super::variable::element_materials(a, &mat, part, &fields)?;
            rig.blocks.push(stiffness_block(it, form, mode, part, &mats, zone.dpge).map_err(|e| {
                let hint = if e.message.contains("property VECT missing") {
                    Some("in 3D a beam needs its local y axis: CARA mo ... 'VECT' (0. 0. 1.) (any vector not along the beam)")
                } else if e.message.contains("property SECY missing") || e.message.contains("property SECZ missing") {
                    Some("TIMO needs the shear areas: SECY (shear along local y) and, in 3D, SECZ")
                } else if e.message.contains("property EPAI missing") {
                    Some("shells need their thickness: CARA mo 'EPAI' t (or MATE mo ... 'EPAI' t)")
                } else {
                    None
                };
                let err = a.err(e.message);
                match hint {
                    Some(h) => err.note(h),
                    None => err,
                }
            })?);
        }
    }
    Ok(vec![Value::Rigi(Rc::new(rig))])
}

/// Element stiffness on every element of one part, as one block. `mats`
/// holds one material for the whole part, or one per element. `extra` is
/// a node every element also holds, after its own (DPGE).
pub(crate) fn stiffness_block(
    it: &Interp,
    form: Formulation,
    mode: Mode,
    part: &crate::fem::mesh::Part,
    mats: &[Material],
    extra: Option<usize>,
) -> Result<Block> {
    let block = super::element_block::part_block(it, part, extra, Symmetry::Symmetric, |e, x| {
        let mat = if mats.len() == 1 { &mats[0] } else { &mats[e] };
        element::stiffness(form, part.ty, mode, x, mat)
            .map_err(|err| Error::runtime(format!("element {}: {}", e + 1, fem_err(err).message)))
    })?;
    block.ok_or_else(|| Error::runtime("the model has no element"))
}

/// Springs to ground: RIGI/APPU (DEPL) (ROTA) (comps) (DIRECTION v) k GEO.
/// Springs (RIGI) or point masses (MASS) on the nodes of a geometry: the
/// two forms read the same arguments and differ only by the subtype.
pub(crate) fn springs(it: &mut Interp, a: &mut Args, subtype: Subtype) -> Result<Vec<Value>> {
    let mut comps: Vec<String> = Vec::new();
    let mut dir: Option<[f64; 3]> = None;
    let mut k: Option<f64> = None;
    let mut geo: Option<Mesh> = None;
    loop {
        if let Some(kw) = a.keyword(&["DEPL", "ROTA", "DIRECTION"]) {
            match kw {
                "DEPL" => comps.extend(dofs::translations(it).iter().map(|s| s.to_string())),
                "ROTA" => comps.extend(dofs::rotations(it).iter().map(|s| s.to_string())),
                _ => dir = Some(it.nodes.get(a.req::<PointId>()?.0)),
            }
        } else if k.is_none() && a.peek_right().is_some_and(|v| v.is_number()) {
            k = a.opt_num_right();
        } else if let Some(l) = a.opt_right::<Rc<Vec<String>>>() {
            comps.extend(l.iter().cloned());
        } else if geo.is_none() && a.peek_right().is_some_and(|v| matches!(v, Value::Point(_) | Value::Mesh(_))) {
            geo = Some(req_geo(a)?);
        } else if let Some(w) = a.word_not_operator() {
            comps.push(w);
        } else {
            break;
        }
    }
    let k = match k {
        Some(k) => k,
        None => a.req_num()?,
    };
    let geo = match geo {
        Some(g) => g,
        None => req_geo(a)?,
    };
    let mut rig = Rigidite::new(subtype);
    let nodes = geo.node_list();
    if let Some(v) = dir {
        let t = dofs::translations(it);
        let norm = v[..t.len()].iter().map(|x| x * x).sum::<f64>().sqrt();
        if norm == 0.0 {
            return Err(a.err("the direction is a zero vector"));
        }
        let n: Vec<f64> = v[..t.len()].iter().map(|x| x / norm).collect();
        let mut mats = Vec::new();
        for _ in &nodes {
            for i in 0..t.len() {
                for j in 0..t.len() {
                    mats.push(k * n[i] * n[j]);
                }
            }
        }
        rig.blocks.push(Block {
            nodes_per_elem: 1,
            conn: nodes,
            dofs: t.iter().map(|c| (0, c.to_string())).collect(),
            duals: t.iter().map(|c| dofs::dual_of(c)).collect(),
            mats,
            symmetry: Symmetry::Symmetric,
        });
    } else {
        if comps.is_empty() {
            return Err(a.missing("the unknowns of the springs"));
        }
        for c in comps {
            rig.blocks.push(Block {
                nodes_per_elem: 1,
                conn: nodes.clone(),
                dofs: vec![(0, c.clone())],
                duals: vec![dofs::dual_of(&c)],
                mats: vec![k; nodes.len()],
                symmetry: Symmetry::Symmetric,
            });
        }
    }
    Ok(vec![Value::Rigi(Rc::new(rig))])
}

fn appu(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    springs(it, a, Subtype::Rigidite)
}
