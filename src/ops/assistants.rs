//! ASSI: hand the rest of an instruction to an "assistant" (assi.notice).
//!
//! Cast3M's assistants are worker processes of its parallel version; its
//! sequential version runs the work on the master, which the notice allows
//! (`OPTI 'ASSI' 0`: the master is assistant 0, and any assistant number
//! maps onto the ones declared). gibi is that sequential version: the
//! values are the same, only computed in order. The objects of a session
//! are reference-counted and not shareable across threads, so running the
//! work on threads would need a copy of every object it reads; that is not
//! worth it for the decks' sizes.
//!
//! `ASSI 'TOUS' ...` runs the instruction once per index of the ESCLAVE
//! tables it reads (each table replaced by its entry at that index), and
//! gathers each result into an ESCLAVE table at the same index.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::tokens::{Tok, TokKind};
use crate::eval::Interp;
use crate::value::{Key, Table, Value};
use std::cell::RefCell;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "ASSI",
    signature: "ASSI ENTIER INSTRUCTION… | ASSI 'TOUS' INSTRUCTION… (with TABLE 'ESCLAVE' operands)",
    doc: "Run the rest of the instruction on an assistant (gibi runs it in order on the master, with the same \
          results). 'TOUS': run it once per index of its ESCLAVE tables, each table replaced by its entry there; \
          each result is an ESCLAVE table with the results at the same indices.",
    example: "x = assi 1 2 + 3 ; t = tabl 'ESCLAVE' ; t . 1 = 1. ; t . 2 = 4. ; r = assi 'TOUS' t ** 0.5 ;",
    f: assi,
}];

fn assi(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let all = a.keyword_next(&["TOUS"]).is_some();
    if !all {
        let n = a.opt_right::<i64>().ok_or_else(|| a.missing("an assistant number (ENTIER) or 'TOUS'"))?;
        if n < 0 {
            return Err(a.err(format!("the assistant number must be 0 or more, found {}", n)));
        }
    }
    let rest = a.take_rest();
    if rest.is_empty() {
        return Err(a.err("no instruction follows to give to the assistant"));
    }
    if !all {
        return Ok(it.run_tokens(rest)?.0);
    }
    let slaves: Vec<(usize, Rc<RefCell<Table>>)> = rest
        .iter()
        .enumerate()
        .filter_map(|(i, t)| match &t.kind {
            TokKind::Val(Value::Table(tab)) if is_slave(&tab.borrow()) => Some((i, tab.clone())),
            _ => None,
        })
        .collect();
    let Some((_, first)) = slaves.first() else {
        return Err(a.err("'TOUS' needs at least one TABLE of subtype ESCLAVE in the instruction"));
    };
    let keys: Vec<Key> = first.borrow().iter().map(|(k, _)| k.clone()).filter(|k| !is_subtype_key(k)).collect();
    for (_, t) in &slaves[1..] {
        let t = t.borrow();
        let n = t.iter().filter(|(k, _)| !is_subtype_key(k)).count();
        if n != keys.len() || keys.iter().any(|k| t.get(k).is_none()) {
            return Err(a.err("with 'TOUS' every ESCLAVE table of the instruction must have the same indices"));
        }
    }
    let mut results: Vec<Table> = Vec::new();
    for k in &keys {
        let mut toks: Vec<Tok> = rest.clone();
        for (i, t) in &slaves {
            let v = t.borrow().get(k).cloned().expect("indices checked above");
            toks[*i].kind = TokKind::Val(v);
        }
        let vals = it.run_tokens(toks)?.0;
        if results.is_empty() {
            results = (0..vals.len()).map(|_| Table::with_subtype("ESCLAVE")).collect();
        } else if vals.len() != results.len() {
            return Err(a.err(format!(
                "the instruction gave {} results at one index and {} at another",
                results.len(),
                vals.len()
            )));
        }
        for (r, v) in results.iter_mut().zip(vals) {
            r.set(k.clone(), v);
        }
    }
    if results.is_empty() {
        // No index: one empty ESCLAVE table, as the instruction gives at
        // least one result.
        results.push(Table::with_subtype("ESCLAVE"));
    }
    Ok(results.into_iter().map(|t| Value::Table(Rc::new(RefCell::new(t)))).collect())
}

fn is_subtype_key(k: &Key) -> bool {
    matches!(k, Key::Mot(s) if s == "SOUSTYPE")
}

fn is_slave(t: &Table) -> bool {
    matches!(t.get(&Key::Mot("SOUSTYPE".into())), Some(Value::Mot(s)) if s.trim().eq_ignore_ascii_case("ESCLAVE"))
}
