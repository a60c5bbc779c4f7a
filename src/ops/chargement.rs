//! CHAR (CHARGEMENT) and TIRE: loads described in space and time.
//! The object is `value::Chargement`; `ET` joins two of them
//! (`fields::union`), LIST shows their parts.

use super::arith::{apply, Bin};
use super::{Args, OpDef};
use crate::analysis::history::TimeFunction;
use crate::error::Result;
use crate::eval::Interp;
use crate::value::chargement::{LoadPart, Timing};
use crate::value::{Chargement, Evolution, Key, Table, Value};
use std::cell::RefCell;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "CHARGEMENT",
        signature: "CHAR ('MOT') CHPOINT|MCHAML EVOLUTIO | CHAR ('MOT') TABLE_TIMES TABLE_FIELDS",
        doc: "A load in space and time: a field times a time function (the first curve of the EVOLUTIO), or \
              fields given at times (two tables indexed 0 1 2 …: the times, then the fields; linear in between). \
              PASAPAS reads the parts by name: 'MECA' forces, 'DIMP' imposed values (DEPI), 'T' temperatures; \
              other names are variables a material may depend on. Join loads with ET.",
        example: "ch = char 'DIMP' (depi cl -1.e-3) (evol manu 'TEMPS' (prog 0. 1.) (prog 0. 1.)) ;",
        f: char,
    },
    OpDef {
        name: "TIRE",
        signature: "TIRE CHARGEMENT (MOT) FLOTTANT ('TABL' | MOT)",
        doc: "The load at a time: the sum of the parts (a CHPOINT or an MCHAML), the parts named MOT only, or \
              with 'TABL' a TABLE of the parts by name.",
        example: "f = tire ch 0.5 'MECA' ;",
        f: tire,
    },
];

/// Options of CHAR that gibi reads but that change nothing for loads tied
/// to the structure (the default): a moving load ('TRAN', 'ROTA', 'TRAJ')
/// is refused by name.
/// The first components that make an unnamed CHPOINT load a 'MECA' one.
const FORCE_NAMES: &[&str] = &["FX", "FY", "FZ", "FR", "FT", "MR", "MT", "MX", "MY", "MZ"];

const CHAR_WORDS: &[&str] = &["LIBRE", "LIE", "TRAN", "ROTA", "TRAJ"];

fn char(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let read_options = |a: &mut Args| -> Result<()> {
        while let Some(k) = a.keyword(CHAR_WORDS) {
            if matches!(k, "TRAN" | "ROTA" | "TRAJ") {
                return Err(a.err(format!("the moving loads of '{}' are not supported", k)));
            }
        }
        Ok(())
    };
    read_options(a)?;
    if let Some(t1) = a.opt::<Rc<RefCell<Table>>>() {
        let t2 = a.req::<Rc<RefCell<Table>>>()?;
        let name = a.opt::<String>();
        read_options(a)?;
        let steps = table_steps(a, &t1.borrow(), &t2.borrow())?;
        return Ok(vec![one(name, Timing::Table(steps))]);
    }
    let name = a.opt::<String>();
    let field = a
        .opt_with(|v| matches!(v, Value::Chpo(_) | Value::Mchaml(_)).then(|| v.clone()))
        .ok_or_else(|| a.missing("CHPOINT or MCHAML (the load in space)"))?;
    let ev = a.req::<Rc<Evolution>>()?;
    read_options(a)?;
    let c = ev.curves.first().ok_or_else(|| a.err("the EVOLUTIO holds no curve"))?;
    let function = TimeFunction::new(c.x.clone(), c.y.clone()).map_err(|e| a.err(e))?;
    // Unnamed, a field of forces is a mechanical load: Cast3M names it
    // 'MECA' when its first component is a force or a moment.
    let name = name.or_else(|| match &field {
        Value::Chpo(c) => c.comps.first().filter(|k| FORCE_NAMES.contains(&k.as_str())).map(|_| "MECA".to_string()),
        _ => None,
    });
    Ok(vec![one(name, Timing::Scaled { field, function })])
}

/// A CHARGEMENT of one part; names are kept as Cast3M keeps them (4 letters).
fn one(name: Option<String>, time: Timing) -> Value {
    let name = name.map(|n| n.trim().to_uppercase().chars().take(4).collect()).unwrap_or_default();
    Value::Charge(Rc::new(Chargement { parts: vec![LoadPart { name, time }] }))
}

