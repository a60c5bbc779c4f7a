//! RAFF: a mesh refined until its elements meet a density field, with the
//! relation elements (MULT) that tie the hanging nodes between levels
//! (`fem::meshing::refine`); RELA of a model made on it turns those into
//! conditions.

use super::mesh::req_geo;
use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::meshing::refine::refine;
use crate::value::{Chpoint, Value};
use std::collections::HashMap;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "RAFF",
    signature: "RAFF GEO1 CHPO1 | RAFF CHPO1 GEO1",
    doc: "Refine a mesh of TRI3, TRI6, QUA4, QUA8 or CUB8 elements: each element is split into 4 (8 for a cube) of its own type until its size (side of the square of its area, or of the cube of its volume; half a square for a triangle) is at most the density CHPO1 (one component, at the mesh's nodes) at its corners. The result also holds MULT relation elements tying the nodes that hang between levels; RELA of a model on it gives their conditions.",
    example: "s = (droi 2 (0 0) (1 0)) tran 2 (0 1) ;\nd = manu 'CHPO' s 1 'SCAL' 0.3 ;\ns2 = raff s d ;",
    f: raff,
}];

fn raff(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let first = a.opt::<Rc<Chpoint>>();
    let geo = req_geo(a)?;
    let field = match first {
        Some(f) => f,
        None => a.req::<Rc<Chpoint>>()?,
    };
    let comps = field.components();
    if comps.len() != 1 {
        return Err(a.err(format!(
            "the density field must have one component, not {} ({})",
            comps.len(),
            comps.join(", ")
        )));
    }
    let density: HashMap<usize, f64> = field.entries().map(|(n, _, v)| (n, v)).collect();
    let mesh = refine(&mut it.nodes, &geo, &|n| density.get(&n).copied()).map_err(|e| a.err(e.message))?;
    Ok(vec![Value::Mesh(Rc::new(mesh))])
}
