//! The pest parser. Nothing outside `src/syntax` may name it.

#[derive(pest_derive::Parser)]
#[grammar = "grammar/gibiane.pest"]
pub struct GibianeParser;
