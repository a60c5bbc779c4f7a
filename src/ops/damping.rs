//! AMOR: damping matrices. The absorbing-boundary form (Lysmer and
//! Kuhlemeyer's viscous boundary of an elastic medium) is here; its
//! numerics are in `fem::absorbing`.

use super::model::{material_for, zone_mode};
use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::absorbing;
use crate::fem::mesh::Mesh;
use crate::value::rigidity::{Subtype, Symmetry};
use crate::value::{Mchaml, Model, Rigidite, Value};
use rustc_hash::FxHashSet;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "AMOR",
    signature: "AMOR MMODEL MAILLAGE MCHAML",
    doc: "Damping matrix (subtype AMORTISSEMENT) of the viscous absorbing boundary of Lysmer and Kuhlemeyer on the faces GEO (edges in 2D, faces in 3D) of an elastic model: ∫ Nᵢ Nⱼ ρ [c_p n nᵀ + c_s (I - n nᵀ)] dS, with the wave speeds c_p, c_s of YOUN, NU, RHO from the material of the zone holding each face.",
    example: "opti dime 2 elem qua4 ; s = (0. 0.) (1. 0.) (1. 1.) (0. 1.) mani 'QUA4' ; b = (0. 0.) droi 1 (1. 0.) ; mo = mode s mecanique elastique ; ma = mate mo youn 1. nu 0. rho 1. ; c = amor mo b ma ;",
    f: amor,
}];

fn amor(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let model = a.req::<Rc<Model>>().map_err(|_| {
        a.err("gibi builds the absorbing-boundary form AMOR MMODEL MAILLAGE MCHAML (modal damping needs a modal basis, which gibi does not compute)")
    })?;
    let faces = a.opt::<Rc<Mesh>>().ok_or_else(|| {
        a.err("the boundary mesh is missing (AMOR MMODEL MAILLAGE MCHAML; material damping 'VISQ' is not available)")
    })?;
    let mut fields: Vec<Rc<Mchaml>> = Vec::new();
    while let Some(f) = a.opt::<Rc<Mchaml>>() {
        fields.push(f);
    }
    if fields.is_empty() {
        return Err(a.err("the material field (YOUN, NU, RHO) is missing"));
    }
    let zone_nodes: Vec<FxHashSet<usize>> =
        model.zones.iter().map(|z| z.mesh.parts.iter().flat_map(|p| p.conn.iter().copied()).collect()).collect();
    let mut rig = Rigidite::new(Subtype::Amortissement);
    for part in &faces.parts {
        // Every face of a part must lie on one zone: the one holding its
        // nodes gives the mode and the material.
        let mut zone_of = Vec::with_capacity(part.len());
        for (e, nodes) in part.elems().enumerate() {
            let z = zone_nodes
                .iter()
                .position(|s| nodes.iter().all(|n| s.contains(n)))
                .ok_or_else(|| a.err(format!("face {} of the boundary mesh is not on the model's elements", e + 1)))?;
            zone_of.push(z);
        }
        let mut props = Vec::with_capacity(model.zones.len());
        for zone in &model.zones {
            let m = material_for(zone, &fields);
            props.push((zone_mode(zone)?, m.youn, m.nu.unwrap_or(0.0), m.rho));
        }
        let block = super::element_block::part_block(it, part, None, Symmetry::Symmetric, |e, x| {
            let (mode, youn, nu, rho) = props[zone_of[e]];
            let (Some(youn), Some(rho)) = (youn, rho) else {
                return Err(a.err("the material needs YOUN and RHO on the zone of the boundary"));
            };
            let fe = |err: crate::fem::element::FemError| a.err(format!("face {}: {}", e + 1, err));
            let (cp, cs) = absorbing::wave_speeds(youn, nu, rho).map_err(fe)?;
            absorbing::lysmer_damping(part.ty, mode, x, rho, cp, cs).map_err(fe)
        })?;
        rig.blocks.extend(block);
    }
    Ok(vec![Value::Rigi(Rc::new(rig))])
}
