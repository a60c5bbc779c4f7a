//! `+ - * / **`: one table keyed by the two operand types. Each row names
//! the rule that combines them; every rule applies the one numeric core
//! (`value::arith`) value by value, and the algebra of each object type
//! lives with the type (`value`). The operator checks the result once
//! ([`super::binary`]).

use crate::error::Result;
use crate::eval::args::Args;
use crate::eval::Interp;
use crate::ops::pointwise::map;
use crate::value::arith::{float_op, numbers, Bin, Number};
use crate::value::{list_value_short, Key, Table, Ty, Value};
use std::cell::RefCell;
use std::rc::Rc;

/// A rule: the result, or None when the operator is not defined for
/// these operand types (`POINT * POINT`).
type Rule = fn(&mut Interp, &Args, Bin, &Value, &Value) -> Result<Option<Value>>;

/// A row: the left types, the right types (empty: any type), the rule.
struct Row {
    x: &'static [Ty],
    y: &'static [Ty],
    rule: Rule,
}

const NUM: &[Ty] = &[Ty::Entier, Ty::Flottant];
const ANY: &[Ty] = &[];

/// The first row whose types match decides.
const ROWS: &[Row] = &[
    Row { x: NUM, y: NUM, rule: scalars },
    Row { x: &[Ty::ListEnti], y: &[Ty::ListEnti, Ty::Entier], rule: integers },
    Row { x: &[Ty::Entier], y: &[Ty::ListEnti], rule: integers },
    Row { x: &[Ty::ListReel, Ty::ListEnti], y: &[Ty::ListReel, Ty::ListEnti, Ty::Entier, Ty::Flottant], rule: reals },
    Row { x: NUM, y: &[Ty::ListReel, Ty::ListEnti], rule: reals },
    Row { x: &[Ty::Point], y: &[Ty::Point, Ty::Entier, Ty::Flottant], rule: points },
    Row { x: NUM, y: &[Ty::Point], rule: points },
    Row { x: &[Ty::Chpoint], y: &[Ty::Chpoint, Ty::Entier, Ty::Flottant], rule: node_fields },
    Row { x: NUM, y: &[Ty::Chpoint], rule: node_fields },
    Row { x: &[Ty::Rigidite], y: &[Ty::Chpoint, Ty::Rigidite, Ty::Entier, Ty::Flottant], rule: rigidities },
    Row { x: &[Ty::Chpoint, Ty::Entier, Ty::Flottant], y: &[Ty::Rigidite], rule: rigidities },
    Row { x: &[Ty::Evolutio], y: &[Ty::Evolutio, Ty::Entier, Ty::Flottant], rule: sampled },
    Row { x: &[Ty::Mchaml], y: &[Ty::Mchaml, Ty::Entier, Ty::Flottant], rule: sampled },
    Row { x: NUM, y: &[Ty::Evolutio, Ty::Mchaml], rule: sampled },
    Row { x: &[Ty::Table], y: ANY, rule: tables },
    Row { x: ANY, y: &[Ty::Table], rule: tables },
];

/// `x op y`, unchecked (callers that build sums, like COLI, check nothing
/// more than the operator does).
pub(crate) fn apply(it: &mut Interp, a: &Args, op: Bin, x: &Value, y: &Value) -> Result<Value> {
    let (tx, ty) = (x.ty(), y.ty());
    let fits = |set: &[Ty], t: Ty| set.is_empty() || set.contains(&t);
    let row = ROWS.iter().find(|r| fits(r.x, tx) && fits(r.y, ty));
    match row {
        Some(r) => match (r.rule)(it, a, op, x, y)? {
            Some(v) => Ok(v),
            None => Err(cannot(a, x, y)),
        },
        None => Err(cannot(a, x, y)),
    }
}

fn cannot(a: &Args, x: &Value, y: &Value) -> crate::error::Error {
    a.err(format!("cannot combine {} and {}", x.type_name(), y.type_name()))
}

fn scalar(v: &Value) -> f64 {
    v.as_f64().unwrap_or(0.0)
}

