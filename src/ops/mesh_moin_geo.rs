//! `GEO2 MOIN GEO1`: the displacement field that carries a mesh onto a
//! topologically equivalent one (node k of element e of GEO1 goes to node
//! k of element e of GEO2), supported by the nodes of GEO1.

use super::Args;
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::value::{Chpoint, Nature, Value};
use std::rc::Rc;

pub(crate) fn mesh_minus_mesh(it: &Interp, a: &Args, geo2: &Mesh, geo1: &Mesh) -> Result<Vec<Value>> {
    let same_shape = geo1.parts.len() == geo2.parts.len()
        && geo1.parts.iter().zip(&geo2.parts).all(|(p, q)| p.ty == q.ty && p.conn.len() == q.conn.len());
    if !same_shape {
        return Err(a.err("the two meshes are not topologically equivalent (same elements in the same order)"));
    }
    let axis = it.opts.mode.starts_with("AXIS") || it.opts.mode.starts_with("FOUR");
    let comps: [&str; 3] = if axis { ["UR", "UZ", "UT"] } else { ["UX", "UY", "UZ"] };
    let dim = it.opts.dime.clamp(1, 3);
    let mut out = Chpoint::new(Nature::Diffus);
    let mut seen = std::collections::HashSet::new();
    for (p, q) in geo1.parts.iter().zip(&geo2.parts) {
        for (&n1, &n2) in p.conn.iter().zip(&q.conn) {
            if !seen.insert(n1) {
                continue;
            }
            let (x1, x2) = (it.nodes.get(n1), it.nodes.get(n2));
            for (k, c) in comps.iter().enumerate().take(dim) {
                out.add(n1, c, x2[k] - x1[k], false);
            }
        }
    }
    Ok(vec![Value::Chpo(Rc::new(out))])
}
