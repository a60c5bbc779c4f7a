//! Stopping a run from outside: Ctrl-C in the CLI, or any thread of an
//! embedding application.
//!
//! The flag is an atomic shared with an [`InterruptHandle`]. The evaluator
//! loads it once per instruction and once per loop pass (a relaxed load
//! costs next to nothing), and long solver loops poll it too, so a run
//! stops within a fraction of a second with an error at the instruction
//! it reached. Every object made before stays.

use super::Interp;
use crate::error::{Error, ErrorKind, Result};
use crate::source::Span;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

/// Stops a running evaluation from another thread (or a signal handler):
/// the run ends with an [`ErrorKind::Interrupted`] error at the
/// instruction it had reached. Cheap to clone; `Send` and `Sync`.
#[derive(Debug, Clone, Default)]
pub struct InterruptHandle(Arc<AtomicBool>);

impl InterruptHandle {
    /// Ask the run to stop (it stops at its next instruction or loop pass).
    pub fn interrupt(&self) {
        self.0.store(true, Ordering::Relaxed);
    }
    /// Whether a stop was asked and not yet acted on.
    pub fn is_pending(&self) -> bool {
        self.0.load(Ordering::Relaxed)
    }
    /// Forget a stop that was asked while nothing ran (the REPL calls it
    /// before each entry).
    pub fn clear(&self) {
        self.0.store(false, Ordering::Relaxed);
    }
    /// The flag itself, for loops outside the language (the solver's
    /// status iteration polls it between solves).
    pub fn shared(&self) -> Arc<AtomicBool> {
        self.0.clone()
    }
}

impl Interp {
    /// The error that stops the run, if a stop was asked (the flag is
    /// taken: the next run goes on). `span` is where the run stands.
    pub fn check_interrupt(&self, span: Span) -> Result<()> {
        if self.interrupt.0.load(Ordering::Relaxed) && self.interrupt.0.swap(false, Ordering::Relaxed) {
            return Err(interrupted().at(span));
        }
        Ok(())
    }
}

/// Where a statement starts, for the interruption error.
pub(super) fn stmt_span(s: &crate::syntax::ast::Stmt) -> Span {
    use crate::syntax::ast::Stmt;
    match s {
        Stmt::Instr(i) | Stmt::Respro(i) => i.span,
        Stmt::If { span, .. }
        | Stmt::Loop { span, .. }
        | Stmt::Quit { span, .. }
        | Stmt::Iter { span, .. }
        | Stmt::Argu { span, .. }
        | Stmt::Broken { span, .. }
        | Stmt::End { span } => *span,
        Stmt::Proc(p) => p.span,
    }
}

/// The interruption error, for code that polls the flag itself.
pub fn interrupted() -> Error {
    Error::new(ErrorKind::Interrupted, "stopped at this instruction")
}
