//! The stack machine that runs one parenthesised group (language.md §2).
//!
//! Items become tokens first: nested groups are evaluated innermost first,
//! left to right, names are resolved (object, else word), and table
//! indexing `T . k` is applied. Then tokens are read left to right: values
//! are pushed, operators run and read their arguments by type among the
//! pushed values and further right, and their results are pushed back.

use super::args::{ends_window, takes_no_argument, Args};
use super::registry::OpSpec;
pub use super::tokens::{GroupState, Tok, TokKind};
use super::Interp;
use crate::error::{Error, Result};
use crate::source::Span;
use crate::syntax::ast::{Item, ItemKind};
use crate::value::{Key, Value};
use std::rc::Rc;

/// A quoted text can act as an operator only if it looks like a word.
fn wordlike(s: &str) -> bool {
    !s.is_empty() && !s.contains(char::is_whitespace)
}

impl Interp {
    /// Evaluate a group of items to its results (a POINT if exactly two or
    /// three numbers remain).
    pub fn eval_items(&mut self, items: &[Item]) -> Result<Vec<Value>> {
        let toks = self.tokens(items)?;
        let span = items.iter().map(|i| i.span).reduce(Span::join).unwrap_or_default();
        let (mut vals, ran_operator) = self.run_tokens(toks)?;
        // Numbers left over become a POINT only when they were written as
        // operands: `x y = coor p` keeps the two results of COOR. Fewer
        // numbers than the dimension cannot be a point, so in 3D
        // `a b = (MINI x) (MAXI x)` keeps its two numbers, as in Cast3M.
        let dim = self.opts.dime;
        let point_sized = (vals.len() == 2 || vals.len() == 3) && (dim == 0 || vals.len() >= dim);
        if !ran_operator && point_sized && vals.iter().all(Value::is_number) {
            vals = vec![self.make_point(&vals).map_err(|e| e.with_span_if_missing(span, &self.source))?];
        }
        Ok(vals)
    }

    pub(super) fn make_point(&mut self, nums: &[Value]) -> Result<Value> {
        let dim = self.opts.dime;
        if dim == 0 {
            return Err(Error::runtime("two or three numbers make a POINT, which needs OPTI DIME first (error 14)"));
        }
        let f: Vec<f64> = nums.iter().filter_map(Value::as_f64).collect();
        if f.len() < dim {
            return Err(Error::runtime(format!(
                "a POINT in dimension {} needs {} coordinates, found {}",
                dim,
                dim,
                f.len()
            )));
        }
        let mut x = [0.0; 3];
        x[..dim].copy_from_slice(&f[..dim]);
        let dens = if f.len() > dim { f[dim] } else { self.opts.dens };
        Ok(Value::Point(self.nodes.push(x, dens)))
    }

    /// Evaluate items without the POINT rule (FINPROC and RESPRO results).
    pub fn eval_items_raw(&mut self, items: &[Item]) -> Result<Vec<Value>> {
        let toks = self.tokens(items)?;
        Ok(self.run_tokens(toks)?.0)
    }

    /// Items -> tokens, resolving names, groups and table indexing.
    fn tokens(&mut self, items: &[Item]) -> Result<Vec<Tok>> {
        let mut out: Vec<Tok> = Vec::with_capacity(items.len());
        let mut i = 0;
        while i < items.len() {
            let it = &items[i];
            let span = it.span;
            match &it.kind {
                // A '.' that ends a group or an instruction separates
                // nothing: Cast3M passes over it (`p = x (-1.*x). ;`).
                ItemKind::Dot if i + 1 == items.len() => {}
                // After an object that is not a TABLE the '.' is only a
                // separator: Cast3M's reader skips it and reads on
                // (`PRES 'MASS' MOD1 pre1 . L13` gives PRES both).
                ItemKind::Dot if matches!(out.last(), Some(Tok { kind: TokKind::Val(v), .. }) if !matches!(v, Value::Table(_)) && crate::value::objet::Objet::of(v).is_none()) =>
                    {}
                ItemKind::Dot => {
                    let key_item = &items[i + 1];
                    let table = match out.pop() {
                        Some(Tok { kind: TokKind::Val(v), span: s, .. }) => (v, s),
                        _ => return Err(Error::runtime("'.' must follow a TABLE").at(span)),
                    };
                    let key = self.key_value(key_item)?;
                    let v = index(&table.0, &key).map_err(|e| e.at(table.1.join(key_item.span)))?;
                    out.push(Tok { kind: TokKind::Val(v), span: table.1.join(key_item.span), named: false });
                    i += 2;
                    continue;
                }
                ItemKind::Sym("%") => {
                    i = self.percent(items, i, &mut out)?;
                    continue;
                }
                ItemKind::Group(g) => {
                    for v in self.nested(span, |it| it.eval_items(g))? {
                        out.push(Tok { kind: TokKind::Val(v), span, named: false });
                    }
                }
                kind => {
                    let named = matches!(kind, ItemKind::Word(_));
                    match self.resolve(kind, span)? {
                        TokKind::Word(w) => self.word_token(w, span, &mut out)?,
                        kind => out.push(Tok { kind, span, named }),
                    }
                }
            }
            i += 1;
        }
        Ok(out)
    }

