//! gibi: an embeddable interpreter for Gibiane, the command language of
//! Cast3M, with a linear-statics solver for bilateral and unilateral
//! conditions.
//!
//! ```
//! use gibi::{Capture, Interpreter, OpSpec, Value};
//!
//! // Output goes to a sink the host chooses; by default it is discarded.
//! let out = Capture::default();
//! let mut gibi = Interpreter::builder().output(out.clone()).build();
//!
//! // A custom operator with typed arguments, read like any Gibiane operator.
//! gibi.register(OpSpec::host("DOUB", "DOUB FLOTTANT", "Twice a number.", |args| {
//!     let x = args.req_num()?;
//!     Ok(vec![Value::Float(2.0 * x)])
//! }));
//!
//! gibi.set("L", 3.0);
//! gibi.run_str("example", "x = 1 + 2 * 3 ; y = doub l ; mess 'x =' x ;").unwrap();
//! assert_eq!(gibi.get_f64("X"), Some(9.0)); // no precedence: (1 + 2) * 3
//! assert_eq!(gibi.get_f64("Y"), Some(6.0));
//! assert_eq!(out.text(), "x = 9\n");
//! ```

pub mod analysis;
pub mod error;
pub mod eval;
pub mod fem;
pub mod io;
pub mod ops;
pub mod props;
pub mod solve;
pub mod source;
pub mod syntax;
pub mod value;

pub use error::{Error, ErrorKind, Result};
pub use eval::args::Args;
pub use eval::registry::{OpSpec, Registry};
pub use eval::{CommandPolicy, FilePolicy, InterruptHandle};
pub use value::Value;

use eval::Interp;
use source::Source;
use std::cell::RefCell;
use std::io::Write;
use std::path::Path;
use std::rc::Rc;

/// An output sink that keeps what was written (for tests and hosts that
/// want the transcript as a string).
#[derive(Debug, Clone, Default)]
pub struct Capture(Rc<RefCell<Vec<u8>>>);

impl Capture {
    /// Everything written so far.
    pub fn text(&self) -> String {
        String::from_utf8_lossy(&self.0.borrow()).into_owned()
    }
    /// Forget what was written.
    pub fn clear(&self) {
        self.0.borrow_mut().clear();
    }
}

