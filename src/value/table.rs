//! TABLE: an associative container with keys of any type and an optional
//! subtype (stored under 'SOUSTYPE', as Cast3M does).

use super::Value;
use std::cell::RefCell;
use std::rc::Rc;

/// A table key. MOT keys ignore trailing blanks (Cast3M pads words);
/// object keys compare by identity.
#[derive(Debug, Clone, PartialEq)]
pub enum Key {
    Int(i64),
    Float(u64),
    Mot(String),
    Bool(bool),
    Point(usize),
    Object(ObjectKey),
}

/// An object used as a key. It is held, not just its address: INDE gives
/// the object back, and a freed address cannot be reused by another object
/// while the key lives.
#[derive(Debug, Clone)]
pub struct ObjectKey(Value);

impl PartialEq for ObjectKey {
    fn eq(&self, other: &Self) -> bool {
        identity(&self.0) == identity(&other.0) && self.0.ty() == other.0.ty()
    }
}

impl Key {
    pub fn from_value(v: &Value) -> Key {
        match v {
            Value::Int(i) => Key::Int(*i),
            Value::Float(f) => Key::Float(f.to_bits()),
            Value::Mot(s) => Key::Mot(s.trim_end().to_string()),
            Value::Bool(b) => Key::Bool(*b),
            Value::Point(p) => Key::Point(*p),
            other => Key::Object(ObjectKey(other.clone())),
        }
    }

    pub fn to_value(&self) -> Value {
        match self {
            Key::Int(i) => Value::Int(*i),
            Key::Float(b) => Value::Float(f64::from_bits(*b)),
            Key::Mot(s) => Value::mot(s),
            Key::Bool(b) => Value::Bool(*b),
            Key::Point(p) => Value::Point(*p),
            Key::Object(o) => o.0.clone(),
        }
    }
}

fn identity(v: &Value) -> usize {
    match v {
        Value::ListReel(r) => Rc::as_ptr(r) as *const u8 as usize,
        Value::ListEnti(r) => Rc::as_ptr(r) as *const u8 as usize,
        Value::ListMots(r) => Rc::as_ptr(r) as *const u8 as usize,
        Value::Table(r) => Rc::as_ptr(r) as *const u8 as usize,
        Value::Proc(r) => Rc::as_ptr(r) as *const u8 as usize,
        Value::Mesh(r) => Rc::as_ptr(r) as *const u8 as usize,
        Value::Chpo(r) => Rc::as_ptr(r) as *const u8 as usize,
        Value::ListChpo(r) => Rc::as_ptr(r) as *const u8 as usize,
        Value::Rigi(r) => Rc::as_ptr(r) as *const u8 as usize,
        Value::Model(r) => Rc::as_ptr(r) as *const u8 as usize,
        Value::Mchaml(r) => Rc::as_ptr(r) as *const u8 as usize,
        Value::Evol(r) => Rc::as_ptr(r) as *const u8 as usize,
        Value::Charge(r) => Rc::as_ptr(r) as *const u8 as usize,
        Value::Nuage(r) => Rc::as_ptr(r) as *const u8 as usize,
        Value::Host(r) => Rc::as_ptr(r) as *const u8 as usize,
        _ => 0,
    }
}

/// Entries keep insertion order, which is what `LIST` shows.
#[derive(Debug, Clone, Default)]
pub struct Table {
    entries: Vec<(Key, Value)>,
}

impl Table {
    pub fn new() -> Self {
        Table::default()
    }
    pub fn with_subtype(sub: &str) -> Self {
        let mut t = Table::new();
        t.set(Key::Mot("SOUSTYPE".into()), Value::mot(sub));
        t
    }
    pub fn get(&self, k: &Key) -> Option<&Value> {
        self.entries.iter().find(|(kk, _)| kk == k).map(|(_, v)| v)
    }
    pub fn set(&mut self, k: Key, v: Value) {
        match self.entries.iter_mut().find(|(kk, _)| *kk == k) {
            Some(e) => e.1 = v,
            None => self.entries.push((k, v)),
        }
    }
    pub fn remove(&mut self, k: &Key) -> Option<Value> {
        let i = self.entries.iter().position(|(kk, _)| kk == k)?;
        Some(self.entries.remove(i).1)
    }
    pub fn len(&self) -> usize {
        self.entries.len()
    }
    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }
    pub fn iter(&self) -> impl Iterator<Item = &(Key, Value)> {
        self.entries.iter()
    }
    /// The values, to replace in place (COPI 'RECU' swaps inner tables
    /// for their copies without looking keys up again).
    pub fn values_mut(&mut self) -> impl Iterator<Item = &mut Value> {
        self.entries.iter_mut().map(|(_, v)| v)
    }
}

/// Dropping a table drops its entries, and the default drop glue would
/// recurse once per nested table: a chain of 100,000 tables
/// (`n . 'X' = t ; t = n ;` in a loop) overflowed the stack when the
/// chain was released. The inner tables this table owns last are taken
/// apart here, one at a time, from an explicit work list.
impl Drop for Table {
    fn drop(&mut self) {
        let mut pending: Vec<Rc<RefCell<Table>>> = Vec::new();
        take_tables(&mut self.entries, &mut pending);
        while let Some(t) = pending.pop() {
            // Shared tables are only released by their last owner.
            if let Ok(cell) = Rc::try_unwrap(t) {
                let mut inner = cell.into_inner();
                take_tables(&mut inner.entries, &mut pending);
                // `inner` drops here, with no table left in it.
            }
        }
    }
}

/// Move the tables held by `entries` (as values or as keys) to `pending`.
fn take_tables(entries: &mut Vec<(Key, Value)>, pending: &mut Vec<Rc<RefCell<Table>>>) {
    for (k, v) in std::mem::take(entries) {
        if let Value::Table(t) = v {
            pending.push(t);
        }
        if let Key::Object(ObjectKey(Value::Table(t))) = k {
            pending.push(t);
        }
    }
}
