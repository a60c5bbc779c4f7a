//! Finding and removing equal items of lists: POSI (where an item is)
//! and UNIQ (the list without its repeats), which share one notion of
//! equality: integers exactly, reals within a tolerance (relative to the
//! machine precision by default, absolute when one is given), words with
//! or without regard to case ('NOCA'); SAUF (the items of a list absent
//! from another) uses the same equality.

use super::lists::short;
use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::{Mesh, Part};
use crate::value::Value;
use std::collections::HashSet;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "POSI",
        signature: "POSI ITEM 'DANS' LIST (TOL | 'NOCA') ('TOUS') | POSI ITEM LIST   (ITEM: ENTIER|FLOTTANT|MOT or a list of them; LIST: LISTENTI|LISTREEL|LISTMOTS|MOT)",
        doc: "Place (from 1) of the first item of LIST equal to ITEM, 0 when it is absent; a LISTENTI of places for a list of items, or of every place with 'TOUS'. In a MOT, the place of a sub-word. Reals are equal within TOL (absolute) if given; 'NOCA' ignores case.",
        example: "i = posi 'UY' 'DANS' (mots 'UX' 'UY') ;",
        f: posi,
    },
    OpDef {
        name: "UNIQ",
        signature: "R1 (R2 …) = UNIQ OBJ1 (OBJ2 …) (TOL) ('NOCA')   (OBJ: LISTENTI|LISTREEL|LISTMOTS|MAILLAGE)",
        doc: "Each object without its repeats, first occurrences kept in order. Reals are equal within TOL (absolute) if given; 'NOCA' ignores case; elements of a mesh are equal when they have the same type and the same nodes, in any order.",
        example: "l = uniq (lect 1 2 1 3) ;",
        f: uniq,
    },
    OpDef {
        name: "SAUF",
        signature: "LIST3 = LIST1 SAUF LIST2 (TOL | 'NOCA')   (LIST: LISTENTI|LISTREEL|LISTMOTS)",
        doc: "The items of LIST1 equal to no item of LIST2, in their order. Reals are equal within TOL (absolute) if given; 'NOCA' ignores case.",
        example: "l = (mots 'UX' 'UY' 'UZ') sauf (mots 'UY') ;",
        f: sauf,
    },
];

/// How two items are compared.
#[derive(Clone, Copy)]
struct Equality {
    tol: Option<f64>,
    nocase: bool,
}

impl Equality {
    fn reals(self, x: f64, y: f64) -> bool {
        match self.tol {
            Some(t) => (x - y).abs() <= t,
            // A few ulps of the larger: what rounding can leave between
            // two computations of one number.
            None => (x - y).abs() <= 4.0 * f64::EPSILON * x.abs().max(y.abs()),
        }
    }

    fn words(self, x: &str, y: &str) -> bool {
        if self.nocase {
            x.to_uppercase() == y.to_uppercase()
        } else {
            x == y
        }
    }

    /// Whether items `i` of `a` and `j` of `b` (lists of one type) are equal.
    fn items(self, a: &Value, i: usize, b: &Value, j: usize) -> bool {
        match (a, b) {
            (Value::ListEnti(a), Value::ListEnti(b)) => a[i] == b[j],
            (Value::ListReel(a), Value::ListReel(b)) => self.reals(a[i], b[j]),
            (Value::ListMots(a), Value::ListMots(b)) => self.words(&short(&a[i]), &short(&b[j])),
            _ => false,
        }
    }
}

fn len(l: &Value) -> usize {
    match l {
        Value::ListEnti(l) => l.len(),
        Value::ListReel(l) => l.len(),
        Value::ListMots(l) => l.len(),
        _ => 0,
    }
}

/// An item as a list of one, of the type of the lists it is sought in.
fn as_list(v: &Value) -> Option<Value> {
    Some(match v {
        Value::Int(i) => Value::ListEnti(Rc::new(vec![*i])),
        Value::Float(x) => Value::ListReel(Rc::new(vec![*x])),
        Value::Mot(w) => Value::ListMots(Rc::new(vec![w.to_string()])),
        Value::ListEnti(_) | Value::ListReel(_) | Value::ListMots(_) => v.clone(),
        _ => return None,
    })
}

/// Tolerance and 'NOCA', in any order, wherever they stand.
fn equality(a: &mut Args) -> Equality {
    let mut eq = Equality { tol: None, nocase: false };
    loop {
        if a.keyword(&["NOCA"]).is_some() {
            eq.nocase = true;
        } else if let Some(t) = a.opt::<f64>() {
            eq.tol = Some(t.abs());
        } else {
            return eq;
        }
    }
}

