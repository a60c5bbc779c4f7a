//! Lists: PROG, LECT, MOTS, SUIT (LISTCHPO), ORDO, DIME, SOMM (POSI and
//! UNIQ are in `lists_search.rs`), and
//! what EXTR and ENLE do with a list or a word (`extract.rs` dispatches).

use super::{limits, Args, FromArg, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::{Chpoint, Key, Table, Value};
use std::cell::RefCell;
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
        signature: "SUIT ('CHPOINT') (CHPOINT1 CHPOINT2 …)",
        doc: "Build a LISTCHPO (ordered list of fields, e.g. load cases for RESO); empty without arguments. Grow it with ET, read it with DIME and EXTR.",
        example: "lf = suit f1 f2 f3 ;",
        f: suit,
    },
    OpDef {
        name: "ORDO",
        signature: "ORDO LIST1 (LIST2 …) ('CROI'|'DECR') ('ABS') ('NOCA') ('UNIQ' (tol)) | ORDO 'COUT' ('HONG'|'COMP') COSTS LIST1 (LIST2 …) | ORDO EVOLUTIO ('CROI'|'DECR') ('ABS') | ORDO MAILLAGE",
        doc: "Sort a LISTREEL, LISTENTI or LISTMOTS (increasing by default); further lists of the same length follow the first one's order, one result per list. 'NOCA' compares words without case; 'UNIQ' (one list only) keeps one item of each run of equal ones (numbers within tol are equal). 'COUT' COSTS (n*n values, C(i,j) at (i-1)*n+j) gives the least total cost of an assignment (Hungarian method; 'COMP' tries every permutation), then each list permuted by it. An EVOLUTIO's curves are sorted by abscissa. A mesh: points by distance to the first, a line as one walk from end to end, other elements by vicinity.",
        example: "ls = ordo (prog 3. 1. 2.) ;",
        f: ordo,
    },
    OpDef {
        name: "DIME",
        signature: "DIME LISTREEL|LISTENTI|LISTMOTS|LISTCHPO|MOT|TABLE|CHPOINT|RIGIDITE|EVOLUTIO",
        doc: "Size of an object.",
        example: "n = dime l ;",
        f: dime,
    },
    OpDef {
        name: "SOMM",
        signature: "SOMM LISTREEL|LISTENTI",
        doc: "Sum of the items of a list (FLOTTANT for a LISTREEL, ENTIER for a LISTENTI).",
        example: "s = somm (prog 1. 2. 3.) ;",
        f: somm,
    },
];

/// Sequence builder shared by PROG and LECT. Everything is read in the
/// order written. `PAS DX` fills the gap between the value just before it
/// and the next value written (`PROG 1. PAS 2. 7.` is 1 3 5 7), so steps
/// chain (`0. PAS 0.1 1. PAS 0.25 2.`) and mix with `N * X`
/// (`3 * 9. PAS 2. 3 * 13.` is 9 9 9 11 13 13 13); `PAS DX NPAS N` adds N
/// values after the previous one. Every count is checked before it is
/// allocated ([`limits`]).
fn sequence(a: &mut Args, int: bool) -> Result<Vec<f64>> {
    let mut out: Vec<f64> = Vec::new();
    // A `PAS` waiting for the value that ends its gap: (start, step).
    let mut pending: Option<(f64, f64)> = None;
    loop {
        let first_new = out.len();
        if let Some(x) = a.opt_num_right() {
            if a.sign_like_star() {
                let v = a.opt_num_right().ok_or_else(|| a.missing("a value after '*'"))?;
                let n = limits::room(a, out.len(), x)?;
                fill_gap(a, &mut out, &mut pending, v, int, n > 0)?;
                out.extend(std::iter::repeat_n(v, n));
            } else {
                fill_gap(a, &mut out, &mut pending, x, int, true)?;
                limits::room(a, out.len(), 1.0)?;
                out.push(x);
            }
        } else if let Some(l) = a.opt_right::<Rc<Vec<f64>>>() {
            fill_gap(a, &mut out, &mut pending, l.first().copied().unwrap_or(0.0), int, !l.is_empty())?;
            limits::room(a, out.len(), l.len() as f64)?;
            out.extend(l.iter());
        } else if let Some(l) = a.opt_right::<Rc<Vec<i64>>>() {
            fill_gap(a, &mut out, &mut pending, l.first().map_or(0.0, |&i| i as f64), int, !l.is_empty())?;
            limits::room(a, out.len(), l.len() as f64)?;
            out.extend(l.iter().map(|&i| i as f64));
        } else {
            break;
        }
        if out.len() == first_new || a.keyword_next(&["PAS"]).is_none() {
            continue;
        }
        let x = out[out.len() - 1];
        let step = a.opt_num_right().ok_or_else(|| a.missing("the step after PAS"))?;
        if a.keyword_next(&["NPAS"]).is_some() {
            let n = a.opt_num_right().ok_or_else(|| a.missing("the count after NPAS"))?;
            if n < 0.0 {
                return Err(a.err(format!("NPAS must be positive or zero, found {}", n)));
            }
            let n = limits::room(a, out.len(), n)?;
            out.extend((1..=n).map(|k| x + k as f64 * step));
        } else {
            pending = Some((x, step));
        }
    }
    if pending.is_some() {
        return Err(a.missing("the value that ends the PAS"));
    }
    Ok(out)
}

