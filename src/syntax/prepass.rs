//! The line layer Cast3M applies before tokenising (language.md §1, §9):
//! a line with `*` in column 1 is a comment even inside a multi-line
//! instruction, and a quote must close on its own line. Comment lines are
//! blanked in place so that every byte offset still points into the
//! original text.

use crate::error::{Error, Result};
use crate::source::Span;

/// Blank the column-1 comment lines and check quotes line by line.
pub fn prepare(text: &str) -> Result<String> {
    let mut out = String::with_capacity(text.len());
    let mut offset = 0;
    for line in text.split_inclusive('\n') {
        if line.starts_with('*') {
            // Replace every byte but the end of line: lengths are preserved.
            for b in line.bytes() {
                out.push(if b == b'\n' || b == b'\r' { b as char } else { ' ' });
            }
        } else {
            check_quotes(line, offset)?;
            out.push_str(line);
        }
        offset += line.len();
    }
    Ok(out)
}

fn check_quotes(line: &str, offset: usize) -> Result<()> {
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
    match open {
        Some(i) => Err(Error::syntax(
            "this quote is not closed on its line (a quoted text must open and close on the same line)",
            Span::new(offset + i, offset + line.trim_end().len().max(i + 1)),
        )),
        None => Ok(()),
    }
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
