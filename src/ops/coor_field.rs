//! `COOR (N1) CHEL1` (coor.notice): the coordinates of the points where an
//! element field has its values, element by element, as element fields of
//! the same layout.

use super::Args;
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::element::gauss_positions;
use crate::value::model::{MchamlZone, ModelZone};
use crate::value::{Mchaml, Value};
use std::rc::Rc;

/// The positions of the points of every element of a zone: its nodes for
/// a field at the nodes, else the formulation's points when their count
/// matches, the centre for one value per element.
fn positions(it: &Interp, a: &Args, z: &MchamlZone) -> Result<Vec<Vec<[f64; 3]>>> {
    let mz = ModelZone {
        mesh: z.mesh.clone(),
        formulation: String::new(),
        behaviour: Vec::new(),
        element: z.element.clone(),
        mode: String::new(),
        dpge: None,
        xfem: None,
        cons: String::new(),
    };
    let form = super::model::formulation(&mz);
    let mut out = Vec::new();
    let mut e = 0;
    for p in &z.mesh.parts {
        for nodes in p.elems() {
            let x: Vec<[f64; 3]> = nodes.iter().map(|&n| it.nodes.get(n)).collect();
            let want = z.values.get(e).map(|v| v.len());
            let pts = if z.at_nodes {
                x.clone()
            } else {
                let g = gauss_positions(form, p.ty, &x);
                match want {
                    Some(1) if g.len() != 1 => {
                        let mut c = [0.0; 3];
                        for xi in &x {
                            for k in 0..3 {
                                c[k] += xi[k] / x.len() as f64;
                            }
                        }
                        vec![c]
                    }
                    Some(n) if n != g.len() => {
                        return Err(a.err(format!(
                            "element {} has values at {} points, its {} element at {}",
                            e + 1,
                            n,
                            z.element,
                            g.len()
                        )))
                    }
                    _ => g,
                }
            };
            out.push(pts);
            e += 1;
        }
    }
    Ok(out)
}

pub(crate) fn coor_of_mchaml(it: &Interp, a: &Args, which: Option<i64>, m: &Mchaml) -> Result<Vec<Value>> {
    let dim = it.opts.dime.max(1) as i64;
    let ks: Vec<i64> = match which {
        None => (1..=dim).collect(),
        Some(k) if (1..=dim).contains(&k) => vec![k],
        Some(k) => {
            return Err(a.err(format!("coordinate {} of an element field does not exist in dimension {}", k, dim)))
        }
    };
    let mut per_zone = Vec::new();
    for z in &m.zones {
        per_zone.push(positions(it, a, z)?);
    }
    Ok(ks
        .into_iter()
        .map(|k| {
            let zones = m
                .zones
                .iter()
                .zip(&per_zone)
                .map(|(z, pos)| MchamlZone {
                    mesh: z.mesh.clone(),
                    element: z.element.clone(),
                    comps: vec!["SCAL".to_string()],
                    values: pos.iter().map(|pts| pts.iter().map(|x| vec![x[k as usize - 1]]).collect()).collect(),
                    at_nodes: z.at_nodes,
                    ..Default::default()
                })
                .collect();
            Value::Mchaml(Rc::new(Mchaml { subtype: "SCALAIRE".into(), zones }))
        })
        .collect())
}
