//! SORT 'CHAI': lines of text to the OPTI SORT file, as MESS would show
//! them on the screen (decks write results there, then checksum the file).

use super::{out_path, wrote, Args};
use crate::error::{Error, ErrorKind, Result};
use crate::eval::Interp;
use crate::value::Value;
use std::io::Write;

pub(super) fn sort(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mut parts = Vec::new();
    while let Some(v) = a.opt::<Value>() {
        if !matches!(v, Value::Mot(_) | Value::Int(_) | Value::Float(_)) {
            return Err(a.err(format!("SORT 'CHAI' writes words and numbers, not a {}", v.type_name())));
        }
        parts.push(super::super::io::show(it, &v));
    }
    if parts.is_empty() {
        return Err(a.missing("MOT, ENTIER or FLOTTANT"));
    }
    let name = super::sort_file(it);
    let p = out_path(it, &name)?;
    let append = it.exports.text_written.as_deref() == Some(name.as_str());
    let file = std::fs::OpenOptions::new().create(true).write(true).append(append).truncate(!append).open(&p);
    let res = file.and_then(|mut f| writeln!(f, "{}", parts.join(" ")));
    res.map_err(|e| Error::new(ErrorKind::Write, format!("cannot write {}: {}", p.display(), e)))?;
    if !append {
        wrote(it, &p);
    }
    it.exports.text_written = Some(name);
    Ok(vec![])
}
