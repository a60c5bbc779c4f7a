//! INSE: a list with one more item, at a given place.

use super::lists::{list_len, AnyList};
use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::{Chpoint, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "INSE",
    signature: "INSE LISTREEL|LISTENTI|LISTMOTS|LISTCHPO N FLOTTANT|ENTIER|MOT|CHPOINT",
    doc: "A copy of the list with the object inserted at place N (1 to the length + 1): it becomes item N.",
    example: "l = inse (prog 1. 3.) 2 2. ;",
    f: inse,
}];

fn inse(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let list = match a.opt::<AnyList>() {
        Some(AnyList(l)) => l,
        None => Value::ListChpo(a.req::<Rc<Vec<Rc<Chpoint>>>>()?),
    };
    let n = match &list {
        Value::ListChpo(l) => l.len(),
        l => list_len(l).unwrap_or(0),
    };
    let i = a.req::<i64>()?;
    let at = usize::try_from(i)
        .ok()
        .and_then(|i| i.checked_sub(1))
        .filter(|&i| i <= n)
        .ok_or_else(|| a.err(format!("place {} is outside 1..{} (the list has {} items)", i, n + 1, n)))?;
    Ok(vec![match list {
        Value::ListReel(l) => {
            let mut v = l.to_vec();
            v.insert(at, a.req::<f64>()?);
            Value::ListReel(Rc::new(v))
        }
        Value::ListEnti(l) => {
            let mut v = l.to_vec();
            v.insert(at, a.req::<i64>()?);
            Value::ListEnti(Rc::new(v))
        }
        Value::ListMots(l) => {
            let mut v = l.to_vec();
            v.insert(at, a.req::<String>()?);
            Value::ListMots(Rc::new(v))
        }
        Value::ListChpo(l) => {
            let mut v = l.to_vec();
            v.insert(at, a.req::<Rc<Chpoint>>()?);
            Value::ListChpo(Rc::new(v))
        }
        other => other,
    }])
}
