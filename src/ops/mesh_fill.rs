//! VOLU of a closed surface (`VOLU SURF ('VERB')`): tetrahedra filling the
//! volume it bounds, with a pyramid on each of its quadrangles. The
//! meshers are `fem::meshing::tet_fill` and `tet_pyramids`; VOLU's other
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
    let lin = if surf.parts.iter().any(|p| !p.is_empty() && !matches!(p.ty, ElemType::Tri3 | ElemType::Qua4)) {
        mg::change_to_linear(surf)
    } else {
        surf.clone()
    };
    let m = if lin.parts.iter().any(|p| !p.is_empty() && p.ty == ElemType::Qua4) {
        mg::tet_pyramids::volu_with_pyramids("VOLU", &mut it.nodes, &lin)?
    } else {
        mg::tet_fill::volu_closed("VOLU", &mut it.nodes, &lin)?
    };
    Ok(vec![Value::Mesh(Rc::new(m))])
}
