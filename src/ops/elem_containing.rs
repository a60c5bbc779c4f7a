//! ELEM's 'CONTENANT' form (elem.notice): the element of a mesh that
//! contains a point, or with 'TOUS' every such element (a point on a
//! shared face, edge or node is in each). The geometry is
//! `fem::meshing::containing`.

use super::mesh::mesh_val;
use super::{Args, PointId};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::{Mesh, Part};
use crate::fem::meshing::containing::containing;
use crate::value::Value;

/// `GEO ELEM 'CONTENANT' P ('TOUS') ('NOVERIF')`, the keyword already read.
pub(crate) fn elem_containing(it: &mut Interp, a: &mut Args, m: &Mesh) -> Result<Vec<Value>> {
    let p = a.req::<PointId>()?;
    // The two words may come in either order.
    let mut all = false;
    let mut noverif = false;
    while let Some(k) = a.keyword(&["TOUS", "NOVERIF"]) {
        all |= k == "TOUS";
        noverif |= k == "NOVERIF";
    }
    let found = containing(m, &it.nodes, p.0, all);
    if found.n_elements() > 0 {
        return Ok(mesh_val(found));
    }
    if !noverif {
        let x = it.nodes.get(p.0);
        return Err(a.err(format!(
            "no element of the mesh contains the point ({}, {}, {}) (NOVERIF allows an empty result)",
            x[0], x[1], x[2]
        )));
    }
    // An empty mesh of the mesh's first element type, as other empty
    // selections give.
    let ty = m.parts.first().map(|q| q.ty).unwrap_or(crate::fem::mesh::ElemType::Poi1);
    Ok(mesh_val(Mesh::single(Part::new(ty))))
}
