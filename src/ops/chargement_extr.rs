//! EXTR of a CHARGEMENT (extr.notice): the names of its elementary loads
//! ('COMP'), one of them by number ('CHAR', 'CHAM', 'EVOL' N, the first by
//! default), or the loads of given names (MOT, LISTMOTS), or a name's
//! times and fields as two tables (MOT 'TABL').

use super::chargement::keyword4;
use super::Args;
use crate::error::Result;
use crate::value::chargement::{LoadPart, Timing};
use crate::value::model::Curve;
use crate::value::{Chargement, Evolution, Key, Table, Value};
use std::cell::RefCell;
use std::rc::Rc;

pub(super) fn extr(a: &mut Args, ch: &Chargement) -> Result<Vec<Value>> {
    if let Some(k) = a.keyword(&["COMP", "CHAR", "CHAM", "EVOL"]) {
        if k == "COMP" {
            let mut names: Vec<String> = Vec::new();
            for p in &ch.parts {
                if !names.contains(&p.name) {
                    names.push(p.name.clone());
                }
            }
            return Ok(vec![Value::ListMots(Rc::new(names))]);
        }
        let i = match a.opt::<i64>() {
            Some(i) => usize::try_from(i)
                .ok()
                .filter(|&i| (1..=ch.parts.len()).contains(&i))
                .ok_or_else(|| a.err(format!("load number {} is outside 1..{}", i, ch.parts.len())))?,
            None => 1,
        };
        let p = ch.parts.get(i - 1).ok_or_else(|| a.err("the CHARGEMENT holds no load"))?;
        return match k {
            "CHAR" => Ok(vec![Value::Charge(Rc::new(Chargement { parts: vec![p.clone()] }))]),
            "CHAM" => Ok(vec![match &p.time {
                Timing::Scaled { field, .. } => field.clone(),
                Timing::Table(steps) => steps[0].1.clone(),
            }]),
            _ => evolution(a, p),
        };
    }
    if let Some(names) = a.opt::<Rc<Vec<String>>>() {
        let keys: Vec<String> = names.iter().map(|n| keyword4(n)).collect();
        return Ok(vec![Value::Charge(Rc::new(named(a, ch, &keys)?))]);
    }
    let name = keyword4(&a.req::<String>()?);
    if a.keyword(&["TABL"]).is_some() {
        return tables(a, ch, &name);
    }
    Ok(vec![Value::Charge(Rc::new(named(a, ch, &[name])?))])
}

/// The loads whose name is one of `keys`; none at all is an error.
fn named(a: &Args, ch: &Chargement, keys: &[String]) -> Result<Chargement> {
    let parts: Vec<LoadPart> = ch.parts.iter().filter(|p| keys.contains(&keyword4(&p.name))).cloned().collect();
    if parts.is_empty() {
        let have: Vec<String> = ch.parts.iter().map(|p| format!("'{}'", p.name)).collect();
        return Err(a.err(format!("no load named {} (the loads are {})", keys.join(" "), have.join(" "))));
    }
    Ok(Chargement { parts })
}

/// The time function of a field-times-function load, as a curve.
fn evolution(a: &Args, p: &LoadPart) -> Result<Vec<Value>> {
    let Timing::Scaled { function, .. } = &p.time else {
        return Err(a.err(format!("the load '{}' is given by tables of times and fields: it has no EVOLUTIO", p.name)));
    };
    let (x, y) = (function.times().to_vec(), function.values().to_vec());
    if !x.iter().all(|t| t.is_finite()) {
        return Err(a.err(format!("the load '{}' is constant in time: it has no EVOLUTIO", p.name)));
    }
    let c = Curve { x_name: "TEMP".into(), y_name: "AMPL".into(), x, y, ..Default::default() };
    Ok(vec![Value::Evol(Rc::new(Evolution { curves: vec![c] }))])
}

/// `MOT 'TABL'`: the times and the fields of the loads of that name, as
/// two tables indexed 0 1 2 ….
fn tables(a: &Args, ch: &Chargement, name: &str) -> Result<Vec<Value>> {
    let sub = named(a, ch, &[name.to_string()])?;
    let (mut tt, mut tf) = (Table::new(), Table::new());
    let mut k = 0;
    for p in &sub.parts {
        let steps: Vec<(f64, Value)> = match &p.time {
            Timing::Table(s) => s.clone(),
            Timing::Scaled { .. } => {
                return Err(a.err(format!(
                    "the load '{}' is a field times a function: 'TABL' reads loads given by tables of fields",
                    p.name
                )))
            }
        };
        for (t, f) in steps {
            tt.set(Key::Int(k), Value::Float(t));
            tf.set(Key::Int(k), f);
            k += 1;
        }
    }
    Ok(vec![Value::Table(Rc::new(RefCell::new(tt))), Value::Table(Rc::new(RefCell::new(tf)))])
}
