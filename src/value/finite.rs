//! Finding a value that is not a finite number in an object.
//!
//! gibi keeps no infinity and no NaN: a NaN fails every comparison, so a
//! `SI (err > tol)` check would take the "converged" branch. Literals are
//! checked by the parser and binary arithmetic by its own operators; the
//! evaluator runs [`first_non_finite`] on every operator's results as a
//! last net, so that no operator (a reduction such as SOMM, a meshing
//! operator with huge coordinates, a host operator) can hand one on.

use super::{Chpoint, Evolution, Mchaml, Rigidite, Value};

/// The first value of `v` that is not finite, if any. Objects that hold no
/// floating value (words, meshes, models, tables) have none: a table's
/// entries were checked when they were made.
pub fn first_non_finite(v: &Value) -> Option<f64> {
    match v {
        Value::Float(x) => bad(*x),
        Value::ListReel(l) => in_slice(l),
        Value::Chpo(c) => in_chpoint(c),
        Value::ListChpo(l) => l.iter().find_map(|c| in_chpoint(c)),
        Value::Mchaml(m) => in_mchaml(m),
        Value::Evol(e) => in_evolution(e),
        Value::Rigi(r) => in_rigidite(r),
        _ => None,
    }
}

/// The first coordinate (or density) of nodes `from..` that is not finite.
pub fn in_nodes(nodes: &crate::fem::mesh::Nodes, from: usize) -> Option<f64> {
    let coords = nodes.coords.get(from..).unwrap_or(&[]);
    coords.iter().find_map(|x| in_slice(x)).or_else(|| in_slice(nodes.density.get(from..).unwrap_or(&[])))
}

fn bad(x: f64) -> Option<f64> {
    (!x.is_finite()).then_some(x)
}

fn in_slice(l: &[f64]) -> Option<f64> {
    l.iter().copied().find(|x| !x.is_finite())
}

fn in_chpoint(c: &Chpoint) -> Option<f64> {
    c.entries().find_map(|(_, _, x)| bad(x))
}

fn in_mchaml(m: &Mchaml) -> Option<f64> {
    m.zones.iter().find_map(|z| {
        z.constants
            .values()
            .find_map(|x| bad(*x))
            .or_else(|| z.vectors.values().find_map(|v| in_slice(v)))
            .or_else(|| z.values.iter().flatten().find_map(|p| in_slice(p)))
    })
}

fn in_evolution(e: &Evolution) -> Option<f64> {
    e.curves.iter().find_map(|c| in_slice(&c.x).or_else(|| in_slice(&c.y)))
}

fn in_rigidite(r: &Rigidite) -> Option<f64> {
    r.blocks
        .iter()
        .find_map(|b| in_slice(&b.mats))
        .or_else(|| r.conds.iter().flat_map(|c| c.terms.iter().chain(c.dual.iter().flatten())).find_map(|t| bad(t.2)))
}

/// How a value that is not finite is named in an error.
pub fn describe(x: f64) -> &'static str {
    match x {
        x if x.is_nan() => "an undefined value (NaN)",
        x if x > 0.0 => "an overflow (+infinity)",
        _ => "an overflow (-infinity)",
    }
}
