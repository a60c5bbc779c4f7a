//! `RELA 'CORI' 'DEPL' 'ROTA' GEO1 (GEO2)`: a rigid-body link, to first
//! order (rela.notice). The first node of GEO1 is the master; every other
//! node i of GEO1 (which has rotation unknowns) follows it as a rigid body,
//! u_i = u_m + θ_m × (x_i − x_m) and θ_i = θ_m, and the nodes of GEO2
//! (translations only) follow its translation field u_m + θ_m × (x − x_m).
//! In the plane modes θ is the single rotation RZ.

use super::bc::mult_node;
use super::mesh::{opt_geo, req_geo};
use super::{dofs, Args};
use crate::error::Result;
use crate::eval::Interp;
use crate::solve::Kind;
use crate::value::rigidity::{CondRow, Subtype};
use crate::value::{Rigidite, Value};
use std::collections::BTreeSet;
use std::rc::Rc;

pub(super) fn rela_cori(it: &mut Interp, a: &mut Args, kind: Kind) -> Result<Vec<Value>> {
    let mut rota = false;
    while let Some(k) = a.keyword(&["DEPL", "ROTA", "NOVERIF"]) {
        rota |= k == "ROTA";
    }
    if !rota {
        return super::rela_cori_dist::rela_cori_distances(it, a, kind);
    }
    let g1 = req_geo(a)?.node_list();
    let g2 = opt_geo(a).map(|g| g.node_list()).unwrap_or_default();
    let master = *g1.first().ok_or_else(|| a.err("CORI: the first mesh has no node"))?;
    let tr: Vec<String> = dofs::translations(it).iter().map(|s| s.to_string()).collect();
    let ro: Vec<String> = dofs::rotations(it).iter().map(|s| s.to_string()).collect();
    let plane = match (tr.len(), ro.len()) {
        (3, 3) => false,
        (2, 1) => true,
        _ => return Err(a.err("CORI: rigid links are available in 3D and in the plane modes")),
    };
    let xm = it.nodes.get(master);
    let mut seen = BTreeSet::from([master]);
    let mut rig = Rigidite::new(Subtype::Blocage);
    let mut push = |it: &mut Interp, n: usize, row: Vec<(usize, String, f64)>| {
        let row: Vec<_> = row.into_iter().filter(|t| t.2 != 0.0).collect();
        let m = mult_node(it, n);
        rig.conds.push(CondRow::new(m, row, kind));
    };
    let with_rot: Vec<(usize, bool)> = g1.iter().map(|&n| (n, true)).chain(g2.iter().map(|&n| (n, false))).collect();
    for (n, own_rot) in with_rot {
        if !seen.insert(n) {
            continue;
        }
        let x = it.nodes.get(n);
        let r = [x[0] - xm[0], x[1] - xm[1], x[2] - xm[2]];
        let t = |c: usize| tr[c].clone();
        let q = |c: usize| ro[c].clone();
        // u_i − u_m − θ_m × r = 0, component by component.
        let rows: Vec<Vec<(usize, String, f64)>> = if plane {
            vec![
                vec![(n, t(0), 1.0), (master, t(0), -1.0), (master, q(0), r[1])],
                vec![(n, t(1), 1.0), (master, t(1), -1.0), (master, q(0), -r[0])],
            ]
        } else {
            vec![
                vec![(n, t(0), 1.0), (master, t(0), -1.0), (master, q(1), -r[2]), (master, q(2), r[1])],
                vec![(n, t(1), 1.0), (master, t(1), -1.0), (master, q(2), -r[0]), (master, q(0), r[2])],
                vec![(n, t(2), 1.0), (master, t(2), -1.0), (master, q(0), -r[1]), (master, q(1), r[0])],
            ]
        };
        for row in rows {
            push(it, n, row);
        }
        if own_rot {
            for c in 0..ro.len() {
                push(it, n, vec![(n, q(c), 1.0), (master, q(c), -1.0)]);
            }
        }
    }
    if rig.conds.is_empty() {
        return Err(a.err("CORI: the meshes have a single node, there is nothing to link"));
    }
    Ok(vec![Value::Rigi(Rc::new(rig))])
}