    /// An unquoted word that names no object. An operator that takes no
    /// argument is evaluated where it is met, as Cast3M does, so it can
    /// stand wherever a value can: `2. * PI`, `MESS PI`, `P = PI PI`,
    /// `PROG 0. PI`.
    fn word_token(&mut self, w: String, span: Span, out: &mut Vec<Tok>) -> Result<()> {
        let op = match self.registry.find(&w) {
            Some(op) if takes_no_argument(&op) => op,
            _ => {
                out.push(Tok { kind: TokKind::Word(w), span, named: true });
                return Ok(());
            }
        };
        let mut st = GroupState::default();
        self.invoke(op, &mut st, span)?;
        if st.left.len() == 1 {
            let value = st.left.pop().expect("one result");
            out.push(Tok { kind: TokKind::Nullary { word: w, value }, span, named: true });
        } else {
            out.extend(st.left.into_iter().map(|v| Tok { kind: TokKind::Val(v), span, named: false }));
        }
        Ok(())
    }

    fn resolve(&self, kind: &ItemKind, span: Span) -> Result<TokKind> {
        Ok(match kind {
            ItemKind::Int(n) => TokKind::Val(Value::Int(*n)),
            ItemKind::Float(f) => TokKind::Val(Value::Float(*f)),
            ItemKind::Str(s) => TokKind::Quoted(Rc::from(s.as_str())),
            ItemKind::Word(w) => match self.store.get(w) {
                Some(v) => TokKind::Val(v.clone()),
                None if w == "VRAI" => TokKind::Val(Value::Bool(true)),
                None if w == "FAUX" => TokKind::Val(Value::Bool(false)),
                None => TokKind::Word(w.clone()),
            },
            ItemKind::Counter(n) => match self.store.counter(n) {
                Some(c) => TokKind::Val(Value::Int(c)),
                // No loop of that name: an object assigned as `&NAME = …`.
                None => match self.store.get(&format!("&{}", n)) {
                    Some(v) => TokKind::Val(v.clone()),
                    None => return Err(Error::runtime(format!("&{}: no REPETER {} has run", n, n)).at(span)),
                },
            },
            ItemKind::Sym(s) => TokKind::Sym(s),
            ItemKind::Dot | ItemKind::Group(_) => unreachable!("handled by tokens()"),
        })
    }

    /// The value of a table key item: a name gives its object, else the word.
    pub fn key_value(&mut self, it: &Item) -> Result<Value> {
        match &it.kind {
            ItemKind::Word(w) => Ok(self.store.get(w).cloned().unwrap_or_else(|| Value::mot(w))),
            ItemKind::Str(s) => Ok(Value::mot(s)),
            ItemKind::Group(g) => {
                let mut v = self.nested(it.span, |me| me.eval_items(g))?;
                if v.len() != 1 {
                    return Err(Error::runtime("a table key must be one value").at(it.span));
                }
                Ok(v.remove(0))
            }
            // `T . . k`: a second '.' where the key should be (found by
            // fuzzing: it reached the unreachable arm of `resolve`).
            ItemKind::Dot => Err(Error::runtime("'.' must be followed by a table key").at(it.span)),
            k => match self.resolve(k, it.span)? {
                TokKind::Val(v) => Ok(v),
                _ => Err(Error::runtime("this is not a table key").at(it.span)),
            },
        }
    }

