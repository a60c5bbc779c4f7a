//! Rebuild SI/SINON/FINSI, REPETER/FIN, DEBPROC/FINPROC blocks from the
//! instructions as they are read. Cast3M executes these as directives one
//! instruction at a time; matching a block before running it lets us report
//! an unclosed block and lets the REPL ask whether the input is complete,
//! while everything before the block still runs first.

use super::ast::*;
use crate::error::{Error, Result};
use crate::source::Span;
use std::rc::Rc;

/// The directive an instruction starts with, by Cast3M's 4-letter rule.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Directive {
    Si,
    Sinon,
    Finsi,
    Repeter,
    Fin,
    Iterer,
    Quitter,
    Debproc,
    Finproc,
    Argu,
    Respro,
}

fn directive(ins: &Instr) -> Option<Directive> {
    if !ins.targets.is_empty() {
        return None;
    }
    let word = match &ins.items.first()?.kind {
        ItemKind::Word(w) => w.clone(),
        ItemKind::Str(s) => s.to_uppercase(),
        _ => return None,
    };
    let key: String = word.chars().take(4).collect();
    Some(match key.as_str() {
        "SI" => Directive::Si,
        "SINO" => Directive::Sinon,
        "FINS" => Directive::Finsi,
        "REPE" => Directive::Repeter,
        "FIN" => Directive::Fin,
        "ITER" => Directive::Iterer,
        "QUIT" => Directive::Quitter,
        // A method is a procedure (debm.notice): only its call differs.
        "DEBP" | "DEBM" => Directive::Debproc,
        "FINP" | "FINM" => Directive::Finproc,
        "ARGU" => Directive::Argu,
        "RESP" => Directive::Respro,
        _ => return None,
    })
}

enum Open {
    If { branches: Vec<Branch>, otherwise: Option<Vec<Stmt>>, span: Span },
    Loop { name: String, count: Option<Instr>, body: Vec<Stmt>, span: Span },
    Proc { name: String, params: Vec<Param>, body: Vec<Stmt>, span: Span },
}

impl Open {
    fn body(&mut self) -> &mut Vec<Stmt> {
        match self {
            Open::If { branches, otherwise, .. } => match otherwise {
                Some(o) => o,
                None => &mut branches.last_mut().expect("an SI has its first branch").body,
            },
            Open::Loop { body, .. } | Open::Proc { body, .. } => body,
        }
    }
    fn describe(&self) -> String {
        match self {
            Open::If { .. } => "SI".into(),
            Open::Loop { name, .. } => format!("REPETER {}", name),
            Open::Proc { name, .. } => format!("DEBPROC {}", name),
        }
    }
    fn span(&self) -> Span {
        match self {
            Open::If { span, .. } | Open::Loop { span, .. } | Open::Proc { span, .. } => *span,
        }
    }
}

/// Rest of an instruction after its directive word.
fn rest(ins: &Instr) -> Instr {
    let items = ins.items[1..].to_vec();
    let span = items.iter().fold(None, |acc: Option<Span>, it| Some(acc.map_or(it.span, |a| a.join(it.span))));
    Instr { targets: vec![], items, span: span.unwrap_or(ins.span) }
}

/// Names are significant to 24 characters (LONOM in Cast3M).
pub fn truncate_name(s: &str) -> String {
    s.chars().take(24).collect()
}

fn word_of(it: &Item) -> Option<String> {
    match &it.kind {
        ItemKind::Word(w) => Some(truncate_name(w)),
        ItemKind::Str(s) => Some(truncate_name(&s.to_uppercase())),
        _ => None,
    }
}

/// Blocks (SI, REPETER, DEBPROC) open at once, at most. The evaluator
/// recurses on blocks: deeper nesting is refused here, at the line that
/// opens one block too many, rather than overflowing the stack.
pub const MAX_BLOCK_DEPTH: usize = 100;

/// Matches blocks as instructions arrive, one at a time (Cast3M reads and
/// runs a deck instruction by instruction): [`push`](Builder::push) hands
/// back a statement as soon as it is complete at the top level.
#[derive(Default)]
pub struct Builder {
    stack: Vec<Open>,
    /// Top-level statements completed by an instruction that holds two
    /// (`FINSI 'FORM' u ;`), waiting for the reader to hand them out.
    pub ready: std::collections::VecDeque<Stmt>,
    /// Forms Cast3M lets pass that are likely mistakes (an extra FINSI,
    /// an SI closed by the end of the text), for the host to show.
    pub warnings: Vec<(String, Span)>,
}

impl Builder {
    fn open(&mut self, o: Open) -> Result<()> {
        if self.stack.len() >= MAX_BLOCK_DEPTH {
            return Err(Error::syntax(
                format!("{} opens a block nested more than {} deep", o.describe(), MAX_BLOCK_DEPTH),
                o.span(),
            ));
        }
        self.stack.push(o);
        Ok(())
    }

