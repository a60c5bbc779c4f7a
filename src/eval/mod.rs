//! The evaluator: runs a [`Program`] statement by statement on the stack
//! machine of [`machine`], with the object store of [`env`]. Operators are
//! looked up in the [`registry`] and read their arguments through
//! [`args`]; their bodies live in `ops`, which this layer never names.

pub mod args;
pub mod catalogue;
mod commands;
mod control;
pub mod env;
mod fast;
mod files;
mod interrupt;
pub mod library;
pub mod machine;
pub mod objet;
mod options;
mod proc;
pub mod registry;
pub mod tokens;
pub mod unimplemented;

pub use commands::CommandPolicy;
pub use files::FilePolicy;
pub use interrupt::{interrupted, InterruptHandle};
pub use options::{Exports, Options, Timers};

use crate::error::{Error, ErrorKind, Result};
use crate::fem::mesh::Nodes;
use crate::source::{Source, Span};
use crate::syntax::ast::Program;
use env::Store;
use registry::Registry;
use std::io::Write;
use std::rc::Rc;

/// Everything one run of Gibiane needs: the frozen operator table, the
/// objects, the node table, the options and the output sink.
pub struct Interp {
    pub registry: Rc<Registry>,
    pub store: Store,
    pub nodes: Nodes,
    pub opts: Options,
    pub out: Box<dyn Write>,
    /// The source being run (for error locations).
    pub source: Rc<Source>,
    pub files: FilePolicy,
    /// Which programs EXTE may run.
    pub commands: CommandPolicy,
    /// Whether a line `wrote <file>` goes to the output for each file
    /// written (`gibi --quiet` turns it off).
    pub report_files: bool,
    pub timers: Timers,
    /// The `.pvd` collection and the picture counter of SORT and TRAC.
    pub exports: Exports,
    pub title: String,
    /// Set by `FIN ;`: the run is over.
    pub finished: bool,
    /// Whether the instruction being run called a procedure: a procedure
    /// may return more results than the caller names, and the extra ones
    /// are dropped (01_language: `z3 = carre 2. 2 ;`).
    pub called_proc: bool,
    /// Instructions executed so far, and the limit a host may set (a
    /// sandbox against runaway `REPETER` loops).
    pub steps: u64,
    pub step_limit: Option<u64>,
    /// Set from outside to stop the run (see [`InterruptHandle`]).
    pub interrupt: InterruptHandle,
    /// Blocks, parenthesised groups and procedure calls being run inside
    /// one another (see [`MAX_NESTING`]).
    pub depth: usize,
    /// The text each procedure was defined in (by definition identity),
    /// so errors in its body point into the right file.
    pub proc_sources: rustc_hash::FxHashMap<usize, Rc<Source>>,
    /// The last direct factorisations, reused by RESO (see
    /// `solve::bilateral::pool`).
    pub factors: crate::solve::FactorPool,
    /// Cast3M procedures loaded from files on first use.
    pub library: library::Library,
    /// Library procedures being run (their instructions echo only with
    /// `OPTI ECHO 2`, as Cast3M's external procedures do).
    pub in_library: usize,
    /// Told of the progress of long operators (PASAPAS: steps done, steps
    /// planned), so a host can show a progress bar; the library itself
    /// prints nothing for it.
    pub progress: Option<Box<dyn FnMut(usize, usize)>>,
    /// BRUI's random generator: seeded the same at every start.
    pub noise: crate::value::signal::noise::Noise,
    /// The OBJETs the methods being run act on (innermost last).
    pub this: Vec<crate::value::Value>,
}

/// How deep blocks, parenthesised groups and procedure calls may run
/// inside one another. The evaluator recurses on each, so the limit keeps
/// the Rust stack bounded (about 1 MB in a release build, with the
/// 200-deep limit on procedure calls): a deck nested too deep gets an
/// error at the offending line, never a stack overflow. The parser already
/// bounds the nesting inside one procedure body or one instruction; this
/// catches nesting that piles up through recursive procedures.
pub const MAX_NESTING: usize = 1000;

/// How a statement ended.
#[derive(Debug, Clone, PartialEq)]
pub enum Flow {
    Next,
    /// `QUITTER name ;` written at the span, on its way to its block.
    Quit(String, Span),
    /// `ITERER name ;` written at the span.
    Iter(String, Span),
    End,
}

impl Flow {
    /// The error for a QUITTER/ITERER that reached no block of its name
    /// (`within` names the procedure it could not leave, if any).
    pub(crate) fn stray(&self, within: &str) -> Error {
        let (directive, name, span) = match self {
            Flow::Quit(n, s) => ("QUITTER", n, *s),
            Flow::Iter(n, s) => ("ITERER", n, *s),
            _ => unreachable!("only QUITTER and ITERER travel up"),
        };
        let (head, what) = match name.as_str() {
            "" => (directive.to_string(), "no REPETER".to_string()),
            n => (format!("{} {}", directive, n), format!("no REPETER {}", n)),
        };
        let msg = match within {
            "" => format!("{}: {} is running", head, what),
            p => format!("{}: {} is running inside procedure {}", head, what, p),
        };
        Error::runtime(msg).at(span)
    }
}

impl Interp {
    pub fn new(registry: Rc<Registry>, out: Box<dyn Write>) -> Self {
        Interp {
            registry,
            store: Store::default(),
            nodes: Nodes::default(),
            opts: Options::default(),
            out,
            source: Source::new("<none>", ""),
            files: FilePolicy::Nothing,
            commands: CommandPolicy::Nothing,
            report_files: true,
            timers: Timers::default(),
            exports: Exports::default(),
            title: String::new(),
            finished: false,
            called_proc: false,
            steps: 0,
            step_limit: None,
            interrupt: InterruptHandle::default(),
            depth: 0,
            proc_sources: Default::default(),
            factors: Default::default(),
            library: Default::default(),
            in_library: 0,
            progress: None,
            noise: Default::default(),
            this: Vec::new(),
        }
    }

    /// Write one line to the output sink. Output errors are ignored: a
    /// closed pipe must not turn into a Gibiane error.
    pub fn println(&mut self, s: &str) {
        let _ = writeln!(self.out, "{}", s);
    }

    /// Run `f` one nesting level deeper (a block body, a group, a
    /// procedure call written at `span`), or refuse past [`MAX_NESTING`].
    pub fn nested<T>(&mut self, span: Span, f: impl FnOnce(&mut Self) -> Result<T>) -> Result<T> {
        if self.depth >= MAX_NESTING {
            return Err(Error::runtime(format!(
                "blocks, parentheses and procedure calls are nested more than {} deep",
                MAX_NESTING
            ))
            .at(span));
        }
        self.depth += 1;
        let r = f(self);
        self.depth -= 1;
        r
    }

    /// Run a parsed program from `source`. Returns Ok(true) when `FIN ;`
    /// ended it.
    pub fn run_program(&mut self, prog: &Program, source: Rc<Source>) -> Result<bool> {
        let saved = std::mem::replace(&mut self.source, source);
        let depth = self.depth;
        let r = self.exec_block(&prog.stmts);
        // An operator that panicked inside a nested call may have skipped
        // a decrement: the run always ends at the depth it started from.
        self.depth = depth;
        self.source = saved;
        let _ = self.out.flush();
        let r = match r {
            Err(e) if e.kind == ErrorKind::Finished => Ok(Flow::End),
            r => r,
        };
        match r? {
            Flow::End => {
                self.finished = true;
                Ok(true)
            }
            Flow::Next => Ok(false),
            f @ (Flow::Quit(..) | Flow::Iter(..)) => Err(f.stray("")),
        }
    }
}
