//! Mesh repair and bookkeeping: REGENERER (merged nodes make lower-order
//! elements), ARETE (sharp edges), TASSER (renumbering the nodes shown, `fem::node_numbering`).
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
    OpDef { name: "TASS", signature: "TASS (GEO) ('NOOP')", doc: "Renumber the nodes: those of GEO get the numbers 1..n (a POI1 mesh in its order, another mesh in the order its elements first name them), the others follow in their former order; without GEO the numbering stays. Objects are unchanged (NOEUD follows the new numbers). Returns the POI1 mesh of the nodes in their former number order (element i is the node formerly numbered i).", example: "tass ;", f: tass },
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
    let geo = a.opt::<Rc<Mesh>>();
    a.keyword(&["NOOP"]);
    // The nodes in the order the elements name them: a POI1 mesh's order,
    // a line's nodes along it.
    let first: Vec<usize> =
        geo.map(|m| m.parts.iter().flat_map(|p| p.conn.iter().copied()).collect()).unwrap_or_default();
    let count = it.nodes.len();
    let former = if first.is_empty() {
        (0..count).map(|k| it.nodes.numbering.node(k)).collect()
    } else {
        it.nodes.numbering.renumber(count, &first)
    };
    Ok(mesh_val(Mesh::points(&former)))
}
