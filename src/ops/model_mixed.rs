//! MODE with several shell element names (`MODE s MECANIQUE COQ4 DKT`):
//! each element of the mesh takes the formulation made for its geometry,
//! one model zone per name, so a mesh mixing QUA4 and TRI3 is one model.

use super::model::shell_geometry;
use super::Args;
use crate::error::Result;
use crate::fem::mesh::Mesh;
use crate::value::model::ModelZone;
use crate::value::{Model, Value};
use std::rc::Rc;

pub(super) fn shells_by_geometry(
    a: &Args,
    geo: Mesh,
    formulation: String,
    behaviour: Vec<String>,
    names: &[String],
    mode: String,
) -> Result<Vec<Value>> {
    if mode != "TRID" && names.iter().any(|n| n != "COQ2") {
        return Err(a.err(format!("{} shells need OPTI DIME 3 MODE TRID, not mode {}", names.join(" "), mode)));
    }
    let mut zones: Vec<ModelZone> = Vec::new();
    for p in &geo.parts {
        let Some(name) = names.iter().find(|n| shell_geometry(n) == Some(p.ty)) else {
            return Err(a.err(format!(
                "none of the elements {} is made for the {} elements of this mesh",
                names.join(" "),
                p.ty.name()
            )));
        };
        match zones.iter_mut().find(|z| &z.element == name) {
            Some(z) => z.mesh.parts.push(p.clone()),
            None => zones.push(ModelZone::on_part(p, &formulation, &behaviour, Some(name), &mode)),
        }
    }
    Ok(vec![Value::Model(Rc::new(Model { zones, ties: Vec::new() }))])
}