fn posi(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let first = a.req::<Value>()?;
    let (item, within) = if a.keyword(&["DANS"]).is_some() {
        (first, a.req::<Value>()?)
    } else {
        // The older form names the list and the item in either order.
        let second = a.req::<Value>()?;
        let is_list = |v: &Value| matches!(v, Value::ListEnti(_) | Value::ListReel(_) | Value::ListMots(_));
        if is_list(&first) && !is_list(&second) {
            (second, first)
        } else {
            (first, second)
        }
    };
    let all = a.keyword(&["TOUS"]).is_some();
    let eq = equality(a);
    let all = all || a.keyword(&["TOUS"]).is_some();
    if let (Value::Mot(w), Value::Mot(s)) = (&item, &within) {
        return Ok(vec![in_word(w, s, eq, all)]);
    }
    // An integer among reals is the same number.
    let item = match (&item, &within) {
        (Value::Int(i), Value::ListReel(_)) => Value::Float(*i as f64),
        _ => item,
    };
    let mismatch = || a.err(format!("cannot look for a {} in a {}", item.type_name(), within.type_name()));
    let items = as_list(&item).ok_or_else(mismatch)?;
    if std::mem::discriminant(&items) != std::mem::discriminant(&within) {
        return Err(mismatch());
    }
    let places = |i: usize| -> Vec<i64> {
        (0..len(&within)).filter(|&j| eq.items(&items, i, &within, j)).map(|j| j as i64 + 1).collect()
    };
    let first = |i: usize| places(i).first().copied().unwrap_or(0);
    let one = !matches!(item, Value::ListEnti(_) | Value::ListReel(_) | Value::ListMots(_));
    Ok(vec![if all {
        if !one {
            return Err(a.err("'TOUS' looks for one item, not a list"));
        }
        Value::ListEnti(Rc::new(places(0)))
    } else if one {
        Value::Int(first(0))
    } else {
        Value::ListEnti(Rc::new((0..len(&items)).map(first).collect()))
    }])
}

/// Places (in characters, from 1) of a sub-word in a word.
fn in_word(w: &str, s: &str, eq: Equality, all: bool) -> Value {
    let (w, s): (Vec<char>, Vec<char>) = if eq.nocase {
        (w.to_uppercase().chars().collect(), s.to_uppercase().chars().collect())
    } else {
        (w.chars().collect(), s.chars().collect())
    };
    let hits: Vec<i64> = if w.is_empty() || w.len() > s.len() {
        Vec::new()
    } else {
        (0..=s.len() - w.len()).filter(|&k| s[k..k + w.len()] == w[..]).map(|k| k as i64 + 1).collect()
    };
    if all {
        Value::ListEnti(Rc::new(hits))
    } else {
        Value::Int(hits.first().copied().unwrap_or(0))
    }
}

fn uniq(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mut objs = Vec::new();
    let mut eq = equality(a);
    while let Some(v) = a.opt_with(|v| match v {
        Value::ListEnti(_) | Value::ListReel(_) | Value::ListMots(_) | Value::Mesh(_) => Some(v.clone()),
        _ => None,
    }) {
        objs.push(v);
        let more = equality(a);
        eq = Equality { tol: more.tol.or(eq.tol), nocase: eq.nocase || more.nocase };
    }
    if objs.is_empty() {
        return Err(a.missing("LISTENTI, LISTREEL, LISTMOTS or MAILLAGE"));
    }
    Ok(objs.iter().map(|o| unique(o, eq)).collect())
}

fn sauf(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let is_list = |v: &Value| matches!(v, Value::ListEnti(_) | Value::ListReel(_) | Value::ListMots(_));
    let take = |a: &mut Args| a.opt_with(|v| is_list(v).then(|| v.clone()));
    let first = take(a).ok_or_else(|| a.missing("LISTENTI, LISTREEL or LISTMOTS"))?;
    let eq0 = equality(a);
    let second = take(a).ok_or_else(|| a.missing("LISTENTI, LISTREEL or LISTMOTS"))?;
    let eq1 = equality(a);
    let eq = Equality { tol: eq1.tol.or(eq0.tol), nocase: eq0.nocase || eq1.nocase };
    if std::mem::discriminant(&first) != std::mem::discriminant(&second) {
        return Err(a.err(format!("cannot take a {} from a {}", second.type_name(), first.type_name())));
    }
    let kept: Vec<usize> =
        (0..len(&first)).filter(|&i| !(0..len(&second)).any(|j| eq.items(&first, i, &second, j))).collect();
    Ok(vec![match &first {
        Value::ListEnti(l) => Value::ListEnti(Rc::new(kept.iter().map(|&i| l[i]).collect())),
        Value::ListReel(l) => Value::ListReel(Rc::new(kept.iter().map(|&i| l[i]).collect())),
        Value::ListMots(l) => Value::ListMots(Rc::new(kept.iter().map(|&i| l[i].clone()).collect())),
        other => other.clone(),
    }])
}

/// One object without its repeats.
fn unique(o: &Value, eq: Equality) -> Value {
    if let Value::Mesh(m) = o {
        return Value::Mesh(Rc::new(unique_elements(m)));
    }
    let mut kept: Vec<usize> = Vec::new();
    for i in 0..len(o) {
        if !kept.iter().any(|&k| eq.items(o, i, o, k)) {
            kept.push(i);
        }
    }
    match o {
        Value::ListEnti(l) => Value::ListEnti(Rc::new(kept.iter().map(|&i| l[i]).collect())),
        Value::ListReel(l) => Value::ListReel(Rc::new(kept.iter().map(|&i| l[i]).collect())),
        Value::ListMots(l) => Value::ListMots(Rc::new(kept.iter().map(|&i| l[i].clone()).collect())),
        other => other.clone(),
    }
}

/// The mesh without elements that repeat one before them (same type, same
/// nodes in any order, whatever the colour).
fn unique_elements(m: &Mesh) -> Mesh {
    let mut seen = HashSet::new();
    let parts = m
        .parts
        .iter()
        .map(|p| {
            let mut conn = Vec::with_capacity(p.conn.len());
            for e in p.elems() {
                let mut key = e.to_vec();
                key.sort_unstable();
                if seen.insert((p.ty, key)) {
                    conn.extend_from_slice(e);
                }
            }
            Part { conn, ..p.clone() }
        })
        .filter(|p| !p.is_empty())
        .collect();
    Mesh { parts }
}
