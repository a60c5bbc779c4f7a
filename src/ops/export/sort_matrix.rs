//! SORT 'MAT': the assembled matrix of a RIGIDITE in MatrixMarket format,
//! with the node and component of every row.

use super::{out_path, write_err, wrote};
use crate::error::Result;
use crate::eval::args::Args;
use crate::eval::Interp;
use crate::io::mtx;
use crate::value::{Rigidite, Value};
use std::collections::HashMap;
use std::rc::Rc;

pub(super) fn sort_mat(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let rig = a.req::<Rc<Rigidite>>()?;
    let file = a.req::<String>()?;
    let (triplets, unknowns, comments) = triplets(&rig);
    let p = out_path(it, &file)?;
    mtx::write(&p, triplets, &unknowns, &comments).map_err(write_err)?;
    wrote(it, &p);
    wrote(it, &mtx::dofs_path(&p));
    Ok(vec![])
}

/// Triplets, the unknown of each row, header comments.
type Triplets = (Vec<(usize, usize, f64)>, Vec<mtx::Unknown>, Vec<String>);

/// Element matrices and condition rows of a RIGIDITE as global
/// (row, col, value) triplets. Unknowns are numbered node by node
/// (components in order of first appearance), then one LX row per
/// condition: a single Lagrange multiplier, not Cast3M's doubled pair,
/// which is the matrix most external tools expect.
fn triplets(r: &Rigidite) -> Triplets {
    let mut comp_rank: HashMap<&str, usize> = HashMap::new();
    let mut keys: Vec<(usize, &str)> = Vec::new();
    for b in &r.blocks {
        for e in 0..b.n_elem() {
            for (local, comp) in &b.dofs {
                let n = comp_rank.len();
                comp_rank.entry(comp).or_insert(n);
                keys.push((b.conn[e * b.nodes_per_elem + local], comp));
            }
        }
    }
    for c in &r.conds {
        for (node, comp, _) in &c.terms {
            let n = comp_rank.len();
            comp_rank.entry(comp).or_insert(n);
            keys.push((*node, comp));
        }
    }
    keys.sort_by_key(|&(n, c)| (n, comp_rank[c]));
    keys.dedup();
    let index: HashMap<(usize, &str), usize> = keys.iter().enumerate().map(|(i, &k)| (k, i)).collect();
    let mut t = Vec::new();
    for b in &r.blocks {
        let nd = b.ndof();
        for e in 0..b.n_elem() {
            let g: Vec<usize> =
                b.dofs.iter().map(|(l, c)| index[&(b.conn[e * b.nodes_per_elem + l], c.as_str())]).collect();
            let m = b.mat(e);
            for i in 0..nd {
                for j in 0..nd {
                    t.push((g[i], g[j], m[i * nd + j]));
                }
            }
        }
    }
    let n = keys.len();
    let mut unknowns: Vec<mtx::Unknown> = keys
        .iter()
        .map(|&(node, c)| mtx::Unknown { node: node + 1, comp: c.to_string(), note: String::new() })
        .collect();
    for (k, c) in r.conds.iter().enumerate() {
        for (node, comp, coef) in &c.terms {
            let j = index[&(*node, comp.as_str())];
            t.push((n + k, j, *coef));
            t.push((j, n + k, *coef));
        }
        let kind = format!("{:?}", c.kind).to_uppercase();
        unknowns.push(mtx::Unknown { node: c.mult_node + 1, comp: "LX".into(), note: kind });
    }
    let comments = vec![
        format!("gibi {}: {} primal unknowns, {} condition rows", r.subtype.name(), n, r.conds.len()),
        "conditions are single Lagrange multipliers (one LX row and column each), not Cast3M's doubled pair".into(),
        "unilateral conditions (MINI/MAXI) appear like equalities; their kind is in the .dofs file".into(),
    ];
    (t, unknowns, comments)
}
