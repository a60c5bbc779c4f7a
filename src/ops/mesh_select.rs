//! Geometric choices on meshes: `POIN 'SPHE'|'CYLI'|'CONE'|'TORE'|'JONC'`
//! (nodes on a surface of revolution, junction nodes) and the side ORIE
//! turns normals to. The algorithms are in `fem::meshing::select` and
//! `fem::meshing::orient_to`.

use super::mesh::{mesh_val, vector};
use super::{Args, PointId};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::fem::meshing as mg;
use crate::fem::meshing::orient_to::Towards;
use crate::fem::meshing::select::Surface;
use crate::value::Value;

/// `GEO POIN k ...` for the keywords of the surfaces and JONC.
pub(crate) fn poin_on(it: &mut Interp, a: &mut Args, m: &Mesh, k: &str) -> Result<Vec<Value>> {
    if k == "JONC" {
        return Ok(mesh_val(mg::select::poin_jonc(m)));
    }
    let count = match k {
        "SPHE" => 2,
        "TORE" => 4,
        _ => 3,
    };
    let mut p = Vec::with_capacity(count);
    for _ in 0..count {
        p.push(vector(it, a).ok_or_else(|| a.missing("POINT"))?);
    }
    let tol = a.opt_num().unwrap_or(default_crit(it));
    let s = match k {
        "SPHE" => Surface::Sphere(p[0], p[1]),
        "CYLI" => Surface::Cylinder(p[0], p[1], p[2]),
        "CONE" => Surface::Cone(p[0], p[1], p[2]),
        _ => Surface::Torus(p[0], p[1], p[2], p[3]),
    };
    Ok(mesh_val(mg::select::poin_on(&it.nodes, m, s, tol)?))
}

/// The distance criterion of POIN's selections when none is given: a
/// tenth of `OPTI DENS` as in Cast3M, or 1e-6 when no density is set
/// (Cast3M refuses that case; decks that rely on an exact match still get
/// one).
pub(crate) fn default_crit(it: &Interp) -> f64 {
    let dens = it.opts.dens;
    if dens > 0.0 && dens.is_finite() {
        0.1 * dens
    } else {
        1e-6
    }
}

/// ORIE's optional side: `('DIRE') VECTOR` or `'POIN' POINT`.
pub(crate) fn towards(it: &Interp, a: &mut Args) -> Result<Option<Towards>> {
    match a.keyword(&["POIN", "DIRE", "VECT"]) {
        Some("POIN") => {
            let p = a.req::<PointId>()?;
            Ok(Some(Towards::Point(it.nodes.get(p.0))))
        }
        Some(_) => {
            let p = a.req::<PointId>()?;
            Ok(Some(Towards::Direction(it.nodes.get(p.0))))
        }
        None => Ok(a.opt::<PointId>().map(|p| Towards::Direction(it.nodes.get(p.0)))),
    }
}

/// `LINE ELEM 'COMP' P1 P2` and `GEO ELEM 'TYPE'`.
pub(crate) fn elem_keyword(it: &mut Interp, a: &mut Args, m: &Mesh, k: &str) -> Result<Vec<Value>> {
    if k == "TYPE" {
        let mut names: Vec<String> = Vec::new();
        // An empty mesh (VIDE, DIFF) still has the type it was made with.
        let empty = m.n_elements() == 0;
        for p in m.parts.iter().filter(|p| empty || !p.is_empty()) {
            if !names.iter().any(|n| n == p.ty.name()) {
                names.push(p.ty.name().to_string());
            }
        }
        return Ok(vec![Value::ListMots(std::rc::Rc::new(names))]);
    }
    let p1 = a.req::<PointId>()?.0;
    let p2 = a.req::<PointId>()?.0;
    Ok(mesh_val(mg::between::elem_compris(&it.nodes, m, p1, p2)?))
}
