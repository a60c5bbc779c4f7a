//! The line layer Cast3M applies before tokenising (language.md §1, §9):
//! a line with `*` in column 1 is a comment even inside a multi-line
//! instruction, and a quote must close on its own line. Comment lines are
//! blanked in place so that every byte offset still points into the
//! original text.

use crate::error::{Error, Result};
use crate::source::Span;

/// Blank the column-1 comment lines (never fails: quotes are checked one
/// instruction at a time, so that text after `FIN ;` is never judged).
pub fn blank_comments(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for line in text.split_inclusive('\n') {
        if line.starts_with('*') {
            // Replace every byte but the end of line: lengths are preserved.
            for b in line.bytes() {
                out.push(if b == b'\n' || b == b'\r' { b as char } else { ' ' });
            }
        } else {
            out.push_str(line);
        }
    }
    out
}

/// End (exclusive) of the instruction starting at `from`: just after the
/// first `;` outside quotes, or None when the text ends first. A quote
/// never spans lines, so a line break closes any open quote.
pub fn instruction_end(text: &str, from: usize) -> Option<usize> {
    let mut quoted = false;
    for (i, b) in text.as_bytes()[from..].iter().enumerate() {
        match b {
            b'\'' => quoted = !quoted,
            b'\n' => quoted = false,
            b';' if !quoted => return Some(from + i + 1),
            _ => {}
        }
    }
    None
}

/// Check that every quote of `chunk` (which starts at byte `offset` of the
/// text, outside any quote) closes on its own line.
pub fn check_quotes(chunk: &str, offset: usize) -> Result<()> {
    let mut start = offset;
    for line in chunk.split_inclusive('\n') {
        let mut open: Option<usize> = None;
        for (i, c) in line.char_indices() {
            if c == '\'' {
                open = match open {
                    Some(_) => None,
                    None => Some(i),
                };
            }
        }
        // `''` inside a string toggles twice, so only a real unclosed quote
        // survives the scan.
        if let Some(i) = open {
            return Err(Error::syntax(
                "this quote is not closed on its line (a quoted text must open and close on the same line)",
                Span::new(start + i, start + line.trim_end().len().max(i + 1)),
            ));
        }
        start += line.len();
    }
    Ok(())
}

/// The `(` that opens a group nested deeper than `max`, if any (parsing
/// and evaluation recurse on groups: deep nesting must be an error, not a
/// stack overflow).
pub fn too_deep_paren(chunk: &str, max: usize) -> Option<usize> {
    let mut depth = 0usize;
    let mut quoted = false;
    for (i, b) in chunk.bytes().enumerate() {
        match b {
            b'\'' => quoted = !quoted,
            b'\n' => quoted = false,
            b'(' if !quoted => {
                depth += 1;
                if depth > max {
                    return Some(i);
                }
            }
            b')' if !quoted => depth = depth.saturating_sub(1),
            _ => {}
        }
    }
    None
}

/// Squeezed length of an instruction (blank runs count as one), for the
/// 500-character limit of Cast3M.
pub fn squeezed_len(text: &str) -> usize {
    let mut n = 0;
    let mut blank = false;
    let mut quoted = false;
    for c in text.trim().chars() {
        if c == '\'' {
            quoted = !quoted;
        }
        if c.is_whitespace() && !quoted {
            if !blank {
                n += 1;
            }
            blank = true;
        } else {
            n += 1;
            blank = false;
        }
    }
    n
}
