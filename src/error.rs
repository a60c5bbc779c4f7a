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
    /// A file could not be read (exit 66).
    Io,
    /// A file could not be written (exit 73).
    Write,
    /// The host's file policy refused a path (exit 77).
    Denied,
    /// The run was stopped from outside (Ctrl-C, an embedder's
    /// `InterruptHandle`): exit 130.
    Interrupted,
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
            ErrorKind::Interrupted => "interrupted",
            _ => "error",
        };
        let mut out = String::new();
        match (&self.source, self.span) {
            (Some(src), Some(span)) => {
                let (line, col) = src.line_col(span.start);
                out.push_str(&format!(
                    "{}:{}:{}: {}: {}\n",
                    escape(&src.name),
                    line,
                    col,
                    label,
                    escape(&self.message)
                ));
                let (end_line, end_col) = src.line_col(span.end.max(span.start + 1) - 1);
                let text: Vec<char> = src.line_text(line).chars().collect();
                let end = if end_line == line { end_col } else { text.len() + 1 };
                let gutter = line.to_string().len();
                out.push_str(&format!("{:w$} |\n", "", w = gutter));
                let (shown, marks) = excerpt(&text, col - 1, end.max(col));
                out.push_str(&format!("{} | {}\n", line, shown));
                out.push_str(&format!("{:w$} | {}\n", "", marks, w = gutter));
            }
            _ => out.push_str(&format!("{}: {}\n", label, escape(&self.message))),
        }
        for n in &self.notes {
            out.push_str(&format!("  = {}\n", escape(n)));
        }
        let t = &self.trace;
        if t.len() > 2 * TRACE_ENDS + 1 {
            for c in &t[..TRACE_ENDS] {
                out.push_str(&format!("  = {}\n", escape(c)));
            }
            out.push_str(&format!("  = … {} more procedure calls …\n", t.len() - 2 * TRACE_ENDS));
            for c in &t[t.len() - TRACE_ENDS..] {
                out.push_str(&format!("  = {}\n", escape(c)));
            }
        } else {
            for c in t {
                out.push_str(&format!("  = {}\n", escape(c)));
            }
        }
        out
    }
}

/// Characters of the source line shown around the error column: a
/// syntax error on a 1.3 MB line shows a window, not the whole line and a
/// caret line as long.
const WINDOW: usize = 200;

/// The shown part of a source line and the caret line under it, for the
/// characters `from..to` (0-based) of `text`: clipped to [`WINDOW`]
/// characters around `from`, with `…` where text is cut, and every
/// control character escaped (the caret follows the escaped width).
fn excerpt(text: &[char], from: usize, to: usize) -> (String, String) {
    let (mut start, mut end) = (0, text.len());
    if text.len() > WINDOW {
        start = from.saturating_sub(WINDOW / 3).min(text.len() - WINDOW);
        end = start + WINDOW;
    }
    let (mut shown, mut marks) = (String::new(), String::new());
    if start > 0 {
        shown.push('…');
        marks.push(' ');
    }
    for (i, &c) in text.iter().enumerate().take(end).skip(start) {
        let s = escape_char(c);
        shown.push_str(&s);
        let w = s.chars().count();
        match c {
            '\t' if i < from => marks.push('\t'),
            _ if i < from => marks.extend(std::iter::repeat_n(' ', w)),
            _ if i < to => marks.extend(std::iter::repeat_n('^', w)),
            _ => {}
        }
    }
    if to > end || from >= end {
        // The span goes on past the window (or starts after it: at the end
        // of the line).
        marks.push('^');
    }
    if end < text.len() {
        shown.push('…');
    }
    (shown, marks)
}

/// A character as an error shows it: control characters (C0, DEL, C1)
/// from a deck would act on the terminal (`\x1B]0;T\x07` retitles it), so
/// they are written as `\x1B`. Tabs stay.
fn escape_char(c: char) -> std::borrow::Cow<'static, str> {
    match c {
        '\t' => "\t".into(),
        c if c.is_control() => format!("\\x{:02X}", c as u32).into(),
        c => c.to_string().into(),
    }
}

/// A message with its control characters escaped (line breaks stay: some
/// messages span lines on purpose).
pub fn escape(s: &str) -> String {
    // A message quoting a huge word keeps its two ends.
    const LONG: usize = 1000;
    if s.len() > LONG {
        let chars: Vec<char> = s.chars().collect();
        if chars.len() > LONG {
            let head: String = chars[..LONG - 200].iter().collect();
            let tail: String = chars[chars.len() - 150..].iter().collect();
            let cut = chars.len() - head.chars().count() - 150;
            return escape(&format!("{} … ({} characters) … {}", head, cut, tail));
        }
    }
    if !s.chars().any(|c| c.is_control() && c != '\n' && c != '\t') {
        return s.to_string();
    }
    s.chars()
        .map(|c| match c {
            '\n' => "\n".into(),
            c => escape_char(c),
        })
        .collect()
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.location() {
            Some((file, l, c)) => write!(f, "{}:{}:{}: {}", escape(&file), l, c, escape(&self.message)),
            None => f.write_str(&escape(&self.message)),
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
