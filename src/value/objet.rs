//! OBJET: a table whose entries are reached only through its methods
//! (obje.notice). It carries its class (the constructor's name), its
//! entries and its methods: names bound to procedures made by DEBMETH.
//! The evaluator (eval/objet.rs) runs the methods; this is only the data.

use super::table::{Key, Table};
use super::{HostObject, Value};
use crate::syntax::ast::ProcDef;
use std::any::Any;
use std::cell::RefCell;
use std::collections::BTreeMap;
use std::rc::Rc;

#[derive(Debug)]
pub struct Objet {
    pub class: String,
    pub entries: RefCell<Table>,
    pub methods: RefCell<BTreeMap<String, Rc<ProcDef>>>,
}

impl Objet {
    pub fn new(class: &str) -> Self {
        Objet { class: class.to_string(), entries: RefCell::new(Table::new()), methods: RefCell::default() }
    }

    /// The OBJET a value holds, if it is one.
    pub fn of(v: &Value) -> Option<&Objet> {
        match v {
            Value::Host(h) => h.as_any().downcast_ref::<Objet>(),
            _ => None,
        }
    }

    pub fn entry(&self, name: &str) -> Option<Value> {
        self.entries.borrow().get(&Key::Mot(name.to_string())).cloned()
    }

    pub fn set_entry(&self, name: &str, v: Value) {
        self.entries.borrow_mut().set(Key::Mot(name.to_string()), v);
    }

    pub fn method(&self, name: &str) -> Option<Rc<ProcDef>> {
        self.methods.borrow().get(name).cloned()
    }

    pub fn set_method(&self, name: &str, p: Rc<ProcDef>) {
        self.methods.borrow_mut().insert(name.to_string(), p);
    }

    /// HERITE: take the methods of `other` that this object lacks (a
    /// method of its own keeps precedence, as a subclass's would).
    pub fn inherit(&self, other: &Objet) {
        let theirs = other.methods.borrow().clone();
        let mut mine = self.methods.borrow_mut();
        for (k, p) in theirs {
            mine.entry(k).or_insert(p);
        }
    }

    pub fn method_names(&self) -> Vec<String> {
        self.methods.borrow().keys().cloned().collect()
    }
}

impl HostObject for Objet {
    fn type_name(&self) -> &str {
        "OBJET"
    }

    fn describe(&self) -> String {
        let mut s = format!("OBJET of class {}\n", self.class);
        let methods = self.methods.borrow();
        s.push_str(&format!("  methods ({}):", methods.len()));
        for (name, p) in methods.iter() {
            s.push_str(&format!(" {}={}", name, p.name));
        }
        let entries = self.entries.borrow();
        s.push_str(&format!("\n  entries ({}):", entries.len()));
        for (k, v) in entries.iter() {
            s.push_str(&format!("\n    {} : {}", super::list_value_short(&k.to_value()), super::list_value_short(v)));
        }
        s
    }

    fn as_any(&self) -> &dyn Any {
        self
    }
}
