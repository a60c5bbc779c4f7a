//! Linear heat conduction: MODE mesh 'THERMIQUE' (read here for
//! `ops/model.rs`), CONDUCTIVITE and CAPACITE. The unknown is T (dual Q);
//! BLOQ 'T', DEPI and RESO solve the conduction problem as they solve
//! statics, and GRAD of a temperature gives T,X T,Y (T,Z). The element
//! numerics are in `fem::thermal`.

use super::model::{formulation, material_for, zone_mode};
use super::{Args, OpDef};
use crate::error::{Error, Result};
use crate::eval::Interp;
use crate::fem::element::{self, Formulation};
use crate::fem::mesh::{ElemType, Mesh};
use crate::value::model::ModelZone;
use crate::value::rigidity::{Subtype, Symmetry};
use crate::value::{Mchaml, Model, Rigidite, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "COND",
        signature: "COND MMODEL_THERMIQUE MCHAML",
        doc: "Conductivity matrix ∫ k ∇Nᵢ·∇Nⱼ of a THERMIQUE model (MATE 'K'), on the unknown T (dual Q); solve it with BLOQ 'T', DEPI and RESO.",
        example: "mo = mode (surf ((0. 0.) (1. 0.) (1. 1.) (0. 1.))) thermique ; k = cond mo (mate mo 'K' 2.) ;",
        f: cond,
    },
    OpDef {
        name: "CAPA",
        signature: "CAPA MMODEL_THERMIQUE MCHAML ('LUMP')",
        doc: "Heat capacity matrix ∫ ρ c Nᵢ Nⱼ of a THERMIQUE model (MATE 'RHO' and 'C'), on the unknown T; 'LUMP' gives it diagonal, keeping its total.",
        example: "mo = mode (surf ((0. 0.) (1. 0.) (1. 1.) (0. 1.))) thermique ; c = capa mo (mate mo 'RHO' 2. 'C' 3.) ;",
        f: capa,
    },
];

/// The formulation name MODE stores for a heat conduction model.
pub(crate) const FORMULATION: &str = "THERMIQUE";

/// Behaviour words of a conduction model (mode.notice, THERMIQUE).
const BEHAVIOURS: &[&str] = &["ISOTROPE", "CONDUCTION"];

/// The massive geometries a conduction model takes, by analysis mode.
fn accepts(ty: ElemType, trid: bool) -> bool {
    crate::fem::solid::is_massive(ty) && (ty.dim() == 3) == trid
}

/// `MODE mesh 'THERMIQUE' ('ISOTROPE') ('CONDUCTION') (element)`: one zone
/// per element type of the mesh, on the massive elements.
pub(crate) fn model(it: &Interp, a: &mut Args, geo: &Mesh) -> Result<Vec<Value>> {
    let mut behaviour = Vec::new();
    while let Some(w) = a.keyword_next(BEHAVIOURS).map(String::from).or_else(|| a.word_not_operator()) {
        let w = w.to_uppercase();
        if let Some(b) = BEHAVIOURS.iter().find(|b| super::args::keyword_matches(&w, b)) {
            behaviour.push(b.to_string());
        } else if ElemType::from_name(&w).is_some() {
            // The element follows the mesh geometry, as for massive
            // mechanical models; a name that does not fit is caught below.
        } else {
            return Err(
                a.err(format!("THERMIQUE {} is not available (isotropic conduction on massive elements is)", w))
            );
        }
    }
    let mode = it.opts.mode.clone();
    let trid = mode == "TRID";
    if let Some(p) = geo.parts.iter().find(|p| !accepts(p.ty, trid)) {
        return Err(a
            .err(format!("a THERMIQUE model in mode {} has no element on {}", mode, p.ty.name()))
            .note("conduction is modelled on surfaces (TRI3, QUA4, TRI6, QUA8) in 2D and volumes in TRID"));
    }
    let zones = geo.parts.iter().map(|p| ModelZone::on_part(p, FORMULATION, &behaviour, None, &mode)).collect();
    Ok(vec![Value::Model(Rc::new(Model { zones, ties: Vec::new() }))])
}

/// The model and material fields of COND and CAPA; every zone must be a
/// conduction one (a mechanical model has RIGI and MASS).
fn thermal_args(a: &mut Args) -> Result<(Rc<Model>, Vec<Rc<Mchaml>>)> {
    let model = a.req::<Rc<Model>>()?;
    let mut fields = Vec::new();
    while let Some(f) = a.opt::<Rc<Mchaml>>() {
        fields.push(f);
    }
    if let Some(z) = model.zones.iter().find(|z| formulation(z) != Formulation::Thermal) {
        return Err(a
            .err(format!("the model is {}, not THERMIQUE", z.formulation))
            .note("a mechanical model's matrices are RIGI and MASS"));
    }
    Ok((model, fields))
}

type ElemFn<'f> = dyn Fn(
        ElemType,
        element::Mode,
        &[[f64; 3]],
        &element::Material,
    ) -> std::result::Result<element::ElemMatrix, element::FemError>
    + 'f;

/// One block per mesh part of the element matrices `f` gives.
fn assemble(
    it: &Interp,
    a: &Args,
    model: &Model,
    fields: &[Rc<Mchaml>],
    subtype: Subtype,
    f: &ElemFn,
) -> Result<Rigidite> {
    let mut rig = Rigidite::new(subtype);
    for zone in &model.zones {
        let mode = zone_mode(zone)?;
        let mat = material_for(zone, fields);
        for part in &zone.mesh.parts {
            let block = super::element_block::part_block(it, part, None, Symmetry::Symmetric, |e, x| {
                f(part.ty, mode, x, &mat).map_err(|err| a.err(format!("element {}: {}", e + 1, err)))
            })?;
            rig.blocks.extend(block);
        }
    }
    if rig.blocks.is_empty() {
        return Err(Error::runtime("the model has no element"));
    }
    Ok(rig)
}

fn cond(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let (model, fields) = thermal_args(a)?;
    let rig = assemble(it, a, &model, &fields, Subtype::Conductivite, &|ty, mode, x, m| {
        element::stiffness(Formulation::Thermal, ty, mode, x, m)
    })?;
    Ok(vec![Value::Rigi(Rc::new(rig))])
}

fn capa(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let (model, fields) = thermal_args(a)?;
    let lumped = a.keyword(&["LUMP", "DIAG"]).is_some();
    let rig = assemble(it, a, &model, &fields, Subtype::Capacite, &|ty, mode, x, m| {
        element::mass(Formulation::Thermal, ty, mode, x, m, lumped)
    })?;
    Ok(vec![Value::Rigi(Rc::new(rig))])
}
