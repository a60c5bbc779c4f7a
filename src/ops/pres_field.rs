//! PRES 'MASS' with a pressure that varies over the faces: given at nodes
//! (a CHPOINT, on the model's boundary faces whose nodes all carry it) or
//! as an element field at the nodes of face elements (CHAN 'CHAM' of a
//! CHPOINT on a face mesh).

use super::model::{material_for, zone_mode};
use super::{dofs, Args};
use crate::error::{Error, Result};
use crate::eval::Interp;
use crate::fem::mesh::ElemType;
use crate::value::{Chpoint, Mchaml, Model, Nature, Value};
use std::rc::Rc;

fn model_dim(model: &Model) -> usize {
    model.zones.iter().flat_map(|z| z.mesh.parts.iter()).map(|p| p.ty.dim()).max().unwrap_or(0)
}

/// Whether an element field lies on faces of the model (one dimension
/// below its elements): then it is a pressure, not a characteristic.
pub(super) fn on_faces(model: &Model, f: &Mchaml) -> bool {
    let d = model_dim(model);
    d > 0 && !f.zones.is_empty() && f.zones.iter().all(|z| z.mesh.parts.iter().all(|p| p.ty.dim() + 1 == d))
}

/// The one component a pressure field carries.
fn component(a: &Args, comps: &[String]) -> Result<String> {
    match comps {
        [c] => Ok(c.clone()),
        _ => Err(a.err(format!("the pressure field must have one component, not {}", comps.len()))),
    }
}

/// Add the forces of one face with nodal pressures `p`.
#[allow(clippy::too_many_arguments)]
fn add_face(
    it: &Interp,
    a: &Args,
    model: &Model,
    fields: &[Rc<Mchaml>],
    out: &mut Chpoint,
    ty: ElemType,
    face: &[usize],
    p: &[f64],
) -> Result<()> {
    let (zone, inside) = super::post::inside_point(it, model, face)
        .ok_or_else(|| a.err(format!("the face through node {} belongs to no element of the model", face[0] + 1)))?;
    let mode = zone_mode(&model.zones[zone])?;
    let t = if fields.is_empty() {
        1.0
    } else {
        material_for(&model.zones[zone], fields)
            .thickness(mode, ty.name())
            .map_err(|e| Error::runtime(e.to_string()))?
    };
    let x: Vec<[f64; 3]> = face.iter().map(|n| it.nodes.get(*n)).collect();
    let pt: Vec<f64> = p.iter().map(|v| v * t).collect();
    let f = crate::fem::loads::pressure_load_nodal(ty, mode, &x, &pt, inside).map_err(|e| a.err(e.to_string()))?;
    let names = dofs::forces(it);
    for (n, v) in face.iter().zip(f) {
        for (k, c) in names.iter().enumerate() {
            out.add(*n, c, v[k], true);
        }
    }
    Ok(())
}

/// PRES 'MASS' MODL CHPO: every face on the boundary of the model whose
/// nodes all carry the pressure.
pub(super) fn from_chpoint(
    it: &mut Interp,
    a: &mut Args,
    model: &Model,
    ch: &Chpoint,
    fields: &[Rc<Mchaml>],
) -> Result<Vec<Value>> {
    let comp = component(a, &ch.components())?;
    let parts = model.zones.iter().flat_map(|z| z.mesh.parts.iter());
    let mut out = Chpoint::new(Nature::Discret);
    for (fty, face) in &crate::fem::meshing::edges::boundary_faces(parts) {
        let p: Option<Vec<f64>> = face.iter().map(|n| ch.get(*n, &comp)).collect();
        if let Some(p) = p {
            add_face(it, a, model, fields, &mut out, *fty, face, &p)?;
        }
    }
    Ok(vec![Value::Chpo(Rc::new(out))])
}

/// PRES 'MASS' MODL CHEL: the face elements of the field, with its values
/// at their nodes.
pub(super) fn from_mchaml(
    it: &mut Interp,
    a: &mut Args,
    model: &Model,
    f: &Mchaml,
    fields: &[Rc<Mchaml>],
) -> Result<Vec<Value>> {
    let mut out = Chpoint::new(Nature::Discret);
    for z in &f.zones {
        let comp = component(a, &z.comps)?;
        let ci = z.comps.iter().position(|c| *c == comp).unwrap_or(0);
        for part in &z.mesh.parts {
            for (e, face) in part.elems().enumerate() {
                let row = z.values.get(e).ok_or_else(|| a.err("the pressure field has fewer values than elements"))?;
                if !z.at_nodes || row.len() != face.len() {
                    return Err(
                        a.err("the pressure field must be given at the nodes of the faces (CHAN 'CHAM' CHPO GEO)")
                    );
                }
                let p: Vec<f64> = row.iter().map(|r| r[ci]).collect();
                add_face(it, a, model, fields, &mut out, part.ty, face, &p)?;
            }
        }
    }
    Ok(vec![Value::Chpo(Rc::new(out))])
}
