//! FSUR: nodal forces equivalent to a surface force density on the faces
//! of a massive model, on shells or on beams. Numerics in
//! `fem::surface_force`.

use super::model::{material_for, zone_mode};
use super::{dofs, Args, OpDef, PointId};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::element::Mode;
use crate::fem::mesh::{ElemType, Mesh};
use crate::fem::surface_force::surface_force;
use crate::value::{Chpoint, Mchaml, Model, Nature, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "FSUR",
    signature: "FSUR 'MASS' MMODEL (POINT_VEC MAILLAGE | CHPOINT) (MCHAML) | FSUR 'COQU'|'POUT' MMODEL (POINT_VEC | CHPOINT)",
    doc: "Nodal forces ∫ Nᵢ f dS of a surface force density f (a constant vector, or a field FX FY (FZ) / FR FZ at nodes, interpolated): 'MASS' on the faces GEO of a massive model (with a field, on the boundary faces whose nodes all carry it; in plane stress times the thickness DIM3 of the characteristics), 'COQU' on a shell model's elements, 'POUT' per unit length of a beam model's elements. AXIS gives the whole ring.",
    example: "opti dime 2 elem qua4 ; s = (0. 0.) (1. 0.) (1. 1.) (0. 1.) mani 'QUA4' ; b = (0. 0.) droi 1 (1. 0.) ; mo = mode s mecanique elastique ; f = fsur 'MASS' mo b (0. 2.) ;",
    f: fsur,
}];

fn fsur(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let kind = a.req_keyword(&["MASS", "COQU", "POUT"])?;
    let model = a.req::<Rc<Model>>()?;
    let mut vec = None;
    let mut geo = None;
    let mut field = None;
    let mut fields: Vec<Rc<Mchaml>> = Vec::new();
    loop {
        if let Some(p) = a.opt::<PointId>() {
            vec = Some(it.nodes.get(p.0));
        } else if let Some(m) = a.opt::<Rc<Mesh>>() {
            geo = Some(m);
        } else if let Some(c) = a.opt::<Rc<Chpoint>>() {
            field = Some(c);
        } else if let Some(f) = a.opt::<Rc<Mchaml>>() {
            fields.push(f);
        } else if a.keyword(&["PROJ"]).is_some() {
            return Err(a.err("'PROJ' (density per projected length) is not available"));
        } else {
            break;
        }
    }
    if vec.is_some() == field.is_some() {
        return Err(a.err("the density is missing: a vector (POINT) or a field (CHPOINT)"));
    }
    let names = dofs::forces(it);
    let density = |n: usize| -> Option<[f64; 3]> {
        match (&vec, &field) {
            (Some(v), _) => Some(*v),
            (_, Some(ch)) => {
                let vals: Vec<Option<f64>> = names.iter().map(|c| ch.get(n, c)).collect();
                if vals.iter().all(|v| v.is_none()) {
                    return None;
                }
                let mut f = [0.0; 3];
                for (k, v) in vals.into_iter().enumerate() {
                    f[k] = v.unwrap_or(0.0);
                }
                Some(f)
            }
            _ => None,
        }
    };
    // The faces (type, nodes, zone) the density acts on.
    let mut faces: Vec<(ElemType, Vec<usize>, usize)> = Vec::new();
    if kind == "MASS" {
        let list: Vec<(ElemType, Vec<usize>)> = match &geo {
            Some(g) => g.parts.iter().flat_map(|p| p.elems().map(move |e| (p.ty, e.to_vec()))).collect(),
            None => {
                let parts = model.zones.iter().flat_map(|z| z.mesh.parts.iter());
                crate::fem::meshing::edges::boundary_faces(parts)
                    .into_iter()
                    .filter(|(_, f)| f.iter().all(|n| density(*n).is_some()))
                    .collect()
            }
        };
        for (ty, face) in list {
            let (zone, _) = super::post::inside_point(it, &model, &face).ok_or_else(|| {
                a.err(format!("the face through node {} belongs to no element of the model", face[0] + 1))
            })?;
            faces.push((ty, face, zone));
        }
    } else {
        for (zi, z) in model.zones.iter().enumerate() {
            for p in &z.mesh.parts {
                for e in p.elems() {
                    if e.iter().all(|n| density(*n).is_some()) {
                        faces.push((p.ty, e.to_vec(), zi));
                    }
                }
            }
        }
    }
    let mut out = Chpoint::new(Nature::Discret);
    for (ty, face, zone) in faces {
        let mode = zone_mode(&model.zones[zone])?;
        let width = if kind == "MASS" && mode == Mode::PlanCont && !fields.is_empty() {
            material_for(&model.zones[zone], &fields).thickness(mode, ty.name()).map_err(|e| a.err(format!("{e}")))?
        } else {
            1.0
        };
        let x: Vec<[f64; 3]> = face.iter().map(|n| it.nodes.get(*n)).collect();
        let f: Vec<[f64; 3]> = face.iter().map(|n| density(*n).unwrap_or([0.0; 3])).collect();
        let forces = surface_force(ty, mode, &x, &f, width)
            .map_err(|e| a.err(format!("face through node {}: {e}", face[0] + 1)))?;
        for (n, v) in face.iter().zip(forces) {
            for (k, c) in names.iter().enumerate() {
                out.add(*n, c, v[k], true);
            }
        }
    }
    Ok(vec![Value::Chpo(Rc::new(out))])
}
