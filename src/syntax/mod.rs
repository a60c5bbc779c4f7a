//! Text -> statements. The only module that names pest: [`Reader`] cuts the
//! text into instructions and hands them one at a time to the grammar in
//! `grammar/gibiane.pest`, `lower` turns pest pairs into our AST with
//! byte spans, and `structure` rebuilds SI/REPETER/DEBPROC blocks as the
//! instructions arrive. [`parse`] collects them into a [`ast::Program`].

pub mod ast;
mod errors;
mod lower;
mod parser;
mod prepass;
mod reader;
mod structure;
pub use reader::Reader;
pub use structure::truncate_name as structure_name;
pub use structure::MAX_BLOCK_DEPTH;

use crate::error::{Error, Result};
use crate::source::Span;
use ast::Program;
use parser::Rule;

/// Longest instruction Cast3M accepts, blanks squeezed (error 3).
pub const MAX_INSTRUCTION: usize = 500;

/// Deepest nesting of parentheses in one instruction. Parsing and
/// evaluation recurse on groups; the 500-character limit already keeps
/// real instructions far below this.
pub const MAX_PAREN_DEPTH: usize = 100;

/// Parse a whole source text, up to a top-level `FIN ;` (what follows it
/// is never read, as in Cast3M).
pub fn parse(text: &str) -> Result<Program> {
    let stmts = Reader::new(text).collect::<Result<Vec<_>>>()?;
    Ok(Program { stmts })
}

/// Whether a REPL entry is a complete program, needs more lines, or is
/// wrong whatever follows. Asks the parser, never counts characters.
#[derive(Debug)]
pub enum Completeness {
    Complete(Program),
    Incomplete,
    Invalid(Error),
}

pub fn check_complete(text: &str) -> Completeness {
    if text.trim().is_empty() {
        return Completeness::Incomplete;
    }
    match parse(text) {
        Ok(p) => Completeness::Complete(p),
        Err(e) => {
            let end = text.trim_end().len() as u32;
            // A failure at the very end means the text stops mid-instruction;
            // an open block means more lines are coming.
            let at_end = e.span.is_some_and(|s| s.start >= end) && e.message.starts_with("unexpected end");
            if at_end || e.message.contains("never closed") {
                Completeness::Incomplete
            } else {
                Completeness::Invalid(e)
            }
        }
    }
}

/// Turn a pest failure into a sentence about Gibiane.
/// `text` is one instruction, starting at byte `base` of the whole text.
fn pest_error(e: pest::error::Error<Rule>, text: &str, base: usize) -> Error {
    let pos = match e.location {
        pest::error::InputLocation::Pos(p) => p,
        pest::error::InputLocation::Span((s, _)) => s,
    };
    let at_end = text[pos.min(text.len())..].trim().is_empty();
    let span = Span::new(base + pos, base + (pos + 1).min(text.len().max(pos)));
    if at_end {
        let open = paren_depth(text);
        let msg = if open > 0 {
            "unexpected end of text: a '(' is not closed".to_string()
        } else {
            "unexpected end of text: the instruction is not ended by ';'".to_string()
        };
        let end = base + text.trim_end().len();
        return Error::syntax(msg, Span::new(end, end + 1));
    }
    let found = text[pos..].chars().next().unwrap_or(' ');
    let msg = match found {
        ')' => "this ')' closes no '('".to_string(),
        ';' if paren_depth(&text[..pos]) > 0 => "';' ends the instruction while a '(' is still open".to_string(),
        '=' => "'=' may appear only once, after the names that receive the results".to_string(),
        _ => {
            let expected = match &e.variant {
                pest::error::ErrorVariant::ParsingError { positives, .. } if !positives.is_empty() => {
                    let names: Vec<&str> = positives.iter().map(errors::rule_name).collect();
                    format!(", expected {}", names.join(" or "))
                }
                _ => String::new(),
            };
            format!("unexpected '{}'{}", found, expected)
        }
    };
    Error::syntax(msg, span)
}

fn paren_depth(text: &str) -> i32 {
    let mut depth = 0;
    let mut quoted = false;
    for c in text.chars() {
        match c {
            '\'' => quoted = !quoted,
            '\n' => quoted = false,
            '(' if !quoted => depth += 1,
            ')' if !quoted => depth -= 1,
            _ => {}
        }
    }
    depth
}

#[cfg(test)]
mod tests;
