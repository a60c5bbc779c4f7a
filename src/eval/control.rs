//! Statements: instructions with assignment, SI, REPETER, QUITTER/ITERER,
//! FIN, and procedure definitions.

use super::{Flow, Interp};
use crate::error::{Error, ErrorKind, Result};
use crate::source::Span;
use crate::syntax::ast::{Instr, Item, ItemKind, Stmt, Target};
use crate::value::{Key, Ty, Value};

impl Interp {
    pub fn exec_block(&mut self, stmts: &[Stmt]) -> Result<Flow> {
        for s in stmts {
            let f = self.exec_stmt(s)?;
            if f != Flow::Next {
                return Ok(f);
            }
        }
        Ok(Flow::Next)
    }

    fn exec_stmt(&mut self, s: &Stmt) -> Result<Flow> {
        self.check_interrupt(super::interrupt::stmt_span(s))?;
        self.steps += 1;
        if let Some(limit) = self.step_limit {
            if self.steps > limit {
                return Err(Error::runtime(format!("the limit of {} executed instructions is reached", limit)));
            }
        }
        match s {
            Stmt::Instr(ins) => {
                if let Err(e) = self.exec_instr(ins) {
                    self.pass_error(e, ins.span)?;
                }
                Ok(Flow::Next)
            }
            Stmt::If { branches, otherwise, span } => {
                for (k, b) in branches.iter().enumerate() {
                    self.echo(&b.cond);
                    if self.condition(&b.cond, k > 0)? {
                        return self.nested(*span, |it| it.exec_block(&b.body));
                    }
                }
                match otherwise {
                    Some(o) => self.nested(*span, |it| it.exec_block(o)),
                    None => Ok(Flow::Next),
                }
            }
            Stmt::Loop { name, count, body, span } => {
                self.nested(*span, |it| it.exec_loop(name, count.as_ref(), body, *span))
            }
            Stmt::Quit { name, span } => Ok(Flow::Quit(name.clone(), *span)),
            Stmt::Iter { name, span } => Ok(Flow::Iter(name.clone(), *span)),
            Stmt::End { .. } => Ok(Flow::End),
            Stmt::Proc(p) => {
                self.proc_sources.insert(super::proc::proc_key(p), self.source.clone());
                self.store.set(&p.name, Value::Proc(p.clone()));
                Ok(Flow::Next)
            }
            Stmt::Broken { message, span } => Err(Error::syntax(message.clone(), *span)),
            Stmt::Argu { params, span } => {
                self.bind_argu(params, *span)?;
                Ok(Flow::Next)
            }
            Stmt::Respro(ins) => {
                let vals =
                    self.eval_items_raw(&ins.items).map_err(|e| e.with_span_if_missing(ins.span, &self.source))?;
                if self.store.top().proc_name.is_none() {
                    return Err(Error::runtime("RESPRO is only allowed inside a procedure").at(ins.span));
                }
                self.store.top_mut().results.extend(vals);
                Ok(Flow::Next)
            }
        }
    }

    /// `OPTI ERRE 'IGNORE'` or `'CONTINUER'`: an ordinary error abandons
    /// its instruction (its results are not assigned) and the deck goes on,
    /// as Cast3M does; the error is still shown, as a warning. An aborting
    /// ERRE, an interruption, a syntax error and a bug of gibi still stop.
    fn pass_error(&mut self, e: Error, span: Span) -> Result<()> {
        let passes = matches!(self.opts.erre.as_str(), "IGNORE" | "CONTINUER")
            && matches!(e.kind, ErrorKind::Runtime | ErrorKind::Denied | ErrorKind::Io | ErrorKind::Write);
        if !passes {
            return Err(e);
        }
        let (at, src) = match (e.span, &e.source) {
            (Some(s), Some(src)) => (s, src.clone()),
            _ => (span, self.source.clone()),
        };
        let (line, col) = src.line_col(at.start);
        let msg = format!(
            "{}:{}:{}: warning: {} (OPTI ERRE {}: the instruction is abandoned)",
            src.name, line, col, e.message, self.opts.erre
        );
        self.println(&msg);
        Ok(())
    }

    fn echo(&mut self, ins: &Instr) {
        // Library procedures echo only at level 2 (opti.notice: ECHO).
        let level = if self.in_library > 0 { 2 } else { 1 };
        if self.opts.echo >= level {
            let text = self.source.slice(ins.span).split_whitespace().collect::<Vec<_>>().join(" ");
            self.println(&format!("$ {}", text));
        }
    }