/// ENTIER and FLOTTANT: the numeric core itself.
fn scalars(_: &mut Interp, a: &Args, op: Bin, x: &Value, y: &Value) -> Result<Option<Value>> {
    let (Some(p), Some(q)) = (Number::of(x), Number::of(y)) else { return Ok(None) };
    numbers(op, p, q).map(|n| Some(n.value())).map_err(|e| a.err(e))
}

/// LISTREEL value by value, with a number or a list of the same length;
/// a LISTENTI with a FLOTTANT or a LISTREEL counts as reals and gives
/// reals (the integer cases took the rows above).
fn reals(_: &mut Interp, a: &Args, op: Bin, x: &Value, y: &Value) -> Result<Option<Value>> {
    let list = |v: &Value| match v {
        Value::ListReel(l) => Some(l.to_vec()),
        Value::ListEnti(l) => Some(l.iter().map(|&i| i as f64).collect()),
        _ => None,
    };
    let out: Vec<f64> = match (list(x), list(y)) {
        (Some(l), Some(m)) => {
            if l.len() != m.len() {
                return Err(a.err(format!("lists of different lengths ({} and {})", l.len(), m.len())));
            }
            l.iter().zip(m.iter()).map(|(p, q)| float_op(op, *p, *q)).collect()
        }
        (Some(l), None) => l.iter().map(|p| float_op(op, *p, scalar(y))).collect(),
        (None, Some(l)) => l.iter().map(|q| float_op(op, scalar(x), *q)).collect(),
        (None, None) => return Ok(None),
    };
    Ok(Some(Value::ListReel(Rc::new(out))))
}

/// LISTENTI value by value: every result must stay an ENTIER.
fn integers(_: &mut Interp, a: &Args, op: Bin, x: &Value, y: &Value) -> Result<Option<Value>> {
    let pairs: Vec<(i64, i64)> = match (x, y) {
        (Value::ListEnti(l), Value::ListEnti(m)) if l.len() == m.len() => {
            l.iter().copied().zip(m.iter().copied()).collect()
        }
        (Value::ListEnti(l), Value::Int(j)) => l.iter().map(|&p| (p, *j)).collect(),
        (Value::Int(i), Value::ListEnti(l)) => l.iter().map(|&q| (*i, q)).collect(),
        _ => return Ok(None),
    };
    let mut out = Vec::with_capacity(pairs.len());
    for (p, q) in pairs {
        match numbers(op, Number::Int(p), Number::Int(q)).map_err(|e| a.err(e))? {
            Number::Int(v) => out.push(v),
            Number::Float(_) => return Err(a.err("integer overflow in a LISTENTI")),
        }
    }
    Ok(Some(Value::ListEnti(Rc::new(out))))
}

/// POINT ± POINT, POINT * or / a number, a number * POINT: a new node,
/// with the density of the point.
fn points(it: &mut Interp, _: &Args, op: Bin, x: &Value, y: &Value) -> Result<Option<Value>> {
    let (p, w) = match (x, y) {
        (Value::Point(p), Value::Point(q)) if matches!(op, Bin::Add | Bin::Sub) => {
            let (u, v) = (it.nodes.get(*p), it.nodes.get(*q));
            (*p, [0, 1, 2].map(|k| float_op(op, u[k], v[k])))
        }
        (Value::Point(p), s) if matches!(op, Bin::Mul | Bin::Div) && s.is_number() => {
            (*p, it.nodes.get(*p).map(|c| float_op(op, c, scalar(s))))
        }
        (s, Value::Point(p)) if op == Bin::Mul => (*p, it.nodes.get(*p).map(|c| c * scalar(s))),
        _ => return Ok(None),
    };
    let d = it.nodes.density[p];
    Ok(Some(Value::Point(it.nodes.push(w, d))))
}

