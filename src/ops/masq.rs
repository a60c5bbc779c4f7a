//! MASQ (MASQUE): where a field meets a comparison, as a field of 1. and
//! 0. on the same support, or with 'SOMM' the number of values that meet
//! it (the sum of that mask, a FLOTTANT like SOMT's).

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::{Chpoint, Mchaml, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "MASQ",
    signature: "MASQ CHPOINT|MCHAML|LISTREEL 'SUPERIEUR'|'EGSUPE'|'EGAL'|'EGINFE'|'INFERIEUR'|'DIFFERENT' FLOTTANT|(same type) ('SOMM')",
    doc: "A mask: 1. where each value meets the comparison with the number (or the value of the second object at the same place), else 0.; with 'SOMM' the number of values that meet it.",
    example: "m = masq sig 'SUPERIEUR' 100. ;",
    f: masq,
}];

const TESTS: &[&str] = &["SUPERIEUR", "EGSUPE", "EGAL", "EGINFE", "INFERIEUR", "DIFFERENT"];

fn meets(test: &str, x: f64, y: f64) -> bool {
    match test {
        "SUPERIEUR" => x > y,
        "EGSUPE" => x >= y,
        "EGAL" => x == y,
        "EGINFE" => x <= y,
        "INFERIEUR" => x < y,
        _ => x != y,
    }
}

fn mask(test: &str, x: f64, y: f64) -> f64 {
    if meets(test, x, y) {
        1.0
    } else {
        0.0
    }
}

enum Obj {
    Chpo(Rc<Chpoint>),
    Mchaml(Rc<Mchaml>),
    List(Rc<Vec<f64>>),
}

fn masq(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let obj = a
        .opt_with(|v| match v {
            Value::Chpo(c) => Some(Obj::Chpo(c.clone())),
            Value::Mchaml(m) => Some(Obj::Mchaml(m.clone())),
            Value::ListReel(l) => Some(Obj::List(l.clone())),
            _ => None,
        })
        .ok_or_else(|| a.missing("CHPOINT, MCHAML or LISTREEL"))?;
    let test = a.req_keyword(TESTS)?;
    let level = a.opt_num();
    let out = match obj {
        Obj::Chpo(c) => {
            let other = match level {
                Some(_) => None,
                None => Some(a.req::<Rc<Chpoint>>()?),
            };
            chpo_mask(a, test, &c, level, other.as_deref())?
        }
        Obj::Mchaml(m) => {
            let other = match level {
                Some(_) => None,
                None => Some(a.req::<Rc<Mchaml>>()?),
            };
            mchaml_mask(a, test, &m, level, other.as_deref())?
        }
        Obj::List(l) => {
            let other = match level {
                Some(_) => None,
                None => Some(a.req::<Rc<Vec<f64>>>()?),
            };
            if let Some(o) = &other {
                if o.len() != l.len() {
                    return Err(a.err(format!("the lists have {} and {} values", l.len(), o.len())));
                }
            }
            let y = |i: usize| level.unwrap_or_else(|| other.as_ref().map_or(0.0, |o| o[i]));
            Value::ListReel(Rc::new(l.iter().enumerate().map(|(i, x)| mask(test, *x, y(i))).collect()))
        }
    };
    if a.keyword(&["SOMM"]).is_some() {
        return Ok(vec![Value::Float(total(&out))]);
    }
    Ok(vec![out])
}

/// The number of 1. in a mask.
fn total(v: &Value) -> f64 {
    match v {
        Value::Chpo(c) => c.entries().map(|(_, _, x)| x).sum(),
        Value::Mchaml(m) => m.zones.iter().flat_map(|z| z.values.iter().flatten().flatten()).sum(),
        Value::ListReel(l) => l.iter().sum(),
        _ => 0.0,
    }
}

/// Against a number, or against a second field at the same node and
/// component. Two fields of one component each are compared whatever
/// their names; otherwise components pair by name, and a value the second
/// field lacks reads as 0 (a field is zero where it is not defined).
fn chpo_mask(a: &Args, test: &str, c: &Chpoint, level: Option<f64>, other: Option<&Chpoint>) -> Result<Value> {
    let pair_single = match other {
        Some(o) => {
            let (h1, h2) = (c.components(), o.components());
            match (h1.as_slice(), h2.as_slice()) {
                ([x], [y]) => Some((x.clone(), y.clone())),
                _ if h2.iter().any(|n| h1.contains(n)) => None,
                _ => {
                    return Err(a.err(format!(
                        "the fields have no component in common ({} and {})",
                        h1.join(" "),
                        h2.join(" ")
                    )))
                }
            }
        }
        None => None,
    };
    let mut out = Chpoint::new(c.nature);
    for (n, comp, x) in c.entries() {
        let y = match (level, other) {
            (Some(v), _) => v,
            (None, Some(o)) => {
                let name = pair_single.as_ref().map_or(comp, |(_, y)| y.as_str());
                o.get(n, name).unwrap_or(0.0)
            }
            (None, None) => 0.0,
        };
        out.add(n, comp, mask(test, x, y), false);
    }
    Ok(Value::Chpo(Rc::new(out)))
}

/// Point by point; against a second field, its zones must match the
/// first's (same elements and points) and components pair by name.
fn mchaml_mask(a: &Args, test: &str, m: &Mchaml, level: Option<f64>, other: Option<&Mchaml>) -> Result<Value> {
    if let Some(o) = other {
        if o.zones.len() != m.zones.len() {
            return Err(a.err(format!("the fields have {} and {} zones", m.zones.len(), o.zones.len())));
        }
    }
    let mut out = Mchaml { subtype: m.subtype.clone(), zones: vec![] };
    for (k, z) in m.zones.iter().enumerate() {
        let oz = other.map(|o| &o.zones[k]);
        let idx: Vec<Option<usize>> = match oz {
            Some(oz) => {
                let shape = |z: &crate::value::model::MchamlZone| z.values.iter().map(Vec::len).collect::<Vec<_>>();
                if oz.mesh.parts != z.mesh.parts || shape(oz) != shape(z) {
                    return Err(
                        a.err(format!("zone {} of the two fields is not on the same elements and points", k + 1))
                    );
                }
                z.comps.iter().map(|c| oz.comps.iter().position(|x| x == c)).collect()
            }
            None => vec![None; z.comps.len()],
        };
        let mut nz = z.clone();
        nz.constants.clear();
        nz.vectors.clear();
        for (e, pts) in nz.values.iter_mut().enumerate() {
            for (p, vals) in pts.iter_mut().enumerate() {
                for (i, x) in vals.iter_mut().enumerate() {
                    let y = match (level, oz, idx[i]) {
                        (Some(v), _, _) => v,
                        (None, Some(oz), Some(j)) => oz.values[e][p][j],
                        _ => 0.0,
                    };
                    *x = mask(test, *x, y);
                }
            }
        }
        out.zones.push(nz);
    }
    Ok(Value::Mchaml(Rc::new(out)))
}
