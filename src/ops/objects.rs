//! Object utilities: TYPE, EXIS, OUBL, DETR, MOT, CHAI, COMM, TABL.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::{fmt_float, Key, Table, Value};
use std::cell::RefCell;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "TYPE",
        signature: "TYPE OBJ",
        doc: "The 8-character type name of an object, as a MOT.",
        example: "t = type x ;",
        f: type_,
    },
    OpDef {
        name: "EXIS",
        signature: "EXIS NAME | TABLE KEY | CHPOINT COMP | LIST VALUE",
        doc: "Whether a name, a table key, a component or a list member exists.",
        example: "si (exis t 'K') ;",
        f: exis,
    },
    OpDef {
        name: "OUBL",
        signature: "OUBL NAME | TABLE KEY",
        doc: "Forget a name, or remove a table entry.",
        example: "oubl t 'K' ;",
        f: oubl,
    },
    OpDef {
        name: "DETR",
        signature: "DETR OBJ",
        doc: "Destroy an object (memory is managed by gibi: no effect).",
        example: "detr x ;",
        f: detr,
    },
    OpDef {
        name: "MOT",
        signature: "MOT WORD",
        doc: "A word as a MOT object (also an operator name kept for later).",
        example: "m = mot 'TRAC' ;",
        f: mot,
    },
    OpDef {
        name: "CHAI",
        signature: "CHAI OBJ1 OBJ2 …",
        doc: "Join words and numbers into one MOT (floats as 1PE12.5).",
        example: "m = chai 'err=' x ;",
        f: chai,
    },
    OpDef {
        name: "COMM",
        signature: "COMM text ;",
        doc: "Comment up to the ';'.",
        example: "comm this is ignored ;",
        f: comm,
    },
    OpDef {
        name: "TABL",
        signature: "TABL ('SUBTYPE') | TABL TABLE",
        doc: "A new TABLE (with a subtype), or another name for the same table.",
        example: "t = tabl ;",
        f: tabl,
    },
    OpDef {
        name: "TEXT",
        signature: "TEXT WORD …",
        doc: "A text (kept as a MOT).",
        example: "t = text 'abc' ;",
        f: chai,
    },
];

fn type_(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let v = a.req::<Value>()?;
    Ok(vec![Value::mot(format!("{:<8}", v.type_name()))])
}

fn exis(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    // An unassigned name: does not exist (how procedures test a missing
    // optional argument).
    if a.left_len() == 0 && a.unbound_word().is_some() {
        return Ok(vec![Value::Bool(false)]);
    }
    let obj = a.req::<Value>()?;
    let r = match &obj {
        Value::Table(t) => match a.right_any() {
            Some(k) => t.borrow().get(&Key::from_value(&k)).is_some(),
            None => true,
        },
        Value::ListMots(l) => match a.opt_right::<String>() {
            Some(w) => l.iter().any(|x| x.trim_end() == w.trim_end()),
            None => true,
        },
        Value::ListReel(l) => match a.opt_num_right() {
            Some(x) => l.contains(&x),
            None => true,
        },
        Value::ListEnti(l) => match a.opt_right::<i64>() {
            Some(x) => l.contains(&x),
            None => true,
        },
        Value::Chpo(c) => match a.opt_right::<String>() {
            Some(comp) => c.components().contains(&comp),
            None => true,
        },
        _ => true,
    };
    Ok(vec![Value::Bool(r)])
}

fn oubl(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if let Some(name) = a.next_name_span().map(|sp| it.source.slice(sp).to_uppercase()) {
        let v = a.req::<Value>()?;
        if let Value::Table(t) = &v {
            if let Some(k) = a.right_any() {
                t.borrow_mut().remove(&Key::from_value(&k));
                return Ok(vec![]);
            }
        }
        it.store.remove(&name);
        return Ok(vec![]);
    }
    if let Some(t) = a.opt::<Rc<RefCell<Table>>>() {
        let k = a.right_any().ok_or_else(|| a.missing("a key"))?;
        t.borrow_mut().remove(&Key::from_value(&k));
        return Ok(vec![]);
    }
    a.unbound_word();
    Ok(vec![])
}

fn detr(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    a.rest();
    Ok(vec![])
}

fn mot(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let w = a.word().ok_or_else(|| a.missing("a word"))?;
    Ok(vec![Value::mot(w)])
}

/// Cast3M's default float format for CHAI, (1PE12.5): `1.00000E+00`.
fn chai(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mut s = String::new();
    let mut parts = Vec::new();
    while let Some(v) = a.opt::<Value>() {
        parts.push(v);
    }
    for v in parts {
        match v {
            Value::Mot(m) => s.push_str(&m),
            Value::Int(i) => s.push_str(&i.to_string()),
            Value::Float(f) => s.push_str(&fmt_float(f)),
            Value::Bool(b) => s.push_str(if b { "VRAI" } else { "FAUX" }),
            Value::Point(p) => {
                let x = it.nodes.get(p);
                let d = it.opts.dime.max(1);
                let c: Vec<String> = x[..d].iter().map(|c| fmt_float(*c)).collect();
                s.push_str(&c.join(" "));
            }
            other => return Err(a.err(format!("cannot put a {} in a text", other.type_name()))),
        }
    }
    if s.chars().count() > 512 {
        return Err(a.err("a text holds at most 512 characters"));
    }
    Ok(vec![Value::mot(s)])
}

fn comm(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    a.drain();
    Ok(vec![])
}

fn tabl(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if let Some(t) = a.opt::<Rc<RefCell<Table>>>() {
        return Ok(vec![Value::Table(t)]);
    }
    let t = match a.opt_right::<String>() {
        Some(sub) => Table::with_subtype(&sub),
        None => Table::new(),
    };
    Ok(vec![Value::Table(Rc::new(RefCell::new(t)))])
}
