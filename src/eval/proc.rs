//! Procedure calls: typed arguments read like an operator's, a fresh frame
//! that reads (never writes) the caller's objects, ARGU, RESPRO, FINPROC
//! results, and QUITTER out of a procedure.

use super::{Flow, Interp};
use crate::error::{Error, Result};
use crate::source::Span;
use crate::syntax::ast::{Param, ProcDef};
use crate::value::{Ty, Value};
use std::rc::Rc;

use super::env::Frame;
use super::machine::{GroupState, TokKind};

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
            }
        }
        frame.pending = std::mem::take(st);
        self.store.frames.push(frame);
        let flow = self.nested(span, |it| it.exec_block(&p.body));
        // `QUITTER procname ;` (or a bare `QUITTER ;`) returns normally.
        let returns = |f: &Flow| match f {
            Flow::Next => true,
            Flow::Quit(n, _) => *n == p.name || n.is_empty(),
            _ => false,
        };
        let flow = flow.and_then(|f| {
            let mut results = std::mem::take(&mut self.store.top_mut().results);
            if returns(&f) {
                results.extend(self.eval_items_raw(&p.results.items)?);
            }
            Ok((f, results))
        });
        let frame = self.store.frames.pop().expect("pushed above");
        *st = frame.pending;
        let (f, results) = flow?;
        match f {
            f if returns(&f) => Ok(results),
            Flow::End => {
                // `FIN ;` inside a procedure ends the whole run: carried up as
                // an error of its own kind that run_program turns into Ok.
                self.finished = true;
                Err(Error::new(crate::error::ErrorKind::Finished, "FIN"))
            }
            f => Err(f.stray(&p.name)),
        }
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
                Ok(None) if p.optional => {}
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

fn missing(proc_name: &str, p: &Param) -> Error {
    Error::runtime(format!(
        "procedure {}: argument {}*{} is missing",
        proc_name,
        p.name,
        p.ty.as_deref().unwrap_or("(any)")
    ))
}

/// One argument of a given type: among the pushed operands first (oldest
/// first), else the next token on the right.
fn take_param(st: &mut GroupState, p: &Param, registry: &crate::ops::Registry) -> Result<Option<Value>> {
    let want = match &p.ty {
        Some(t) => Some(Ty::from_name(t).ok_or_else(|| Error::runtime(format!("unknown type {} for {}", t, p.name)))?),
        None => None,
    };
    let fits = |v: &Value| match want {
        None => true,
        Some(Ty::Flottant) => v.is_number(),
        Some(t) => v.ty() == t,
    };
    if let Some(i) = st.left.iter().position(fits) {
        let v = st.left.remove(i);
        return Ok(Some(coerce(v, want)));
    }
    let next = match st.right.front().map(|t| &t.kind) {
        Some(TokKind::Val(v)) if !matches!(v, Value::Proc(_)) => Some(v.clone()),
        Some(TokKind::Quoted(s)) => Some(Value::Mot(s.clone())),
        Some(TokKind::Word(w)) if registry.find(w).is_none() => Some(Value::mot(w)),
        _ => None,
    };
    match next {
        Some(v) if fits(&v) => {
            st.right.pop_front();
            Ok(Some(coerce(v, want)))
        }
        _ => Ok(None),
    }
}

fn coerce(v: Value, want: Option<Ty>) -> Value {
    match (v, want) {
        (Value::Int(i), Some(Ty::Flottant)) => Value::Float(i as f64),
        (v, _) => v,
    }
}