    /// The test of a SI, or of a SINON when `sinon`: Cast3M decks write
    /// `'SINON' 'ERREUR' 0 ;` with no `;` after SINON, so an instruction
    /// there that gives no value is a plain SINON whose first instruction
    /// has just run.
    fn condition(&mut self, cond: &Instr, sinon: bool) -> Result<bool> {
        let vals = self.eval_items(&cond.items).map_err(|e| e.with_span_if_missing(cond.span, &self.source))?;
        match vals.as_slice() {
            [Value::Bool(b)] => Ok(*b),
            [] if sinon => Ok(true),
            [v] => Err(Error::runtime(format!("SI needs a LOGIQUE, found {}", v.type_name())).at(cond.span)),
            _ => Err(Error::runtime(format!("SI needs one LOGIQUE, found {} values", vals.len())).at(cond.span)),
        }
    }

    fn exec_loop(&mut self, name: &str, count: Option<&Instr>, body: &[Stmt], span: Span) -> Result<Flow> {
        let n = match count {
            None => None,
            Some(c) => match self.eval_items(&c.items)?.as_slice() {
                [Value::Int(n)] if *n >= 0 => Some(*n),
                [Value::Int(_)] => None,
                // A literal of ten digits or more is a FLOTTANT (redlec.eso),
                // and Cast3M decks count passes with one (shock2d: `NITER =
                // 1000000000`): a whole count in a FLOTTANT is taken.
                [Value::Float(x)] if x.fract() == 0.0 && (0.0..9.0e18).contains(x) => Some(*x as i64),
                [v] => {
                    return Err(Error::runtime(format!(
                        "REPETER {}: the count must be an ENTIER, found {}",
                        name,
                        v.type_name()
                    ))
                    .at(c.span))
                }
                _ => return Err(Error::runtime(format!("REPETER {}: one count expected", name)).at(c.span)),
            },
        };
        self.store.set(name, Value::Bloc(name.into()));
        self.store.top_mut().loops.push((name.to_string(), 0));
        let mut pass = 0i64;
        let result = loop {
            if n.is_some_and(|n| pass >= n) {
                break Ok(Flow::Next);
            }
            pass += 1;
            // An empty body runs no instruction: the pass checks too.
            if let Err(e) = self.check_interrupt(span) {
                break Err(e);
            }
            if let Some(l) = self.store.top_mut().loops.last_mut() {
                l.1 = pass;
            }
            match self.exec_block(body) {
                Err(e) => break Err(e),
                Ok(Flow::Next) => {}
                Ok(Flow::Iter(q, _)) if q == name || q.is_empty() => {}
                Ok(Flow::Quit(q, _)) if q == name || q.is_empty() => break Ok(Flow::Next),
                Ok(other) => break Ok(other),
            }
        };
        let frame = self.store.top_mut();
        frame.loops.pop();
        // An inner loop ends once per outer pass: reuse its entry.
        match frame.ended.get_mut(name) {
            Some(last) => *last = pass,
            None => {
                frame.ended.insert(name.to_string(), pass);
            }
        }
        result
    }

