//! LIST text for the finite-element objects.

use super::{fmt_float, Value};

/// At most this many lines of values per object, so LIST of a big field
/// stays readable.
const MAX_LINES: usize = 20;

pub fn describe(v: &Value) -> String {
    match v {
        Value::Mesh(m) => {
            let parts: Vec<String> = m
                .parts
                .iter()
                .map(|p| match p.colour.is_default() {
                    true => format!("{} {}", p.len(), p.ty.name()),
                    false => format!("{} {} {}", p.len(), p.ty.name(), p.colour.name()),
                })
                .collect();
            format!("{} element(s) ({}), {} node(s)", m.n_elements(), parts.join(", "), m.node_list().len())
        }
        Value::Chpo(c) => chpoint(c),
        Value::ListChpo(l) => {
            // Each field as CHPOINT's LIST shows it, indented under its rank.
            let mut s = format!("{} field(s)", l.len());
            for (i, c) in l.iter().enumerate() {
                if i == MAX_LINES {
                    s.push_str(&format!("\n  ... ({} more field(s))", l.len() - MAX_LINES));
                    break;
                }
                s.push_str(&format!("\n  field {}: {}", i + 1, chpoint(c).replace('\n', "\n  ")));
            }
            s
        }
        Value::Rigi(r) => rigidity(r),
        Value::Model(m) => {
            let mut s = format!("{} zone(s)", m.zones.len());
            for (i, z) in m.zones.iter().enumerate() {
                s.push_str(&format!(
                    "\n  zone {}: {} {} {}, {} element(s), mode {}",
                    i + 1,
                    z.formulation,
                    z.behaviour.join(" "),
                    z.element,
                    z.mesh.n_elements(),
                    z.mode
                ));
            }
            s
        }
        Value::Mchaml(m) => {
            let mut s = format!("{}, {} zone(s)", m.subtype, m.zones.len());
            for (i, z) in m.zones.iter().enumerate() {
                s.push_str(&format!("\n  zone {} ({}, {} element(s))", i + 1, z.element, z.mesh.n_elements()));
                for (k, v) in &z.constants {
                    s.push_str(&format!(" {} {}", k, fmt_float(*v)));
                }
                for (k, v) in &z.vectors {
                    s.push_str(&format!(" {} ({} {} {})", k, fmt_float(v[0]), fmt_float(v[1]), fmt_float(v[2])));
                }
                for (k, c) in &z.laws {
                    s.push_str(&format!(" {} EVOLUTIO of {} ({} points)", k, c.x_name, c.x.len()));
                }
                let mut lines = 0;
                if !z.comps.is_empty() {
                    s.push_str(&format!(
                        "\n    elem point{}",
                        z.comps.iter().map(|c| format!(" {:>12}", c)).collect::<String>()
                    ));
                }
                'all: for (e, pts) in z.values.iter().enumerate() {
                    for (p, vals) in pts.iter().enumerate() {
                        if lines == MAX_LINES {
                            s.push_str("\n    ...");
                            break 'all;
                        }
                        lines += 1;
                        let vals: String = vals.iter().map(|x| format!(" {:>12}", fmt_float(*x))).collect();
                        s.push_str(&format!("\n    {:>4} {:>5}{}", e + 1, p + 1, vals));
                    }
                }
            }
            s
        }
        Value::Evol(e) => {
            let mut s = format!("{} curve(s)", e.curves.len());
            for (i, c) in e.curves.iter().enumerate() {
                s.push_str(&format!("\n  curve {}", i + 1));
                if !c.legend.is_empty() {
                    s.push_str(&format!(" '{}'", c.legend));
                }
                let or = |n: &str, d: &'static str| if n.is_empty() { d.to_string() } else { n.to_string() };
                s.push_str(&format!(": {} point(s), {} against {}", c.x.len(), or(&c.y_name, "Y"), or(&c.x_name, "X")));
                for (k, (x, y)) in c.x.iter().zip(&c.y).enumerate() {
                    if k == MAX_LINES {
                        s.push_str("\n    ...");
                        break;
                    }
                    s.push_str(&format!("\n    {:>12} {:>12}", fmt_float(*x), fmt_float(*y)));
                }
            }
            s
        }
        Value::Charge(c) => chargement(c),
        Value::Nuage(n) => {
            let mut s = format!("{} tuple(s) of {} component(s)", n.len(), n.comps.len());
            for (name, col) in &n.comps {
                let ty = col.first().map_or("FLOTTANT".to_string(), Value::type_name);
                s.push_str(&format!("\n  {} ({}):", name, ty));
                for v in col.iter().take(MAX_LINES) {
                    s.push_str(&format!(" {}", v.as_f64().map_or_else(|| v.type_name(), fmt_float)));
                }
                if col.len() > MAX_LINES {
                    s.push_str(" ...");
                }
            }
            s
        }
        other => other.type_name(),
    }
}

/// One line per elementary load: its name, what it is in space and its
/// time function (or the times of the table form).
fn chargement(c: &crate::value::Chargement) -> String {
    use crate::value::chargement::Timing;
    let mut s = format!("{} load(s)", c.parts.len());
    for (i, p) in c.parts.iter().enumerate() {
        let name = if p.name.is_empty() { "(no name)".to_string() } else { format!("'{}'", p.name) };
        match &p.time {
            Timing::Scaled { field, function } => {
                let t = function.times();
                s.push_str(&format!(
                    "\n  load {} {}: {} times a time function of {} point(s) from {} to {}",
                    i + 1,
                    name,
                    field.type_name(),
                    t.len(),
                    fmt_float(t[0]),
                    fmt_float(t[t.len() - 1])
                ));
                let first = describe(field);
                s.push_str(&format!("\n    {}", first.replace('\n', "\n    ")));
            }
            Timing::Table(steps) => s.push_str(&format!(
                "\n  load {} {}: {} field(s) at times {}",
                i + 1,
                name,
                steps.len(),
                steps.iter().map(|(t, _)| fmt_float(*t)).collect::<Vec<_>>().join(" ")
            )),
        }
    }
    s
}

/// Nature, components, then one line per node (at most MAX_LINES).
fn chpoint(c: &crate::value::Chpoint) -> String {
    let comps = c.components();
    let mut s = format!("{} field, components {}, {} value(s)", c.nature.name(), comps.join(" "), c.len());
    s.push_str(&format!("\n  node {}", comps.iter().map(|c| format!(" {:>12}", c)).collect::<String>()));
    for (k, n) in c.nodes.iter().enumerate() {
        if k == MAX_LINES {
            s.push_str(&format!("\n  ... ({} more node(s))", c.nodes.len() - MAX_LINES));
            break;
        }
        let vals: String = comps
            .iter()
            .map(|comp| c.get(*n, comp).map_or(format!(" {:>12}", "-"), |x| format!(" {:>12}", fmt_float(x))))
            .collect();
        s.push_str(&format!("\n  {:>4}{}", n + 1, vals));
    }
    s
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
        let show = |t: &[(usize, String, f64)]| -> String {
            t.iter()
                .map(|(n, comp, k)| format!("{} {}(node {})", super::fmt_float(*k), comp, n + 1))
                .collect::<Vec<_>>()
                .join(" + ")
        };
        s.push_str(&format!("\n  condition {} (LX on node {}): {} {} d", i + 1, c.mult_node + 1, show(&c.terms), kind));
        if let Some(d) = &c.dual {
            s.push_str(&format!(", reaction along {}", show(d)));
        }
    }
    if r.conds.len() > 50 {
        s.push_str(&format!("\n  … {} conditions in all", r.conds.len()));
    }
    s
}
