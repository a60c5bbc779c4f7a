//! gibi: an embeddable interpreter for Gibiane, the command language of Cast3M.

pub mod fem;
pub mod solve;
