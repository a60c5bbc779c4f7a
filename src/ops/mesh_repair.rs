//! Mesh repair and bookkeeping: REGENERER (merged nodes make lower-order
//! elements), ARETE (sharp edges), TASSER (renumbering, a no-op in gibi).
//! The algorithms are in `fem::meshing::{regenerate, edges}`.

use super::mesh::{mesh_val, req_geo};
use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::fem::meshing as mg;
use crate::value::Value;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef { name: "REGE", signature: "REGE GEO ('VERI')", doc: "The mesh with elements whose nodes were merged (ELIM) turned into the elements they now are: QUA4 with a repeated node a TRI3, CUB8 with a crushed face a PRI6, SEG2 on one node a POI1.", example: "s = rege s ;", f: rege },
    OpDef { name: "ARET", signature: "ARET GEO (angle)", doc: "The sharp edges (SEG2) of a mesh in space: edges of its surface elements or of its volume's skin that border one facet, or two whose normals differ by more than angle degrees (20 by default).", example: "a = aret v ;", f: aret },
    OpDef { name: "TASS", signature: "TASS (GEO) ('NOOP')", doc: "Compact the node table: gibi never renumbers nodes, so this does nothing; returns the POI1 mesh of the nodes in number order (node i is element i).", example: "tass ;", f: tass },
];

fn rege(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let m = a.req::<Rc<Mesh>>()?;
    a.keyword(&["VERI"]);
    Ok(mesh_val(mg::regenerate::rege(&it.nodes, &m)?))
}

fn aret(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let m = req_geo(a)?;
    let angle = a.opt_num().unwrap_or(20.0);
    Ok(mesh_val(mg::edges::aret(&it.nodes, &m, angle)?))
}

fn tass(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let _ = a.opt::<Rc<Mesh>>();
    a.keyword(&["NOOP"]);
    let all: Vec<usize> = (0..it.nodes.len()).collect();
    Ok(mesh_val(Mesh::points(&all)))
}
