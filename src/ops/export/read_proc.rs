//! LIRE 'PROC': procedures from a file, as if the deck defined them.

use crate::error::{Error, Result};
use crate::eval::args::Args;
use crate::eval::Interp;
use crate::value::Value;

/// LIRE 'PROC' file ('NAME'): every procedure of a `$$$$ NAME` file (or
/// only NAME), the DEBPROCs of a plain file, or a plain file of
/// instructions as the procedure NAME.
pub(super) fn lire(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let file = a.req::<String>()?;
    let only = a.opt::<String>().map(|s| s.trim().to_uppercase());
    let path = it.files.check_read(&file)?;
    let bytes = crate::io::read_file(&path).map_err(|e| Error::io(e.0))?;
    let (procs, source) = crate::eval::library::file_procs(&file, &bytes, only.as_deref())?;
    it.define_file_procs(procs, source);
    Ok(vec![])
}
