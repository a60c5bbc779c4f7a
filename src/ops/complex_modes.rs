//! VIBC: complex modes of `M ẍ + C ẋ + K x = 0`, as a modal-basis table.
//! The numerics (a QZ on the linearised pencil) are in
//! `solve::complex_modes`.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::solve::complex_modes::quadratic_modes;
use crate::value::field::Nature;
use crate::value::rigidity::Subtype;
use crate::value::table::Key;
use crate::value::{Chpoint, Rigidite, Table, Value};
use std::cell::RefCell;
use std::collections::{HashMap, HashSet};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "VIBC",
    signature: "VIBC RIGIDITE_MASSE RIGIDITE_RAIDEUR (RIGIDITE_AMORTISSEMENT) (ENTIER)",
    doc: "Complex modes λ of (λ²M + λC + K)φ = 0 by the QZ algorithm (small problems; K and C may be non-symmetric). Matrices of subtypes MASSE, RIGIDITE, AMORTISSEMENT are taken by subtype, others in the order mass, stiffness, damping; unknowns blocked by a single-term condition are left out. Returns a table 'BASE_MODALE': .'MODES'.i (by increasing |λ|, the ENTIER lowest pairs only) has 'FREQUENCE_REELLE' Im λ/2π, 'FREQUENCE_IMAGINAIRE' -Re λ/2π, 'DEFORMEE_MODALE_REELLE'/'_IMAGINAIRE' (largest component 1), 'NUMERO_MODE', 'POINT_REPERE'; an infinite λ (singular mass) gives a mode of subtype 'MODE_ANNULE'.",
    example: "opti dime 2 ; p = 0. 0. ; m = manu rigi type masse p (mots ux) (prog 1.) ; k = manu rigi p (mots ux) (prog 4.) ; b = vibc m k ; f = b.'MODES'.1.'FREQUENCE_REELLE' ;",
    f: vibc,
}];

