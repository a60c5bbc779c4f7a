//! `NOMC MOT1 CHE1 | NOMC LISTMOT1 LISTMOT2 CHE1` (nomc.notice): an element
//! field with components renamed. One name renames a field's single
//! component (a procedure names a scalar product after the component it
//! stands for); two lists rename each listed component that is present.

use super::Args;
use crate::error::Result;
use crate::value::{Mchaml, Value};
use std::rc::Rc;

pub(crate) fn nomc(a: &mut Args, m: &Mchaml) -> Result<Vec<Value>> {
    let first = names(a).ok_or_else(|| a.missing("new component names"))?;
    let second = names(a);
    let mut out = m.clone();
    for z in out.zones.iter_mut() {
        let present: Vec<String> = z.comps.iter().chain(z.constants.keys()).cloned().collect();
        let (old, new) = match &second {
            Some(s) => (first.clone(), s.clone()),
            None => (present.clone(), first.clone()),
        };
        if old.len() != new.len() {
            return Err(a.err(format!("{} component(s) to rename with {} name(s)", old.len(), new.len())));
        }
        let rename = |c: &str| old.iter().position(|x| x == c).map_or(c.to_string(), |i| new[i].clone());
        z.comps = z.comps.iter().map(|c| rename(c)).collect();
        z.constants = std::mem::take(&mut z.constants).into_iter().map(|(k, v)| (rename(&k), v)).collect();
    }
    Ok(vec![Value::Mchaml(Rc::new(out))])
}

/// A LISTMOTS or one word; names are 4 characters, trailing blanks dropped.
fn names(a: &mut Args) -> Option<Vec<String>> {
    let l = match a.opt::<Rc<Vec<String>>>() {
        Some(l) => l.to_vec(),
        None => vec![a.word_not_operator()?],
    };
    Some(l.iter().map(|c| c.trim_end().to_string()).collect())
}
