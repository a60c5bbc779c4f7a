//! The X-FEM zone of a model (MODE … XQ4R) and what RIGI, SIGM, EPSI, GRAD
//! and BSIG compute on it. The zone carries its enrichment (set by TRIE,
//! `ops/xfem.rs`); the element numerics are in `fem::xfem`. Before TRIE,
//! or where no node is enriched, an XQ4R element is the classical QUA4.

use super::model::{material_for, zone_mode};
use super::Args;
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::element::{dual_name, FemError};
use crate::fem::mesh::{ElemType, Mesh, Part};
use crate::fem::xfem::q4::{self, Field, XElem};
use crate::fem::xfem::{Enrichment, NodeKind};
use crate::fem::xfem_c8r as c8r;
use crate::value::model::{MchamlZone, ModelZone};
use crate::value::rigidity::{Block, Symmetry};
use crate::value::{Chpoint, Mchaml, Model, Value};
use std::cell::RefCell;
use std::collections::BTreeMap;
use std::rc::Rc;

pub(super) type Shared = Rc<RefCell<Enrichment>>;

/// MODE GEO 'MECANIQUE' … 'XQ4R' (QUA4, plane modes) or 'XC8R' (CUB8,
/// TRID): one X-FEM zone, not yet enriched.
pub(super) fn model(
    a: &Args,
    geo: Mesh,
    formulation: String,
    behaviour: Vec<String>,
    mode: String,
    element: &str,
) -> Result<Vec<Value>> {
    let (ty, modes, need): (ElemType, &[&str], &str) = if element == "XC8R" {
        (ElemType::Cub8, &["TRID"], "OPTI MODE TRID")
    } else {
        (ElemType::Qua4, &["PLAN DEFO", "PLAN CONT"], "a plane mode (OPTI MODE PLAN DEFO or PLAN CONT)")
    };
    if let Some(p) = geo.parts.iter().find(|p| p.ty != ty) {
        return Err(a.err(format!(
            "{element} is an X-FEM element on {} meshes; this mesh has {} elements",
            ty.name(),
            p.ty.name()
        )));
    }
    if !modes.contains(&mode.as_str()) {
        return Err(a.err(format!("{element} elements need {need}, not {mode}")));
    }
    let zone = ModelZone {
        mesh: geo,
        formulation,
        behaviour,
        element: element.into(),
        mode,
        dpge: None,
        xfem: Some(Rc::new(RefCell::new(Enrichment::default()))),
        cons: String::new(),
    };
    Ok(vec![Value::Model(Rc::new(Model { zones: vec![zone], ties: Vec::new() }))])
}

/// Is the zone made of XC8R (else XQ4R)?
pub(super) fn is_c8(zone: &ModelZone) -> bool {
    zone.element == "XC8R"
}

/// The geometry of the zone's elements.
pub(super) fn geometry(zone: &ModelZone) -> ElemType {
    if is_c8(zone) {
        ElemType::Cub8
    } else {
        ElemType::Qua4
    }
}

/// The physical displacement components of the zone.
pub(super) fn components(zone: &ModelZone) -> &'static [&'static str] {
    if is_c8(zone) {
        &["UX", "UY", "UZ"]
    } else {
        &["UX", "UY"]
    }
}

pub(super) fn el_dofs(zone: &ModelZone, kinds: &[Option<NodeKind>]) -> Vec<(usize, &'static str)> {
    if is_c8(zone) {
        c8r::dofs(kinds)
    } else {
        q4::dofs(kinds)
    }
}

/// The displacement at reference point `xi` of an element of the zone.
pub(super) fn el_displacement(
    zone: &ModelZone,
    e: &XElem,
    xi: [f64; 3],
    u: &[f64],
    side: Option<f64>,
) -> std::result::Result<Vec<f64>, FemError> {
    if is_c8(zone) {
        Ok(c8r::displacement_at(e.x, &c8r::crack_of(e)?, u, xi, side)?.to_vec())
    } else {
        Ok(q4::displacement(e, xi, u, side)?.to_vec())
    }
}

/// One element's corners, level sets and node enrichments.
pub(super) struct ElemData {
    pub x: Vec<[f64; 3]>,
    pub psi: Vec<f64>,
    pub phi: Vec<f64>,
    pub kinds: Vec<Option<NodeKind>>,
}

impl ElemData {
    pub fn elem(&self) -> XElem<'_> {
        XElem { x: &self.x, psi: &self.psi, phi: &self.phi, kinds: &self.kinds }
    }
}

pub(super) fn elem_data(it: &Interp, a: &Args, enr: &Enrichment, nodes: &[usize]) -> Result<ElemData> {
    let x = nodes.iter().map(|n| it.nodes.get(*n)).collect();
    let kinds: Vec<Option<NodeKind>> = nodes.iter().map(|n| enr.kind(*n)).collect();
    let (psi, phi) = match enr.element_levels(nodes) {
        Some(l) => l,
        None if kinds.iter().all(|k| k.is_none()) => (vec![0.0; nodes.len()], vec![0.0; nodes.len()]),
        None => {
            let n = nodes.iter().find(|n| !enr.levels.contains_key(n)).copied().unwrap_or(nodes[0]);
            return Err(a.err(format!(
                "node {} of an enriched XQ4R element has no level set: give TRIE level sets on the whole X-FEM zone",
                n + 1
            )));
        }
    };
    Ok(ElemData { x, psi, phi, kinds })
}