    /// Take one instruction. Returns a top-level statement when one is
    /// complete (an instruction outside any block, or a block just closed).
    pub fn push(&mut self, ins: Instr) -> Result<Option<Stmt>> {
        let span = ins.span;
        let stmt = match directive(&ins) {
            None => Some(Stmt::Instr(ins)),
            Some(Directive::Si) => {
                let first = Branch { cond: rest(&ins), body: vec![] };
                self.open(Open::If { branches: vec![first], otherwise: None, span })?;
                None
            }
            // `SINON ;` opens the last branch; `SINON cond ;` is an else-if
            // (newer Cast3M), tried only when every condition before failed.
            Some(Directive::Sinon) => match self.stack.last_mut() {
                Some(Open::If { otherwise: Some(_), .. }) => {
                    return Err(Error::syntax("SINON after the SINON ; that opened the last branch", span))
                }
                Some(Open::If { branches, otherwise, .. }) => {
                    let cond = rest(&ins);
                    if cond.items.is_empty() {
                        *otherwise = Some(vec![]);
                    } else {
                        branches.push(Branch { cond, body: vec![] });
                    }
                    None
                }
                _ => return Err(Error::syntax("SINON without an open SI", span)),
            },
            // A FINSI that closes no SI: in Cast3M FINSI does nothing when it
            // runs, and Cast3M's own procedures and decks hold a few extra
            // ones. Noted, and passed over.
            Some(Directive::Finsi) if !self.stack.iter().any(|o| matches!(o, Open::If { .. })) => {
                self.warnings.push(("FINSI closes no SI: passed over, as Cast3M does".into(), span));
                None
            }
            Some(Directive::Finsi) => {
                let closed = match self.stack.pop() {
                    Some(Open::If { branches, otherwise, span: s }) => Stmt::If { branches, otherwise, span: s },
                    Some(o) => return Err(mismatch("FINSI", &o, span)),
                    None => return Err(Error::syntax("FINSI without an open SI", span)),
                };
                // Cast3M runs the operators of an instruction one after
                // the other: after FINSI (its `;` forgotten), a directive or
                // a quoted operator name starts an instruction of its own
                // (`'FINSI' 'SI' ok ;`). Anything else is a mistake.
                if ins.items.len() > 1 {
                    let next = rest(&ins);
                    let runs = directive(&next).is_some()
                        || matches!(&next.items[0].kind, ItemKind::Str(w) if !w.contains(' '));
                    if !runs {
                        nothing_after("FINSI", &ins)?;
                    }
                    let first = self.place(closed);
                    let second = self.push(next)?;
                    return Ok(match (first, second) {
                        (Some(a), Some(b)) => {
                            self.ready.push_back(b);
                            Some(a)
                        }
                        (a, b) => a.or(b),
                    });
                }
                Some(closed)
            }
            Some(Directive::Repeter) => {
                let r = rest(&ins);
                let (name, count) = loop_header(&r)
                    .ok_or_else(|| Error::syntax("REPETER needs a block name (REPETER name (count) ;)", span))?;
                self.open(Open::Loop { name, count, body: vec![], span })?;
                None
            }
            Some(Directive::Fin) => {
                let r = rest(&ins);
                match r.items.first().and_then(word_of) {
                    None if r.items.is_empty() => Some(Stmt::End { span }),
                    None => return Err(Error::syntax("FIN takes a block name or nothing", span)),
                    Some(_) if r.items.len() > 1 => {
                        return Err(Error::syntax(
                            "FIN takes a block name or nothing",
                            r.items[1..].iter().map(|i| i.span).reduce(Span::join).unwrap_or(span),
                        ))
                    }
                    Some(n) => match self.stack.pop() {
                        Some(Open::Loop { name, count, body, span: s }) if name == n => {
                            Some(Stmt::Loop { name, count, body, span: s })
                        }
                        Some(o) => return Err(mismatch(&format!("FIN {}", n), &o, span)),
                        None => return Err(Error::syntax(format!("FIN {} closes no REPETER", n), span)),
                    },
                }
            }
            Some(d @ (Directive::Iterer | Directive::Quitter)) => {
                let name = ins.items.get(1).and_then(word_of).unwrap_or_default();
                Some(if d == Directive::Iterer { Stmt::Iter { name, span } } else { Stmt::Quit { name, span } })
            }
            Some(Directive::Debproc) => {
                let r = rest(&ins);
                let name = r
                    .items
                    .first()
                    .and_then(word_of)
                    .ok_or_else(|| Error::syntax("DEBPROC needs a procedure name", span))?;
                let params = params(&r.items[1..])?;
                self.open(Open::Proc { name, params, body: vec![], span })?;
                None
            }
            Some(Directive::Finproc) => match self.stack.pop() {
                Some(Open::Proc { name, params, body, span: s }) => {
                    let results = rest(&ins);
                    Some(Stmt::Proc(Rc::new(ProcDef { name, params, body, results, span: s.join(span) })))
                }
                Some(o) => return Err(mismatch("FINPROC", &o, span)),
                None => return Err(Error::syntax("FINPROC without DEBPROC", span)),
            },
            Some(Directive::Argu) => Some(Stmt::Argu { params: params(&ins.items[1..])?, span }),
            Some(Directive::Respro) => Some(Stmt::Respro(rest(&ins))),
        };
        Ok(stmt.and_then(|s| self.place(s)))
    }

