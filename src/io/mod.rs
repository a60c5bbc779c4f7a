//! The ecosystem layer: files other tools read or write.
//!
//! - [`vtk`]: ParaView `.vtu` meshes with point and cell fields, `.pvd`
//!   time collections;
//! - [`gmsh`]: Gmsh `.msh` meshes (formats 2.2 and 4.1, ASCII);
//! - [`plot`]: meshes, fields and curves as SVG or PNG images;
//! - [`mtx`]: MatrixMarket dumps of assembled matrices.
//!
//! Like `solve`, this layer knows nothing of the language: it works on the
//! FE core's plain data (`fem::mesh`) and on numbers and names. The Gibiane
//! operators that call it live in `ops/export.rs`. It prints nothing; every
//! failure is an [`IoError`] with a message a user can act on.

pub mod gmsh;
pub mod mtx;
pub mod plot;
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

/// Write a whole file, naming the path in the error.
pub(crate) fn write_file(path: &Path, bytes: &[u8]) -> Result<()> {
    std::fs::write(path, bytes).map_err(|e| IoError(format!("cannot write {}: {}", path.display(), e)))
}
