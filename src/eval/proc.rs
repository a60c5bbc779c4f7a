//! Procedure calls: typed arguments read like an operator's, a fresh frame
//! that reads (never writes) the caller's objects, ARGU, RESPRO, FINPROC
//! results, and QUITTER out of a procedure.

use super::{Flow, Interp};
use crate::error::{Error, Result};
use crate::source::Span;
use crate::syntax::ast::{Param, ProcDef};
use crate::value::objet::Objet;
use crate::value::{Ty, Value};
use std::rc::Rc;

use super::env::Frame;
use super::tokens::{GroupState, Tok, TokKind};

impl Interp {
    pub fn call_proc(&mut self, p: Rc<ProcDef>, st: &mut GroupState, span: Span) -> Result<Vec<Value>> {
        if self.store.frames.len() > 200 {
            return Err(Error::runtime(format!("{}: procedures nested more than 200 deep", p.name)).at(span));
        }
        let mut frame = Frame { proc_name: Some(p.name.clone()), ..Frame::default() };
        for param in &p.params {
            if let Some(v) = take_param(st, param, &self.registry)? {
                frame.vars.insert(param.name.clone(), v);
            } else if !param.optional {
                return Err(missing(&p.name, param).at(span).with_span_if_missing(span, &self.source));
            } else {
                frame.absent.push(param.name.clone());
            }
        }
        frame.pending = std::mem::take(st);
        // The body's spans point into the text that defined it, which may
        // be another file or an earlier REPL entry.
        let defined_in = self.proc_sources.get(&proc_key(&p)).cloned().unwrap_or_else(|| self.source.clone());
        let from_library = usize::from(self.library.owns(&p));
        self.nested(span, |it| {
            it.store.frames.push(frame);
            let caller_source = std::mem::replace(&mut it.source, defined_in);
            it.in_library += from_library;
            let r = it.run_body(&p);
            it.in_library -= from_library;
            it.source = caller_source;
            let frame = it.store.frames.pop().expect("pushed above");
            *st = frame.pending;
            r.map_err(|e| it.called_from(e, &p.name, span))
        })
    }

    /// The body of a called procedure and its results, in its own frame.
    fn run_body(&mut self, p: &ProcDef) -> Result<Vec<Value>> {
        // `QUITTER procname ;` (or a bare `QUITTER ;`) returns normally.
        let returns = |f: &Flow| match f {
            Flow::Next => true,
            Flow::Quit(n, _) => *n == p.name || n.is_empty(),
            _ => false,
        };
        let r = match self.exec_block(&p.body) {
            Err(e) => Err(e),
            Ok(f) if returns(&f) => {
                let mut results = std::mem::take(&mut self.store.top_mut().results);
                self.eval_items_raw(&p.results.items).map(|r| {
                    results.extend(r);
                    results
                })
            }
            Ok(Flow::End) => {
                // `FIN ;` inside a procedure ends the whole run: carried up as
                // an error of its own kind that run_program turns into Ok.
                self.finished = true;
                Err(Error::new(crate::error::ErrorKind::Finished, "FIN"))
            }
            Ok(f) => Err(f.stray(&p.name)),
        };
        // An error located in the body is located in the body's text.
        r.map_err(|mut e| {
            if e.span.is_some() && e.source.is_none() {
                e.source = Some(self.source.clone());
            }
            e
        })
    }

    /// An error leaving procedure `name`, called at `span`: one line of
    /// call trace (the failing instruction inside already said which
    /// objects it used).
    fn called_from(&self, mut e: Error, name: &str, span: Span) -> Error {
        if e.kind != crate::error::ErrorKind::Finished {
            let (line, col) = self.source.line_col(span.start);
            e = e.with_span_if_missing(span, &self.source);
            e.trace.push(format!("in procedure {} called at {}:{}:{}", name, self.source.name, line, col));
        }
        e
    }

    /// ARGU: read more arguments of the current call.
    pub fn bind_argu(&mut self, params: &[Param], span: Span) -> Result<()> {
        let name = self
            .store
            .top()
            .proc_name
            .clone()
            .ok_or_else(|| Error::runtime("ARGU is only allowed inside a procedure").at(span))?;
        let mut st = std::mem::take(&mut self.store.top_mut().pending);
        let mut r = Ok(());
        for p in params {
            match take_param(&mut st, p, &self.registry) {
                Ok(Some(v)) => self.store.top_mut().vars.insert(p.name.clone(), v).map_or((), |_| ()),
                Ok(None) if p.optional => self.store.hide(&p.name),
                Ok(None) => {
                    r = Err(missing(&name, p).at(span));
                    break;
                }
                Err(e) => {
                    r = Err(e.at(span));
                    break;
                }
            }
        }
        self.store.top_mut().pending = st;
        r
    }
}

/// Identity of a procedure definition (the same text defines the same
/// procedure however many names it is bound to).
pub(super) fn proc_key(p: &Rc<ProcDef>) -> usize {
    Rc::as_ptr(p) as usize
}

fn missing(proc_name: &str, p: &Param) -> Error {
    Error::runtime(format!(
        "procedure {}: argument {}*{} is missing",
        proc_name,
        p.name,
        p.ty.as_deref().unwrap_or("(any)")
    ))
}

/// One argument of a given type, read like an operator's: among the
/// pushed operands first (oldest first), else in the right window.
fn take_param(st: &mut GroupState, p: &Param, registry: &super::registry::Registry) -> Result<Option<Value>> {
    // OBJET is not one of the value types: its objects are host values.
    if p.ty.as_deref() == Some("OBJET") {
        let stop = |_: &Tok| false;
        let v = super::args::take_typed_before(st, registry, |v| Objet::of(v).map(|_| v.clone()), stop);
        return Ok(v);
    }
    let want = match &p.ty {
        Some(t) => Some(Ty::from_name(t).ok_or_else(|| Error::runtime(format!("unknown type {} for {}", t, p.name)))?),
        None => None,
    };
    let fits = |v: &Value| match want {
        None => true,
        Some(Ty::Flottant) => v.is_number(),
        Some(t) => v.ty() == t,
    };
    // An optional argument is not looked for past a word: the words of a
    // call are the procedure's keywords, and what follows one belongs to
    // it (`@POINTIR ... 'GERM' 1`: an optional ENTIER read before 'GERM'
    // must not take the 1 that belongs to 'GERM').
    let is_word = |t: &Tok| match &t.kind {
        TokKind::Quoted(_) | TokKind::Word(_) => true,
        TokKind::Val(v) => matches!(v, Value::Mot(_)),
        _ => false,
    };
    let stop = |t: &Tok| p.optional && is_word(t);
    let v = super::args::take_typed_before(st, registry, |v| fits(v).then(|| v.clone()), stop);
    Ok(v.map(|v| coerce(v, want)))
}

fn coerce(v: Value, want: Option<Ty>) -> Value {
    match (v, want) {
        (Value::Int(i), Some(Ty::Flottant)) => Value::Float(i as f64),
        (v, _) => v,
    }
}
