//! `+ - * / **`, comparisons and logic. Infix operators take the newest
//! pushed operand on their left, else read two operands on their right
//! (`'-' 10 4`), so `1 + 2 * 3` is 9: there is no precedence.

use super::{pointwise, Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::Value;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "+",
        signature: "OBJ1 + OBJ2",
        doc: "Sum: numbers, lists element-wise, points, fields, rigidities.",
        example: "x = 1 + 2 ;",
        f: plus,
    },
    OpDef {
        name: "-",
        signature: "OBJ1 - OBJ2",
        doc: "Difference: numbers, lists element-wise, points, fields, rigidities.",
        example: "x = 5 - 2 ;",
        f: minus,
    },
    OpDef {
        name: "*",
        signature: "OBJ1 * OBJ2",
        doc: "Product: numbers, lists element-wise, scaling; RIGIDITE * CHPOINT is the matrix-vector product.",
        example: "x = 2 * 3. ;",
        f: times,
    },
    OpDef {
        name: "/",
        signature: "OBJ1 / OBJ2",
        doc: "Quotient; ENTIER / ENTIER truncates.",
        example: "x = 7 / 2 ;",
        f: divide,
    },
    OpDef { name: "**", signature: "OBJ1 ** OBJ2", doc: "Power.", example: "x = 2. ** 0.5 ;", f: power },
    OpDef { name: "<", signature: "NUM1 < NUM2", doc: "Less than.", example: "si (x < 1.) ;", f: lt },
    OpDef { name: ">", signature: "NUM1 > NUM2", doc: "Greater than.", example: "si (x > 1.) ;", f: gt },
    OpDef { name: "<EG", signature: "NUM1 <EG NUM2", doc: "Less than or equal.", example: "si (x <EG 1.) ;", f: le },
    OpDef { name: ">EG", signature: "NUM1 >EG NUM2", doc: "Greater than or equal.", example: "si (x >EG 1.) ;", f: ge },
    OpDef {
        name: "EGA",
        signature: "OBJ1 EGA OBJ2 (TOLERANCE)",
        doc: "Equality of numbers, words, logicals, points, integer lists.",
        example: "si (i ega 3) ;",
        f: ega,
    },
    OpDef {
        name: "NEG",
        signature: "OBJ1 NEG OBJ2 (TOLERANCE)",
        doc: "Inequality (the negation of EGA).",
        example: "si (m neg 'TOTO') ;",
        f: neg,
    },
    OpDef { name: "OU", signature: "LOG1 OU LOG2", doc: "Logical or.", example: "si ((x > 1) ou (y > 1)) ;", f: ou },
    OpDef { name: "NON", signature: "NON LOG1", doc: "Logical negation.", example: "si (non (exis t 1)) ;", f: non },
];

/// The two operands of an infix operator.
fn operands(a: &mut Args) -> Result<(Value, Value)> {
    let x = match a.left_value() {
        Some(v) => v,
        None => a.right_any().ok_or_else(|| a.missing("a left operand"))?,
    };
    let y = a.right_any().ok_or_else(|| a.missing("a right operand"))?;
    Ok((x, y))
}

#[derive(Clone, Copy, PartialEq)]
pub(crate) enum Bin {
    Add,
    Sub,
    Mul,
    Div,
    Pow,
}

/// The operation on two FLOTTANTs: the one definition that every
/// operand type (numbers, lists, points, fields, curves) applies.
pub(crate) fn float_op(op: Bin, x: f64, y: f64) -> f64 {
    match op {
        Bin::Add => x + y,
        Bin::Sub => x - y,
        Bin::Mul => x * y,
        Bin::Div => x / y,
        Bin::Pow => x.powf(y),
    }
}

fn int_op(a: &Args, op: Bin, x: i64, y: i64) -> Result<Value> {
    let r = match op {
        Bin::Add => x.checked_add(y),
        Bin::Sub => x.checked_sub(y),
        Bin::Mul => x.checked_mul(y),
        Bin::Div => {
            if y == 0 {
                return Err(a.err("division of an ENTIER by zero"));
            }
            x.checked_div(y)
        }
        Bin::Pow => {
            if y < 0 {
                return Ok(Value::Float((x as f64).powf(y as f64)));
            }
            u32::try_from(y).ok().and_then(|e| x.checked_pow(e))
        }
    };
    Ok(r.map(Value::Int).unwrap_or_else(|| Value::Float(float_op(op, x as f64, y as f64))))
}

