//! VSUR and JACO: surface (or tangent) vectors and jacobians of a model's
//! elements at their output points, as MCHAML. Numerics in
//! `fem::surface_vectors`.

use super::model::{formulation, zone_mode};
use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::element::Mode;
use crate::fem::surface_vectors::{jacobians, surface_vectors};
use crate::value::model::MchamlZone;
use crate::value::{Mchaml, Model, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "VSUR",
        signature: "VSUR MMODEL ('NORM')",
        doc: "Surface vectors at the points of a model's shell elements (the normal, on the side of the node order, of length the jacobian there), tangent vectors of its beams (dX/dξ), none for other elements; unit vectors with 'NORM'. Components VX VY (VZ), VR VZ in AXIS.",
        example: "v = vsur mo 'NORM' ;",
        f: vsur,
    },
    OpDef {
        name: "JACO",
        signature: "JACO MMODEL",
        doc: "The absolute value of the jacobian of the reference-to-element map at the points of a model's elements (|dX/dξ| on lines, |dX/dξ × dX/dη| on surfaces, |det| in volumes): component SCAL.",
        example: "j = jaco mo ;",
        f: jaco,
    },
];

fn vsur(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let model = a.req::<Rc<Model>>()?;
    let unit = a.keyword(&["NORM"]).is_some();
    let mut out = Mchaml { subtype: if unit { "NORMALES" } else { "VECTEURS SURFACE" }.into(), zones: vec![] };
    for z in &model.zones {
        let (form, mode) = (formulation(z), zone_mode(z)?);
        let comps: &[&str] = match mode {
            Mode::Trid => &["VX", "VY", "VZ"],
            Mode::Axis | Mode::Fourier(_) => &["VR", "VZ"],
            _ => &["VX", "VY"],
        };
        let mut nz = MchamlZone { mesh: z.mesh.clone(), element: z.element.clone(), ..Default::default() };
        nz.comps = comps.iter().map(|c| c.to_string()).collect();
        for p in &z.mesh.parts {
            for nodes in p.elems() {
                let x: Vec<[f64; 3]> = nodes.iter().map(|n| it.nodes.get(*n)).collect();
                match surface_vectors(form, p.ty, mode, &x, unit).map_err(|e| a.err(e.to_string()))? {
                    Some(v) => nz.values.push(v.iter().map(|v| v[..comps.len()].to_vec()).collect()),
                    None => break,
                }
            }
        }
        if !nz.values.is_empty() {
            out.zones.push(nz);
        }
    }
    Ok(vec![Value::Mchaml(Rc::new(out))])
}

fn jaco(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let model = a.req::<Rc<Model>>()?;
    let mut out = Mchaml { subtype: "SCALAIRE".into(), zones: vec![] };
    for z in &model.zones {
        let form = formulation(z);
        let mut nz = MchamlZone { mesh: z.mesh.clone(), element: z.element.clone(), ..Default::default() };
        nz.comps = vec!["SCAL".into()];
        for p in &z.mesh.parts {
            for nodes in p.elems() {
                let x: Vec<[f64; 3]> = nodes.iter().map(|n| it.nodes.get(*n)).collect();
                let j = jacobians(form, p.ty, &x).map_err(|e| a.err(e.to_string()))?;
                nz.values.push(j.into_iter().map(|v| vec![v]).collect());
            }
        }
        // A zone without elements has no points.
        if !nz.values.is_empty() {
            out.zones.push(nz);
        }
    }
    Ok(vec![Value::Mchaml(Rc::new(out))])
}
