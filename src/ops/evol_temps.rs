//! `EVOL 'TEMP'`: a result against time at points (evol.notice), from the
//! tables of a PASAPAS run (indexed 0 1 2 …, times in 'TEMPS') or from a
//! LISTCHPO and its LISTREEL of times.

use super::{Args, PointId};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::value::model::Curve;
use crate::value::{Evolution, Key, Table, Value};
use std::cell::RefCell;
use std::rc::Rc;

pub(super) fn evol_temp(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let _ = it;
    // The (time, field) pairs.
    let mut series: Vec<(f64, Value)> = Vec::new();
    let mut what = String::from("DEPLACEMENTS");
    // A word that is no result of the table is the component.
    let mut first_word: Option<String> = None;
    if let Some(t) = a.opt::<Rc<RefCell<Table>>>() {
        let t = t.borrow();
        if let Some(w) = a.opt::<String>() {
            let w = w.trim().to_uppercase();
            if matches!(t.get(&Key::Mot(w.clone())), Some(Value::Table(_))) {
                what = w;
            } else {
                first_word = Some(w);
            }
        }
        let get = |k: &str| match t.get(&Key::Mot(k.into())) {
            Some(Value::Table(x)) => Some(x.clone()),
            _ => None,
        };
        let times = get("TEMPS").ok_or_else(|| a.err("the TABLE has no 'TEMPS' (is it a PASAPAS result?)"))?;
        let fields = get(&what).ok_or_else(|| a.err(format!("the TABLE has no result '{}'", what)))?;
        let mut idx: Vec<i64> =
            times.borrow().iter().filter_map(|(k, _)| if let Key::Int(i) = k { Some(*i) } else { None }).collect();
        idx.sort_unstable();
        for i in idx {
            let ti = times.borrow().get(&Key::Int(i)).and_then(Value::as_f64);
            let f = fields.borrow().get(&Key::Int(i)).cloned();
            if let (Some(ti), Some(f)) = (ti, f) {
                series.push((ti, f));
            }
        }
    } else if let Some(l) = a.opt::<Rc<Vec<Rc<crate::value::Chpoint>>>>() {
        let times = a.req::<Rc<Vec<f64>>>()?;
        if times.len() != l.len() {
            return Err(a.err(format!("{} fields for {} times", l.len(), times.len())));
        }
        series = times.iter().zip(l.iter()).map(|(t, c)| (*t, Value::Chpo(c.clone()))).collect();
    } else {
        return Err(a.missing("TABLE (of PASAPAS) or LISTCHPO"));
    }
    // Steps to keep (1-based ranks among the series).
    if let Some(keep) = a.opt::<Rc<Vec<i64>>>() {
        let all = std::mem::take(&mut series);
        for k in keep.iter() {
            let s = usize::try_from(*k - 1)
                .ok()
                .and_then(|i| all.get(i))
                .ok_or_else(|| a.err(format!("step {} does not exist ({} saved)", k, all.len())))?;
            series.push(s.clone());
        }
    }
    if series.is_empty() {
        return Err(a.err("no saved step to draw"));
    }
    let comps: Vec<String> = match (first_word, a.opt::<Rc<Vec<String>>>()) {
        (_, Some(l)) => l.to_vec(),
        (Some(w), None) => vec![w],
        (None, None) => {
            vec![a.opt::<String>().ok_or_else(|| a.missing("the component (MOT or LISTMOTS)"))?.trim().to_uppercase()]
        }
    };
    let x: Vec<f64> = series.iter().map(|(t, _)| *t).collect();
    let mut curves = Vec::new();
    if matches!(series[0].1, Value::Mchaml(_)) {
        // Point N3 of element N2 of zone N1, one component.
        let (z, e, p) = (a.req::<i64>()?, a.req::<i64>()?, a.req::<i64>()?);
        let mut y = Vec::with_capacity(series.len());
        for (t, v) in &series {
            let Value::Mchaml(m) = v else { return Err(a.err("the results are not all MCHAML")) };
            let at = |n: i64| usize::try_from(n - 1).ok();
            let val = at(z)
                .and_then(|z| m.zones.get(z))
                .and_then(|zone| {
                    let ci = zone.comps.iter().position(|c| *c == comps[0])?;
                    zone.values.get(at(e)?)?.get(at(p)?)?.get(ci).copied()
                })
                .ok_or_else(|| {
                    a.err(format!("no {} at point {} of element {} of zone {} at time {}", comps[0], p, e, z, t))
                })?;
            y.push(val);
        }
        curves.push(Curve { legend: String::new(), x_name: "TEMPS".into(), y_name: comps[0].clone(), x, y });
        return Ok(vec![Value::Evol(Rc::new(Evolution { curves }))]);
    }
    let nodes: Vec<usize> = if let Some(p) = a.opt::<PointId>() { vec![p.0] } else { a.req::<Rc<Mesh>>()?.node_list() };
    for n in &nodes {
        for c in &comps {
            let mut y = Vec::with_capacity(series.len());
            for (t, v) in &series {
                let Value::Chpo(f) = v else { return Err(a.err("the results are not all CHPOINT")) };
                y.push(f.get(*n, c).ok_or_else(|| a.err(format!("no {} at node {} at time {}", c, n + 1, t)))?);
            }
            curves.push(Curve { legend: String::new(), x_name: "TEMPS".into(), y_name: c.clone(), x: x.clone(), y });
        }
    }
    Ok(vec![Value::Evol(Rc::new(Evolution { curves }))])
}