fn binary(it: &mut Interp, a: &mut Args, op: Bin) -> Result<Vec<Value>> {
    let (x, y) = operands(a)?;
    // A FLOTTANT divided by zero or a power with no real value would give
    // inf or NaN, and a NaN passes every `SI (err > tol)` check: both are
    // errors, as the division of an ENTIER by zero already is. (Purely
    // numeric instructions take eval's fast path, which does not check yet.)
    if op == Bin::Div && y.as_f64() == Some(0.0) && !matches!((&x, &y), (Value::Int(_), Value::Int(_))) {
        return Err(a.err(format!("division of {} by zero", pointwise::describe(&x))));
    }
    let r = apply(it, a, op, x.clone(), y.clone())?;
    if matches!(op, Bin::Div | Bin::Pow) && pointwise::finite(&x) && pointwise::finite(&y) && !pointwise::finite(&r) {
        let (dx, dy) = (pointwise::describe(&x), pointwise::describe(&y));
        return Err(a.err(match op {
            Bin::Div => format!("{} / {} divides by zero", dx, dy),
            _ => format!("{} ** {} has no finite real value", dx, dy),
        }));
    }
    Ok(vec![r])
}

pub(crate) fn apply(it: &mut Interp, a: &Args, op: Bin, x: Value, y: Value) -> Result<Value> {
    use Value::*;
    Ok(match (&x, &y) {
        (Int(i), Int(j)) => int_op(a, op, *i, *j)?,
        (Int(_) | Float(_), Int(_) | Float(_)) => {
            Float(float_op(op, x.as_f64().unwrap_or(0.0), y.as_f64().unwrap_or(0.0)))
        }
        (ListReel(l), ListReel(m)) => {
            if l.len() != m.len() {
                return Err(a.err(format!("lists of different lengths ({} and {})", l.len(), m.len())));
            }
            ListReel(Rc::new(l.iter().zip(m.iter()).map(|(p, q)| float_op(op, *p, *q)).collect()))
        }
        (ListReel(l), Int(_) | Float(_)) => {
            let s = y.as_f64().unwrap_or(0.0);
            ListReel(Rc::new(l.iter().map(|p| float_op(op, *p, s)).collect()))
        }
        (Int(_) | Float(_), ListReel(l)) => {
            let s = x.as_f64().unwrap_or(0.0);
            ListReel(Rc::new(l.iter().map(|p| float_op(op, s, *p)).collect()))
        }
        (ListEnti(l), ListEnti(m)) if l.len() == m.len() => {
            let mut out = Vec::with_capacity(l.len());
            for (p, q) in l.iter().zip(m.iter()) {
                match int_op(a, op, *p, *q)? {
                    Int(v) => out.push(v),
                    _ => return Err(a.err("integer overflow in a LISTENTI")),
                }
            }
            ListEnti(Rc::new(out))
        }
        (ListEnti(l), Int(j)) => {
            let mut out = Vec::with_capacity(l.len());
            for p in l.iter() {
                match int_op(a, op, *p, *j)? {
                    Int(v) => out.push(v),
                    _ => return Err(a.err("integer overflow in a LISTENTI")),
                }
            }
            ListEnti(Rc::new(out))
        }
        (Int(i), ListEnti(l)) => {
            let mut out = Vec::with_capacity(l.len());
            for q in l.iter() {
                match int_op(a, op, *i, *q)? {
                    Int(v) => out.push(v),
                    _ => return Err(a.err("integer overflow in a LISTENTI")),
                }
            }
            ListEnti(Rc::new(out))
        }
        // A LISTENTI with a FLOTTANT, or with a LISTREEL, gives reals.
        (ListEnti(l), Float(s)) => ListReel(Rc::new(l.iter().map(|p| float_op(op, *p as f64, *s)).collect())),
        (Float(s), ListEnti(l)) => ListReel(Rc::new(l.iter().map(|p| float_op(op, *s, *p as f64)).collect())),
        (ListEnti(_), ListReel(_)) | (ListReel(_), ListEnti(_)) => {
            let reals = |v: &Value| match v {
                ListEnti(l) => l.iter().map(|i| *i as f64).collect::<Vec<f64>>(),
                ListReel(l) => l.to_vec(),
                _ => Vec::new(),
            };
            let (l, m) = (reals(&x), reals(&y));
            if l.len() != m.len() {
                return Err(a.err(format!("lists of different lengths ({} and {})", l.len(), m.len())));
            }
            ListReel(Rc::new(l.iter().zip(m.iter()).map(|(p, q)| float_op(op, *p, *q)).collect()))
        }
        (Point(p), Point(q)) if matches!(op, Bin::Add | Bin::Sub) => {
            let (u, v) = (it.nodes.get(*p), it.nodes.get(*q));
            let w = [0, 1, 2].map(|k| float_op(op, u[k], v[k]));
            let d = it.nodes.density[*p];
            Point(it.nodes.push(w, d))
        }
        (Point(p), Int(_) | Float(_)) if matches!(op, Bin::Mul | Bin::Div) => {
            let s = y.as_f64().unwrap_or(0.0);
            let u = it.nodes.get(*p);
            let d = it.nodes.density[*p];
            Point(it.nodes.push(u.map(|c| float_op(op, c, s)), d))
        }
        (Int(_) | Float(_), Point(p)) if op == Bin::Mul => {
            let s = x.as_f64().unwrap_or(0.0);
            let u = it.nodes.get(*p);
            let d = it.nodes.density[*p];
            Point(it.nodes.push(u.map(|c| c * s), d))
        }
        _ => match super::union::fields_binary(it, a, op, &x, &y)? {
            Some(v) => v,
            None => return Err(a.err(format!("cannot combine {} and {}", x.type_name(), y.type_name()))),
        },
    })
}