/// The values strictly between a pending PAS's start and `end`. A step
/// that does not divide the gap becomes the nearest one that does
/// (prog.notice); a step going the wrong way adds nothing.
fn fill_gap(
    a: &Args,
    out: &mut Vec<f64>,
    pending: &mut Option<(f64, f64)>,
    end: f64,
    int: bool,
    has: bool,
) -> Result<()> {
    let Some((x, step)) = pending.take() else { return Ok(()) };
    if !has {
        *pending = Some((x, step));
        return Ok(());
    }
    if step == 0.0 {
        return Err(a.err("PAS 0 cannot reach another value"));
    }
    let ratio = (end - x) / step;
    if ratio <= 0.0 {
        return Ok(());
    }
    let n = ratio.round().max(1.0);
    if int && (ratio - n).abs() > 1e-9 {
        return Err(a.err(format!("PAS {} does not divide the interval from {} to {}", step, x, end)));
    }
    let dx = (end - x) / n;
    let n = limits::room(a, out.len(), n - 1.0)?;
    out.extend((1..=n).map(|k| x + k as f64 * dx));
    Ok(())
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

/// MOTS reads what follows it as words, operator names included
/// (`MOTS PRES FORC`, `MOTS UX MAXI`): Cast3M's MOTS reads words, so
/// mots.notice asks to write MOTS first. A name bound to a MOT gives its
/// value; anything else ends the list.
fn mots(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mut out = Vec::new();
    loop {
        if let Some(n) = a.opt_num_right() {
            if !a.sign_like_star() {
                return Err(a.err("expected '*' after a repeat count"));
            }
            let w = a.word().ok_or_else(|| a.missing("a word after '*'"))?;
            let n = limits::room(a, out.len(), n)?;
            out.extend(std::iter::repeat_n(short(&w), n));
        } else if let Some(l) = a.opt_right::<Rc<Vec<String>>>() {
            out.extend(l.iter().cloned());
        } else if let Some(w) = a.word() {
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
    // The type of the list may be named first ('CHPOINT' is the only one).
    a.keyword_next(&["CHPO"]);
    let mut out = Vec::new();
    while let Some(c) = a.opt::<Rc<Chpoint>>() {
        out.push(c);
    }
    Ok(vec![Value::ListChpo(Rc::new(out))])
}

/// LISTMOTS hold 4-character words (trailing blanks dropped); a longer
/// word looked up in one is compared by the same first four characters.
pub(crate) fn short(w: &str) -> String {
    w.chars().take(4).collect::<String>().trim_end().to_string()
}

/// EXTR on a list: the item at a place, or the sub-list at the places of
/// a LISTENTI.
pub(crate) fn extr_list(a: &mut Args, l: Value) -> Result<Vec<Value>> {
    let idx = a.opt::<Rc<Vec<i64>>>();
    Ok(vec![match (l, idx) {
        (Value::ListReel(l), Some(idx)) => Value::ListReel(Rc::new(sublist(a, &l, &idx)?)),
        (Value::ListEnti(l), Some(idx)) => Value::ListEnti(Rc::new(sublist(a, &l, &idx)?)),
        (Value::ListMots(l), Some(idx)) => Value::ListMots(Rc::new(sublist(a, &l, &idx)?)),
        (Value::ListReel(l), None) => Value::Float(l[a.req_index(l.len())?]),
        (Value::ListEnti(l), None) => Value::Int(l[a.req_index(l.len())?]),
        (Value::ListMots(l), None) => Value::mot(&l[a.req_index(l.len())?]),
        (other, _) => other,
    }])
}

/// EXTR on a word: the characters I (to J).
pub(crate) fn extr_word(a: &mut Args, m: &str) -> Result<Vec<Value>> {
    let chars: Vec<char> = m.chars().collect();
    let i = a.req_index(chars.len())?;
    let j = match a.opt::<i64>() {
        Some(j) if j as usize > i && j as usize <= chars.len() => j as usize,
        Some(j) => return Err(a.err(format!("end index {} is outside {}..{}", j, i + 1, chars.len()))),
        None => i + 1,
    };
    Ok(vec![Value::mot(chars[i..j].iter().collect::<String>())])
}

/// A LISTREEL, LISTENTI or LISTMOTS argument.
pub(crate) struct AnyList(pub Value);
impl FromArg for AnyList {
    const EXPECT: &'static str = "LISTREEL, LISTENTI or LISTMOTS";
    fn from_value(v: &Value) -> Option<Self> {
        list_len(v).map(|_| AnyList(v.clone()))
    }
}

pub(crate) fn list_len(v: &Value) -> Option<usize> {
    match v {
        Value::ListReel(l) => Some(l.len()),
        Value::ListEnti(l) => Some(l.len()),
        Value::ListMots(l) => Some(l.len()),
        _ => None,
    }
}

/// ORDO: a stable sort of the first list; the others follow its order.
fn ordo(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if let Some(m) = a.opt::<Rc<crate::fem::mesh::Mesh>>() {
        return Ok(vec![Value::Mesh(Rc::new(crate::fem::meshing::order::ordo(&it.nodes, &m)?))]);
    }
    if a.keyword(&["COUT"]).is_some() {
        return super::ordo_cost::ordo_cost(a);
    }
    let mut order = None;
    let mut use_abs = false;
    if let Some(ev) = a.opt::<Rc<crate::value::Evolution>>() {
        while let Some(k) = a.keyword(&["CROI", "DECR", "ABS"]) {
            match k {
                "ABS" => use_abs = true,
                k => order = Some(k),
            }
        }
        return Ok(vec![Value::Evol(Rc::new(super::evol_extr::sorted(&ev, order == Some("DECR"), use_abs)))]);
    }
    let mut lists: Vec<Value> = Vec::new();
    let (mut nocase, mut unique, mut tol) = (false, false, 0.0);
    let mut table: Option<Rc<RefCell<Table>>> = None;
    let mut table_keys: Vec<Key> = Vec::new();
    loop {
        if let Some(k) = a.keyword(&["CROI", "DECR", "ABS", "NOCA", "UNIQ"]) {
            match k {
                "ABS" => use_abs = true,
                "NOCA" => nocase = true,
                "UNIQ" => {
                    unique = true;
                    tol = a.opt_num_right().unwrap_or(0.0);
                }
                k => order = Some(k),
            }
            continue;
        }
        // A TABLE of lists and the key of the one that sets the order.
        if lists.is_empty() && table.is_none() {
            if let Some(t) = a.opt::<Rc<RefCell<Table>>>() {
                let k = a.opt::<Value>().ok_or_else(|| a.missing("the key of the list to sort the TABLE by"))?;
                let k = Key::from_value(&k);
                let entries = t.borrow();
                let Some(first) = entries.get(&k).filter(|v| list_len(v).is_some()) else {
                    return Err(a.err("the TABLE has no list at that key"));
                };
                lists.push(first.clone());
                for (key, v) in entries.iter().filter(|(key, v)| *key != k && list_len(v).is_some()) {
                    lists.push(v.clone());
                    table_keys.push(key.clone());
                }
                table_keys.insert(0, k);
                drop(entries);
                table = Some(t);
                continue;
            }
        }
        if table.is_some() {
            break;
        }
        // The key list may have been pushed before ORDO; the others follow.
        let next = if lists.is_empty() { a.opt::<AnyList>() } else { a.opt_right::<AnyList>() };
        match next {
            Some(AnyList(v)) => lists.push(v),
            None => break,
        }
    }
    let Some(key) = lists.first() else { return Err(a.missing(AnyList::EXPECT)) };
    let n = list_len(key).unwrap_or(0);
    if let Some(other) = lists.iter().find(|l| list_len(l) != Some(n)) {
        return Err(a.err(format!("the lists have different lengths ({} and {})", n, list_len(other).unwrap_or(0))));
    }
    let num = |x: f64| if use_abs { x.abs() } else { x };
    let cmp = |i: usize, j: usize| match key {
        Value::ListReel(l) => num(l[i]).total_cmp(&num(l[j])),
        Value::ListEnti(l) if use_abs => l[i].abs().cmp(&l[j].abs()),
        Value::ListEnti(l) => l[i].cmp(&l[j]),
        Value::ListMots(l) if nocase => l[i].to_uppercase().cmp(&l[j].to_uppercase()),
        Value::ListMots(l) => l[i].cmp(&l[j]),
        _ => std::cmp::Ordering::Equal,
    };
    if unique && lists.len() > 1 {
        return Err(a.err("'UNIQ' sorts one list only"));
    }
    // Stable either way: equal keys keep their order.
    let decr = order == Some("DECR");
    let mut perm: Vec<usize> = (0..n).collect();
    perm.sort_by(|&i, &j| if decr { cmp(j, i) } else { cmp(i, j) });
    if unique {
        // An item equal to the last one kept is dropped (within tol for
        // numbers, without case under 'NOCA' for words).
        let same = |i: usize, j: usize| match key {
            Value::ListReel(l) => (num(l[i]) - num(l[j])).abs() <= tol,
            Value::ListEnti(l) => (num(l[i] as f64) - num(l[j] as f64)).abs() <= tol,
            _ => cmp(i, j) == std::cmp::Ordering::Equal,
        };
        let mut kept: Vec<usize> = Vec::with_capacity(perm.len());
        for &i in &perm {
            if kept.last().is_none_or(|&k| !same(k, i)) {
                kept.push(i);
            }
        }
        perm = kept;
    }
    let sorted = lists
        .iter()
        .map(|l| match l {
            Value::ListReel(l) => Value::ListReel(Rc::new(perm.iter().map(|&i| l[i]).collect())),
            Value::ListEnti(l) => Value::ListEnti(Rc::new(perm.iter().map(|&i| l[i]).collect())),
            Value::ListMots(l) => Value::ListMots(Rc::new(perm.iter().map(|&i| l[i].clone()).collect())),
            other => other.clone(),
        })
        .collect::<Vec<_>>();
    match table {
        // A new TABLE: the same entries, its lists permuted.
        Some(t) => {
            let mut out = t.borrow().clone();
            for (k, v) in table_keys.into_iter().zip(sorted) {
                out.set(k, v);
            }
            Ok(vec![Value::Table(Rc::new(RefCell::new(out)))])
        }
        None => Ok(sorted),
    }
}

/// `EXTR LIST LISTENTI`: the items at the given (1-based) places, in the
/// order of the places.
fn sublist<T: Clone>(a: &Args, l: &[T], idx: &[i64]) -> Result<Vec<T>> {
    idx.iter()
        .map(|&i| match usize::try_from(i).ok().and_then(|i| i.checked_sub(1)).and_then(|i| l.get(i)) {
            Some(x) => Ok(x.clone()),
            None => Err(a.err(format!("index {} is outside 1..{}", i, l.len()))),
        })
        .collect()
}

/// `ENLE LIST I|LISTENTI`: the list without the items at those places.
pub(crate) fn enle(a: &mut Args, l: Value) -> Result<Vec<Value>> {
    let n = match &l {
        Value::ListChpo(c) => c.len(),
        l => list_len(l).unwrap_or(0),
    };
    let places: Vec<i64> = match a.opt::<i64>() {
        Some(i) => vec![i],
        None => a.req::<Rc<Vec<i64>>>()?.to_vec(),
    };
    let mut keep = vec![true; n];
    for i in places {
        match usize::try_from(i).ok().and_then(|i| i.checked_sub(1)).filter(|&i| i < n) {
            Some(i) => keep[i] = false,
            None => return Err(a.err(format!("index {} is outside 1..{}", i, n))),
        }
    }
    let pick = |k: &usize| keep[*k];
    Ok(vec![match l {
        Value::ListReel(l) => Value::ListReel(Rc::new((0..n).filter(pick).map(|k| l[k]).collect())),
        Value::ListEnti(l) => Value::ListEnti(Rc::new((0..n).filter(pick).map(|k| l[k]).collect())),
        Value::ListMots(l) => Value::ListMots(Rc::new((0..n).filter(pick).map(|k| l[k].clone()).collect())),
        Value::ListChpo(l) => Value::ListChpo(Rc::new((0..n).filter(pick).map(|k| l[k].clone()).collect())),
        other => other,
    }])
}

fn somm(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if let Some(l) = a.opt::<Rc<Vec<f64>>>() {
        let s: f64 = l.iter().sum();
        if !s.is_finite() {
            return Err(a.err("the sum overflows a FLOTTANT (beyond about 1.8E+308)"));
        }
        return Ok(vec![Value::Float(s)]);
    }
    let l = a.req::<Rc<Vec<i64>>>()?;
    let s = l.iter().try_fold(0i64, |s, &x| s.checked_add(x)).ok_or_else(|| a.err("the sum overflows an ENTIER"))?;
    Ok(vec![Value::Int(s)])
}

/// POSI: the object is the first operand written (`POSI 'UY' LM`), read
/// before the list so that a MOT list never stands for the object.
fn dime(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let v = a.req::<Value>()?;
    let n = match &v {
        Value::ListReel(l) => l.len() as i64,
        Value::ListEnti(l) => l.len() as i64,
        Value::ListMots(l) => l.len() as i64,
        Value::ListChpo(l) => l.len() as i64,
        Value::Mot(s) => s.chars().count() as i64,
        Value::Table(t) => t.borrow().len() as i64,
        Value::Chpo(c) => c.len() as i64,
        Value::Rigi(r) => r.n_unknowns() as i64,
        Value::Evol(e) => e.curves.len() as i64,
        other => return Err(a.err(format!("no size for a {}", other.type_name()))),
    };
    Ok(vec![Value::Int(n)])
}
