//! LIST text for the finite-element objects.

use super::Value;
use crate::eval::Interp;

pub fn describe(_it: &Interp, v: &Value) -> String {
    match v {
        Value::Mesh(m) => {
            let parts: Vec<String> = m.parts.iter().map(|p| format!("{} {}", p.len(), p.ty.name())).collect();
            format!("{} element(s) ({}), {} node(s)", m.n_elements(), parts.join(", "), m.node_list().len())
        }
        Value::Chpo(c) => {
            format!("{} field, components {}, {} value(s)", c.nature.name(), c.components().join(" "), c.len())
        }
        Value::Rigi(r) => format!("{}: {} block(s), {} condition(s)", r.subtype.name(), r.blocks.len(), r.conds.len()),
        other => other.type_name(),
    }
}