fn plus(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    binary(it, a, Bin::Add)
}
fn minus(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    binary(it, a, Bin::Sub)
}
fn times(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    binary(it, a, Bin::Mul)
}
fn divide(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    binary(it, a, Bin::Div)
}
fn power(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    binary(it, a, Bin::Pow)
}

fn compare(a: &mut Args, f: fn(f64, f64) -> bool) -> Result<Vec<Value>> {
    let (x, y) = operands(a)?;
    match (x.as_f64(), y.as_f64()) {
        (Some(p), Some(q)) => Ok(vec![Value::Bool(f(p, q))]),
        _ => Err(a.err(format!("compares numbers, found {} and {}", x.type_name(), y.type_name()))),
    }
}
fn lt(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    compare(a, |p, q| p < q)
}
fn gt(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    compare(a, |p, q| p > q)
}
fn le(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    compare(a, |p, q| p <= q)
}
fn ge(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    compare(a, |p, q| p >= q)
}

/// EGA/NEG equality, with an optional absolute tolerance for numbers.
fn equal(it: &Interp, a: &mut Args) -> Result<bool> {
    let (x, y) = operands(a)?;
    let tol = if x.is_number() { a.opt_num_right().unwrap_or(0.0) } else { 0.0 };
    use Value::*;
    Ok(match (&x, &y) {
        (Int(i), Int(j)) => i == j,
        (Int(_) | Float(_), Int(_) | Float(_)) => (x.as_f64().unwrap_or(0.0) - y.as_f64().unwrap_or(0.0)).abs() <= tol,
        (Mot(s), Mot(t)) => s.trim_end() == t.trim_end(),
        (Bool(p), Bool(q)) => p == q,
        (Point(p), Point(q)) => p == q || it.nodes.get(*p) == it.nodes.get(*q),
        (ListEnti(l), ListEnti(m)) => l == m,
        (ListReel(l), ListReel(m)) => l == m,
        (ListMots(l), ListMots(m)) => l == m,
        _ => {
            return Err(a.err(format!("cannot compare {} with {}", x.type_name(), y.type_name())));
        }
    })
}
fn ega(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    Ok(vec![Value::Bool(equal(it, a)?)])
}
fn neg(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    Ok(vec![Value::Bool(!equal(it, a)?)])
}

fn ou(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let (x, y) = operands(a)?;
    match (x, y) {
        (Value::Bool(p), Value::Bool(q)) => Ok(vec![Value::Bool(p || q)]),
        (x, y) => Err(a.err(format!("needs two LOGIQUE, found {} and {}", x.type_name(), y.type_name()))),
    }
}

fn non(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let b = match a.left_top::<bool>() {
        Some(b) => b,
        None => a.opt_right::<bool>().ok_or_else(|| a.missing("LOGIQUE"))?,
    };
    Ok(vec![Value::Bool(!b)])
}
