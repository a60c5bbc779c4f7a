//! The one error type of gibi and its renderer.
//!
//! Every error has a kind (which decides the CLI exit code), a message, and
//! — once it has crossed the evaluator — a span in a named source. Operators
//! return errors without a span; the evaluator attaches the call site
//! ([`Error::with_span_if_missing`]) so the innermost location wins.

use crate::solve::SolveError;
use crate::source::{Source, Span};
use std::fmt;
use std::rc::Rc;

/// What went wrong, coarsely: decides exit codes and REPL behaviour.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ErrorKind {
    /// The text is not Gibiane (exit 65).
    Syntax,
    /// An operator or the evaluator refused (exit 70).
    Runtime,
    /// An operator failed inside: a bug of gibi, not of the deck (exit 70).
    /// The session survives it; tests fail on it.
    Internal,
    /// `ERRE n` with a severity that aborts the run (exit 70).
    Abort,
    /// A file could not be read or written, or the host forbade it.
    Io,
    /// Not an error: `FIN ;` reached inside a procedure call.
    Finished,
}

/// A gibi error: kind, message, location and notes.
#[derive(Debug, Clone)]
pub struct Error {
    pub kind: ErrorKind,
    pub message: String,
    pub span: Option<Span>,
    pub source: Option<Rc<Source>>,
    /// Extra lines printed after the excerpt (`usage: …`, objects involved).
    pub notes: Vec<String>,
    /// The procedure calls the error crossed, innermost first
    /// (`in procedure F called at deck.dgibi:12:5`).
    pub trace: Vec<String>,
}

/// Calls shown at each end of a long trace (a runaway recursion crosses
/// 200 calls; the middle of it says nothing more).
const TRACE_ENDS: usize = 3;

impl Error {
    pub fn new(kind: ErrorKind, message: impl Into<String>) -> Self {
        Error { kind, message: message.into(), span: None, source: None, notes: Vec::new(), trace: Vec::new() }
    }
    pub fn runtime(message: impl Into<String>) -> Self {
        Error::new(ErrorKind::Runtime, message)
    }
    pub fn internal(message: impl Into<String>) -> Self {
        Error::new(ErrorKind::Internal, message)
    }
    pub fn syntax(message: impl Into<String>, span: Span) -> Self {
        Error::new(ErrorKind::Syntax, message).at(span)
    }
    pub fn io(message: impl Into<String>) -> Self {
        Error::new(ErrorKind::Io, message)
    }
    pub fn at(mut self, span: Span) -> Self {
        self.span = Some(span);
        self
    }
    pub fn note(mut self, note: impl Into<String>) -> Self {
        self.notes.push(note.into());
        self
    }
    /// Attach a location unless a more precise one is already there.
    pub fn with_span_if_missing(mut self, span: Span, source: &Rc<Source>) -> Self {
        if self.span.is_none() {
            self.span = Some(span);
        }
        if self.source.is_none() {
            self.source = Some(source.clone());
        }
        self
    }

    /// `file:line:col` of the error, when known.
    pub fn location(&self) -> Option<(String, usize, usize)> {
        let (src, span) = (self.source.as_ref()?, self.span?);
        let (l, c) = src.line_col(span.start);
        Some((src.name.clone(), l, c))
    }

    /// The full report: `file:line:col: error: message`, the source line, a
    /// caret under the offending text, then the notes.
    pub fn render(&self) -> String {
        let label = match self.kind {
            ErrorKind::Syntax => "syntax error",
            ErrorKind::Abort => "aborted",
            _ => "error",
        };
        let mut out = String::new();
        match (&self.source, self.span) {
            (Some(src), Some(span)) => {
                let (line, col) = src.line_col(span.start);
                out.push_str(&format!("{}:{}:{}: {}: {}\n", src.name, line, col, label, self.message));
                let text = src.line_text(line);
                let gutter = line.to_string().len();
                out.push_str(&format!("{:w$} |\n", "", w = gutter));
                out.push_str(&format!("{} | {}\n", line, text));
                let (end_line, end_col) = src.line_col(span.end.max(span.start + 1) - 1);
                let width = if end_line == line { end_col + 1 - col } else { text.chars().count() + 1 - col };
                let pad: String = text.chars().take(col - 1).map(|c| if c == '\t' { '\t' } else { ' ' }).collect();
                out.push_str(&format!("{:w$} | {}{}\n", "", pad, "^".repeat(width.max(1)), w = gutter));
            }
            _ => out.push_str(&format!("{}: {}\n", label, self.message)),
        }
        for n in &self.notes {
            out.push_str(&format!("  = {}\n", n));
        }
        let t = &self.trace;
        if t.len() > 2 * TRACE_ENDS + 1 {
            for c in &t[..TRACE_ENDS] {
                out.push_str(&format!("  = {}\n", c));
            }
            out.push_str(&format!("  = … {} more procedure calls …\n", t.len() - 2 * TRACE_ENDS));
            for c in &t[t.len() - TRACE_ENDS..] {
                out.push_str(&format!("  = {}\n", c));
            }
        } else {
            for c in t {
                out.push_str(&format!("  = {}\n", c));
            }
        }
        out
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.location() {
            Some((file, l, c)) => write!(f, "{}:{}:{}: {}", file, l, c, self.message),
            None => f.write_str(&self.message),
        }
    }
}

impl std::error::Error for Error {}

impl From<SolveError> for Error {
    fn from(e: SolveError) -> Self {
        Error::runtime(e.to_string())
    }
}

/// Shorthand used throughout the crate.
pub type Result<T, E = Error> = std::result::Result<T, E>;

impl From<crate::fem::meshing::MeshError> for Error {
    fn from(e: crate::fem::meshing::MeshError) -> Self {
        Error::runtime(e.to_string())
    }
}
