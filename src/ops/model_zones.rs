//! EXTR of a model's zones (extr.notice, MMODEL): 'ZONE' gives a table
//! holding, for zone i, the one-zone model at index 2i-1 and its mesh at
//! 2i; 'NBZO' gives the number of zones.

use crate::eval::args::Args;
use crate::value::table::{Key, Table};
use crate::value::{Model, Value};
use std::cell::RefCell;
use std::rc::Rc;

/// The 'ZONE' or 'NBZO' forms, when the next word asks for one.
pub(crate) fn extr_zones(a: &mut Args, m: &Model) -> Option<Value> {
    match a.keyword_next(&["ZONE", "NBZO"])? {
        "ZONE" => {
            let mut t = Table::new();
            for (i, z) in m.zones.iter().enumerate() {
                let k = 2 * i as i64;
                t.set(Key::Int(k + 1), Value::Model(Rc::new(Model { zones: vec![z.clone()], ties: Vec::new() })));
                t.set(Key::Int(k + 2), Value::Mesh(Rc::new(z.mesh.clone())));
            }
            Some(Value::Table(Rc::new(RefCell::new(t))))
        }
        _ => Some(Value::Int(m.zones.len() as i64)),
    }
}