/// The element values of a displacement field, in the element's dof order.
pub(super) fn element_dofs(
    a: &Args,
    zone: &ModelZone,
    u: &Chpoint,
    nodes: &[usize],
    kinds: &[Option<NodeKind>],
) -> Result<Vec<f64>> {
    if let Some(n) = nodes.iter().find(|n| u.get(**n, "UX").is_none() && u.get(**n, "UY").is_none()) {
        return Err(a.err(format!(
            "node {} of an {} element has no displacement in the CHPOINT (is it the solution for this model?)",
            n + 1,
            zone.element
        )));
    }
    Ok(el_dofs(zone, kinds).iter().map(|(l, c)| u.get(nodes[*l], c).unwrap_or(0.0)).collect())
}

/// RIGI of an X-FEM zone: one block per layout of enriched unknowns
/// (a block's elements share their dofs).
pub(super) fn stiffness_blocks(
    it: &Interp,
    a: &Args,
    zone: &ModelZone,
    x: &Shared,
    fields: &[Rc<Mchaml>],
) -> Result<Vec<Block>> {
    let mode = zone_mode(zone)?;
    let mat = material_for(zone, fields);
    let enr = x.borrow();
    let mut groups: BTreeMap<Vec<u8>, Vec<usize>> = BTreeMap::new();
    for part in &zone.mesh.parts {
        for nodes in part.elems() {
            let sig = nodes.iter().map(|n| NodeKind::code(enr.kind(*n)) as u8).collect();
            groups.entry(sig).or_default().extend_from_slice(nodes);
        }
    }
    let mut out = Vec::new();
    for conn in groups.into_values() {
        let part = Part::with(geometry(zone), conn);
        let block = super::element_block::part_block(it, &part, None, Symmetry::Symmetric, |e, _| {
            let d = elem_data(it, a, &enr, part.elem(e))?;
            let k = if is_c8(zone) {
                c8r::crack_of(&d.elem()).and_then(|c| c8r::stiffness(&d.x, &c, &mat))
            } else {
                q4::stiffness(mode, &d.elem(), &mat)
            };
            k.map_err(|err| a.err(format!("{} element: {}", zone.element, err)))
        })?;
        out.extend(block);
    }
    Ok(out)
}

/// SIGM, EPSI or GRAD (by the subtype of the field made) on an X-FEM zone.
pub(super) fn gauss_zones(
    it: &Interp,
    a: &Args,
    zone: &ModelZone,
    x: &Shared,
    fields: &[Rc<Mchaml>],
    u: &Chpoint,
    subtype: &str,
) -> Result<Vec<MchamlZone>> {
    let what = match subtype {
        "CONTRAINTES" => Field::Stress,
        "DEFORMATIONS" => Field::Strain,
        _ => Field::Gradient,
    };
    let mode = zone_mode(zone)?;
    let mat = material_for(zone, fields);
    let enr = x.borrow();
    let mut out = Vec::new();
    for part in &zone.mesh.parts {
        let mut z =
            MchamlZone { mesh: Mesh::single(part.clone()), element: zone.element.clone(), ..Default::default() };
        for (e, nodes) in part.elems().enumerate() {
            let d = elem_data(it, a, &enr, nodes)?;
            let ue = element_dofs(a, zone, u, nodes, &d.kinds)?;
            let g = if is_c8(zone) {
                c8r::field_of(&d.elem(), &mat, &ue, what)
            } else {
                q4::field(mode, &d.elem(), &mat, &ue, what)
            };
            let g = g.map_err(|err| a.err(format!("element {}: {}", e + 1, err)))?;
            if z.comps.is_empty() {
                z.comps = g.comps.iter().map(|c| c.to_string()).collect();
            }
            z.values.push(g.values);
        }
        out.push(z);
    }
    Ok(out)
}

/// BSIG on an X-FEM zone: the forces on every unknown, enriched ones too.
pub(super) fn bsig_zone(
    it: &Interp,
    a: &Args,
    zone: &ModelZone,
    x: &Shared,
    z: &MchamlZone,
    fields: &[Rc<Mchaml>],
    out: &mut Chpoint,
) -> Result<()> {
    let mode = zone_mode(zone)?;
    let mat = material_for(zone, fields);
    let enr = x.borrow();
    let mut e = 0;
    for part in &z.mesh.parts {
        for nodes in part.elems() {
            if e >= z.values.len() {
                return Err(a.err(format!("the stress field has no values on element {}", e + 1)));
            }
            let d = elem_data(it, a, &enr, nodes)?;
            let sig = super::post::to_gauss(z, e);
            let f = if is_c8(zone) {
                c8r::crack_of(&d.elem()).and_then(|c| c8r::internal_forces(&d.x, &c, &sig))
            } else {
                q4::internal_forces(mode, &d.elem(), &mat, &sig)
            };
            let f = f.map_err(|err| a.err(format!("element {}: {}", e + 1, err)))?;
            for ((l, c), v) in el_dofs(zone, &d.kinds).iter().zip(f) {
                out.add(nodes[*l], &dual_name(c), v, true);
            }
            e += 1;
        }
    }
    Ok(())
}
