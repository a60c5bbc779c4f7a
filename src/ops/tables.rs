//! Table utilities: INDE (the keys, so decks can loop over a table), ENLE
//! of a key, OTER (the same, in place), and COPI (a new table with the same entries). The arithmetic
//! of VECTEUR tables is a row of the `+ - * /` table (`arith::table`).

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::{list_value_short, Key, Table, Value};
use rustc_hash::FxHashMap;
use std::cell::RefCell;
use std::cmp::Ordering;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "INDE",
        signature: "INDE TABLE",
        doc: "The keys of a table, as a TABLE indexed 1..n: ENTIER keys increasing, then FLOTTANT, then objects as inserted, then MOT in alphabetical order.",
        example: "ind = inde t ; repeter b (dime ind) ; mess (t . (ind . &b)) ; fin b ;",
        f: inde,
    },
    OpDef {
        name: "COPI",
        signature: "COPI TABLE ('RECU') | COPI OBJ",
        doc: "A new table holding the same entries (TABL T would only name the same table again); with 'RECU' the tables it holds are copied too. Other objects never change in place, so their copy is the object itself.",
        example: "t2 = copi t ; t2 . 'X' = 1 ;",
        f: copi,
    },
    OpDef {
        name: "OTER",
        signature: "OTER TABLE KEY",
        doc: "Remove the entry KEY from the table, in place (nothing to do when it has none).",
        example: "t = tabl ; t . 'A' = 1 ; oter t 'A' ;",
        f: oter,
    },
];

/// OTER: the table itself changes, as OUBL TABLE KEY does.
fn oter(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let t = a.req::<Rc<RefCell<Table>>>()?;
    let k = a.req::<Value>()?;
    t.borrow_mut().remove(&Key::from_value(&k));
    Ok(vec![])
}

/// COPI: `T2 = TABL T` aliases, so decks that change a table and keep the
/// original (a table of parameters per load case) copy it with COPI.
fn copi(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let recu = a.keyword(&["RECU"]).is_some();
    let v = a.req::<Value>()?;
    let recu = recu || a.keyword(&["RECU"]).is_some();
    let Value::Table(t) = v else { return Ok(vec![v]) };
    Ok(vec![Value::Table(copy_table(&t, recu))])
}

/// The copy of `root`; with `recu`, every table it reaches is copied once
/// (a table met twice, or holding itself, maps to the same copy, so
/// cycles end). The tables still to fill are kept on an explicit list, not
/// the Rust stack: a chain of 100,000 nested tables copies like a flat one.
fn copy_table(root: &Rc<RefCell<Table>>, recu: bool) -> Rc<RefCell<Table>> {
    let copy = Rc::new(RefCell::new(root.borrow().clone()));
    if !recu {
        return copy;
    }
    let mut done: FxHashMap<*const RefCell<Table>, Rc<RefCell<Table>>> = FxHashMap::default();
    done.insert(Rc::as_ptr(root), copy.clone());
    let mut to_fill = vec![copy.clone()];
    while let Some(t) = to_fill.pop() {
        for v in t.borrow_mut().values_mut() {
            let Value::Table(inner) = v else { continue };
            let c = done.entry(Rc::as_ptr(inner)).or_insert_with(|| {
                let c = Rc::new(RefCell::new(inner.borrow().clone()));
                to_fill.push(c.clone());
                c
            });
            *v = Value::Table(c.clone());
        }
    }
    copy
}

/// Sort rank of a key's type, then the order within it.
fn rank(k: &Key) -> u8 {
    match k {
        Key::Int(_) => 0,
        Key::Float(_) => 1,
        // Objects before words: G_CALCUL loops over a table keyed by the
        // crack-front points then 'GLOBAL', and takes the last key as it.
        Key::Point(_) | Key::Object(_) => 2,
        Key::Mot(_) => 3,
        Key::Bool(_) => 4,
    }
}

fn key_order(p: &Key, q: &Key) -> Ordering {
    match (p, q) {
        (Key::Int(i), Key::Int(j)) => i.cmp(j),
        (Key::Float(x), Key::Float(y)) => f64::from_bits(*x).total_cmp(&f64::from_bits(*y)),
        (Key::Mot(s), Key::Mot(t)) => s.cmp(t),
        (Key::Bool(b), Key::Bool(c)) => b.cmp(c),
        _ => rank(p).cmp(&rank(q)),
    }
}

fn inde(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let t = a.req::<Rc<RefCell<Table>>>()?;
    let mut keys: Vec<Key> = t.borrow().iter().map(|(k, _)| k.clone()).collect();
    // A stable sort: objects and points keep their insertion order.
    keys.sort_by(key_order);
    let mut out = Table::new();
    for (i, k) in keys.iter().enumerate() {
        out.set(Key::Int(i as i64 + 1), k.to_value());
    }
    Ok(vec![Value::Table(Rc::new(RefCell::new(out)))])
}

/// `ENLE TABLE KEY`: a copy of the table without that key (OUBL removes
/// it in place).
pub(crate) fn enle(a: &mut Args, t: &RefCell<Table>) -> Result<Vec<Value>> {
    let k = a.right_any().ok_or_else(|| a.missing("a key"))?;
    let key = Key::from_value(&k);
    let mut copy = t.borrow().clone();
    if copy.remove(&key).is_none() {
        return Err(a.err(format!("the TABLE has no entry {}", list_value_short(&k))));
    }
    Ok(vec![Value::Table(Rc::new(RefCell::new(copy)))])
}
