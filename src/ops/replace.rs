//! REMP (REMPLACER): the directive that changes items of a list in place.
//!
//! In Cast3M a list is an object that every name bound to it shares, and
//! REMP rewrites that object: every name (in any procedure frame) and
//! every table entry bound to the same list sees the new items. gibi's
//! lists are immutable shared values, so the directive builds the new list
//! and rebinds, everywhere in the store, what was bound to the old one.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::table::Table;
use crate::value::Value;
use std::cell::RefCell;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "REMP",
    signature: "REMP LISTREEL|LISTENTI|LISTMOTS|LISTCHPO ENTIER|LISTENTI FLOTTANT|ENTIER|MOT|CHPOINT|list",
    doc: "Directive: replace item N of the list (or the items of a LISTENTI of places, by one value or by \
          the items of a list of the same length) in place; every name bound to the list sees the change.",
    example: "l = prog 1. 2. 3. ; remp l 2 5. ; remp l (lect 1 3) 0. ;",
    f: remp,
}];

fn remp(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let list = a.right_any().ok_or_else(|| a.missing("LISTREEL, LISTENTI, LISTMOTS or LISTCHPO"))?;
    let n = match &list {
        Value::ListReel(l) => l.len(),
        Value::ListEnti(l) => l.len(),
        Value::ListMots(l) => l.len(),
        Value::ListChpo(l) => l.len(),
        v => {
            return Err(a.err(format!(
                "the object to change must be a LISTREEL, LISTENTI, LISTMOTS or LISTCHPO, found {}",
                v.type_name()
            )))
        }
    };
    let places: Vec<i64> = match a.right_any() {
        Some(Value::Int(i)) => vec![i],
        Some(Value::ListEnti(l)) => l.to_vec(),
        Some(v) => return Err(a.err(format!("the place must be an ENTIER or a LISTENTI, found {}", v.type_name()))),
        None => return Err(a.missing("ENTIER or LISTENTI")),
    };
    let places = places
        .iter()
        .map(|&i| {
            usize::try_from(i)
                .ok()
                .and_then(|i| i.checked_sub(1))
                .filter(|&i| i < n)
                .ok_or_else(|| a.err(format!("place {} is outside 1..{} (the list has {} items)", i, n, n)))
        })
        .collect::<Result<Vec<usize>>>()?;
    let by = a.right_any().ok_or_else(|| a.missing("the new value"))?;
    // A list of new values gives one value per place; anything else is
    // the same value at every place.
    let each = |k: usize| -> Result<Value> {
        let item = match &by {
            Value::ListReel(l) if l.len() == places.len() => Value::Float(l[k]),
            Value::ListEnti(l) if l.len() == places.len() => Value::Int(l[k]),
            Value::ListMots(l) if l.len() == places.len() => Value::mot(&l[k]),
            Value::ListChpo(l) if l.len() == places.len() => Value::Chpo(l[k].clone()),
            Value::ListReel(_) | Value::ListEnti(_) | Value::ListMots(_) | Value::ListChpo(_) => {
                return Err(a.err(format!("the list of new values must have {} items, one per place", places.len())))
            }
            v => v.clone(),
        };
        Ok(item)
    };
    let bad = |v: &Value, want: &str| a.err(format!("a {} item cannot be replaced by a {}", want, v.type_name()));
    // One loop for every list type: `conv` takes a new value or refuses it.
    fn put<T: Clone>(
        l: &[T],
        places: &[usize],
        each: &dyn Fn(usize) -> Result<Value>,
        conv: impl Fn(Value) -> std::result::Result<T, Value>,
        refuse: impl Fn(&Value) -> crate::error::Error,
    ) -> Result<Rc<Vec<T>>> {
        let mut v = l.to_vec();
        for (k, &p) in places.iter().enumerate() {
            v[p] = conv(each(k)?).map_err(|o| refuse(&o))?;
        }
        Ok(Rc::new(v))
    }
    let new = match &list {
        Value::ListReel(l) => Value::ListReel(put(
            l,
            &places,
            &each,
            |o| match o {
                Value::Float(x) if x.is_finite() => Ok(x),
                Value::Int(i) => Ok(i as f64),
                o => Err(o),
            },
            |o| bad(o, "LISTREEL"),
        )?),
        Value::ListEnti(l) => Value::ListEnti(put(
            l,
            &places,
            &each,
            |o| if let Value::Int(i) = o { Ok(i) } else { Err(o) },
            |o| bad(o, "LISTENTI"),
        )?),
        Value::ListMots(l) => Value::ListMots(put(
            l,
            &places,
            &each,
            |o| if let Value::Mot(m) = o { Ok(m.to_string()) } else { Err(o) },
            |o| bad(o, "LISTMOTS"),
        )?),
        Value::ListChpo(l) => Value::ListChpo(put(
            l,
            &places,
            &each,
            |o| if let Value::Chpo(c) = o { Ok(c) } else { Err(o) },
            |o| bad(o, "LISTCHPO"),
        )?),
        o => return Err(a.err(format!("REMP changes a list in place, not a {}", o.type_name()))),
    };
    rebind(it, &list, &new);
    Ok(vec![])
}

/// The same list object (not merely equal items).
fn same(a: &Value, b: &Value) -> bool {
    match (a, b) {
        (Value::ListReel(x), Value::ListReel(y)) => Rc::ptr_eq(x, y),
        (Value::ListEnti(x), Value::ListEnti(y)) => Rc::ptr_eq(x, y),
        (Value::ListMots(x), Value::ListMots(y)) => Rc::ptr_eq(x, y),
        (Value::ListChpo(x), Value::ListChpo(y)) => Rc::ptr_eq(x, y),
        (Value::Evol(x), Value::Evol(y)) => Rc::ptr_eq(x, y),
        _ => false,
    }
}

/// Bind `new` wherever `old` was bound: names of every frame and entries
/// of every table reachable from them (each table visited once: tables
/// may hold themselves).
pub(super) fn rebind(it: &mut Interp, old: &Value, new: &Value) {
    let mut tables: Vec<Rc<RefCell<Table>>> = Vec::new();
    for f in it.store.frames.iter_mut() {
        for v in f.vars.values_mut() {
            if same(v, old) {
                *v = new.clone();
            } else if let Value::Table(t) = v {
                tables.push(t.clone());
            }
        }
    }
    let mut seen: Vec<*const RefCell<Table>> = Vec::new();
    while let Some(t) = tables.pop() {
        if seen.contains(&Rc::as_ptr(&t)) {
            continue;
        }
        seen.push(Rc::as_ptr(&t));
        let Ok(mut tab) = t.try_borrow_mut() else { continue };
        for v in tab.values_mut() {
            if same(v, old) {
                *v = new.clone();
            } else if let Value::Table(s) = v {
                tables.push(s.clone());
            }
        }
    }
}
