//! BORNER: clamp the values of a list, of curves of an evolution or of
//! components of a field. Only the curves or components named are kept.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::{Chpoint, Evolution, Mchaml, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "BORN",
    signature: "BORN LISTREEL|LISTENTI BOUNDS | BORN EVOLUTIO (ENTIER BOUNDS)... | BORN CHPOINT|MCHAML (MOT BOUNDS)... where BOUNDS is 'MAXIMUM' hi | 'MINIMUM' lo | 'COMPRIS' lo hi",
    doc: "Clamp values: 'MAXIMUM' caps them, 'MINIMUM' floors them, 'COMPRIS' does both (floor first). For an evolution or a field, each curve number or component name takes its own bounds and only those are kept.",
    example: "l2 = born l1 'COMPRIS' 0. 1. ;",
    f: born,
}];

/// (floor, cap) of one clamp.
type Bounds = (Option<f64>, Option<f64>);

fn bounds(a: &mut Args) -> Result<Bounds> {
    Ok(match a.req_keyword(&["MAXIMUM", "MINIMUM", "COMPRIS"])? {
        "MAXIMUM" => (None, Some(a.req_num()?)),
        "MINIMUM" => (Some(a.req_num()?), None),
        _ => (Some(a.req_num()?), Some(a.req_num()?)),
    })
}

fn clamp(x: f64, (lo, hi): Bounds) -> f64 {
    let x = lo.map_or(x, |l| x.max(l));
    hi.map_or(x, |h| x.min(h))
}

fn born(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let obj = a.req::<Value>()?;
    let out = match obj {
        Value::ListReel(l) => {
            let b = bounds(a)?;
            Value::ListReel(Rc::new(l.iter().map(|x| clamp(*x, b)).collect()))
        }
        Value::ListEnti(l) => {
            let b = bounds(a)?;
            // Integer bounds on integers: the clamp stays integral.
            Value::ListEnti(Rc::new(l.iter().map(|x| clamp(*x as f64, b) as i64).collect()))
        }
        Value::Evol(e) => {
            let mut out = Evolution::default();
            while let Some(k) = a.opt::<i64>() {
                let Some(c) = usize::try_from(k).ok().and_then(|k| k.checked_sub(1)).and_then(|k| e.curves.get(k))
                else {
                    return Err(a.err(format!("the evolution has no curve {k} (it has {})", e.curves.len())));
                };
                let b = bounds(a)?;
                let mut c = c.clone();
                c.y.iter_mut().for_each(|y| *y = clamp(*y, b));
                out.curves.push(c);
            }
            if out.curves.is_empty() {
                return Err(a.missing("the number of the curve to bound"));
            }
            Value::Evol(Rc::new(out))
        }
        Value::Chpo(c) => {
            let mut out = Chpoint::new(c.nature);
            for (comp, b) in components(a, &c.components())? {
                for (n, name, x) in c.entries().filter(|(_, name, _)| *name == comp) {
                    out.add(n, name, clamp(x, b), false);
                }
            }
            Value::Chpo(Rc::new(out))
        }
        Value::Mchaml(m) => Value::Mchaml(Rc::new(mchaml(a, &m)?)),
        other => {
            return Err(
                a.err(format!("expected LISTREEL, LISTENTI, EVOLUTIO, CHPOINT or MCHAML, found {}", other.type_name()))
            )
        }
    };
    Ok(vec![out])
}

/// The (component, bounds) pairs of a field, each component checked.
fn components(a: &mut Args, known: &[String]) -> Result<Vec<(String, Bounds)>> {
    let mut out = Vec::new();
    while let Some(w) = a.word_not_operator() {
        if !known.contains(&w) {
            return Err(a.err(format!("the field has no component {w} (it has {})", known.join(" "))));
        }
        let b = bounds(a)?;
        out.push((w, b));
    }
    if out.is_empty() {
        return Err(a.missing("the name of the component to bound"));
    }
    Ok(out)
}

fn mchaml(a: &mut Args, m: &Mchaml) -> Result<Mchaml> {
    let mut known: Vec<String> = Vec::new();
    for z in &m.zones {
        known.extend(
            z.comps.iter().chain(z.constants.keys()).filter(|c| !known.contains(c)).cloned().collect::<Vec<_>>(),
        );
    }
    let wanted = components(a, &known)?;
    let mut out = Mchaml { subtype: m.subtype.clone(), zones: vec![] };
    for z in &m.zones {
        let mut nz = z.clone();
        nz.vectors.clear();
        nz.laws.clear();
        nz.constants = z
            .constants
            .iter()
            .filter_map(|(k, v)| wanted.iter().find(|(c, _)| c == k).map(|(_, b)| (k.clone(), clamp(*v, *b))))
            .collect();
        let keep: Vec<(usize, Bounds)> =
            wanted.iter().filter_map(|(c, b)| z.comps.iter().position(|x| x == c).map(|i| (i, *b))).collect();
        nz.comps = keep.iter().map(|(i, _)| z.comps[*i].clone()).collect();
        nz.values = z
            .values
            .iter()
            .map(|pts| pts.iter().map(|vals| keep.iter().map(|(i, b)| clamp(vals[*i], *b)).collect()).collect())
            .collect();
        out.zones.push(nz);
    }
    Ok(out)
}
