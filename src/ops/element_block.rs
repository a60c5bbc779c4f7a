//! One block of a RIGIDITE built from the matrix of each element of a mesh
//! part. Stiffness, mass, conductivity, capacity and KP differ only by the
//! element routine they call; the block layout (connectivity, dof names,
//! duals, one dense matrix per element) is the same, so it is written here
//! once.

use super::dofs;
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::element::ElemMatrix;
use crate::fem::mesh::Part;
use crate::value::rigidity::{Block, Symmetry};

/// The block of `part`: `elem(e, x)` gives the matrix of element `e` (from 0)
/// whose node coordinates are `x`. `extra` is a node appended to every
/// element (the point carrying generalised plane strain's unknowns). None for a part without elements. The
/// dof layout is taken from the first element, as every element of a part
/// has the same type and formulation. Errors are worded by the caller, who
/// knows which operator it runs.
pub(crate) fn part_block(
    it: &Interp,
    part: &Part,
    extra: Option<usize>,
    symmetry: Symmetry,
    mut elem: impl FnMut(usize, &[[f64; 3]]) -> Result<ElemMatrix>,
) -> Result<Option<Block>> {
    let npe = part.ty.nodes() + usize::from(extra.is_some());
    let mut x = vec![[0.0; 3]; npe];
    let mut block: Option<Block> = None;
    let mut elem_nodes = Vec::with_capacity(npe);
    for (e, nodes) in part.elems().enumerate() {
        elem_nodes.clear();
        elem_nodes.extend_from_slice(nodes);
        elem_nodes.extend(extra);
        let nodes = &elem_nodes[..];
        for (k, n) in nodes.iter().enumerate() {
            x[k] = it.nodes.get(*n);
        }
        let em = elem(e, &x)?;
        let b = block.get_or_insert_with(|| Block {
            nodes_per_elem: npe,
            conn: Vec::with_capacity(part.len() * npe),
            dofs: em.dofs.iter().map(|(l, c)| (*l, c.to_string())).collect(),
            duals: em.dofs.iter().map(|(_, c)| dofs::dual_of(c)).collect(),
            mats: Vec::with_capacity(part.len() * em.k.len()),
            symmetry,
        });
        b.conn.extend_from_slice(nodes);
        b.mats.extend_from_slice(&em.k);
    }
    Ok(block)
}
