//! INTE 'GEOM': two triangulated surfaces cut along the curve where they
//! cross (the geometry is in fem::meshing::surface_cut).

use super::mesh::{mesh_val, req_geo};
use super::Args;
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::{ElemType, Mesh, Part};
use crate::fem::meshing::surface_cut::cut_surfaces;
use crate::value::Value;

/// `s1b s2b c1 c2 = INTE 'GEOM' s1 s2 ('NOVERIF')`: the cut surfaces and
/// the crossing curve on the nodes of each. Surfaces that do not cross are
/// an error, unless 'NOVERIF' asks for the surfaces unchanged and empty
/// curves.
pub(crate) fn inte_geom(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let x = req_geo(a)?;
    let y = req_geo(a)?;
    let quiet = a.keyword(&["NOVERIF"]).is_some();
    let cut = cut_surfaces(&mut it.nodes, &x, &y)?;
    if cut.curve_first.n_elements() == 0 && !quiet {
        return Err(a.err("the two surfaces do not cross (add 'NOVERIF' to accept it)"));
    }
    let empty = || Mesh::single(Part::new(ElemType::Seg2));
    let (c1, c2) =
        if cut.curve_first.n_elements() == 0 { (empty(), empty()) } else { (cut.curve_first, cut.curve_second) };
    Ok([cut.first, cut.second, c1, c2].into_iter().flat_map(mesh_val).collect())
}
