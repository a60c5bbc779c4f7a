//! `RELA 'MILI' (LISTMOTS) GEO`: each mid-side node of the quadratic
//! elements of GEO follows the mean of its edge's two vertices, so a
//! quadratic mesh moves as a linear one on those unknowns (rela.notice:
//! quadratic elements against a linear contact mesh).

use super::bc::mult_node;
use super::mesh::req_geo;
use super::{dofs, Args};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::midside::midside;
use crate::solve::Kind;
use crate::value::rigidity::{CondRow, Subtype};
use crate::value::{Rigidite, Value};
use std::collections::BTreeSet;
use std::rc::Rc;

pub(super) fn rela_mili(it: &mut Interp, a: &mut Args, kind: Kind) -> Result<Vec<Value>> {
    let mut comps: Vec<String> = match a.opt::<Rc<Vec<String>>>() {
        Some(l) => l.iter().map(|c| c.trim().to_uppercase()).collect(),
        None => Vec::new(),
    };
    let geo = req_geo(a)?;
    if comps.is_empty() {
        comps = dofs::translations(it).iter().map(|c| c.to_string()).collect();
    }
    // A mid-side node shared by two elements gets one relation.
    let mut seen = BTreeSet::new();
    let mut rig = Rigidite::new(Subtype::Blocage);
    for part in &geo.parts {
        let table = midside(part.ty);
        for conn in part.elems() {
            for &(m, p, q) in &table {
                if !seen.insert(conn[m]) {
                    continue;
                }
                for c in &comps {
                    let row = vec![(conn[m], c.clone(), 1.0), (conn[p], c.clone(), -0.5), (conn[q], c.clone(), -0.5)];
                    let mn = mult_node(it, conn[m]);
                    rig.conds.push(CondRow::new(mn, row, kind));
                }
            }
        }
    }
    if rig.conds.is_empty() {
        return Err(a.err("MILI: the mesh has no quadratic element (no mid-side node)"));
    }
    Ok(vec![Value::Rigi(Rc::new(rig))])
}
