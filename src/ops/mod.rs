//! Operators, as tables of specs. Each family file exports
//! `pub(crate) const OPS: &[OpDef]`; [`Registry::standard`] concatenates
//! them (the Lua `linit.c` pattern). Adding an operator touches one file.

mod args;
mod arith;
mod assemble;
mod bc;
mod chargement;
mod colour;
mod contact;
mod curves;
mod dofs;
mod evol;
mod evol_temps;
mod export;
mod export_pasapas;
mod fieldfn;
mod fields;
mod format;
mod integrate;
mod io;
mod limits;
mod lists;
mod manu;
mod masq;
mod math;
mod mesh;
mod model;
mod objects;
mod pasapas;
mod pasapas_fields;
mod pasapas_model;
mod pointwise;
mod post;
mod principal;
mod products;
mod reso;
mod restrict;
pub mod solver_cache;
mod superele;
mod tables;
mod thermo;
mod transform;
pub mod unimplemented;
mod union;

pub use args::{ends_window, take_typed, takes_no_argument, Args, FromArg, PointId};

use crate::error::Result;
use crate::eval::Interp;
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
    /// Cast3M names gibi lacks: found like operators (so a deck that calls
    /// one stops there, named), but not part of the manual.
    missing: HashMap<String, Rc<OpSpec>>,
}

impl Registry {
    /// Every built-in family.
    pub fn standard() -> Self {
        let mut r = Registry::default();
        for table in [
            arith::OPS,
            math::OPS,
            lists::OPS,
            objects::OPS,
            io::OPS,
            union::OPS,
            mesh::OPS,
            transform::OPS,
            colour::OPS,
            bc::OPS,
            contact::OPS,
            chargement::OPS,
            model::OPS,
            manu::OPS,
            fields::OPS,
            products::OPS,
            masq::OPS,
            restrict::OPS,
            reso::OPS,
            post::OPS,
            thermo::OPS,
            principal::OPS,
            integrate::OPS,
            superele::OPS,
            export::OPS,
            evol::OPS,
            curves::OPS,
            tables::OPS,
            pasapas::OPS,
        ] {
            for d in table {
                r.insert(OpSpec::from(d));
            }
        }
        // After every family, so that a stub never hides an operator.
        for d in unimplemented::ops() {
            let key = op_key(d.name).to_string();
            if !r.ops.contains_key(&key) {
                r.missing.insert(key, Rc::new(OpSpec::from(&d)));
            }
        }
        r
    }

    pub fn insert(&mut self, spec: OpSpec) {
        self.ops.insert(op_key(&spec.name.to_uppercase()).to_string(), Rc::new(spec));
    }

    /// The operator a word names, by its first 4 letters.
    pub fn find(&self, word: &str) -> Option<Rc<OpSpec>> {
        let key = op_key(word);
        self.ops.get(key).or_else(|| self.missing.get(key)).cloned()
    }

    /// Every operator, sorted by name.
    pub fn all(&self) -> Vec<Rc<OpSpec>> {
        let mut v: Vec<_> = self.ops.values().cloned().collect();
        v.sort_by_key(|o| o.name);
        v
    }
}
