//! Table utilities: INDE (the keys, so decks can loop over a table), ENLE
//! of a key, and COPI (a new table with the same entries). The arithmetic
//! of VECTEUR tables is a row of the `+ - * /` table (`arith::table`).

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::{list_value_short, Key, Table, Value};
use std::cell::RefCell;
use std::cmp::Ordering;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "INDE",
        signature: "INDE TABLE",
        doc: "The keys of a table, as a TABLE indexed 1..n: ENTIER keys increasing, then FLOTTANT, then MOT in alphabetical order, then the others as inserted.",
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
];

/// COPI: `T2 = TABL T` aliases, so decks that change a table and keep the
/// original (a table of parameters per load case) copy it with COPI.
fn copi(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let recu = a.keyword(&["RECU"]).is_some();
    let v = a.req::<Value>()?;
    let recu = recu || a.keyword(&["RECU"]).is_some();
    let Value::Table(t) = v else { return Ok(vec![v]) };
    let mut done = Vec::new();
    Ok(vec![Value::Table(copy_table(&t, recu, &mut done))])
}

/// `done` maps every table already copied to its copy, so a table met
/// twice (or holding itself) is copied once and cycles end.
type Copied = Vec<(*const RefCell<Table>, Rc<RefCell<Table>>)>;

fn copy_table(t: &Rc<RefCell<Table>>, recu: bool, done: &mut Copied) -> Rc<RefCell<Table>> {
    if let Some((_, c)) = done.iter().find(|(p, _)| *p == Rc::as_ptr(t)) {
        return c.clone();
    }
    let out = Rc::new(RefCell::new(Table::new()));
    done.push((Rc::as_ptr(t), out.clone()));
    let entries: Vec<(Key, Value)> = t.borrow().iter().map(|(k, v)| (k.clone(), v.clone())).collect();
    for (k, v) in entries {
        let v = match v {
            Value::Table(inner) if recu => Value::Table(copy_table(&inner, recu, done)),
            other => other,
        };
        out.borrow_mut().set(k, v);
    }
    out
}

/// Sort rank of a key's type, then the order within it.
fn rank(k: &Key) -> u8 {
    match k {
        Key::Int(_) => 0,
        Key::Float(_) => 1,
        Key::Mot(_) => 2,
        Key::Bool(_) => 3,
        Key::Point(_) | Key::Object(_) => 4,
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