impl Write for Capture {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.0.borrow_mut().extend_from_slice(buf);
        Ok(buf.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

/// How a run ended without error.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Outcome {
    /// The text was run to its end.
    EndOfInput,
    /// `FIN ;` ended the run.
    Finished,
}

/// Builds an [`Interpreter`]: output sink, file policy, extra operators.
pub struct InterpreterBuilder {
    out: Box<dyn Write>,
    files: FilePolicy,
    commands: CommandPolicy,
    registry: Registry,
    step_limit: Option<u64>,
    report_files: bool,
    procedures: Vec<std::path::PathBuf>,
    progress: Option<Box<dyn FnMut(usize, usize)>>,
}

impl InterpreterBuilder {
    /// Told of the progress of long operators (PASAPAS calls it after each
    /// step with the steps done and planned): a host's progress bar.
    pub fn progress(mut self, f: impl FnMut(usize, usize) + 'static) -> Self {
        self.progress = Some(Box::new(f));
        self
    }
    /// Where MESS, LIST, … write. Default: discarded.
    pub fn output(mut self, w: impl Write + 'static) -> Self {
        self.out = Box::new(w);
        self
    }
    /// Which files scripts may read or write. Default: none.
    pub fn files(mut self, policy: FilePolicy) -> Self {
        self.files = policy;
        self
    }
    /// Which programs of the host scripts may run (EXTE). Default: none.
    pub fn commands(mut self, policy: CommandPolicy) -> Self {
        self.commands = policy;
        self
    }
    /// Stop any run after this many executed instructions (a sandbox
    /// against runaway loops). Default: no limit.
    pub fn step_limit(mut self, n: u64) -> Self {
        self.step_limit = Some(n);
        self
    }
    /// Whether each file a script writes is reported by a line `wrote
    /// <file>` on the output (relative to the allowed directory). Default:
    /// reported.
    pub fn report_files(mut self, on: bool) -> Self {
        self.report_files = on;
        self
    }
    /// Where Cast3M procedures are found when a deck names one it has
    /// not defined: files of `$$$$ NAME` procedures (Cast3M's UTILPROC
    /// format) or folders of `*.procedur` files. Paths add up; the first
    /// that has a name wins. Default: none (gibi ships no procedure).
    pub fn procedures<P: Into<std::path::PathBuf>>(mut self, paths: impl IntoIterator<Item = P>) -> Self {
        self.procedures.extend(paths.into_iter().map(Into::into));
        self
    }
    /// Add an operator before the registry is frozen.
    pub fn operator(mut self, op: OpSpec) -> Self {
        self.registry.insert(op);
        self
    }
    pub fn build(self) -> Interpreter {
        let mut interp = Interp::new(Rc::new(self.registry), self.out);
        interp.files = self.files;
        interp.commands = self.commands;
        interp.step_limit = self.step_limit;
        interp.report_files = self.report_files;
        interp.library = eval::library::Library::new(self.procedures);
        interp.progress = self.progress;
        Interpreter { interp }
    }
}

/// A Gibiane session: objects persist from one `run_*` call to the next.
pub struct Interpreter {
    interp: Interp,
}

impl Default for Interpreter {
    fn default() -> Self {
        Interpreter::builder().build()
    }
}

impl Interpreter {
    /// A session with the standard operators, output discarded, no file access.
    pub fn new() -> Self {
        Interpreter::default()
    }

    pub fn builder() -> InterpreterBuilder {
        InterpreterBuilder {
            out: Box::new(std::io::sink()),
            files: FilePolicy::Nothing,
            commands: CommandPolicy::Nothing,
            registry: Registry::standard(),
            step_limit: None,
            report_files: true,
            procedures: Vec::new(),
            progress: None,
        }
    }

    /// A handle that stops the running evaluation from any thread: the run
    /// returns an [`ErrorKind::Interrupted`] error at the instruction it
    /// reached (within a fraction of a second), and every object stays.
    ///
    /// ```
    /// let mut gibi = gibi::Interpreter::new();
    /// let stop = gibi.interrupt_handle();
    /// std::thread::spawn(move || {
    ///     std::thread::sleep(std::time::Duration::from_millis(50));
    ///     stop.interrupt();
    /// });
    /// let e = gibi.run_str("t", "x = 1 ; repeter b ; fin b ;").unwrap_err();
    /// assert_eq!(e.kind, gibi::ErrorKind::Interrupted);
    /// assert_eq!(gibi.get_f64("x"), Some(1.0));
    /// ```
    pub fn interrupt_handle(&self) -> InterruptHandle {
        self.interp.interrupt.clone()
    }

    /// Register (or replace) an operator.
    pub fn register(&mut self, op: OpSpec) {
        let mut r = (*self.interp.registry).clone();
        r.insert(op);
        self.interp.registry = Rc::new(r);
    }

    /// The operator table (for help and completion).
    pub fn registry(&self) -> &Registry {
        &self.interp.registry
    }

    /// Read and run a text, one statement at a time as Cast3M does: the
    /// statements before a syntax error run, and nothing after a top-level
    /// `FIN ;` is read. `name` is used in error locations.
    pub fn run_str(&mut self, name: &str, text: &str) -> Result<Outcome> {
        let src = Source::new(name, text);
        let mut reader = syntax::Reader::to_run(text);
        while let Some(stmt) = reader.next() {
            for (w, span) in reader.take_warnings() {
                let (line, col) = src.line_col(span.start);
                self.interp.println(&format!("{}:{}:{}: warning: {}", name, line, col, w));
            }
            let stmt = stmt.map_err(|mut e| {
                e.source = Some(src.clone());
                e
            })?;
            let prog = syntax::ast::Program { stmts: vec![stmt] };
            if self.run_parsed(&prog, src.clone())? == Outcome::Finished {
                return Ok(Outcome::Finished);
            }
        }
        Ok(Outcome::EndOfInput)
    }

