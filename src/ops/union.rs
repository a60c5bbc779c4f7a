//! ET: the overloaded union (language.md §5): logical AND, list and word
//! concatenation, mesh union, field merge, rigidity assembly: one entry,
//! every pair of types in one match, each object's own union in `value`.

use super::export::Vecteur;
use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::value::Value;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "ET",
    signature: "OBJ1 ET ('TELQUEL') OBJ2 ('NOER') | ET TABLE",
    doc: "Logical and; union of meshes; assembly of rigidities; merge of fields; concatenation of lists and words (LISTCHPO ET CHPOINT|LISTCHPO appends); curves gathered into one EVOLUTIO; two numbers make a list (ENTIER ET ENTIER a LISTENTI, else a LISTREEL); VECTEUR arrows gathered; ET of a table joins all its objects.",
    example: "l = l1 et l2 ;",
    f: et,
}];

fn et(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    // 'TELQUEL' keeps the operands' order (meshes) and blanks (words,
    // which gibi always keeps).
    let mut telq = a.keyword_next(&["TELQUEL"]).is_some();
    let x = match a.left_value() {
        Some(v) => v,
        None => a.right_any().ok_or_else(|| a.missing("a left operand"))?,
    };
    telq |= a.keyword_next(&["TELQUEL"]).is_some();
    let y = match a.right_any() {
        Some(y) => y,
        // `ET tab`: the union of every object the table holds (et.notice).
        None => match &x {
            Value::Table(t) => return Ok(vec![union_of_table(it, a, t)?]),
            _ => return Err(a.missing("a right operand")),
        },
    };
    let mut noer = false;
    while let Some(k) = a.keyword(&["NOER", "TELQUEL"]) {
        noer |= k == "NOER";
        telq |= k == "TELQUEL";
    }
    // Two meshes (points join as POI1 elements in order, in `union`).
    if let (false, Value::Mesh(m), Value::Mesh(n)) = (telq, &x, &y) {
        return Ok(vec![Value::Mesh(Rc::new(m.union_continuous(n)))]);
    }
    Ok(vec![union(it, a, x, y, noer)?])
}

/// The objects of a table (its subtype left aside) joined in order.
fn union_of_table(it: &mut Interp, a: &Args, t: &std::cell::RefCell<crate::value::Table>) -> Result<Value> {
    let items: Vec<Value> = t
        .borrow()
        .iter()
        .filter(|(k, _)| !matches!(k, crate::value::Key::Mot(m) if m == "SOUSTYPE"))
        .map(|(_, v)| v.clone())
        .collect();
    let mut items = items.into_iter();
    let first = items.next().ok_or_else(|| a.err("the table holds no object to join"))?;
    // Points alone join into a mesh of POI1 elements.
    let mut acc = match first {
        Value::Point(_) => Value::Mesh(Rc::new(as_mesh(&first).unwrap_or_default())),
        v => v,
    };
    for v in items {
        acc = union(it, a, acc, v, false)?;
    }
    Ok(acc)
}

