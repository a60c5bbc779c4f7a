//! Lists: PROG, LECT, MOTS, SUIT (LISTCHPO), EXTR, DIME.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::{Chpoint, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "PROG",
        signature: "PROG (X1 X2 …) (X PAS DX (NPAS N | XEND)) (N * X) (LISTREEL)",
        doc: "Build a LISTREEL.",
        example: "l = prog 0. pas 0.5 2. ;",
        f: prog,
    },
    OpDef {
        name: "LECT",
        signature: "LECT (I1 I2 …) (I PAS DI (NPAS N | IEND)) (N * I) (LISTENTI)",
        doc: "Build a LISTENTI.",
        example: "l = lect 1 pas 1 4 ;",
        f: lect,
    },
    OpDef {
        name: "MOTS",
        signature: "MOTS WORD1 WORD2 … (N * WORD)",
        doc: "Build a LISTMOTS of 4-character words.",
        example: "m = mots 'UX' 'UY' ;",
        f: mots,
    },
    OpDef {
        name: "SUIT",
        signature: "SUIT (CHPOINT1 CHPOINT2 …)",
        doc: "Build a LISTCHPO (ordered list of fields, e.g. load cases for RESO); empty without arguments. Grow it with ET, read it with DIME and EXTR.",
        example: "lf = suit f1 f2 f3 ;",
        f: suit,
    },
    OpDef {
        name: "EXTR",
        signature: "EXTR LISTREEL|LISTENTI|LISTMOTS|LISTCHPO I | MOT I J | CHPOINT COMP POINT | …",
        doc: "Extract a part of an object (list element, I from 1; substring; field value; …).",
        example: "x = extr l 2 ;",
        f: extr,
    },
    OpDef {
        name: "DIME",
        signature: "DIME LISTREEL|LISTENTI|LISTMOTS|LISTCHPO|MOT|TABLE|CHPOINT|RIGIDITE|EVOLUTIO",
        doc: "Size of an object.",
        example: "n = dime l ;",
        f: dime,
    },
];

/// Sequence builder shared by PROG and LECT. Everything is read in the
/// order written, from the next token (`PAS` belongs to the value just
/// before it, not to one further on).
fn sequence(a: &mut Args, int: bool) -> Result<Vec<f64>> {
    let mut out = Vec::new();
    loop {
        if let Some(x) = a.opt_num_right() {
            if a.sign_like_star() {
                let v = a.opt_num_right().ok_or_else(|| a.missing("a value after '*'"))?;
                if x < 0.0 || x.fract() != 0.0 {
                    return Err(a.err(format!("a repeat count must be a non-negative ENTIER, found {}", x)));
                }
                out.extend(std::iter::repeat_n(v, x as usize));
            } else if a.keyword_next(&["PAS"]).is_some() {
                let step = a.opt_num_right().ok_or_else(|| a.missing("the step after PAS"))?;
                if a.keyword_next(&["NPAS"]).is_some() {
                    let n = a.opt_num_right().ok_or_else(|| a.missing("the count after NPAS"))?;
                    for k in 0..=(n.max(0.0) as usize) {
                        out.push(x + k as f64 * step);
                    }
                } else {
                    let end = a.opt_num_right().ok_or_else(|| a.missing("the last value after PAS"))?;
                    if step == 0.0 || (end - x) * step < 0.0 {
                        return Err(a.err(format!("PAS {} cannot go from {} to {}", step, x, end)));
                    }
                    let n = ((end - x) / step + 1e-9).floor();
                    if int && ((end - x) / step - n).abs() > 1e-9 {
                        return Err(a.err(format!("PAS {} does not divide the interval from {} to {}", step, x, end)));
                    }
                    if n > 1.0e8 {
                        return Err(a.err("too many values"));
                    }
                    for k in 0..=(n as usize) {
                        out.push(x + k as f64 * step);
                    }
                }
            } else {
                out.push(x);
            }
        } else if let Some(l) = a.opt_right::<Rc<Vec<f64>>>() {
            out.extend(l.iter());
        } else if let Some(l) = a.opt_right::<Rc<Vec<i64>>>() {
            out.extend(l.iter().map(|&i| i as f64));
        } else {
            break;
        }
    }
    Ok(out)
}

