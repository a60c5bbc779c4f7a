//! `RELA GEO1 'ACCRO' GEO2 (LMOTS) (FLOT1)`: every node of GEO1 lying in an
//! element of GEO2 follows the interpolation of that element's nodes,
//! u(x) = Σ Nᵢ(ξ) uᵢ with ξ the reference coordinates of x (rela.notice).

use super::bc::mult_node;
use super::mesh::req_geo;
use super::{dofs, Args};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::locate::locate;
use crate::fem::shape;
use crate::solve::Kind;
use crate::value::rigidity::{CondRow, Subtype};
use crate::value::{Rigidite, Value};
use std::rc::Rc;

/// Interpolation weights below this are dropped: the node sits on a side
/// or a vertex of the element and those nodes play no part.
const ZERO: f64 = 1e-12;

pub(super) fn rela_accro(
    it: &mut Interp,
    a: &mut Args,
    kind: Kind,
    geo1: &crate::fem::mesh::Mesh,
) -> Result<Vec<Value>> {
    let geo2 = req_geo(a)?;
    let mut comps: Vec<String> = match a.opt::<Rc<Vec<String>>>() {
        Some(l) => l.iter().map(|c| c.trim().to_uppercase()).collect(),
        None => dofs::translations(it).iter().map(|c| c.to_string()).collect(),
    };
    comps.dedup();
    // FLOT1 widens the capture of nodes slightly outside GEO2; the locator
    // has its own relative tolerance, which covers the default 1e-5.
    let _ = a.opt_num();
    let mut rig = Rigidite::new(Subtype::Blocage);
    for n in geo1.node_list() {
        let x = it.nodes.get(n);
        let Some(terms) = host(it, &geo2, n, x) else { continue };
        for c in &comps {
            let mut row = vec![(n, c.clone(), 1.0)];
            row.extend(terms.iter().map(|&(m, w)| (m, c.clone(), -w)));
            let mn = mult_node(it, n);
            rig.conds.push(CondRow::new(mn, row, kind));
        }
    }
    Ok(vec![Value::Rigi(Rc::new(rig))])
}

/// The nodes and weights of the first element of `geo` holding `x`, or
/// None when no element does or when node `n` is itself one of its nodes
/// (the relation would be an identity).
fn host(it: &Interp, geo: &crate::fem::mesh::Mesh, n: usize, x: [f64; 3]) -> Option<Vec<(usize, f64)>> {
    for part in &geo.parts {
        for conn in part.elems() {
            let xs: Vec<[f64; 3]> = conn.iter().map(|&m| it.nodes.get(m)).collect();
            let Some(xi) = locate(part.ty, &xs, x) else { continue };
            if conn.contains(&n) {
                return None;
            }
            let s = shape::eval(part.ty, xi);
            return Some(conn.iter().zip(&s.n).filter(|(_, w)| w.abs() > ZERO).map(|(&m, &w)| (m, w)).collect());
        }
    }
    None
}