fn vibc(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mut mats: Vec<Rc<Rigidite>> = Vec::new();
    while let Some(r) = a.opt::<Rc<Rigidite>>() {
        mats.push(r);
    }
    if a.opt::<Rc<RefCell<Table>>>().is_some() {
        return Err(a.err(
            "matrices projected on a modal basis (BAS1) are not available; give the matrices on the physical unknowns",
        ));
    }
    let pairs = a.opt::<i64>();
    if mats.len() == 4 {
        return Err(a.err("the eigenvalues of a monodromy matrix (4 RIGIDITEs) are not available"));
    }
    if !(2..=3).contains(&mats.len()) {
        return Err(a.err("a mass and a stiffness matrix (and optionally a damping matrix)"));
    }
    let (m, k, c) = sort_matrices(&mats);
    // The unknowns: every one the blocks name, less those a single-term
    // condition blocks.
    let mut blocked = HashSet::new();
    for r in &mats {
        for cond in &r.conds {
            match cond.terms.as_slice() {
                [(n, comp, _)] => {
                    blocked.insert((*n, comp.clone()));
                }
                _ => return Err(a.err("only conditions on a single unknown (BLOQ) are supported")),
            }
        }
    }
    let mut unknowns: Vec<(usize, String)> = Vec::new();
    let mut seen = HashSet::new();
    for r in &mats {
        for b in &r.blocks {
            for e in 0..b.n_elem() {
                for (l, comp) in &b.dofs {
                    let key = (b.conn[e * b.nodes_per_elem + l], comp.clone());
                    if !blocked.contains(&key) && seen.insert(key.clone()) {
                        unknowns.push(key);
                    }
                }
            }
        }
    }
    if unknowns.is_empty() {
        return Err(a.err("the matrices have no free unknown"));
    }
    if unknowns.len() > 2000 {
        return Err(a.err(format!("{} unknowns is too many for the dense QZ algorithm (2000 at most)", unknowns.len())));
    }
    // Blocked unknowns are numbered past the free ones and cut off.
    let mut index: HashMap<(usize, String), usize> =
        unknowns.iter().cloned().enumerate().map(|(i, u)| (u, i)).collect();
    for u in &blocked {
        let next = index.len();
        index.entry(u.clone()).or_insert(next);
    }
    let n = unknowns.len();
    let dense = |r: &Rigidite| -> Result<Vec<f64>> {
        let full = r
            .dense(&index)
            .map_err(|(node, comp)| a.err(format!("unknown {comp} of node {} is not numbered", node + 1)))?;
        let nt = index.len();
        Ok((0..n).flat_map(|i| full[i * nt..i * nt + n].to_vec()).collect())
    };
    let (dm, dk) = (dense(m)?, dense(k)?);
    let dc = c.map(dense).transpose()?;
    let modes = quadratic_modes(n, &dm, dc.as_deref(), &dk).map_err(|e| a.err(e.to_string()))?;
    let keep = match pairs {
        Some(p) if p < 1 => return Err(a.err("the number of pairs of modes must be positive")),
        Some(p) => (2 * p as usize).min(modes.len()),
        None => modes.len(),
    };

    let nodes: Vec<usize> = {
        let mut s = HashSet::new();
        unknowns.iter().filter(|(n, _)| s.insert(*n)).map(|(n, _)| *n).collect()
    };
    let mut tab2 = Table::with_subtype("BASE_DE_MODES");
    tab2.set(mot_key("MAILLAGE"), Value::Mesh(Rc::new(Mesh::points(&nodes))));
    let origin = it.nodes.get(nodes[0]);
    let dens = it.opts.dens;
    let tau = std::f64::consts::TAU;
    for (i, mode) in modes.iter().take(keep).enumerate() {
        let mut t3 = Table::with_subtype(if mode.lambda.is_some() { "MODE_COMPLEXE" } else { "MODE_ANNULE" });
        t3.set(mot_key("POINT_REPERE"), Value::Point(it.nodes.push(origin, dens)));
        t3.set(mot_key("NUMERO_MODE"), Value::Int(i as i64 + 1));
        if let Some((re, im)) = mode.lambda {
            t3.set(mot_key("FREQUENCE_REELLE"), Value::Float(im / tau));
            t3.set(mot_key("FREQUENCE_IMAGINAIRE"), Value::Float(-re / tau));
        }
        let field = |part: fn(&(f64, f64)) -> f64| {
            let entries = unknowns.iter().zip(&mode.shape).map(|((n, c), v)| (*n, c.as_str(), part(v)));
            Value::Chpo(Rc::new(Chpoint::from_entries(Nature::Diffus, entries)))
        };
        t3.set(mot_key("DEFORMEE_MODALE_REELLE"), field(|v| v.0));
        t3.set(mot_key("DEFORMEE_MODALE_IMAGINAIRE"), field(|v| v.1));
        tab2.set(Key::Int(i as i64 + 1), Value::Table(Rc::new(RefCell::new(t3))));
    }
    let mut bas = Table::with_subtype("BASE_MODALE");
    bas.set(mot_key("MODES"), Value::Table(Rc::new(RefCell::new(tab2))));
    bas.set(mot_key("CONVERGENCE"), Value::Bool(true));
    Ok(vec![Value::Table(Rc::new(RefCell::new(bas)))])
}

fn mot_key(s: &str) -> Key {
    Key::Mot(s.into())
}

/// (mass, stiffness, damping): by subtype when every matrix has a
/// distinct one of the three, else in the order given.
fn sort_matrices(mats: &[Rc<Rigidite>]) -> (&Rigidite, &Rigidite, Option<&Rigidite>) {
    let find = |s: Subtype| mats.iter().filter(|r| r.subtype == s).map(|r| r.as_ref()).collect::<Vec<&Rigidite>>();
    let (m, k, c) = (find(Subtype::Masse), find(Subtype::Rigidite), find(Subtype::Amortissement));
    let by_type = m.len() == 1 && k.len() == 1 && c.len() == usize::from(mats.len() == 3);
    if by_type {
        (m[0], k[0], c.first().copied())
    } else {
        (&mats[0], &mats[1], mats.get(2).map(|r| r.as_ref()))
    }
}