pub(crate) fn union(_: &mut Interp, a: &Args, x: Value, y: Value, noer: bool) -> Result<Value> {
    use Value::*;
    // `l = l ET l` in a loop doubles each pass: check before allocating.
    super::limits::check_len(a, item_count(&x).saturating_add(item_count(&y)))?;
    Ok(match (&x, &y) {
        (Bool(p), Bool(q)) => Bool(*p && *q),
        (Mot(s), Mot(t)) => Value::mot(format!("{}{}", s, t)),
        (Int(i), Int(j)) => ListEnti(Rc::new(vec![*i, *j])),
        (Int(_) | Float(_), Int(_) | Float(_)) => {
            ListReel(Rc::new(vec![x.as_f64().unwrap_or(0.0), y.as_f64().unwrap_or(0.0)]))
        }
        (ListReel(l), ListReel(m)) => ListReel(Rc::new(l.iter().chain(m.iter()).copied().collect())),
        (ListReel(l), Int(_) | Float(_)) => {
            let mut v = (**l).clone();
            v.push(y.as_f64().unwrap_or(0.0));
            ListReel(Rc::new(v))
        }
        (Int(_) | Float(_), ListReel(l)) => {
            let mut v = vec![x.as_f64().unwrap_or(0.0)];
            v.extend(l.iter());
            ListReel(Rc::new(v))
        }
        (ListEnti(l), ListEnti(m)) => ListEnti(Rc::new(l.iter().chain(m.iter()).copied().collect())),
        (ListEnti(l), Int(j)) => {
            let mut v = (**l).clone();
            v.push(*j);
            ListEnti(Rc::new(v))
        }
        (Int(i), ListEnti(l)) => {
            let mut v = vec![*i];
            v.extend(l.iter());
            ListEnti(Rc::new(v))
        }
        (ListMots(l), ListMots(m)) => ListMots(Rc::new(l.iter().chain(m.iter()).cloned().collect())),
        (ListMots(l), Mot(s)) => {
            let mut v = (**l).clone();
            v.push(s.to_string());
            ListMots(Rc::new(v))
        }
        (Mot(s), ListMots(l)) => ListMots(Rc::new([s.to_string()].into_iter().chain(l.iter().cloned()).collect())),
        (Host(p), Host(q)) if p.type_name() == "VECTEUR" && q.type_name() == "VECTEUR" => {
            match (p.as_any().downcast_ref::<Vecteur>(), q.as_any().downcast_ref::<Vecteur>()) {
                (Some(p), Some(q)) => Host(Rc::new(p.join(q))),
                _ => return Err(a.err("cannot join these VECTEUR objects")),
            }
        }
        // A LISTCHPO grows by appending: its fields are separate load
        // cases, never merged as `CHPOINT ET CHPOINT` would merge them.
        (ListChpo(l), ListChpo(m)) => ListChpo(Rc::new(l.iter().chain(m.iter()).cloned().collect())),
        (ListChpo(l), Chpo(c)) => ListChpo(Rc::new(l.iter().chain([c]).cloned().collect())),
        (Chpo(c), ListChpo(l)) => ListChpo(Rc::new([c].into_iter().chain(l.iter()).cloned().collect())),
        // Curves gather into one multi-curve EVOLUTIO (what DESS draws).
        (Evol(e), Evol(f)) => {
            Evol(Rc::new(crate::value::Evolution { curves: e.curves.iter().chain(f.curves.iter()).cloned().collect() }))
        }
        // A point joins a mesh of points as one more POI1 element even if
        // it is already there: decks build lists of points, repeats
        // included, with `m = m ET p` (cinema1).
        (Point(p), Mesh(m)) => Mesh(Rc::new(crate::fem::meshing::points::add_point(m, *p, true))),
        (Mesh(m), Point(p)) => Mesh(Rc::new(crate::fem::meshing::points::add_point(m, *p, false))),
        (Point(_) | Mesh(_), Point(_) | Mesh(_)) => {
            Mesh(Rc::new(as_mesh(&x).unwrap_or_default().union(&as_mesh(&y).unwrap_or_default())))
        }
        (Chpo(p), Chpo(q)) => Chpo(Rc::new(p.merge(q, noer).map_err(|e| a.err(e))?)),
        (Rigi(p), Rigi(q)) => Rigi(Rc::new(p.union(q))),
        (Model(p), Model(q)) => Model(Rc::new(p.union(q))),
        (Mchaml(p), Mchaml(q)) => Mchaml(Rc::new(p.merge(q))),
        // Loads join part by part, in order (several parts may share a name:
        // PASAPAS and TIRE sum them).
        (Charge(p), Charge(q)) => {
            Charge(Rc::new(crate::value::Chargement { parts: p.parts.iter().chain(&q.parts).cloned().collect() }))
        }
        _ => return Err(a.err(format!("cannot join {} and {}", x.type_name(), y.type_name()))),
    })
}

/// Items of a list or characters of a word (0 for other objects).
fn item_count(v: &Value) -> usize {
    match v {
        Value::ListReel(l) => l.len(),
        Value::ListEnti(l) => l.len(),
        Value::ListMots(l) => l.len(),
        Value::ListChpo(l) => l.len(),
        Value::Mot(s) => s.len(),
        _ => 0,
    }
}

/// A POINT or a MAILLAGE as a mesh (a point is a POI1 element).
pub(crate) fn as_mesh(v: &Value) -> Option<Mesh> {
    match v {
        Value::Point(p) => Some(Mesh::points(&[*p])),
        Value::Mesh(m) => Some((**m).clone()),
        _ => None,
    }
}
