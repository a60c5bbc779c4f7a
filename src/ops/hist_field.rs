//! HIST on an element field: the density of distribution of the values
//! of each component over the classes given by their bounds, as one
//! curve per component (numerics in `value::signal::histogram`). Each
//! value of the field (one per element point) counts once: the density
//! is of the values, not weighted by the measure of the points.

use super::Args;
use crate::error::Result;
use crate::value::model::Curve;
use crate::value::signal::histogram;
use crate::value::{Evolution, Mchaml, Value};
use std::rc::Rc;

/// `MOD1 CHAM1 ('ABS') LRE1 (MOT1 | LMOT1)`, the model already read.
pub(crate) fn hist_field(a: &mut Args) -> Result<Vec<Value>> {
    let cham = a.req::<Rc<Mchaml>>()?;
    let abs = a.keyword(&["ABS"]).is_some();
    let bounds = a.req::<Rc<Vec<f64>>>()?;
    if bounds.len() < 2 || bounds.windows(2).any(|w| w[0] >= w[1]) {
        return Err(a.err("the class bounds must be at least 2 strictly increasing values"));
    }
    let comps: Vec<String> = if let Some(l) = a.opt::<Rc<Vec<String>>>() {
        l.to_vec()
    } else if let Some(w) = a.word() {
        vec![w]
    } else {
        // Every component, in the order of the zones.
        let mut all: Vec<String> = Vec::new();
        for z in &cham.zones {
            for c in &z.comps {
                if !all.contains(c) {
                    all.push(c.clone());
                }
            }
        }
        all
    };
    if comps.is_empty() {
        return Err(a.err("the field has no point values to sort into classes"));
    }
    let mut curves = Vec::new();
    for name in comps {
        let mut values = Vec::new();
        for z in &cham.zones {
            if let Some(k) = z.comps.iter().position(|c| c.eq_ignore_ascii_case(&name)) {
                values.extend(z.values.iter().flatten().map(|p| p[k]));
            }
        }
        if values.is_empty() {
            return Err(a.err(format!("the field has no component {}", name)));
        }
        if abs {
            values.iter_mut().for_each(|v| *v = v.abs());
        }
        let y = histogram::density(&values, &bounds);
        curves.push(Curve { legend: name.clone(), x_name: name, y_name: "DENSITE".into(), x: bounds.to_vec(), y });
    }
    Ok(vec![Value::Evol(Rc::new(Evolution { curves }))])
}
