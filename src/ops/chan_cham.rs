//! CHAN 'CHAM': a node field made a field by element of a model, at the
//! elements' nodes, or at the points where they give their stresses
//! (subtype 'STRESSES' / 'CONTRAINTES'), interpolated by the shape
//! functions. On a mesh instead of a model, at the nodes of each of its
//! elements.

use super::model::formulation;
use super::Args;
use crate::error::Result;
use crate::fem::mesh::Mesh;
use crate::fem::{element, shape};
use crate::value::model::{MchamlZone, ModelZone};
use crate::value::{Chpoint, Mchaml, Model, Value};
use std::rc::Rc;

pub(crate) fn chan_cham(a: &mut Args) -> Result<Vec<Value>> {
    let model = a
        .opt_with(|v| match v {
            Value::Model(m) => Some(m.clone()),
            // A mesh: a zone per part, named by its element type.
            Value::Mesh(g) => Some(Rc::new(Model {
                zones: g
                    .parts
                    .iter()
                    .filter(|p| !p.is_empty())
                    .map(|p| ModelZone {
                        mesh: Mesh::single(p.clone()),
                        formulation: String::new(),
                        behaviour: Vec::new(),
                        element: p.ty.name().to_string(),
                        mode: String::new(),
                    })
                    .collect(),
            })),
            _ => None,
        })
        .ok_or_else(|| a.missing("MMODEL or MAILLAGE"))?;
    let field = a.req_find::<Rc<Chpoint>>()?;
    let at_stress_points = matches!(a.keyword(&["NOEUD", "STRESSES", "CONTRAINTES"]), Some("STRESSES" | "CONTRAINTES"));
    let comps = field.components();
    let mut zones = Vec::new();
    for mz in &model.zones {
        let f = formulation(mz);
        let mut values = Vec::new();
        for p in &mz.mesh.parts {
            for nodes in p.elems() {
                let at_nodes: Vec<Vec<f64>> = nodes
                    .iter()
                    .map(|&n| {
                        comps
                            .iter()
                            .map(|c| {
                                field
                                    .get(n, c)
                                    .ok_or_else(|| a.err(format!("the CHPOINT has no {} at node {}", c, n + 1)))
                            })
                            .collect::<Result<Vec<f64>>>()
                    })
                    .collect::<Result<_>>()?;
                if !at_stress_points {
                    values.push(at_nodes);
                    continue;
                }
                let pts = element::gauss_points(f, p.ty)
                    .into_iter()
                    .map(|(xi, _)| {
                        let s = shape::eval(p.ty, xi);
                        (0..comps.len()).map(|c| s.n.iter().zip(&at_nodes).map(|(w, v)| w * v[c]).sum()).collect()
                    })
                    .collect();
                values.push(pts);
            }
        }
        zones.push(MchamlZone {
            mesh: mz.mesh.clone(),
            element: mz.element.clone(),
            comps: comps.clone(),
            values,
            at_nodes: !at_stress_points,
            ..Default::default()
        });
    }
    let subtype = if at_stress_points { "CONTRAINTES" } else { "SCALAIRE" };
    Ok(vec![Value::Mchaml(Rc::new(Mchaml { subtype: subtype.into(), zones }))])
}
