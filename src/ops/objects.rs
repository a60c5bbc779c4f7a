//! Object utilities: TYPE, EXIS, OUBL, DETR, MOT, CHAI, COMM, TABL.

use super::format::{self, Edit};
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
        signature: "EXIS NAME | TABLE KEY | CHPOINT COMP | CHARGEMENT NAME | LIST VALUE | LISTMOTS LISTMOTS ('ET'|'OU') | MMODEL 'FORM'|'ELEM'|'MATE' MOT…",
        doc: "Whether a name, a table key, a component or a list member exists.",
        example: "si (exis t 'K') ; mess 'yes' ; finsi ;",
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
        name: "MENA",
        signature: "MENAGE ('OBLI') (ENTIER)",
        doc: "Free memory no longer reachable (gibi frees objects as they become unreachable: no effect).",
        example: "menage ;",
        f: mena,
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
        signature: "CHAI ('FORMAT' '(F8.3)') OBJ1 (*N) OBJ2 …",
        doc: "Join words and numbers into one MOT (floats as 1PE12.5 unless a Fortran format F, E, 1PE, ES, D, G, I or A is given; *N starts the next item at column N).",
        example: "m = chai 'err=' 'FORMAT' '(F8.3)' x *20 'done' ;",
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
        Value::ListMots(l) => {
            let has = |w: &str| {
                let w = super::lists::short(w);
                l.iter().any(|x| super::lists::short(x) == w)
            };
            if let Some(words) = a.opt_right::<Rc<Vec<String>>>() {
                // A second list: all of it ('ET'), any of it ('OU'), or
                // one answer per word.
                return Ok(match a.keyword_next(&["ET", "OU"]) {
                    Some("ET") => vec![Value::Bool(words.iter().all(|w| has(w)))],
                    Some(_) => vec![Value::Bool(words.iter().any(|w| has(w)))],
                    None => words.iter().map(|w| Value::Bool(has(w))).collect(),
                });
            }
            match a.opt_right::<String>() {
                Some(w) => has(&w),
                None => true,
            }
        }
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
        // Whether some zone has that component, as point values or as
        // material data (`EXIS MAT 'TRAC'`: the word is read even when it
        // names an operator).
        Value::Mchaml(m) => match a.word() {
            Some(comp) => {
                let comp = comp.trim_end();
                m.zones.iter().any(|z| {
                    z.comps.iter().any(|c| c == comp)
                        || z.constants.contains_key(comp)
                        || z.laws.contains_key(comp)
                        || z.vectors.contains_key(comp)
                        || z.objects.contains_key(comp)
                })
            }
            None => true,
        },
        // Whether a load of that name is part of a CHARGEMENT.
        Value::Charge(c) => match a.opt_right::<String>() {
            Some(name) => c.has(&name.trim().to_uppercase().chars().take(4).collect::<String>()),
            None => true,
        },
        // Whether some zone has one of the formulations, elements or
        // behaviour words named.
        Value::Model(m) => match super::fields::zone_selection(a, "MATE")? {
            Some((key, words)) => !m.zones_with(key, &words).zones.is_empty(),
            None => true,
        },
        v if super::impact::is_annule(v) => false,
        _ => true,
    };
    Ok(vec![Value::Bool(r)])
}

