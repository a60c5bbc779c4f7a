//! Value-by-value arithmetic on containers: a scalar function applied to
//! every value of a list, a node field, an element field or the ordinates
//! of a curve (SIN, EXP, ABS, … and `MCHAML * 2.`). Node fields keep their
//! own algebra in fields.rs; curves and element fields get theirs here.

use super::arith::{float_op, Bin};
use crate::value::model::{Curve, MchamlZone};
use crate::value::{Evolution, Mchaml, Value};
use std::cell::Cell;
use std::rc::Rc;

/// `f` applied to every value of `v`; None when `v` holds no numbers.
/// ENTIER inputs give FLOTTANT results (a LISTENTI gives a LISTREEL).
pub(crate) fn map(v: &Value, f: &dyn Fn(f64) -> f64) -> Option<Value> {
    Some(match v {
        Value::Int(i) => Value::Float(f(*i as f64)),
        Value::Float(x) => Value::Float(f(*x)),
        Value::ListReel(l) => Value::ListReel(Rc::new(l.iter().map(|x| f(*x)).collect())),
        Value::ListEnti(l) => Value::ListReel(Rc::new(l.iter().map(|i| f(*i as f64)).collect())),
        Value::Chpo(c) => Value::Chpo(Rc::new(c.map(f))),
        Value::Mchaml(m) => Value::Mchaml(Rc::new(map_mchaml(m, f))),
        Value::Evol(e) => Value::Evol(Rc::new(map_evol(e, f))),
        _ => return None,
    })
}

/// Like [`map`], but the first input for which `f` gives NaN is returned
/// as an error value: a NaN would pass every `SI (err > tol)` check.
pub(crate) fn map_checked(v: &Value, f: &dyn Fn(f64) -> f64) -> Option<Result<Value, f64>> {
    let bad = Cell::new(None);
    let g = |x: f64| {
        let y = f(x);
        if y.is_nan() && !x.is_nan() && bad.get().is_none() {
            bad.set(Some(x));
        }
        y
    };
    let r = map(v, &g)?;
    Some(match bad.get() {
        Some(x) => Err(x),
        None => Ok(r),
    })
}

fn map_mchaml(m: &Mchaml, f: &dyn Fn(f64) -> f64) -> Mchaml {
    let mut out = m.clone();
    for z in out.zones.iter_mut() {
        for v in z.constants.values_mut() {
            *v = f(*v);
        }
        for v in z.values.iter_mut().flatten().flatten() {
            *v = f(*v);
        }
    }
    out
}

/// Functions of a curve act on its ordinates.
fn map_evol(e: &Evolution, f: &dyn Fn(f64) -> f64) -> Evolution {
    let mut out = e.clone();
    for c in out.curves.iter_mut() {
        for y in c.y.iter_mut() {
            *y = f(*y);
        }
    }
    out
}

/// `+ - * / **` with an EVOLUTIO or an MCHAML on either side. None when
/// neither operand is one; an error message when they do not match.
pub(crate) fn binary(op: Bin, x: &Value, y: &Value) -> Option<Result<Value, String>> {
    use Value::*;
    let scalar = |v: &Value| v.as_f64();
    Some(Ok(match (x, y) {
        (Evol(_) | Mchaml(_), Int(_) | Float(_)) => {
            let s = scalar(y)?;
            map(x, &|p| float_op(op, p, s))?
        }
        (Int(_) | Float(_), Evol(_) | Mchaml(_)) => {
            let s = scalar(x)?;
            map(y, &|q| float_op(op, s, q))?
        }
        (Evol(a), Evol(b)) => match evol_pair(op, a, b) {
            Ok(e) => Evol(Rc::new(e)),
            Err(m) => return Some(Err(m)),
        },
        (Mchaml(a), Mchaml(b)) => match mchaml_pair(op, a, b) {
            Ok(m) => Mchaml(Rc::new(m)),
            Err(m) => return Some(Err(m)),
        },
        _ => return None,
    }))
}

/// Two curves combine point by point: same number of curves, same
/// abscissae (a curve is a function sampled at its abscissae; adding two
/// samplings of different points would need an interpolation the deck
/// did not ask for).
fn evol_pair(op: Bin, a: &Evolution, b: &Evolution) -> Result<Evolution, String> {
    if a.curves.len() != b.curves.len() {
        return Err(format!("the curves do not match: {} curve(s) and {}", a.curves.len(), b.curves.len()));
    }
    let mut out = a.clone();
    for (k, (c, d)) in out.curves.iter_mut().zip(&b.curves).enumerate() {
        if !same_abscissae(c, d) {
            return Err(format!("curve {} of each side does not have the same abscissae", k + 1));
        }
        for (p, q) in c.y.iter_mut().zip(&d.y) {
            *p = float_op(op, *p, *q);
        }
    }
    Ok(out)
}

fn same_abscissae(c: &Curve, d: &Curve) -> bool {
    let scale = c.x.iter().chain(&d.x).fold(0.0f64, |m, x| m.max(x.abs())).max(1e-300);
    c.x.len() == d.x.len() && c.x.iter().zip(&d.x).all(|(p, q)| (p - q).abs() <= 1e-12 * scale)
}

/// Two element fields combine value by value when they have the same
/// layout (zones, elements, points, components), as fields made on one
/// model do.
fn mchaml_pair(op: Bin, a: &Mchaml, b: &Mchaml) -> Result<Mchaml, String> {
    let shape = |z: &MchamlZone| {
        (
            z.comps.clone(),
            z.values.iter().map(|e| e.len()).collect::<Vec<_>>(),
            z.constants.keys().cloned().collect::<Vec<_>>(),
        )
    };
    if a.zones.len() != b.zones.len() || a.zones.iter().zip(&b.zones).any(|(p, q)| shape(p) != shape(q)) {
        return Err("the element fields do not have the same zones, elements and components".into());
    }
    let mut out = a.clone();
    for (z, w) in out.zones.iter_mut().zip(&b.zones) {
        for (k, v) in z.constants.iter_mut() {
            *v = float_op(op, *v, w.constants[k]);
        }
        for (p, q) in z.values.iter_mut().flatten().flatten().zip(w.values.iter().flatten().flatten()) {
            *p = float_op(op, *p, *q);
        }
    }
    Ok(out)
}

/// Whether every value of `v` is finite (objects without numbers are).
pub(crate) fn finite(v: &Value) -> bool {
    let ok = |x: &f64| x.is_finite();
    match v {
        Value::Float(x) => x.is_finite(),
        Value::ListReel(l) => l.iter().all(ok),
        Value::Chpo(c) => c.entries().all(|(_, _, x)| x.is_finite()),
        Value::Mchaml(m) => {
            m.zones.iter().all(|z| z.constants.values().all(ok) && z.values.iter().flatten().flatten().all(ok))
        }
        Value::Evol(e) => e.curves.iter().all(|c| c.x.iter().chain(&c.y).all(ok)),
        _ => true,
    }
}

/// A number as messages show it; other operands by their type.
pub(crate) fn describe(v: &Value) -> String {
    match v {
        Value::Int(i) => i.to_string(),
        Value::Float(x) => crate::value::fmt_float(*x),
        other => {
            let t = other.type_name();
            format!("{} {}", if t.starts_with(['A', 'E', 'I', 'O', 'U']) { "an" } else { "a" }, t)
        }
    }
}
