//! The ecosystem layer: files other tools read or write.
//!
//! - [`vtk`]: ParaView `.vtu` meshes with point and cell fields, `.pvd`
//!   time collections;
//! - [`gmsh`]: Gmsh `.msh` meshes (formats 2.2 and 4.1, ASCII);
//! - [`plot`]: meshes, fields and curves as SVG or PNG images;
//! - [`mtx`]: MatrixMarket dumps of assembled matrices;
//! - [`avs`]: AVS UCD ASCII meshes with node, cell and model data;
//! - [`nastran`]: Nastran bulk data (grids, elements, constraints, loads);
//! - [`stl`]: STL triangle surfaces (ASCII or binary in, binary out);
//! - [`csv_table`]: numeric columns of delimited text files.
//!
//! Like `solve`, this layer knows nothing of the language: it works on the
//! FE core's plain data (`fem::mesh`) and on numbers and names. The Gibiane
//! operators that call it live in `ops/export/`. It prints nothing; every
//! failure is an [`IoError`] with a message a user can act on.

pub mod avs;
pub mod csv_table;
pub mod gmsh;
pub mod mtx;
pub mod named_meshes;
pub mod nastran;
pub mod plot;
pub mod stl;
pub mod vtk;

use std::fmt;
use std::path::Path;

/// A failure to read or write an ecosystem file.
#[derive(Debug, Clone, PartialEq)]
pub struct IoError(pub String);

impl fmt::Display for IoError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for IoError {}

pub type Result<T> = std::result::Result<T, IoError>;

fn err<T>(msg: impl Into<String>) -> Result<T> {
    Err(IoError(msg.into()))
}

/// Write a whole file, naming the path in the error. A symbolic link in
/// the final component is not followed (the file policy checked the real
/// path; a link put there since would lead elsewhere).
pub(crate) fn write_file(path: &Path, bytes: &[u8]) -> Result<()> {
    use std::io::Write;
    let mut o = std::fs::OpenOptions::new();
    o.write(true).create(true).truncate(true);
    no_follow(&mut o);
    let fail = |e: std::io::Error| IoError(format!("cannot write {}: {}", path.display(), link_error(e)));
    o.open(path).map_err(fail)?.write_all(bytes).map_err(fail)
}

/// Add to the end of a file (created if need be), not following a
/// symbolic link in the final component (see [`write_file`]).
pub(crate) fn append_file(path: &Path, bytes: &[u8]) -> Result<()> {
    use std::io::Write;
    let mut o = std::fs::OpenOptions::new();
    o.append(true).create(true);
    no_follow(&mut o);
    let fail = |e: std::io::Error| IoError(format!("cannot write {}: {}", path.display(), link_error(e)));
    o.open(path).map_err(fail)?.write_all(bytes).map_err(fail)
}

/// Read a whole file, not following a symbolic link in the final
/// component (see [`write_file`]).
pub(crate) fn read_file(path: &Path) -> Result<Vec<u8>> {
    use std::io::Read;
    let mut o = std::fs::OpenOptions::new();
    o.read(true);
    no_follow(&mut o);
    let fail = |e: std::io::Error| IoError(format!("cannot read {}: {}", path.display(), link_error(e)));
    let mut bytes = Vec::new();
    o.open(path).map_err(fail)?.read_to_end(&mut bytes).map_err(fail)?;
    Ok(bytes)
}

#[cfg(unix)]
fn no_follow(o: &mut std::fs::OpenOptions) {
    use std::os::unix::fs::OpenOptionsExt;
    o.custom_flags(libc::O_NOFOLLOW);
}

#[cfg(not(unix))]
fn no_follow(_: &mut std::fs::OpenOptions) {}

/// O_NOFOLLOW on a link fails with ELOOP ("too many levels of symbolic
/// links"), which would puzzle a user: say what it is.
fn link_error(e: std::io::Error) -> String {
    #[cfg(unix)]
    if e.raw_os_error() == Some(libc::ELOOP) {
        return "it is a symbolic link, which is not followed".into();
    }
    e.to_string()
}