    /// `[targets =] items ;`
    pub fn exec_instr(&mut self, ins: &Instr) -> Result<()> {
        self.echo(ins);
        if let [t] = ins.targets.as_slice() {
            if t.keys.is_empty() && t.typed.is_none() && t.base.is_none() && !t.name.starts_with('%') {
                match self.fast_value(&ins.items) {
                    Some(Ok(v)) => {
                        self.store.set(&t.name, v);
                        return Ok(());
                    }
                    Some(Err(e)) => {
                        return Err(self.with_objects(e.with_span_if_missing(ins.span, &self.source), &ins.items))
                    }
                    None => {}
                }
            }
        }
        self.called_proc = false;
        let mut vals = match self.eval_items(&ins.items) {
            Ok(v) => v,
            Err(e) => return Err(self.with_objects(e.with_span_if_missing(ins.span, &self.source), &ins.items)),
        };
        if ins.targets.is_empty() {
            return Ok(());
        }
        if self.called_proc && vals.len() > ins.targets.len() {
            vals.truncate(ins.targets.len());
        }
        // One name for two or three numbers left by an operator and the
        // operands after it (`p = (MINI x) 0.`): they make a POINT, as
        // numbers written alone do (language.md §2 rule 6).
        if ins.targets.len() == 1 && (vals.len() == 2 || vals.len() == 3) && vals.iter().all(Value::is_number) {
            vals = vec![self.make_point(&vals).map_err(|e| e.with_span_if_missing(ins.span, &self.source))?];
        }
        if vals.len() != ins.targets.len() {
            let msg = if vals.len() > ins.targets.len() {
                format!("{} results for {} name(s): a result is left over (error 11)", vals.len(), ins.targets.len())
            } else {
                format!("{} result(s) for {} names", vals.len(), ins.targets.len())
            };
            let types: Vec<String> = vals.iter().map(|v| v.type_name()).collect();
            let mut e = Error::runtime(msg).at(ins.span).with_span_if_missing(ins.span, &self.source);
            if !types.is_empty() {
                e = e.note(format!("results: {}", types.join(" ")));
            }
            return Err(e);
        }
        for (t, v) in ins.targets.iter().zip(vals) {
            self.assign(t, v).map_err(|e| e.with_span_if_missing(t.span, &self.source))?;
        }
        Ok(())
    }

    /// Add a note listing the named objects of the failing instruction with
    /// their types (the usual cause of an argument error).
    fn with_objects(&self, e: Error, items: &[Item]) -> Error {
        fn walk(it: &Interp, items: &[Item], out: &mut Vec<String>) {
            for i in items {
                match &i.kind {
                    ItemKind::Word(w) => {
                        if let Some(v) = it.store.get(w) {
                            let s = format!("{} ({})", w, v.type_name());
                            if !out.contains(&s) {
                                out.push(s);
                            }
                        }
                    }
                    ItemKind::Group(g) => walk(it, g, out),
                    _ => {}
                }
            }
        }
        // An error from inside a procedure already lists the objects of
        // the instruction that failed there; the call is in its trace.
        if !matches!(e.kind, ErrorKind::Runtime | ErrorKind::Internal) || !e.trace.is_empty() {
            return e;
        }
        let mut names = Vec::new();
        walk(self, items, &mut names);
        if names.is_empty() {
            e
        } else {
            e.note(format!("objects: {}", names.join(", ")))
        }
    }

    fn assign(&mut self, t: &Target, v: Value) -> Result<()> {
        if let Some(ty) = &t.typed {
            let want = Ty::from_name(ty).ok_or_else(|| Error::runtime(format!("unknown type {}", ty)))?;
            let ok = v.ty() == want || (want == Ty::Flottant && v.ty() == Ty::Entier);
            if !ok {
                return Err(Error::runtime(format!("{} is declared {} but receives a {}", t.name, ty, v.type_name())));
            }
        }
        if let (Some(m), true) = (t.name.strip_prefix('%'), t.keys.is_empty()) {
            return self.set_member(m, v);
        }
        if t.keys.is_empty() && t.base.is_none() {
            self.store.set(&t.name, v);
            return Ok(());
        }
        // T . k1 . k2 = v : walk to the last table, then set in place. The
        // table may be given by a group: `(T . 1) . 'K' = v`.
        let mut cur = match &t.base {
            Some(items) => match self.nested(t.span, |it| it.eval_items(items))?.as_slice() {
                [v] if !t.keys.is_empty() => v.clone(),
                _ => return Err(Error::runtime("a group receiving a result must give one TABLE, then . key")),
            },
            None if t.name.starts_with('%') => self.member(&t.name[1..])?,
            None => self
                .store
                .get(&t.name)
                .cloned()
                .ok_or_else(|| Error::runtime(format!("{} is not a TABLE (it does not exist)", t.name)))?,
        };
        let n = t.keys.len();
        for (i, kit) in t.keys.iter().enumerate() {
            let key = self.key_value(kit)?;
            let table = match &cur {
                Value::Table(tb) => tb.clone(),
                other => {
                    return Err(Error::runtime(format!("'.' indexes a TABLE, not a {}", other.type_name())).at(kit.span))
                }
            };
            if i + 1 == n {
                table.borrow_mut().set(Key::from_value(&key), v);
                return Ok(());
            }
            cur = super::machine::index(&cur, &key).map_err(|e| e.at(kit.span))?;
        }
        Ok(())
    }
}