    /// A complete statement goes into the innermost open block, or out
    /// when no block is open.
    fn place(&mut self, s: Stmt) -> Option<Stmt> {
        match self.stack.last_mut() {
            Some(o) => {
                o.body().push(s);
                None
            }
            None => Some(s),
        }
    }

    /// An instruction that failed to parse inside an open block: kept as
    /// a statement that raises the error when it runs. Outside any block
    /// the error is returned at once (it would run right away).
    pub fn push_broken(&mut self, e: Error) -> Result<Option<Stmt>> {
        match (self.stack.last_mut(), e.span) {
            (Some(o), Some(span)) if e.kind == crate::error::ErrorKind::Syntax => {
                o.body().push(Stmt::Broken { message: e.message, span });
                Ok(None)
            }
            _ => Err(e),
        }
    }

    /// The end of a deck or a procedure file: an SI still open ends with
    /// the text (Cast3M runs an SI branch up to its FINSI or SINON and
    /// never looks further: a deck that forgets the last FINSI runs), and
    /// a REPETER still open runs once (Cast3M meets the end of the text in
    /// its first pass). The statement completed that way, if any; an open
    /// DEBPROC is an error.
    pub fn finish_text(&mut self) -> Result<Option<Stmt>> {
        let mut done = None;
        loop {
            let closed = match self.stack.pop() {
                Some(Open::If { branches, otherwise, span }) => {
                    let w = "this SI is never closed by FINSI: it ends with the text, as in Cast3M";
                    self.warnings.push((w.into(), span));
                    Stmt::If { branches, otherwise, span }
                }
                // Cast3M reaches the end of the text in the first pass, and
                // stops there: one pass.
                Some(Open::Loop { name, body, span, .. }) => {
                    let w = format!(
                        "REPETER {} is never closed by FIN: it runs once, up to the end of the text, as in Cast3M",
                        name
                    );
                    self.warnings.push((w, span));
                    let one = Item { kind: ItemKind::Int(1), span };
                    Stmt::Loop { name, count: Some(Instr { targets: vec![], items: vec![one], span }), body, span }
                }
                Some(o) => {
                    self.stack.push(o);
                    break;
                }
                None => break,
            };
            done = self.place(closed);
        }
        self.finish()?;
        Ok(done)
    }

    /// The text has ended: every block must be closed.
    pub fn finish(&mut self) -> Result<()> {
        match self.stack.pop() {
            Some(o) => Err(Error::syntax(format!("{} is never closed", o.describe()), o.span())),
            None => Ok(()),
        }
    }
}

/// A closing directive written with something after it (`FINSI x ;`).
fn nothing_after(directive: &str, ins: &Instr) -> Result<()> {
    match ins.items.get(1..).and_then(|r| r.iter().map(|i| i.span).reduce(Span::join)) {
        Some(extra) => Err(Error::syntax(format!("{} takes nothing after it", directive), extra)),
        None => Ok(()),
    }
}

fn mismatch(closer: &str, open: &Open, span: Span) -> Error {
    Error::syntax(format!("{} found while {} is still open", closer, open.describe()), span)
}

/// `REPETER name (count)` or `REPETER count name`.
fn loop_header(r: &Instr) -> Option<(String, Option<Instr>)> {
    let items = &r.items;
    let first = items.first()?;
    let (name, count_items) = if let ItemKind::Word(w) = &first.kind {
        (truncate_name(w), items[1..].to_vec())
    } else if let Some(ItemKind::Word(w)) = items.last().map(|i| &i.kind) {
        (truncate_name(w), items[..items.len() - 1].to_vec())
    } else {
        return None;
    };
    let count = if count_items.is_empty() {
        None
    } else {
        let span = count_items.iter().map(|i| i.span).reduce(Span::join).unwrap_or(r.span);
        Some(Instr { targets: vec![], items: count_items, span })
    };
    Some((name, count))
}

/// `a*TYPE b/TYPE c` parameter lists of DEBPROC and ARGU.
fn params(items: &[Item]) -> Result<Vec<Param>> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < items.len() {
        let it = &items[i];
        let name = word_of(it).ok_or_else(|| Error::syntax("expected a parameter name", it.span))?;
        let mut p = Param { name, ty: None, optional: false, span: it.span };
        if let Some(ItemKind::Sym(s @ ("*" | "/"))) = items.get(i + 1).map(|x| &x.kind) {
            let ty = items
                .get(i + 2)
                .and_then(word_of)
                .ok_or_else(|| Error::syntax(format!("expected a type name after '{}'", s), items[i + 1].span))?;
            p.optional = *s == "/";
            p.ty = Some(ty);
            p.span = p.span.join(items[i + 2].span);
            i += 2;
        }
        out.push(p);
        i += 1;
    }
    Ok(out)
}