/// CHPOINT ± CHPOINT over the union of the supports, CHPOINT * or / CHPOINT
/// (SCAL fields scale), and with a number value by value.
fn node_fields(_: &mut Interp, a: &Args, op: Bin, x: &Value, y: &Value) -> Result<Option<Value>> {
    let f = |p: f64, q: f64| float_op(op, p, q);
    Ok(Some(Value::Chpo(Rc::new(match (x, y) {
        (Value::Chpo(c), Value::Chpo(d)) => match op {
            Bin::Add | Bin::Sub => c.combine(d, f),
            Bin::Mul | Bin::Div => c.product(d, op == Bin::Div),
            Bin::Pow => return Err(a.err("no power of two fields")),
        },
        (Value::Chpo(c), s) => c.map(|v| f(v, scalar(s))),
        (s, Value::Chpo(c)) => c.map(|v| f(scalar(s), v)),
        _ => return Ok(None),
    }))))
}

/// RIGIDITE * CHPOINT (K u), a number times a RIGIDITE or a RIGIDITE
/// divided by one, and the sum or difference of two (assembly by
/// concatenation).
fn rigidities(_: &mut Interp, a: &Args, op: Bin, x: &Value, y: &Value) -> Result<Option<Value>> {
    Ok(Some(match (x, y, op) {
        (Value::Rigi(r), Value::Chpo(u), Bin::Mul) | (Value::Chpo(u), Value::Rigi(r), Bin::Mul) => {
            Value::Chpo(Rc::new(r.matvec(u)))
        }
        (Value::Rigi(r), s, Bin::Mul) | (s, Value::Rigi(r), Bin::Mul) if s.is_number() => {
            Value::Rigi(Rc::new(r.scaled(scalar(s))))
        }
        (Value::Rigi(r), s, Bin::Div) if s.is_number() => match scalar(s) {
            0.0 => return Err(a.err("a RIGIDITE divided by zero")),
            d => Value::Rigi(Rc::new(r.scaled(1.0 / d))),
        },
        (Value::Rigi(r), Value::Rigi(s), Bin::Add) => Value::Rigi(Rc::new(r.union(s))),
        (Value::Rigi(r), Value::Rigi(s), Bin::Sub) => Value::Rigi(Rc::new(r.union(&s.scaled(-1.0)))),
        _ => return Ok(None),
    }))
}

/// EVOLUTIO and MCHAML: their values with a number (the ordinates of a
/// curve), or two of the same layout (curves at the same abscissae, element
/// fields on the same zones) value by value.
fn sampled(_: &mut Interp, a: &Args, op: Bin, x: &Value, y: &Value) -> Result<Option<Value>> {
    let f = |p: f64, q: f64| float_op(op, p, q);
    Ok(Some(match (x, y) {
        (Value::Evol(e), Value::Evol(g)) => match crate::value::signal::complex::combine(e, g, op) {
            Some(r) => Value::Evol(Rc::new(r.map_err(|m| a.err(m))?)),
            None => Value::Evol(Rc::new(e.combine(g, f).map_err(|m| a.err(m))?)),
        },
        (Value::Mchaml(m), Value::Mchaml(n)) => {
            let fill = matches!(op, Bin::Add | Bin::Sub);
            // Realigned only onto a layout of as many elements: a sum must
            // not drop the elements one side has alone.
            let count = |x: &crate::value::Mchaml| x.zones.iter().map(|z| z.values.len()).sum::<usize>();
            let same = count(m) == count(n);
            // A product or quotient by a one-component field (a norm)
            // scales every component, on the first field's layout.
            let scaled = || {
                crate::value::mchaml_scale::scale(m, n, f)
                    .or_else(|| n.realign(m).and_then(|n2| crate::value::mchaml_scale::scale(m, &n2, f)))
            };
            let r = m.combine(n, f).or_else(|e| match (!fill).then(scaled).flatten() {
                Some(r) => Ok(r),
                None => Err(e),
            });
            let r = r.or_else(|e| match n.realign(m).filter(|_| same || !fill) {
                Some(n2) => m.combine_union(&n2, f, fill),
                None => match m.realign(n) {
                    Some(m2) if !fill => m2.combine_union(n, f, fill),
                    _ if fill => match (n.embed_in(m), m.embed_in(n)) {
                        (Some(n2), _) => m.combine_union(&n2, f, fill),
                        (None, Some(m2)) => m2.combine_union(n, f, fill),
                        _ => m.combine_union(n, f, fill),
                    },
                    _ => Err(e),
                },
            });
            Value::Mchaml(Rc::new(r.map_err(|e| a.err(e))?))
        }
        (v, s) if s.is_number() => return Ok(map(v, &|p| f(p, scalar(s)))),
        (s, v) => return Ok(map(v, &|q| f(scalar(s), q))),
    }))
}

