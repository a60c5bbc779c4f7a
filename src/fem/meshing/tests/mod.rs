//! Tests with real numbers for the meshing operators.

mod helpers;