/// The (time, field) pairs of `CHAR TAB1 TAB2`: both indexed 0 1 … N.
fn table_steps(a: &Args, times: &Table, fields: &Table) -> Result<Vec<(f64, Value)>> {
    let n = times.iter().filter(|(k, _)| matches!(k, Key::Int(_))).count();
    if n == 0 {
        return Err(a.err("the table of times holds no entry 0 1 2 …"));
    }
    let mut out: Vec<(f64, Value)> = Vec::with_capacity(n);
    for i in 0..n as i64 {
        let t = times.get(&Key::Int(i)).and_then(Value::as_f64).ok_or_else(|| {
            a.err(format!("the table of times must be indexed 0 1 2 … with numbers; entry {i} is not"))
        })?;
        let f = fields
            .get(&Key::Int(i))
            .filter(|v| matches!(v, Value::Chpo(_) | Value::Mchaml(_)))
            .ok_or_else(|| a.err(format!("the table of fields has no CHPOINT or MCHAML at index {i}")))?;
        if out.last().is_some_and(|(p, _)| t < *p) {
            return Err(a.err(format!("the times decrease at index {i}")));
        }
        out.push((t, f.clone()));
    }
    Ok(out)
}

fn tire(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let Some(ch) = a.opt_with(|v| match v {
        Value::Charge(c) => Some(c.clone()),
        _ => None,
    }) else {
        // TIRE of a SOLUTION object (dynamics) is not implemented.
        return Err(a.missing("CHARGEMENT"));
    };
    // The name may come before the time (TIRE ch 'PRES' t), as G_THETA
    // writes it, or after it.
    let early = a.opt::<String>().map(|n| n.trim().to_uppercase());
    let t = a.req_num()?;
    if early.as_deref() == Some("TABL") || a.keyword(&["TABL"]).is_some() {
        let mut names: Vec<&str> = Vec::new();
        for p in &ch.parts {
            if !names.contains(&p.name.as_str()) {
                names.push(&p.name);
            }
        }
        let mut tab = Table::new();
        for n in names {
            tab.set(Key::Mot(n.to_string()), at(it, a, &ch, Some(n), t)?);
        }
        return Ok(vec![Value::Table(Rc::new(RefCell::new(tab)))]);
    }
    let name = early.or_else(|| a.opt::<String>().map(|n| n.trim().to_uppercase()));
    Ok(vec![at(it, a, &ch, name.as_deref(), t)?])
}

/// The parts named `name` (all parts for None) summed at time `t`.
pub(crate) fn at(it: &mut Interp, a: &Args, ch: &Chargement, name: Option<&str>, t: f64) -> Result<Value> {
    let mut terms: Vec<(f64, Value)> = Vec::new();
    for p in ch.parts.iter().filter(|p| name.is_none_or(|n| keyword4(&p.name) == keyword4(n))) {
        let w = p.weights(t).map_err(|e| a.err(format!("load '{}': {}", p.name, e)))?;
        terms.extend(w.into_iter().map(|(w, v)| (w, v.clone())));
    }
    if terms.is_empty() {
        let have: Vec<String> = ch.parts.iter().map(|p| format!("'{}'", p.name)).collect();
        return Err(a.err(format!(
            "the CHARGEMENT has no load named '{}' (it has {})",
            name.unwrap_or(""),
            have.join(" ")
        )));
    }
    weighted_sum(it, a, &terms)
}

pub(super) fn keyword4(s: &str) -> String {
    s.trim().to_uppercase().chars().take(4).collect()
}

/// Σ wᵢ fieldᵢ with the field algebra of `+` and `*` (the arithmetic
/// table's rules).
pub(crate) fn weighted_sum(it: &mut Interp, a: &Args, terms: &[(f64, Value)]) -> Result<Value> {
    let mut acc: Option<Value> = None;
    for (w, f) in terms {
        let scaled = apply(it, a, Bin::Mul, f, &Value::Float(*w))?;
        acc = Some(match acc {
            None => scaled,
            Some(s) => apply(it, a, Bin::Add, &s, &scaled)?,
        });
    }
    acc.ok_or_else(|| a.err("no load to sum"))
}
