//! `CHAN 'CHPO' MMODEL MCHAML 'SUPP'`: a node field carried by the
//! integration points of the element field, one new node per point, with
//! the value there (chan.notice: no extrapolation to the element nodes).
//! Zones of the field outside the model are left out, so a field of a
//! whole model can be taken on one of its sub-models.

use super::model::formulation;
use super::post::zone_of;
use super::Args;
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::element::{gauss_points, gauss_positions};
use crate::value::{Chpoint, Mchaml, Model, Nature, Value};

pub(crate) fn on_points(it: &mut Interp, a: &Args, model: &Model, m: &Mchaml) -> Result<Vec<Value>> {
    let mut out = Chpoint::new(Nature::Diffus);
    let mut found = false;
    for z in &m.zones {
        let Some(mz) = zone_of(model, z) else { continue };
        found = true;
        if z.values.is_empty() {
            continue;
        }
        let form = formulation(mz);
        let mut e = 0;
        for part in &z.mesh.parts {
            let gauss = gauss_points(form, part.ty);
            for nodes in part.elems() {
                let Some(v) = z.values.get(e) else { break };
                e += 1;
                let x: Vec<[f64; 3]> = nodes.iter().map(|n| it.nodes.get(*n)).collect();
                // Where each value sits: the element's nodes for a field
                // at the nodes, its centre for one value, else its
                // integration points.
                let points: Vec<[f64; 3]> = if z.at_nodes && v.len() == nodes.len() {
                    x.clone()
                } else if v.len() == gauss.len() {
                    gauss_positions(form, part.ty, &x)
                } else if v.len() == 1 {
                    // The reference centre, carried like an integration point.
                    let r = crate::fem::shape::ref_nodes(part.ty);
                    let c = r.iter().fold([0.0; 3], |s, p| [0, 1, 2].map(|i| s[i] + p[i] / r.len() as f64));
                    let n = crate::fem::shape::eval(part.ty, c).n;
                    vec![[0, 1, 2].map(|k| n.iter().zip(&x).map(|(w, xi)| w * xi[k]).sum())]
                } else {
                    return Err(a.err(format!(
                        "cannot place the {} values of a {} element on its {} integration points",
                        v.len(),
                        part.ty.name(),
                        gauss.len()
                    )));
                };
                let dens = nodes.first().map(|n| it.nodes.density[*n]).unwrap_or(0.0);
                for (row, p) in v.iter().zip(points) {
                    let node = it.nodes.push(p, dens);
                    for (c, name) in z.comps.iter().enumerate() {
                        out.add(node, name, row[c], false);
                    }
                }
            }
        }
    }
    if !found {
        return Err(a.err("the field does not belong to this model"));
    }
    Ok(vec![Value::Chpo(std::rc::Rc::new(out))])
}