fn oubl(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    // A name bound to nothing (even an operator's, `OUBL CHPO`) has nothing to forget.
    if a.unbound_word().is_some() {
        return Ok(vec![]);
    }
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

fn mena(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    a.keyword_next(&["OBLI"]);
    a.opt::<i64>();
    Ok(vec![])
}

fn mot(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let w = a.word().ok_or_else(|| a.missing("a word"))?;
    Ok(vec![Value::mot(w)])
}

/// Longest MOT CHAI builds (chai.notice).
const MAX_TEXT: usize = 512;

/// CHAI joins words and numbers into one MOT. Floats default to Cast3M's
/// (1PE12.5) digits, `1.00000E+00`, without the field's leading blank.
/// `'FORMAT' '(F8.3)'` sets how the following FLOTTANTs are written (an
/// I descriptor sets ENTIERs, an A descriptor words); `*N` starts the
/// next item at column N.
fn chai(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mut s = String::new();
    let (mut real, mut int, mut text): (Option<Edit>, Option<Edit>, Option<Edit>) = (None, None, None);
    loop {
        // Operands pushed before CHAI come first, as written.
        if a.left_len() == 0 {
            if is_format_word(a.peek_word()) {
                a.word();
                let f = a.opt_right::<String>().ok_or_else(|| a.missing("a Fortran format such as '(F8.3)'"))?;
                let e = format::parse(&f).map_err(|m| a.err(m))?;
                match e {
                    Edit::I { .. } => int = Some(e),
                    Edit::A { .. } => text = Some(e),
                    _ => real = Some(e),
                }
                continue;
            }
            if a.sign_like_star() {
                let col = a.opt_right::<i64>().ok_or_else(|| a.missing("a column number after '*'"))?;
                if col < 1 || col as usize > MAX_TEXT {
                    return Err(a.err(format!("column {} is outside 1..{}", col, MAX_TEXT)));
                }
                let have = s.chars().count();
                if have + 1 < col as usize {
                    s.push_str(&" ".repeat(col as usize - 1 - have));
                }
                continue;
            }
        }
        let v = match a.word_before_text() {
            Some(w) => Value::mot(w),
            None => match a.opt::<Value>() {
                Some(v) => v,
                None => break,
            },
        };
        match v {
            Value::Mot(m) => s.push_str(&text.as_ref().map_or_else(|| m.to_string(), |e| format::text(e, &m))),
            Value::Int(i) => s.push_str(&int.as_ref().map_or_else(|| i.to_string(), |e| format::int(e, i))),
            Value::Float(f) => s.push_str(&real.as_ref().map_or_else(|| fmt_float(f), |e| format::real(e, f))),
            Value::Bool(b) => s.push_str(if b { "VRAI" } else { "FAUX" }),
            Value::Point(p) => {
                let x = it.nodes.get(p);
                let d = it.opts.dime.max(1);
                let show = |c: f64| real.as_ref().map_or_else(|| fmt_float(c), |e| format::real(e, c));
                let c: Vec<String> = x[..d].iter().map(|c| show(*c)).collect();
                s.push_str(&c.join(" "));
            }
            other => return Err(a.err(format!("cannot put a {} in a text", other.type_name()))),
        }
        if s.chars().count() > MAX_TEXT {
            return Err(a.err(format!("a text holds at most {} characters", MAX_TEXT)));
        }
    }
    Ok(vec![Value::mot(s)])
}

/// `'FORMAT'` (or `'FORM'`, `'FORMA'`): not any word that starts with
/// FORM, so a text like 'FORMULE' stays a text.
/// Unquoted too: `CHAINE FORMAT '(F9.2)' …` (FORM names an operator, but
/// CHAI reads the word as its keyword).
fn is_format_word(w: Option<String>) -> bool {
    match w {
        Some(w) => {
            let w = w.trim().to_uppercase();
            w.len() >= 4 && "FORMAT".starts_with(&w)
        }
        None => false,
    }
}

fn comm(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    a.drain();
    Ok(vec![])
}

fn tabl(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if let Some(t) = a.opt::<Rc<RefCell<Table>>>() {
        return Ok(vec![Value::Table(t)]);
    }
    // The subtype is read as a word even when it names an operator
    // (`TABL VECTEUR`): Cast3M's TABL reads a text there, never runs it.
    let t = match a.word() {
        Some(sub) => Table::with_subtype(&sub),
        None => Table::new(),
    };
    Ok(vec![Value::Table(Rc::new(RefCell::new(t)))])
}
