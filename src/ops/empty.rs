//! VIDE: empty objects of a type (and subtype), to start a loop that
//! grows an object with ET without testing whether it exists yet.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::{ElemType, Mesh, Part};
use crate::value::model::Model;
use crate::value::rigidity::Subtype;
use crate::value::{Chargement, Chpoint, Evolution, Key, Mchaml, Nature, Rigidite, Table, Value};
use std::cell::RefCell;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "VIDE",
    signature: "OBJ1 (OBJ2 …) = VIDE GROUP1 (GROUP2 …) | TAB = VIDE 'TABU' (LISTENTI|LISTREEL|LISTMOTS) GROUP1 (GROUP2 …)   (GROUP: TYPE(/SUBTYPE)(*N))",
    doc: "Empty objects: MAILLAGE (/element type, OPTI ELEM by default), CHPOINT (/DIFFUS|DISCRET), MCHAML, MMODEL, RIGIDITE (/RIGIDITE|MASSE), EVOLUTIO, LISTENTI, LISTREEL, LISTMOTS, LISTCHPO, TABLE (/subtype), CHARGEME; N of each with *N. With 'TABU' they are put in a table, at the keys of the list, then at integers counting the objects.",
    example: "m = vide 'MAILLAGE'/'TRI3' ;",
    f: vide,
}];

fn vide(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let tabular = a.keyword(&["TABU"]).is_some();
    let keys: Vec<Key> = if tabular {
        a.opt_with(|v| match v {
            Value::ListEnti(l) => Some(l.iter().map(|i| Key::Int(*i)).collect()),
            Value::ListReel(_) | Value::ListMots(_) => Some(list_keys(v)),
            _ => None,
        })
        .unwrap_or_default()
    } else {
        Vec::new()
    };
    let mut out = Vec::new();
    while let Some(ty) = a.word() {
        let sub = if a.keyword_next(&["/"]).is_some() {
            Some(a.word().ok_or_else(|| a.missing(&format!("the subtype of {} after '/'", ty)))?)
        } else {
            None
        };
        let n = if a.sign_like_star() {
            let n = a.opt_num_right().ok_or_else(|| a.missing("a number of objects after '*'"))?;
            if n.fract() != 0.0 || !(0.0..=1e6).contains(&n) {
                return Err(a.err(format!("cannot make {} objects", n)));
            }
            n as usize
        } else {
            1
        };
        let v = empty(it, a, &ty, sub.as_deref())?;
        out.extend(std::iter::repeat_n(v, n));
    }
    if out.is_empty() {
        return Err(a.missing("the type of the empty object (MAILLAGE, CHPOINT, LISTREEL, …)"));
    }
    if !tabular {
        return Ok(out);
    }
    let mut t = Table::new();
    for (i, v) in out.into_iter().enumerate() {
        let k = keys.get(i).cloned().unwrap_or(Key::Int(i as i64 + 1));
        t.set(k, v);
    }
    Ok(vec![Value::Table(Rc::new(RefCell::new(t)))])
}

fn list_keys(v: &Value) -> Vec<Key> {
    match v {
        Value::ListReel(l) => l.iter().map(|x| Key::from_value(&Value::Float(*x))).collect(),
        Value::ListMots(l) => l.iter().map(|w| Key::Mot(w.clone())).collect(),
        _ => Vec::new(),
    }
}

/// One empty object of type `ty` (8 letters count, as in Cast3M).
fn empty(it: &Interp, a: &Args, ty: &str, sub: Option<&str>) -> Result<Value> {
    let ty: String = ty.trim().to_uppercase().chars().take(8).collect();
    let sub = sub.map(|s| s.trim().to_uppercase());
    let no_subtype = |v: Value| match &sub {
        Some(s) => Err(a.err(format!("an empty {} has no subtype ({} given)", ty, s))),
        None => Ok(v),
    };
    match ty.as_str() {
        "MAILLAGE" => {
            let name = sub.clone().unwrap_or_else(|| it.opts.elem.to_uppercase());
            let et = ElemType::from_name(&name).ok_or_else(|| a.err(format!("{} is not an element type", name)))?;
            Ok(Value::Mesh(Rc::new(Mesh::single(Part::new(et)))))
        }
        "CHPOINT" => {
            let nature = match sub.as_deref() {
                None => Nature::Indeter,
                Some(s) if s.starts_with("DIFF") => Nature::Diffus,
                Some(s) if s.starts_with("DISC") => Nature::Discret,
                Some(s) => return Err(a.err(format!("{} is not a nature of CHPOINT (DIFFUS or DISCRET)", s))),
            };
            Ok(Value::Chpo(Rc::new(Chpoint::new(nature))))
        }
        "RIGIDITE" => {
            let subtype = match sub.as_deref() {
                None => Subtype::Rigidite,
                Some(s) if s.starts_with("RIGI") => Subtype::Rigidite,
                Some(s) if s.starts_with("MASS") => Subtype::Masse,
                Some(s) if s.starts_with("BLOC") => Subtype::Blocage,
                Some(s) => return Err(a.err(format!("{} is not a subtype of RIGIDITE gibi knows", s))),
            };
            Ok(Value::Rigi(Rc::new(Rigidite::new(subtype))))
        }
        "TABLE" => Ok(Value::Table(Rc::new(RefCell::new(match &sub {
            Some(s) => Table::with_subtype(s),
            None => Table::new(),
        })))),
        // The subtype of a curve (REEL or COMPLEXE) changes nothing here.
        "EVOLUTIO" => Ok(Value::Evol(Rc::new(Evolution::default()))),
        "MCHAML" => no_subtype(Value::Mchaml(Rc::new(Mchaml::default()))),
        "MMODEL" => no_subtype(Value::Model(Rc::new(Model { zones: Vec::new(), ties: Vec::new() }))),
        "LISTENTI" => no_subtype(Value::ListEnti(Rc::new(Vec::new()))),
        "LISTREEL" => no_subtype(Value::ListReel(Rc::new(Vec::new()))),
        "LISTMOTS" => no_subtype(Value::ListMots(Rc::new(Vec::new()))),
        "LISTCHPO" => no_subtype(Value::ListChpo(Rc::new(Vec::new()))),
        "CHARGEME" => no_subtype(Value::Charge(Rc::new(Chargement::default()))),
        _ => Err(a.err(format!("gibi makes no empty {}", ty))),
    }
}
