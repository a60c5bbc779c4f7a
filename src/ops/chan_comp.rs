//! `CHAN 'COMP'`: a field (CHPOINT or MCHAML) with some components renamed,
//! either its only component (one new name) or the i-th of a list of old
//! names to the i-th of a list of new ones (chan.notice). A CHPOINT may
//! also take a new nature ('NATU' …).

use super::fields::nature_word;
use super::Args;
use crate::error::Result;
use crate::value::{Chpoint, Mchaml, Value};
use std::collections::BTreeMap;
use std::rc::Rc;

pub(crate) fn rename_components(a: &mut Args) -> Result<Vec<Value>> {
    let (old, new) = names(a)?;
    let field = a.opt_with(|v| match v {
        Value::Chpo(_) | Value::Mchaml(_) => Some(v.clone()),
        _ => None,
    });
    let nature = nature_word(a)?;
    match field {
        Some(Value::Chpo(ch)) => {
            let old = pair_up(a, old, &new, ch.components())?;
            let mut out = Chpoint::new(nature.unwrap_or(ch.nature));
            for (n, c, v) in ch.entries() {
                out.add(n, renamed(c, &old, &new), v, false);
            }
            Ok(vec![Value::Chpo(Rc::new(out))])
        }
        Some(Value::Mchaml(m)) => {
            let mut present: Vec<String> = Vec::new();
            for z in &m.zones {
                for c in z.comps.iter().chain(z.constants.keys()).chain(z.vectors.keys()).chain(z.laws.keys()) {
                    if !present.contains(c) {
                        present.push(c.clone());
                    }
                }
            }
            let old = pair_up(a, old, &new, present)?;
            let mut out = Mchaml::clone(&m);
            for z in out.zones.iter_mut() {
                for c in z.comps.iter_mut() {
                    *c = renamed(c, &old, &new).to_string();
                }
                z.constants = rekey(&z.constants, &old, &new);
                z.vectors = rekey(&z.vectors, &old, &new);
                z.laws = rekey(&z.laws, &old, &new);
            }
            Ok(vec![Value::Mchaml(Rc::new(out))])
        }
        _ => Err(a.missing("CHPOINT or MCHAML")),
    }
}

/// One new name (MOT) or the lists of old and new names (LISTMOTS LISTMOTS).
/// Names are 4 characters: trailing blanks are dropped.
fn names(a: &mut Args) -> Result<(Option<Vec<String>>, Vec<String>)> {
    let trim = |l: &[String]| l.iter().map(|c| c.trim_end().to_string()).collect::<Vec<_>>();
    if let Some(first) = a.opt::<Rc<Vec<String>>>() {
        let second = a.req::<Rc<Vec<String>>>()?;
        return Ok((Some(trim(&first)), trim(&second)));
    }
    let w = a.word_not_operator().ok_or_else(|| a.missing("a new component name or two LISTMOTS"))?;
    Ok((None, vec![w.trim_end().to_string()]))
}

/// The old names: as given, or the field's only component for one new name.
fn pair_up(a: &Args, old: Option<Vec<String>>, new: &[String], present: Vec<String>) -> Result<Vec<String>> {
    let old = match old {
        Some(o) => o,
        None if present.len() == 1 => present,
        None => {
            return Err(a.err(format!(
                "one new name is for a field of one component; this one has {} ({}): give the old and new names as two LISTMOTS",
                present.len(),
                present.join(" ")
            )))
        }
    };
    if old.len() != new.len() {
        return Err(a.err(format!("{} component(s) to rename with {} name(s)", old.len(), new.len())));
    }
    Ok(old)
}

fn renamed<'a>(c: &'a str, old: &[String], new: &'a [String]) -> &'a str {
    old.iter().position(|x| x == c).map_or(c, |i| new[i].as_str())
}

fn rekey<T: Clone>(m: &BTreeMap<String, T>, old: &[String], new: &[String]) -> BTreeMap<String, T> {
    m.iter().map(|(k, v)| (renamed(k, old, new).to_string(), v.clone())).collect()
}