    /// Run an already parsed program (the REPL parses to know whether the
    /// input is complete).
    pub fn run_parsed(&mut self, prog: &syntax::ast::Program, src: Rc<Source>) -> Result<Outcome> {
        let fin = self.run_guarded(prog, src.clone()).map_err(|mut e| {
            if e.source.is_none() {
                e.source = Some(src);
            }
            e
        })?;
        Ok(if fin { Outcome::Finished } else { Outcome::EndOfInput })
    }

    /// Run a program; a bug in gibi that panics (operators are guarded one
    /// by one, this catches the evaluator itself) becomes an error, and the
    /// session is put back as it stood between instructions, so the REPL
    /// and hosts keep their objects.
    fn run_guarded(&mut self, prog: &syntax::ast::Program, src: Rc<Source>) -> Result<bool> {
        let it = &mut self.interp;
        let (frames, depth, source) = (it.store.frames.len(), it.depth, it.source.clone());
        let loops = it.store.top().loops.len();
        let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| it.run_program(prog, src)));
        r.unwrap_or_else(|p| {
            it.store.frames.truncate(frames);
            it.store.top_mut().loops.truncate(loops);
            (it.depth, it.source) = (depth, source);
            let msg = p.downcast_ref::<String>().map(String::as_str).or_else(|| p.downcast_ref::<&str>().copied());
            Err(Error::internal(format!(
                "internal error ({}); please report it with the deck",
                msg.unwrap_or("unknown cause")
            )))
        })
    }

    /// Read and run a file (named as given in error locations). Bytes that
    /// are not UTF-8 are read as Latin-1 ([`source::decode`]).
    pub fn run_file(&mut self, path: impl AsRef<Path>) -> Result<Outcome> {
        let path = path.as_ref();
        let bytes = std::fs::read(path).map_err(|e| Error::io(format!("cannot read {}: {}", path.display(), e)))?;
        self.run_str(&path.display().to_string(), &source::decode(&bytes))
    }

    /// The object bound to a name (names are upper-cased as in Gibiane).
    pub fn get(&self, name: &str) -> Option<Value> {
        self.interp.store.get(&name.to_uppercase()).cloned()
    }

    /// A number bound to a name (ENTIER or FLOTTANT).
    pub fn get_f64(&self, name: &str) -> Option<f64> {
        self.get(name)?.as_f64()
    }

    /// Read an object as a typed Rust value.
    pub fn get_as<T: eval::args::FromArg>(&self, name: &str) -> Result<T> {
        let v = self.get(name).ok_or_else(|| Error::runtime(format!("no object named {}", name.to_uppercase())))?;
        T::from_value(&v).ok_or_else(|| {
            Error::runtime(format!("{} is a {}, not a {}", name.to_uppercase(), v.type_name(), T::EXPECT))
        })
    }

    /// Bind a name in the global frame.
    pub fn set(&mut self, name: &str, v: impl Into<Value>) {
        self.interp.store.set(&name.to_uppercase(), v.into());
    }

    /// Every visible name with its object.
    pub fn objects(&self) -> Vec<(String, Value)> {
        self.interp.store.visible()
    }

    /// Coordinates of a POINT object.
    pub fn point_coords(&self, v: &Value) -> Option<[f64; 3]> {
        match v {
            Value::Point(p) => Some(self.interp.nodes.get(*p)),
            _ => None,
        }
    }

    /// Whether `FIN ;` has been reached.
    pub fn finished(&self) -> bool {
        self.interp.finished
    }

    /// Low-level access for the CLI and tests.
    pub fn interp(&mut self) -> &mut Interp {
        &mut self.interp
    }
}