fn is_vecteur(t: &Table) -> bool {
    let sub = t.get(&Key::Mot("SOUSTYPE".into())).and_then(|v| v.as_mot()).map(|s| s.trim().to_uppercase());
    sub.as_deref() == Some("VECTEUR")
}

/// Tables of subtype VECTEUR (aaa5.notice): two combine entry by entry
/// (same keys), one is multiplied or divided by a number. Entries combine
/// by this same table, whatever they hold.
fn tables(it: &mut Interp, a: &Args, op: Bin, x: &Value, y: &Value) -> Result<Option<Value>> {
    let as_table = |v: &Value| if let Value::Table(t) = v { Some(t.clone()) } else { None };
    let (tx, ty) = (as_table(x), as_table(y));
    for t in [&tx, &ty].into_iter().flatten() {
        if !is_vecteur(&t.borrow()) {
            return Err(a.err("arithmetic on tables needs tables of subtype VECTEUR (TABLE 'VECTEUR')"));
        }
    }
    // Entries that are VECTEUR tables themselves combine by a recursive
    // call: it counts as one nesting level, so a chain of 100,000 tables
    // is an error, not a stack overflow.
    if it.depth >= crate::eval::MAX_NESTING {
        return Err(a.err(format!("VECTEUR tables nested more than {} deep", crate::eval::MAX_NESTING)));
    }
    it.depth += 1;
    let r = table_entries(it, a, op, x, y, tx, ty);
    it.depth -= 1;
    r
}

/// The entries of [`tables`]' result, the operands already checked.
fn table_entries(
    it: &mut Interp,
    a: &Args,
    op: Bin,
    x: &Value,
    y: &Value,
    tx: Option<Rc<RefCell<Table>>>,
    ty: Option<Rc<RefCell<Table>>>,
) -> Result<Option<Value>> {
    let soustype = Key::Mot("SOUSTYPE".into());
    let mut out = Table::with_subtype("VECTEUR");
    match (tx, ty) {
        (Some(p), Some(q)) => {
            if op == Bin::Pow {
                return Err(a.err("no power of two tables"));
            }
            let (p, q) = (p.borrow().clone(), q.borrow().clone());
            let keys = |t: &Table| t.iter().filter(|(k, _)| *k != soustype).map(|(k, _)| k.clone()).collect::<Vec<_>>();
            let (kp, kq) = (keys(&p), keys(&q));
            if let Some(k) = kp.iter().find(|k| !kq.contains(k)).or_else(|| kq.iter().find(|k| !kp.contains(k))) {
                return Err(a.err(format!(
                    "the tables do not have the same keys: {} is in only one of them",
                    list_value_short(&k.to_value())
                )));
            }
            for k in kp {
                let (u, v) = (p.get(&k).cloned(), q.get(&k).cloned());
                let r = apply(it, a, op, &u.unwrap_or(Value::Int(0)), &v.unwrap_or(Value::Int(0)))?;
                out.set(k, r);
            }
        }
        (tx, ty) => {
            let left = tx.is_some();
            let (t, scalar) = match (tx, ty) {
                (Some(t), _) => (t, y),
                (_, Some(t)) => (t, x),
                _ => return Ok(None),
            };
            let allowed = match op {
                Bin::Mul => true,
                Bin::Div => left,
                _ => false,
            };
            if !scalar.is_number() || !allowed {
                return Err(a.err(format!(
                    "a VECTEUR table combines with another one, or is multiplied or divided by a number (found {})",
                    scalar.type_name()
                )));
            }
            let t = t.borrow().clone();
            for (k, v) in t.iter().filter(|(k, _)| *k != soustype) {
                let r = if left { apply(it, a, op, v, scalar)? } else { apply(it, a, op, scalar, v)? };
                out.set(k.clone(), r);
            }
        }
    }
    Ok(Some(Value::Table(Rc::new(RefCell::new(out)))))
}
