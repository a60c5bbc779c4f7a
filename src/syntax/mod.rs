//! Text -> [`ast::Program`]. The only module that names pest: the grammar in
//! `grammar/gibiane.pest` gives a flat list of instructions, [`lower`] turns
//! pest pairs into our AST with byte spans, and [`structure`] rebuilds
//! SI/REPETER/DEBPROC blocks.

pub mod ast;
mod errors;
mod lower;
mod parser;
mod prepass;
mod structure;
pub use structure::truncate_name as structure_name;

use crate::error::{Error, Result};
use crate::source::Span;
use ast::{Instr, Program};
use parser::{GibianeParser, Rule};
use pest::Parser;

/// Longest instruction Cast3M accepts, blanks squeezed (error 3).
pub const MAX_INSTRUCTION: usize = 500;

/// Parse a whole source text.
pub fn parse(text: &str) -> Result<Program> {
    let instrs = parse_instructions(text)?;
    structure::build(instrs)
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
    match parse_instructions(text) {
        Err(e) => {
            let end = text.trim_end().len() as u32;
            // A failure at the very end means the text stops mid-instruction.
            if e.span.is_some_and(|s| s.start >= end) && e.message.starts_with("unexpected end") {
                Completeness::Incomplete
            } else {
                Completeness::Invalid(e)
            }
        }
        Ok(instrs) => match structure::build(instrs) {
            Ok(p) => Completeness::Complete(p),
            Err(e) if e.message.contains("never closed") => Completeness::Incomplete,
            Err(e) => Completeness::Invalid(e),
        },
    }
}

fn parse_instructions(text: &str) -> Result<Vec<Instr>> {
    let prepared = prepass::prepare(text)?;
    let pairs = GibianeParser::parse(Rule::program, &prepared).map_err(|e| pest_error(e, &prepared))?;
    let mut out = Vec::new();
    for program in pairs {
        for p in program.into_inner() {
            if p.as_rule() != Rule::instruction {
                continue;
            }
            let s = p.as_span();
            if prepass::squeezed_len(s.as_str()) > MAX_INSTRUCTION {
                return Err(Error::syntax(
                    format!("an instruction cannot exceed {} characters (blanks squeezed)", MAX_INSTRUCTION),
                    Span::new(s.start(), s.end()),
                ));
            }
            out.push(lower::instruction(p)?);
        }
    }
    Ok(out)
}

/// Turn a pest failure into a sentence about Gibiane.
fn pest_error(e: pest::error::Error<Rule>, text: &str) -> Error {
    let pos = match e.location {
        pest::error::InputLocation::Pos(p) => p,
        pest::error::InputLocation::Span((s, _)) => s,
    };
    let at_end = text[pos.min(text.len())..].trim().is_empty();
    let span = Span::new(pos, (pos + 1).min(text.len().max(pos)));
    if at_end {
        let open = paren_depth(text);
        let msg = if open > 0 {
            "unexpected end of text: a '(' is not closed".to_string()
        } else {
            "unexpected end of text: the instruction is not ended by ';'".to_string()
        };
        return Error::syntax(msg, Span::new(text.trim_end().len(), text.trim_end().len() + 1));
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
