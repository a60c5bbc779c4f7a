//! A scalar function applied to every value of a list, a node field, an
//! element field or the ordinates of a curve (SIN, EXP, ABS, IPOL …).

use crate::value::Value;
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
        Value::Mchaml(m) => Value::Mchaml(Rc::new(m.map(f))),
        Value::Evol(e) => Value::Evol(Rc::new(e.map(f))),
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