    /// Read tokens left to right, running operators as they come.
    pub fn run_tokens(&mut self, toks: Vec<Tok>) -> Result<(Vec<Value>, bool)> {
        let mut st = GroupState { left: Vec::new(), right: toks.into() };
        let mut ran = false;
        // The last operator run in this group: a Cast3M name met after it
        // may be an argument it does not take.
        let mut last_op: Option<&'static str> = None;
        while let Some(t) = st.right.pop_front() {
            // A MOT object written by its name in operator position, with
            // an argument after it, calls the operator it names (`OPE =
            // MOT 'MESS' ; OPE 'BONJOUR' ;`, mot.notice). An operator
            // reading its arguments takes it before this point, as a word.
            // Followed by an operator or by nothing, it stays an operand:
            // `TY = TYPE K ; SI (TY EGA 'RIGIDITE')` must not run RIGI.
            if let TokKind::Val(Value::Mot(s)) = &t.kind {
                let has_argument = st.right.front().is_some_and(|n| !ends_window(n, &self.registry));
                // A MOT naming a procedure calls it the same way, named or
                // made by TEXT (text.notice: a text stands for its content):
                // `(TEXT NOMFCT) x p` calls the procedure NOMFCT names.
                if has_argument && wordlike(s) {
                    if let Some(p) = self.proc_named(&s.to_uppercase(), t.span)? {
                        let r = self.call_proc(p, &mut st, t.span)?;
                        self.called_proc = true;
                        st.left.extend(r);
                        ran = true;
                        continue;
                    }
                }
                if t.named && has_argument && wordlike(s) {
                    if let Some(op) = self.registry.find(s) {
                        last_op = Some(op.name);
                        self.invoke(op, &mut st, t.span)?;
                        ran = true;
                        continue;
                    }
                    self.refuse(s, t.span, last_op)?;
                }
            }
            ran |= !matches!(t.kind, TokKind::Val(ref v) if !matches!(v, Value::Proc(_)))
                && !matches!(t.kind, TokKind::Nullary { .. });
            match t.kind {
                TokKind::Nullary { value, .. } => st.left.push(value),
                TokKind::Val(Value::Proc(p)) => {
                    let r = self.call_proc(p, &mut st, t.span)?;
                    self.called_proc = true;
                    st.left.extend(r);
                }
                TokKind::Val(v) if super::objet::is_bound(&v) => {
                    let r = self.run_bound(&v, &mut st, t.span)?;
                    self.called_proc = true;
                    ran = true;
                    st.left.extend(r);
                }
                TokKind::Val(v) => st.left.push(v),
                TokKind::Quoted(s) => match self.registry.find(&s).filter(|_| wordlike(&s)) {
                    Some(op) => {
                        last_op = Some(op.name);
                        self.invoke(op, &mut st, t.span)?
                    }
                    None => {
                        // Decks quote operator names ('BRUI' 'BLAN' …), never
                        // procedure names: those are object names.
                        if let Some(e) = super::catalogue::operator(&s).filter(|_| wordlike(&s)) {
                            return Err(refused(super::unimplemented::message(e, false), &s, t.span, last_op));
                        }
                        st.left.push(Value::Mot(s))
                    }
                },
                // A procedure of the library runs where its name would run
                // (before an operator whose 4 letters it merely begins
                // with: TRANSGEN is not TRAN). Where an operator reads its
                // arguments the name is a word (`VARI PSATT x`: PSATT is
                // also a library procedure), as in Cast3M, which loads a
                // library procedure only when it comes to run it.
                TokKind::Word(w) => match self.library_proc(&w, t.span)? {
                    Some(p) => {
                        let r = self.call_proc(p, &mut st, t.span)?;
                        self.called_proc = true;
                        st.left.extend(r);
                    }
                    None => match self.registry.find(&w) {
                        Some(op) => {
                            last_op = Some(op.name);
                            self.invoke(op, &mut st, t.span)?
                        }
                        None => {
                            self.refuse(&w, t.span, last_op)?;
                            st.left.push(Value::mot(&w))
                        }
                    },
                },
                TokKind::Sym(s) => match self.registry.find(s) {
                    Some(op) => {
                        last_op = Some(op.name);
                        self.invoke(op, &mut st, t.span)?
                    }
                    None => return Err(Error::runtime(format!("'{}' is not an operator here", s)).at(t.span)),
                },
            }
        }
        Ok((st.left, ran))
    }

