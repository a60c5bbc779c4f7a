//! The operator table: what an operator is (its row [`OpDef`], its
//! registered form [`OpSpec`]), and the [`Registry`] the machine looks
//! words up in. The families of operators fill it (`ops`); the machine and
//! the argument reader only read it.

use super::args::Args;
use super::Interp;
use crate::error::Result;
use crate::value::Value;
use rustc_hash::FxHashMap as HashMap;
use std::cell::Cell;
use std::rc::Rc;
use std::time::Duration;

/// A built-in operator body.
pub type OpFn = fn(&mut Interp, &mut Args) -> Result<Vec<Value>>;
/// An operator registered by an embedding application.
pub type HostFn = Rc<dyn Fn(&mut Args) -> Result<Vec<Value>>>;

/// A row of an operator table: name (matched on its first 4 letters),
/// signature (shown in argument errors and `help`), one-line description,
/// example, body.
#[derive(Clone, Copy)]
pub struct OpDef {
    pub name: &'static str,
    pub signature: &'static str,
    pub doc: &'static str,
    pub example: &'static str,
    pub f: OpFn,
}

#[derive(Clone)]
enum OpImpl {
    Builtin(OpFn),
    Host(HostFn),
}

/// An operator as the registry holds it.
#[derive(Clone)]
pub struct OpSpec {
    pub name: &'static str,
    pub signature: &'static str,
    pub doc: &'static str,
    pub example: &'static str,
    imp: OpImpl,
    /// Calls and cumulative time, for TEMP. Kept here so that timing an
    /// operator costs no map lookup.
    stats: Cell<(u64, Duration)>,
}

impl std::fmt::Debug for OpSpec {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "OpSpec({})", self.name)
    }
}

impl OpSpec {
    /// An operator implemented by the host application.
    pub fn host(
        name: &str,
        signature: &str,
        doc: &str,
        f: impl Fn(&mut Args) -> Result<Vec<Value>> + 'static,
    ) -> OpSpec {
        // Host names live as long as the registry; leaking a few bytes per
        // registered operator keeps OpSpec `Copy`-friendly and lock-free.
        OpSpec {
            name: Box::leak(name.to_uppercase().into_boxed_str()),
            signature: Box::leak(signature.to_string().into_boxed_str()),
            doc: Box::leak(doc.to_string().into_boxed_str()),
            example: "",
            imp: OpImpl::Host(Rc::new(f)),
            stats: Cell::default(),
        }
    }

    /// Record one call of `d` seconds.
    pub fn record(&self, d: Duration) {
        let (n, t) = self.stats.get();
        self.stats.set((n + 1, t + d));
    }

    /// Calls and cumulative time so far.
    pub fn stats(&self) -> (u64, Duration) {
        self.stats.get()
    }

    /// Forget the timings (TEMP 'ZERO').
    pub fn reset_stats(&self) {
        self.stats.set(Default::default());
    }

    pub fn call(&self, it: &mut Interp, args: &mut Args) -> Result<Vec<Value>> {
        match &self.imp {
            OpImpl::Builtin(f) => f(it, args),
            OpImpl::Host(f) => f(args),
        }
    }
}

impl From<&OpDef> for OpSpec {
    fn from(d: &OpDef) -> Self {
        OpSpec {
            name: d.name,
            signature: d.signature,
            doc: d.doc,
            example: d.example,
            imp: OpImpl::Builtin(d.f),
            stats: Cell::default(),
        }
    }
}

/// The 4-letter key Cast3M matches operator names on. Words are already
/// upper-cased by the lexer and quoted text is compared as written
/// (language.md §1), so this is a plain prefix: no allocation on the hot path.
pub fn op_key(word: &str) -> &str {
    match word.char_indices().nth(4) {
        Some((i, _)) => &word[..i],
        None => word,
    }
}

/// The operator table: built once, then shared by every run.
#[derive(Debug, Clone, Default)]
pub struct Registry {
    ops: HashMap<String, Rc<OpSpec>>,
}

impl Registry {
    pub fn insert(&mut self, spec: OpSpec) {
        self.ops.insert(op_key(&spec.name.to_uppercase()).to_string(), Rc::new(spec));
    }

    /// The operator a word names, by its first 4 letters, unless the word
    /// is the full name of a Cast3M procedure: Cast3M finds procedures
    /// before operators, so TRANSGEN is a procedure, never TRAN.
    pub fn find(&self, word: &str) -> Option<Rc<OpSpec>> {
        let op = self.ops.get(op_key(word))?;
        if word.len() > 4 && op.name != word && super::catalogue::procedure(word).is_some() {
            return None;
        }
        Some(op.clone())
    }

    /// Every operator, sorted by name.
    pub fn all(&self) -> Vec<Rc<OpSpec>> {
        let mut v: Vec<_> = self.ops.values().cloned().collect();
        v.sort_by_key(|o| o.name);
        v
    }
}
