//! `+ - * / **`, comparisons and logic. Infix operators take the newest
//! pushed operand on their left, else read two operands on their right
//! (`'-' 10 4`), so `1 + 2 * 3` is 9: there is no precedence.

mod components;
mod table;

pub(crate) use table::apply;
// The operator kind of the numeric core, where families have always found it.
pub(crate) use crate::value::arith::Bin;

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::arith;
use crate::value::Value;

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
        doc: "Quotient; ENTIER / ENTIER truncates. Two CHPOINT or MCHAML with three LISTMOTS: component LMOTS3(i) is LMOTS1(i) of the first over LMOTS2(i) of the second (same for + - *).",
        example: "x = 7 / 2 ;",
        f: divide,
    },
    OpDef { name: "**", signature: "OBJ1 ** OBJ2", doc: "Power.", example: "x = 2. ** 0.5 ;", f: power },
    OpDef {
        name: "<",
        signature: "NUM1 < NUM2",
        doc: "Less than.",
        example: "si (x < 1.) ; mess 'yes' ; finsi ;",
        f: lt,
    },
    OpDef {
        name: ">",
        signature: "NUM1 > NUM2",
        doc: "Greater than.",
        example: "si (x > 1.) ; mess 'yes' ; finsi ;",
        f: gt,
    },
    OpDef {
        name: "<EG",
        signature: "NUM1 <EG NUM2",
        doc: "Less than or equal.",
        example: "si (x <EG 1.) ; mess 'yes' ; finsi ;",
        f: le,
    },
    OpDef {
        name: ">EG",
        signature: "NUM1 >EG NUM2",
        doc: "Greater than or equal.",
        example: "si (x >EG 1.) ; mess 'yes' ; finsi ;",
        f: ge,
    },
    OpDef {
        name: "EGA",
        signature: "OBJ1 EGA OBJ2 (TOLERANCE)",
        doc: "Equality of numbers, words, logicals, points, integer lists.",
        example: "si (i ega 3) ; mess 'yes' ; finsi ;",
        f: ega,
    },
    OpDef {
        name: "NEG",
        signature: "OBJ1 NEG OBJ2 (TOLERANCE)",
        doc: "Inequality (the negation of EGA).",
        example: "si (m neg 'TOTO') ; mess 'yes' ; finsi ;",
        f: neg,
    },
    OpDef {
        name: "OU",
        signature: "LOG1 OU LOG2",
        doc: "Logical or.",
        example: "si ((x > 1) ou (y > 1)) ; mess 'yes' ; finsi ;",
        f: ou,
    },
    OpDef {
        name: "NON",
        signature: "NON LOG1",
        doc: "Logical negation.",
        example: "si (non (exis t 1)) ; mess 'yes' ; finsi ;",
        f: non,
    },
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

/// `x op y` for the infix operators: a division by the number zero is
/// refused before it is computed, the rule comes from the table, and a
/// result that is not finite is an error naming the operation.
fn binary(it: &mut Interp, a: &mut Args, op: Bin) -> Result<Vec<Value>> {
    let (x, mut y) = operands(a)?;
    // `OBJ1 * MODL1 OBJ2` (aaa2.notice): the model names the support of
    // two element fields; the product itself is the same, so the model
    // is read and set aside.
    let mut with_model = false;
    if op == Bin::Mul && matches!(x, Value::Mchaml(_)) && matches!(y, Value::Model(_)) {
        y = a.right_any().ok_or_else(|| a.missing("the MCHAML after the model"))?;
        with_model = true;
    }
    // `(MODL1) MCHAML * MCHAML` (aaa2.notice): the model may also stand
    // before the first field.
    if op == Bin::Mul && !with_model && matches!((&x, &y), (Value::Mchaml(_), Value::Mchaml(_))) {
        with_model = a.left_top::<std::rc::Rc<crate::value::Model>>().is_some();
    }
    if op == Bin::Mul && crate::ops::hooke::is_hooke(&x) {
        if let Some(r) = crate::ops::hooke::product(a, &x, &y)? {
            return Ok(vec![r]);
        }
    }
    if with_model {
        if let Some(r) = crate::ops::work::gradient_product(a, &x, &y)? {
            return Ok(vec![r]);
        }
    }
    if let Some(e) = arith::divides_by_zero(op, &x, &y) {
        return Err(a.err(e));
    }
    // The prefix form `'*' X L1 Y L2 L3`: the first list between the fields.
    let mut first = None;
    if let (Value::Chpo(_) | Value::Mchaml(_), Value::ListMots(l)) = (&x, &y) {
        if a.has_any::<Value>() {
            first = Some(l.clone());
            y = a.right_any().ok_or_else(|| a.missing("the second field"))?;
        }
    }
    let r = match components::apply(a, op, &x, &y, first)? {
        Some(r) => r,
        None => table::apply(it, a, op, &x, &y)?,
    };
    let r = arith::check(op, &x, &y, r).map_err(|e| a.err(e))?;
    // Two fields combined may be given the result's nature
    // (`c1 * c2 'NATURE' 'DISCRET'`).
    if let Value::Chpo(c) = &r {
        if let Some(n) = crate::ops::fields::nature_word(a)? {
            let mut c = (**c).clone();
            c.nature = n;
            return Ok(vec![Value::Chpo(std::rc::Rc::new(c))]);
        }
    }
    Ok(vec![r])
}