    /// The procedure a name stands for: an object of the deck, else one
    /// of the procedure library.
    fn proc_named(&mut self, name: &str, span: Span) -> Result<Option<Rc<crate::syntax::ast::ProcDef>>> {
        match self.store.get(name) {
            Some(Value::Proc(p)) => Ok(Some(p.clone())),
            Some(_) => Ok(None),
            None => self.library_proc(name, span),
        }
    }

    /// Stop at a Cast3M name that gibi lacks, written where it would run
    /// (see eval::unimplemented); any other word is a MOT.
    fn refuse(&self, word: &str, span: Span, last_op: Option<&str>) -> Result<()> {
        match super::unimplemented::refusal(word, &self.registry, self.library.is_configured()) {
            Some(e) => Err(refused(e, word, span, last_op)),
            None => Ok(()),
        }
    }

    /// Run one operator: it reads its arguments through `Args`, and its
    /// results are pushed back for the next operator (chaining).
    pub fn invoke(&mut self, op: Rc<OpSpec>, st: &mut GroupState, span: Span) -> Result<()> {
        let registry = self.registry.clone();
        let start = std::time::Instant::now();
        let nodes_before = self.nodes.len();
        let res = {
            let mut args = Args::new(&op, st, &registry, span);
            // A bug in one operator must not take the session down (the REPL
            // would lose every object): it becomes an error at the call site.
            std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| op.call(self, &mut args))).unwrap_or_else(|p| {
                let msg = p
                    .downcast_ref::<String>()
                    .map(String::as_str)
                    .or_else(|| p.downcast_ref::<&str>().copied())
                    .unwrap_or("unknown cause");
                Err(Error::internal(format!("{}: internal error ({}); please report it with the deck", op.name, msg)))
            })
        };
        op.record(start.elapsed());
        let res = res.and_then(|r| finite_results(&op, r, &self.nodes, nodes_before));
        let res = res.map_err(|e| e.with_span_if_missing(span, &self.source))?;
        st.left.extend(res);
        Ok(())
    }
}

/// The last net against NaN and infinities (value::finite): an
/// operator's results, and the nodes it made, hold finite numbers only.
fn finite_results(op: &OpSpec, r: Vec<Value>, nodes: &crate::fem::mesh::Nodes, from: usize) -> Result<Vec<Value>> {
    use crate::value::finite::{describe, first_non_finite, in_nodes};
    if let Some(x) = r.iter().find_map(first_non_finite) {
        return Err(Error::runtime(format!("{}: the result holds {}", op.name, describe(x))));
    }
    if let Some(x) = in_nodes(nodes, from) {
        return Err(Error::runtime(format!("{}: a node it made has {} as a coordinate", op.name, describe(x))));
    }
    Ok(r)
}

/// A refusal at `span`; after an operator of the same group, the word may
/// rather be an argument that operator left over.
fn refused(e: Error, word: &str, span: Span, last_op: Option<&str>) -> Error {
    let e = e.at(span);
    match last_op {
        Some(op) => e.note(format!("if {} is meant as an argument of {}, {} does not take it", word, op, op)),
        None => e,
    }
}

/// `T . k`: the entry of a table (or of an object that acts like one).
pub fn index(v: &Value, key: &Value) -> Result<Value> {
    match v {
        Value::Table(t) => {
            t.borrow().get(&Key::from_value(key)).cloned().ok_or_else(|| {
                Error::runtime(format!("the TABLE has no entry {}", crate::value::list_value_short(key)))
            })
        }
        // `O . 'CLASSE'`: the class of an OBJET (the constructor's name);
        // any other key is one of its entries.
        other => match crate::value::objet::Objet::of(other) {
            Some(o) => match key {
                Value::Mot(k) if k.trim_end().eq_ignore_ascii_case("CLASSE") => Ok(Value::mot(&o.class)),
                _ => o.entries.borrow().get(&Key::from_value(key)).cloned().ok_or_else(|| {
                    Error::runtime(format!("the OBJET has no entry {}", crate::value::list_value_short(key)))
                }),
            },
            None => Err(Error::runtime(format!("'.' indexes a TABLE, not a {}", other.type_name()))),
        },
    }
}
