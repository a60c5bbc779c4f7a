//! Deterministic text for MESS and LIST: floats always in one fixed
//! format, so transcripts can be snapshotted.

use super::{Table, Value};
use crate::fem::mesh::Nodes;

/// Cast3M's 1PE12.5 layout without padding: `1.23457E+02`.
pub fn fmt_float(x: f64) -> String {
    if !x.is_finite() {
        return format!("{}", x);
    }
    // No "-0.00000E+00": a reaction of an inactive condition is just 0.
    let x = if x == 0.0 { 0.0 } else { x };
    let s = format!("{:.5E}", x);
    match s.split_once('E') {
        Some((m, e)) => {
            let e: i32 = e.parse().unwrap_or(0);
            format!("{}E{}{:02}", m, if e < 0 { '-' } else { '+' }, e.abs())
        }
        None => s,
    }
}

/// A short rendering of a value (for keys and messages).
pub fn list_value_short(v: &Value) -> String {
    match v {
        Value::Int(i) => i.to_string(),
        Value::Float(f) => fmt_float(*f),
        Value::Mot(s) => format!("'{}'", s),
        Value::Bool(b) => (if *b { "VRAI" } else { "FAUX" }).into(),
        other => format!("<{}>", other.type_name()),
    }
}

fn floats(l: &[f64]) -> String {
    l.iter().map(|x| fmt_float(*x)).collect::<Vec<_>>().join(" ")
}

/// What LIST prints for one object (a POINT by its coordinates in the
/// node table, the first `dime` of them).
pub fn list_value(nodes: &Nodes, dime: usize, name: Option<&str>, v: &Value) -> String {
    let head = match name {
        Some(n) => format!("{} ({})", n, v.type_name()),
        None => v.type_name(),
    };
    let body = match v {
        Value::Int(_) | Value::Float(_) | Value::Mot(_) | Value::Bool(_) => list_value_short(v),
        Value::Point(p) => {
            let x = nodes.get(*p);
            let d = dime.max(1);
            format!("node {}: {}", p + 1, floats(&x[..d]))
        }
        Value::ListReel(l) => format!("{} value(s): {}", l.len(), floats(l)),
        Value::ListEnti(l) => {
            format!("{} value(s): {}", l.len(), l.iter().map(|i| i.to_string()).collect::<Vec<_>>().join(" "))
        }
        Value::ListMots(l) => format!("{} word(s): {}", l.len(), l.join(" ")),
        Value::Table(t) => table(&t.borrow()),
        Value::Proc(p) => format!("procedure {} ({} parameter(s))", p.name, p.params.len()),
        Value::Bloc(n) => format!("block {}", n),
        Value::Host(h) => h.describe(),
        other => super::describe::describe(other),
    };
    format!("{}: {}", head, body)
}

fn table(t: &Table) -> String {
    let mut s = format!("{} entr{}", t.len(), if t.len() == 1 { "y" } else { "ies" });
    for (k, v) in t.iter() {
        s.push_str(&format!("\n  {} -> {}", list_value_short(&k.to_value()), list_value_short(v)));
    }
    s
}
