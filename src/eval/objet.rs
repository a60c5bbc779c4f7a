//! The object layer (obje.notice, meth.notice, heri.notice): `OBJET CTOR`
//! makes an OBJET and runs its constructor on it; `o%METH args` calls a
//! method of `o`; inside a method `%ELE` reads and `%ELE = …` writes an
//! entry of the object the method runs on. Methods are procedures (DEBMETH
//! is DEBPROC), so they run through `call_proc`, with the object pushed on
//! `Interp::this` for the length of the call.

use super::tokens::{GroupState, Tok, TokKind};
use super::Interp;
use crate::error::{Error, Result};
use crate::source::Span;
use crate::syntax::ast::{Item, ItemKind, ProcDef};
use crate::value::objet::Objet;
use crate::value::{HostObject, Value};
use std::any::Any;
use std::rc::Rc;

/// The methods every OBJET has.
const ATTACH: &str = "METHODE";
const INHERIT: &str = "HERITE";

/// `o%NAME` read but not yet run: a method bound to its object. It runs
/// where the machine reaches it, reading its arguments like a procedure.
#[derive(Debug)]
pub struct Bound {
    obj: Value,
    name: String,
}

impl HostObject for Bound {
    fn type_name(&self) -> &str {
        "METHODE"
    }
    fn as_any(&self) -> &dyn Any {
        self
    }
}

/// Whether a value is a bound method (it ends an operator's window, as a
/// procedure does).
pub fn is_bound(v: &Value) -> bool {
    matches!(v, Value::Host(h) if h.as_any().is::<Bound>())
}

/// Whether the last token read is the operator EXIS.
fn after_exis(out: &[Tok]) -> bool {
    let w = match out.last().map(|t| &t.kind) {
        Some(TokKind::Word(w)) => w.to_string(),
        Some(TokKind::Quoted(w)) => w.to_string(),
        _ => return false,
    };
    w.trim().to_uppercase().starts_with("EXIS")
}

impl Interp {
    /// `% NAME` at `items[i]`: returns the index of the next item to read.
    /// After an OBJET it is a method call on it; otherwise it is the entry
    /// (or else the method) NAME of the object the current method runs on.
    pub(super) fn percent(&mut self, items: &[Item], i: usize, out: &mut Vec<Tok>) -> Result<usize> {
        let pct = items[i].span;
        let (name, span) = match items.get(i + 1).map(|it| (&it.kind, it.span)) {
            Some((ItemKind::Word(w), s)) => (w.clone(), pct.join(s)),
            Some((ItemKind::Str(w), s)) => (w.to_uppercase(), pct.join(s)),
            _ => return Err(Error::runtime("'%' must be followed by the name of an entry or a method").at(pct)),
        };
        let explicit = matches!(out.last(), Some(Tok { kind: TokKind::Val(v), .. }) if Objet::of(v).is_some());
        let obj = match explicit {
            true => match out.pop() {
                Some(Tok { kind: TokKind::Val(v), .. }) => v,
                _ => unreachable!("checked above"),
            },
            false => self.this.last().cloned().ok_or_else(|| {
                Error::runtime(format!("%{}: there is no current OBJET outside a method (made by DEBMETH)", name))
                    .at(span)
            })?,
        };
        let o = Objet::of(&obj).expect("an OBJET");
        if !explicit {
            if let Some(v) = o.entry(&name) {
                out.push(Tok { kind: TokKind::Val(v), span, named: false });
                return Ok(i + 2);
            }
            if name != ATTACH && name != INHERIT && o.method(&name).is_none() {
                // `EXIS %NAME` asks whether the entry exists: a missing one
                // is a name bound to nothing, which EXIS answers FAUX.
                if after_exis(out) {
                    out.push(Tok { kind: TokKind::Word(format!("%{}", name)), span, named: false });
                    return Ok(i + 2);
                }
                return Err(Error::runtime(format!(
                    "%{}: the OBJET of class {} has no entry or method {}",
                    name, o.class, name
                ))
                .at(span));
            }
        }
        let mut next = i + 2;
        let bound = Bound { obj: obj.clone(), name: name.clone() };
        out.push(Tok { kind: TokKind::Val(Value::Host(Rc::new(bound))), span, named: false });
        // METHODE takes the *name* of its first argument, bound or not.
        if name == ATTACH {
            if let Some(it) = items.get(next) {
                if let ItemKind::Word(w) = &it.kind {
                    out.push(Tok { kind: TokKind::Quoted(Rc::from(w.as_str())), span: it.span, named: false });
                    next += 1;
                }
            }
        }
        Ok(next)
    }