fn prog(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    Ok(vec![Value::ListReel(Rc::new(sequence(a, false)?))])
}

fn lect(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let v = sequence(a, true)?;
    if let Some(x) = v.iter().find(|x| x.fract() != 0.0) {
        return Err(a.err(format!("LECT takes integers, found {}", x)));
    }
    Ok(vec![Value::ListEnti(Rc::new(v.into_iter().map(|x| x as i64).collect()))])
}

fn mots(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mut out = Vec::new();
    loop {
        if let Some(n) = a.opt_right::<i64>() {
            if !a.sign_like_star() {
                return Err(a.err("expected '*' after a repeat count"));
            }
            let w = a.word().ok_or_else(|| a.missing("a word after '*'"))?;
            out.extend(std::iter::repeat_n(short(&w), n.max(0) as usize));
        } else if let Some(l) = a.opt_right::<Rc<Vec<String>>>() {
            out.extend(l.iter().cloned());
        } else if let Some(w) = a.word_not_operator() {
            out.push(short(&w));
        } else {
            break;
        }
    }
    Ok(vec![Value::ListMots(Rc::new(out))])
}

/// SUIT: the fields in the order written, from the pushed operands then
/// the right (`SUIT ;` alone is the empty list that `ET` grows).
fn suit(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mut out = Vec::new();
    while let Some(c) = a.opt::<Rc<Chpoint>>() {
        out.push(c);
    }
    Ok(vec![Value::ListChpo(Rc::new(out))])
}

/// LISTMOTS hold 4-character words (trailing blanks dropped).
fn short(w: &str) -> String {
    w.chars().take(4).collect::<String>().trim_end().to_string()
}

fn extr(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if let Some(v) = crate::ops::fieldfn::extr(it, a)? {
        return Ok(v);
    }
    if let Some(l) = a.opt::<Rc<Vec<f64>>>() {
        let i = a.req_index(l.len())?;
        return Ok(vec![Value::Float(l[i])]);
    }
    if let Some(l) = a.opt::<Rc<Vec<i64>>>() {
        let i = a.req_index(l.len())?;
        return Ok(vec![Value::Int(l[i])]);
    }
    if let Some(l) = a.opt::<Rc<Vec<String>>>() {
        let i = a.req_index(l.len())?;
        return Ok(vec![Value::mot(&l[i])]);
    }
    if let Some(l) = a.opt::<Rc<Vec<Rc<Chpoint>>>>() {
        let i = a.req_index(l.len())?;
        return Ok(vec![Value::Chpo(l[i].clone())]);
    }
    if let Some(m) = a.opt::<String>() {
        let chars: Vec<char> = m.chars().collect();
        let i = a.req_index(chars.len())?;
        let j = match a.opt::<i64>() {
            Some(j) if j as usize > i && j as usize <= chars.len() => j as usize,
            Some(j) => return Err(a.err(format!("end index {} is outside {}..{}", j, i + 1, chars.len()))),
            None => i + 1,
        };
        return Ok(vec![Value::mot(chars[i..j].iter().collect::<String>())]);
    }
    Err(a.missing("an object to extract from"))
}

fn dime(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let v = a.req::<Value>()?;
    let n = match &v {
        Value::ListReel(l) => l.len() as i64,
        Value::ListEnti(l) => l.len() as i64,
        Value::ListMots(l) => l.len() as i64,
        Value::ListChpo(l) => l.len() as i64,
        Value::Mot(s) => s.chars().count() as i64,
        Value::Table(t) => t.borrow().len() as i64,
        other => {
            crate::ops::fieldfn::dime(other).ok_or_else(|| a.err(format!("no size for a {}", other.type_name())))?
        }
    };
    Ok(vec![Value::Int(n)])
}