fn plus(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if let Some(sum) = table_sum(it, a)? {
        return Ok(vec![sum]);
    }
    binary(it, a, Bin::Add)
}

/// `+ TAB`, Cast3M's one-operand form: the sum of every object of a table
/// (the per-domain pieces of a result gathered back into one), its
/// 'SOUSTYPE' word left out. Only when `+` has no left operand and the
/// table is its last operand.
fn table_sum(it: &mut Interp, a: &mut Args) -> Result<Option<Value>> {
    let Some(Value::Table(t)) = a.peek_right() else { return Ok(None) };
    if a.left_len() > 0 {
        return Ok(None);
    }
    a.right_any();
    if a.peek_right().is_some() {
        return Err(a.err("+ of a TABLE takes no other operand".to_string()));
    }
    let items: Vec<Value> = t
        .borrow()
        .iter()
        .filter(|(k, _)| !matches!(k, crate::value::table::Key::Mot(m) if m.trim() == "SOUSTYPE"))
        .map(|(_, v)| v.clone())
        .collect();
    let mut it_items = items.into_iter();
    let Some(mut acc) = it_items.next() else {
        return Err(a.err("+ of an empty TABLE has nothing to sum".to_string()));
    };
    for v in it_items {
        let r = match components::apply(a, Bin::Add, &acc, &v, None)? {
            Some(r) => r,
            None => table::apply(it, a, Bin::Add, &acc, &v)?,
        };
        acc = arith::check(Bin::Add, &acc, &v, r).map_err(|e| a.err(e))?;
    }
    Ok(Some(acc))
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
    // A word compared with an unquoted name that is also an operator's
    // (`NEG (TYPE T) TABLE`) compares with the name: Cast3M reads it as
    // a word there.
    let x = match a.left_value() {
        Some(v) => v,
        None => a.right_any().ok_or_else(|| a.missing("a left operand"))?,
    };
    let word = if matches!(x, Value::Mot(_)) { a.word_before_text() } else { None };
    let y = match word {
        Some(w) => Value::mot(w),
        None => a.right_any().ok_or_else(|| a.missing("a right operand"))?,
    };
    let tol = if x.is_number() || matches!((&x, &y), (Value::Point(_), Value::Point(_))) {
        a.opt_num_right().unwrap_or(0.0)
    } else {
        0.0
    };
    use Value::*;
    Ok(match (&x, &y) {
        (Int(i), Int(j)) => i == j,
        (Int(_) | Float(_), Int(_) | Float(_)) => (x.as_f64().unwrap_or(0.0) - y.as_f64().unwrap_or(0.0)).abs() <= tol,
        (Mot(s), Mot(t)) => s.trim_end() == t.trim_end(),
        (Bool(p), Bool(q)) => p == q,
        (Point(p), Point(q)) => {
            let (u, v) = (it.nodes.get(*p), it.nodes.get(*q));
            p == q || (0..3).map(|k| (u[k] - v[k]).powi(2)).sum::<f64>().sqrt() <= tol
        }
        (ListEnti(l), ListEnti(m)) => l == m,
        (ListReel(l), ListReel(m)) => l == m,
        (ListMots(l), ListMots(m)) => l == m,
        // Other objects are equal when they are the same object (two names
        // of it, or an item taken back from a list that holds it).
        (Chpo(p), Chpo(q)) => std::rc::Rc::ptr_eq(p, q),
        (Mesh(p), Mesh(q)) => std::rc::Rc::ptr_eq(p, q),
        (Mchaml(p), Mchaml(q)) => std::rc::Rc::ptr_eq(p, q),
        (Rigi(p), Rigi(q)) => std::rc::Rc::ptr_eq(p, q),
        (Model(p), Model(q)) => std::rc::Rc::ptr_eq(p, q),
        (Evol(p), Evol(q)) => std::rc::Rc::ptr_eq(p, q),
        (Table(p), Table(q)) => std::rc::Rc::ptr_eq(p, q),
        (ListChpo(p), ListChpo(q)) => std::rc::Rc::ptr_eq(p, q),
        // A word is not equal to an object of another type: an unset name
        // reads as a word (`EGA f 0.` with f never assigned is FAUX).
        (Mot(_), _) | (_, Mot(_)) => false,
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
