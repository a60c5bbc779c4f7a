//! `RELA MODEL`: the conditions of the relation elements (MULT, from RAFF)
//! of a model's meshes. Each ties its hanging node to the side it lies on:
//! u(hanging) = Σ N_k(ξ) u(k), N the shape functions of that side (SEG2,
//! SEG3 or QUA4) at the hanging node's place ξ, so the finer elements
//! follow the coarser one's displacement along their common side.

use super::bc::mult_node;
use super::{dofs, Args};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::{locate::locate, shape};
use crate::solve::Kind;
use crate::value::rigidity::{CondRow, Subtype};
use crate::value::{Model, Rigidite, Value};
use std::rc::Rc;

/// Weights below this are dropped (a hanging node at a side's node of a
/// finer level has exact zeros that rounding makes tiny).
const TINY: f64 = 1e-12;

pub(super) fn rela_model(it: &mut Interp, a: &mut Args, kind: Kind, model: &Model) -> Result<Vec<Value>> {
    let comps: Vec<String> = if model.zones.iter().all(|z| z.formulation.to_uppercase().starts_with("THER")) {
        vec!["T".into()]
    } else {
        dofs::translations(it).iter().map(|c| c.to_string()).collect()
    };
    let mut rig = Rigidite::new(Subtype::Blocage);
    for part in &model.ties {
        let Some(side) = part.ty.tie_side() else { continue };
        for e in part.elems() {
            let xs: Vec<[f64; 3]> = e[1..].iter().map(|&n| it.nodes.get(n)).collect();
            let x = it.nodes.get(e[0]);
            let xi = locate(side, &xs, x).ok_or_else(|| {
                a.err(format!("RELA: the hanging node {} does not lie on the {} it is tied to", e[0] + 1, side.name()))
            })?;
            let w = shape::eval(side, xi).n;
            for c in &comps {
                let mut row = vec![(e[0], c.clone(), 1.0)];
                row.extend(e[1..].iter().zip(&w).filter(|(_, w)| w.abs() > TINY).map(|(&n, &w)| (n, c.clone(), -w)));
                let m = mult_node(it, e[0]);
                rig.conds.push(CondRow::new(m, row, kind));
            }
        }
    }
    Ok(vec![Value::Rigi(Rc::new(rig))])
}
