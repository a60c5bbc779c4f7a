//! LIRE 'CSV': the columns of a delimited text file as LISTREELs.

use crate::error::Result;
use crate::eval::args::Args;
use crate::eval::Interp;
use crate::io::csv_table;
use crate::value::{Key, Table, Value};
use std::cell::RefCell;
use std::rc::Rc;

/// LIRE 'CSV' file ('DEBU' line) ('SEPA' char): a TABLE of LISTREEL
/// indexed 1..N, one per column; ';' separates fields by default.
pub(super) fn lire(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let file = a.req::<String>()?;
    let mut first = 1usize;
    let mut sep = b';';
    while let Some(k) = a.keyword(&["DEBU", "SEPA"]) {
        if k == "DEBU" {
            let n = a.req::<i64>()?;
            first = usize::try_from(n)
                .ok()
                .filter(|&n| n >= 1)
                .ok_or_else(|| a.err(format!("'DEBU' takes a line number from 1 on, found {}", n)))?;
        } else {
            let s = a.req::<String>()?;
            sep = match s.as_bytes() {
                [c] if c.is_ascii() => *c,
                _ => return Err(a.err(format!("'SEPA' takes one ASCII character, found '{}'", s))),
            };
        }
    }
    let path = it.files.check_read(&file)?;
    let cols = csv_table::read_columns(&path, first, sep).map_err(|e| a.err(format!("'{}': {}", file, e.0)))?;
    let mut t = Table::new();
    for (k, c) in cols.into_iter().enumerate() {
        t.set(Key::Int(k as i64 + 1), Value::ListReel(Rc::new(c)));
    }
    Ok(vec![Value::Table(Rc::new(RefCell::new(t)))])
}
