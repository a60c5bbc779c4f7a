//! Reading a text one instruction at a time, as Cast3M does: each
//! instruction (up to its `;`) is parsed on its own, blocks are matched as
//! they arrive, and a complete top-level statement is handed out before
//! the next instruction is even looked at. So the statements before a
//! syntax error run, and nothing after a top-level `FIN ;` is read.

use super::ast::{Instr, Stmt};
use super::parser::{GibianeParser, Rule};
use super::structure::Builder;
use super::{lower, pest_error, prepass, MAX_INSTRUCTION, MAX_PAREN_DEPTH};
use crate::error::{Error, Result};
use crate::source::Span;
use pest::Parser;

/// An iterator over the top-level statements of a text. It stops after
/// the first error and after a top-level `FIN ;`.
pub struct Reader {
    /// The text with column-1 comment lines blanked (same byte offsets).
    text: String,
    pos: usize,
    /// Where `text` starts in the whole source (spans are given in the
    /// whole source's offsets).
    base: usize,
    /// Whether an SI still open at the end closes there (decks and
    /// procedure files, read to run) or is an error (the REPL asks whether
    /// an entry is complete).
    lenient_end: bool,
    blocks: Builder,
    done: bool,
}

impl Reader {
    pub fn new(text: &str) -> Self {
        Reader {
            text: prepass::blank_comments(text),
            pos: 0,
            base: 0,
            lenient_end: false,
            blocks: Builder::default(),
            done: false,
        }
    }

    /// A reader for a text that is run to its end (a deck): an SI left
    /// open ends with the text, as in Cast3M.
    pub fn to_run(text: &str) -> Self {
        Reader { lenient_end: true, ..Reader::new(text) }
    }

    /// Warnings about forms Cast3M lets pass (an extra FINSI, an SI that
    /// the end of the text closes), with their spans, since last asked.
    pub fn take_warnings(&mut self) -> Vec<(String, Span)> {
        std::mem::take(&mut self.blocks.warnings)
    }

    /// Read only `text[start..end]`, with spans in the offsets of the whole
    /// `text` (one procedure of a procedure library file: the file's other
    /// procedures are not even looked at).
    pub fn range(text: &str, start: usize, end: usize) -> Self {
        let text = prepass::blank_comments(&text[start..end]);
        Reader { text, pos: 0, base: start, lenient_end: true, blocks: Builder::default(), done: false }
    }

    /// The next instruction, or None at the end of the text.
    fn instruction(&mut self) -> Option<Result<Instr>> {
        let start = self.pos;
        let end = match prepass::instruction_end(&self.text, start) {
            Some(e) => e,
            None if self.text[start..].trim().is_empty() => return None,
            None => self.text.len(),
        };
        self.pos = end;
        Some(parse_one(&self.text[start..end], self.base + start))
    }
}

impl Iterator for Reader {
    type Item = Result<Stmt>;

    fn next(&mut self) -> Option<Result<Stmt>> {
        if let Some(s) = self.blocks.ready.pop_front() {
            return Some(Ok(s));
        }
        while !self.done {
            let r = match self.instruction() {
                None => {
                    self.done = true;
                    if self.lenient_end {
                        return self.blocks.finish_text().transpose();
                    }
                    return self.blocks.finish().err().map(Err);
                }
                Some(Ok(ins)) => self.blocks.push(ins),
                Some(Err(e)) => self.blocks.push_broken(e),
            };
            match r {
                Err(e) => {
                    self.done = true;
                    return Some(Err(e));
                }
                Ok(None) => {}
                Ok(Some(s)) => {
                    // A top-level `FIN ;` ends the reading: what follows may
                    // be notes or anything else, never looked at.
                    self.done = matches!(s, Stmt::End { .. });
                    return Some(Ok(s));
                }
            }
        }
        None
    }
}

/// Parse one instruction: `chunk` is the text from the end of the previous
/// instruction up to and including its `;` (or to the end of the text when
/// the `;` is missing), and starts at byte `base`.
fn parse_one(chunk: &str, base: usize) -> Result<Instr> {
    prepass::check_quotes(chunk, base)?;
    if let Some(i) = prepass::too_deep_paren(chunk, MAX_PAREN_DEPTH) {
        return Err(Error::syntax(
            format!("parentheses are nested more than {} deep", MAX_PAREN_DEPTH),
            Span::new(base + i, base + i + 1),
        ));
    }
    let pairs = GibianeParser::parse(Rule::program, chunk).map_err(|e| pest_error(e, chunk, base))?;
    for program in pairs {
        for p in program.into_inner() {
            if p.as_rule() != Rule::instruction {
                continue;
            }
            let s = p.as_span();
            if prepass::squeezed_len(s.as_str()) > MAX_INSTRUCTION {
                return Err(Error::syntax(
                    format!("an instruction cannot exceed {} characters (blanks squeezed)", MAX_INSTRUCTION),
                    Span::new(base + s.start(), base + s.end()),
                ));
            }
            return lower::instruction(p, base);
        }
    }
    // Only blanks before the end of the text: the caller never asks that.
    Err(Error::syntax("expected an instruction", Span::new(base, base + chunk.len().max(1))))
}
