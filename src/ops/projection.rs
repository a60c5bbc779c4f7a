//! PROI: an element field at the nodes of another mesh, or on the nodes or
//! element centres of a model, interpolated with the shape functions of the
//! element holding each point (proi.notice); the computing is in
//! `value::projection`.

use super::model::formulation;
use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::value::projection::{self, Onto};
use crate::value::{Mchaml, Model, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "PROI",
    signature: "PROI GEO2 MCHAML | PROI MMODEL MCHAML ('NOEUD' | 'GRAVITE' | 'RIGIDITE' | 'MASSE' | 'STRESSES')",
    doc: "Project an element field given at the nodes of its elements (a field by element, constant in each, is taken as such) onto the nodes of a mesh (a diffuse CHPOINT) or onto the nodes, centres or integration points of the elements of a model (an MCHAML), interpolating in the element that holds each point.",
    example: "opti dime 2 elem qua4 ; s = (droi 1 (0. 0.) (1. 0.)) tran 1 (0. 1.) ; mo = mode s mecanique elastique ; ch = manu 'CHML' mo 'T' 1. 'NOEUD' ; c = proi (0.5 0.5) ch ;",
    f: proi,
}];

fn proi(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if let Some(model) = a.opt::<Rc<Model>>() {
        let field = a.req::<Rc<Mchaml>>()?;
        let onto = match a.keyword(&["NOEUD", "GRAVITE", "RIGIDITE", "MASSE", "STRESSES"]) {
            None | Some("NOEUD") => Onto::Nodes,
            Some("GRAVITE") => Onto::Centres,
            Some(_) => Onto::Gauss(&formulation),
        };
        let out = projection::onto_model(&field, &model, onto, &it.nodes).map_err(|m| a.err(m))?;
        return Ok(vec![Value::Mchaml(Rc::new(out))]);
    }
    let geo = match a.opt_with(|v| match v {
        Value::Mesh(m) => Some((**m).clone()),
        Value::Point(p) => Some(Mesh::points(&[*p])),
        _ => None,
    }) {
        Some(g) => g,
        None => return Err(a.missing("MAILLAGE, POINT or MMODEL")),
    };
    let field = a.req::<Rc<Mchaml>>()?;
    // A trailing search tolerance (used by Cast3M's own procedures): the
    // search here already takes points on an element's boundary.
    let _ = a.opt_num();
    let out = projection::onto_mesh(&field, &geo, &it.nodes).map_err(|m| a.err(m))?;
    Ok(vec![Value::Chpo(Rc::new(out))])
}
