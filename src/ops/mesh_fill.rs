//! VOLU of a closed surface (`VOLU SURF ('VERB')`): tetrahedra filling the
//! volume it bounds. The mesher is `fem::meshing::tet_fill`; VOLU's other
//! forms (sweeps, between two surfaces) are in `ops/mesh.rs`.

use super::Args;
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::{ElemType, Mesh};
use crate::fem::meshing as mg;
use crate::value::Value;
use std::rc::Rc;

pub(crate) fn volu_closed(it: &mut Interp, a: &mut Args, surf: &Mesh) -> Result<Vec<Value>> {
    // 'VERB' asks Cast3M's mesher to tell its steps; gibi's has none worth
    // printing, and the mesh is the same with or without it.
    a.keyword(&["VERB"]);
    // Quadrangles are cut in two along their 1-3 diagonal; the volume is then
    // bounded by those triangles.
    let tri = if surf.parts.iter().any(|p| !p.is_empty() && p.ty != ElemType::Tri3) {
        mg::change_to_triangles(surf)
    } else {
        surf.clone()
    };
    let m = mg::tet_fill::volu_closed("VOLU", &mut it.nodes, &tri)?;
    Ok(vec![Value::Mesh(Rc::new(m))])
}
