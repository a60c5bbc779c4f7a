//! Tests with real numbers for the meshing operators.

mod dall;
mod edit;
mod extract;
mod helpers;
mod line;
mod surf;
mod sweep;
