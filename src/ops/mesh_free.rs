//! Free meshing: SURF. The mesher is `fem::meshing::surf`; this file reads
//! the Gibiane arguments.

use super::{Args, OpDef, PointId};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::fem::meshing as mg;
use crate::value::{Chpoint, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "SURF",
    signature: "SURF (CHPO_SIZES) LINE ('PLAN' (crit) | 'SPHE' CENTRE)",
    doc: "Free meshing of the inside of closed contours (holes are inner contours) lying in a plane, or on a sphere ('SPHE' and its centre: a cap smaller than a hemisphere): TRI3/TRI6, or under OPTI ELEM QUA4/QUA8 quadrangles with a few triangles. Element size from the contour (node densities, else its segment lengths), or from a CHPOINT of sizes.",
    example: "s = surf (d1 et d2 et d3 et d4) 'PLAN' ;",
    f: surf,
}];

/// Cast3M's default planarity criterion (cosine between the plane's normal
/// and the directions to the contour points).
const PLANE_CRIT: f64 = 1e-2;

fn surf(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let sizes = a.opt::<Rc<Chpoint>>();
    let contour = a.req::<Rc<Mesh>>()?;
    let sizes = match sizes.or_else(|| a.opt::<Rc<Chpoint>>()) {
        Some(ch) => size_field(a, &ch)?,
        None => Default::default(),
    };
    let mut crit = PLANE_CRIT;
    let mut sphere = None;
    match a.keyword(&["PLAN", "SPHE", "CYLI", "CONI", "TORI", "POLY"]) {
        None => {}
        Some("PLAN") => {
            if let Some(c) = a.opt_num() {
                if !(c.is_finite() && c > 0.0) {
                    return Err(a.err(format!("the planarity criterion must be positive (got {c})")));
                }
                crit = c;
            }
        }
        Some("SPHE") => sphere = Some(it.nodes.get(a.req::<PointId>()?.0)),
        Some(k) => {
            return Err(a.err(format!(
                "'{k}' surfaces are not available: gibi meshes plane contours ('PLAN') and caps of a \
                 sphere ('SPHE'); \
                 mesh a curved surface with DALL, TRAN or ROTA"
            )))
        }
    }
    let dim = it.opts.dime.max(2);
    let ty = mg::surf::surface_type(&it.opts.elem);
    let o = mg::surf::SurfOptions { space_dim: dim, crit, sizes, sphere };
    Ok(vec![Value::Mesh(Rc::new(mg::surf::surf(&mut it.nodes, &contour, ty, &o)?))])
}

/// A CHPOINT of target sizes: one component, positive values.
fn size_field(a: &Args, ch: &Chpoint) -> Result<std::collections::HashMap<usize, f64>> {
    let comps = ch.components();
    if comps.len() != 1 {
        return Err(a.err(format!("the field of sizes must have one component, it has {}", comps.len())));
    }
    let mut out = std::collections::HashMap::new();
    for (n, _, v) in ch.entries() {
        if !(v.is_finite() && v > 0.0) {
            return Err(a.err(format!("the field of sizes must be positive: it is {v} at node {}", n + 1)));
        }
        out.insert(n, v);
    }
    Ok(out)
}