    /// Run a bound method reached by the machine.
    pub(super) fn run_bound(&mut self, v: &Value, st: &mut GroupState, span: Span) -> Result<Vec<Value>> {
        let b = match v {
            Value::Host(h) => h.as_any().downcast_ref::<Bound>().expect("a bound method"),
            _ => unreachable!("checked by is_bound"),
        };
        let o = Objet::of(&b.obj).expect("an OBJET");
        match b.name.as_str() {
            ATTACH => {
                let name = match st.right.pop_front().map(|t| t.kind) {
                    Some(TokKind::Quoted(s)) => s.to_uppercase(),
                    Some(TokKind::Word(w)) => w,
                    Some(TokKind::Val(Value::Mot(s))) => s.trim_end().to_uppercase(),
                    _ => {
                        return Err(Error::runtime("METHODE: expected the name of the method, then the method").at(span))
                    }
                };
                let p = match st.right.pop_front().map(|t| t.kind) {
                    Some(TokKind::Val(Value::Proc(p))) => p,
                    Some(TokKind::Word(w)) => self.library_proc(&w, span)?.ok_or_else(|| {
                        Error::runtime(format!("METHODE {}: {} is not a method (made by DEBMETH)", name, w)).at(span)
                    })?,
                    _ => {
                        return Err(Error::runtime(format!(
                            "METHODE {}: expected a method (made by DEBMETH) after its name",
                            name
                        ))
                        .at(span))
                    }
                };
                o.set_method(&name, p);
                Ok(vec![])
            }
            INHERIT => match st.right.pop_front().map(|t| t.kind) {
                Some(TokKind::Val(other)) if Objet::of(&other).is_some() => {
                    o.inherit(Objet::of(&other).expect("checked"));
                    Ok(vec![])
                }
                _ => Err(Error::runtime("HERITE: expected the OBJET whose methods are inherited").at(span)),
            },
            name => {
                let p = o.method(name).ok_or_else(|| {
                    let known = o.method_names();
                    let e = Error::runtime(format!("the OBJET of class {} has no method {}", o.class, name)).at(span);
                    match known.is_empty() {
                        true => e.note("it has no method yet (METHODE attaches one)"),
                        false => e.note(format!("its methods: {} (and METHODE, HERITE)", known.join(" "))),
                    }
                })?;
                self.call_method(b.obj.clone(), p, st, span)
            }
        }
    }

    /// Run method `p` on `obj`.
    fn call_method(&mut self, obj: Value, p: Rc<ProcDef>, st: &mut GroupState, span: Span) -> Result<Vec<Value>> {
        self.this.push(obj);
        let r = self.call_proc(p, st, span);
        self.this.pop();
        r
    }

    /// OBJET: a new object of class `ctor`, on which `ctor` has run.
    pub fn new_objet(&mut self, ctor: Rc<ProcDef>, span: Span) -> Result<Value> {
        let obj = Value::Host(Rc::new(Objet::new(&ctor.name)));
        let mut st = GroupState::default();
        self.call_method(obj.clone(), ctor, &mut st, span)?;
        Ok(obj)
    }

    /// A method given by name (a procedure of the library).
    pub fn method_named(&mut self, name: &str, span: Span) -> Result<Option<Rc<ProcDef>>> {
        match self.store.get(name) {
            Some(Value::Proc(p)) => Ok(Some(p.clone())),
            Some(_) => Ok(None),
            None => self.library_proc(name, span),
        }
    }

    /// `%NAME = v`: set entry NAME of the current object.
    pub(super) fn set_member(&mut self, name: &str, v: Value) -> Result<()> {
        let obj = self.current_objet(name)?;
        Objet::of(&obj).expect("an OBJET").set_entry(name, v);
        Ok(())
    }

    /// The entry NAME of the current object (a table written `%T . k = …`).
    pub(super) fn member(&mut self, name: &str) -> Result<Value> {
        let obj = self.current_objet(name)?;
        let o = Objet::of(&obj).expect("an OBJET");
        o.entry(name)
            .ok_or_else(|| Error::runtime(format!("%{}: the OBJET of class {} has no entry {}", name, o.class, name)))
    }

    fn current_objet(&self, name: &str) -> Result<Value> {
        self.this.last().cloned().ok_or_else(|| {
            Error::runtime(format!("%{}: there is no current OBJET outside a method (made by DEBMETH)", name))
        })
    }
}
