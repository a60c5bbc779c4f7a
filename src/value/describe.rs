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
        Value::Rigi(r) => rigidity(r),
        other => other.type_name(),
    }
}

/// Blocks in one line each; conditions row by row (the LX node, the terms,
/// the kind), as Cast3M's LIST shows its multiplier elements.
fn rigidity(r: &crate::value::Rigidite) -> String {
    use crate::solve::Kind;
    let mut s = format!("{}: {} block(s), {} condition(s)", r.subtype.name(), r.blocks.len(), r.conds.len());
    for (i, b) in r.blocks.iter().enumerate() {
        let comps: Vec<&str> = b.dofs.iter().map(|(_, c)| c.as_str()).collect();
        s.push_str(&format!(
            "\n  block {}: {} element(s) of {} node(s), unknowns {}",
            i + 1,
            b.n_elem(),
            b.nodes_per_elem,
            comps.join(" ")
        ));
    }
    for (i, c) in r.conds.iter().enumerate().take(50) {
        let kind = match c.kind {
            Kind::Equal => "=",
            Kind::Mini => ">= (MINI)",
            Kind::Maxi => "<= (MAXI)",
        };
        let terms: Vec<String> =
            c.terms.iter().map(|(n, comp, k)| format!("{} {}(node {})", super::fmt_float(*k), comp, n + 1)).collect();
        s.push_str(&format!(
            "\n  condition {} (LX on node {}): {} {} d",
            i + 1,
            c.mult_node + 1,
            terms.join(" + "),
            kind
        ));
    }
    if r.conds.len() > 50 {
        s.push_str(&format!("\n  … {} conditions in all", r.conds.len()));
    }
    s
}
