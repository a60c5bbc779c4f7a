//! `Args`: how an operator reads its arguments, and the only place where
//! argument and arity errors are worded.
//!
//! Cast3M's rule (language.md §2 rule 4): an operator looks for an argument
//! of the type it wants among the operands already pushed in the
//! instruction (oldest first), then further right, so arguments of
//! different types come in almost any order (`EXTR 2 L` = `EXTR L 2`).
//! On the right it reads its *window*: the tokens up to the next symbol,
//! operator word or procedure, which belong to the operators that follow.
//! Keywords are read as words in the window, whatever they would otherwise
//! mean (`MINI L 'ABS'` reads ABS as MINI's keyword, not as the operator).
//! The `_right` and `_next` readers look at the next token only, for
//! operators that read a sequence in order (PROG, MOTS).

use super::registry::{OpSpec, Registry};
use super::tokens::{GroupState, Tok, TokKind};
use crate::error::{Error, Result};
use crate::fem::mesh::Mesh;
use crate::source::Span;
use crate::value::{Chpoint, Evolution, Mchaml, Model, Rigidite, Table, Value};
use std::cell::RefCell;
use std::rc::Rc;

/// A node used as a POINT argument.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PointId(pub usize);

/// A Rust type an argument can be read as.
pub trait FromArg: Sized {
    /// The Gibiane type name(s), for messages.
    const EXPECT: &'static str;
    fn from_value(v: &Value) -> Option<Self>;
}

macro_rules! from_arg {
    ($t:ty, $name:expr, $pat:pat => $e:expr) => {
        impl FromArg for $t {
            const EXPECT: &'static str = $name;
            fn from_value(v: &Value) -> Option<Self> {
                match v {
                    $pat => Some($e),
                    _ => None,
                }
            }
        }
    };
}

from_arg!(f64, "FLOTTANT", Value::Float(f) => *f);
from_arg!(i64, "ENTIER", Value::Int(i) => *i);
from_arg!(bool, "LOGIQUE", Value::Bool(b) => *b);
from_arg!(String, "MOT", Value::Mot(s) => s.to_string());
from_arg!(PointId, "POINT", Value::Point(p) => PointId(*p));
from_arg!(Rc<Vec<f64>>, "LISTREEL", Value::ListReel(l) => l.clone());
from_arg!(Rc<Vec<i64>>, "LISTENTI", Value::ListEnti(l) => l.clone());
from_arg!(Rc<Vec<String>>, "LISTMOTS", Value::ListMots(l) => l.clone());
from_arg!(Rc<RefCell<Table>>, "TABLE", Value::Table(t) => t.clone());
from_arg!(Rc<Mesh>, "MAILLAGE", Value::Mesh(m) => m.clone());
from_arg!(Rc<Chpoint>, "CHPOINT", Value::Chpo(c) => c.clone());
from_arg!(Rc<Vec<Rc<Chpoint>>>, "LISTCHPO", Value::ListChpo(l) => l.clone());
from_arg!(Rc<Rigidite>, "RIGIDITE", Value::Rigi(r) => r.clone());
from_arg!(Rc<Model>, "MMODEL", Value::Model(m) => m.clone());
from_arg!(Rc<Mchaml>, "MCHAML", Value::Mchaml(m) => m.clone());
from_arg!(Rc<Evolution>, "EVOLUTIO", Value::Evol(e) => e.clone());

/// A FLOTTANT argument also accepts an ENTIER (lirabj.eso).
#[derive(Debug, Clone, Copy)]
pub struct Num(pub f64);
from_arg!(Num, "FLOTTANT", Value::Float(f) => Num(*f));
impl Num {
    pub(crate) fn accept(v: &Value) -> Option<Num> {
        v.as_f64().map(Num)
    }
}

impl FromArg for Value {
    const EXPECT: &'static str = "an object";
    fn from_value(v: &Value) -> Option<Self> {
        Some(v.clone())
    }
}

pub struct Args<'a> {
    pub op: &'a OpSpec,
    st: &'a mut GroupState,
    registry: &'a Registry,
    pub span: Span,
}

/// Compare keywords on their first 4 letters (`'MINIMUM'` = `'MINI'`). A
/// choice of fewer letters is itself a short form and matches the words
/// it begins (`'ABS'` and `'ABSOLU'` both give `ABS`).
pub fn keyword_matches(word: &str, choice: &str) -> bool {
    let k = |s: &str| s.chars().take(4).collect::<String>();
    let (w, c) = (k(word), k(choice));
    w == c || (c.chars().count() < 4 && w.starts_with(&c))
}

impl<'a> Args<'a> {
    pub fn new(op: &'a OpSpec, st: &'a mut GroupState, registry: &'a Registry, span: Span) -> Self {
        Args { op, st, registry, span }
    }

    // ---- errors: every wording lives here -------------------------------

    /// `OP: message` with the operator's usage as a note.
    pub fn err(&self, msg: impl std::fmt::Display) -> Error {
        operator_error(self.op, msg)
    }

    /// A required argument is missing: says what was found instead.
    pub fn missing(&self, what: &str) -> Error {
        self.err(format!("expected {}, found {}", what, self.describe_next()))
    }

    /// What the next unread token is, in words.
    pub fn describe_next(&self) -> String {
        match self.st.right.front().map(|t| &t.kind) {
            None => "nothing".into(),
            Some(TokKind::Val(v) | TokKind::Nullary { value: v, .. }) => {
                format!("{} {}", article(&v.type_name()), v.type_name())
            }
            Some(TokKind::Quoted(s)) => format!("the word '{}'", s),
            Some(TokKind::Word(w)) if self.registry.find(w).is_some() => {
                format!("the operator {}", w)
            }
            Some(TokKind::Word(w)) => format!("the word {}", w),
            Some(TokKind::Sym(s)) => format!("'{}'", s),
        }
    }

    // ---- reading by type ------------------------------------------------

    /// The next right token as a value, if it is one (operators and
    /// symbols are not values).
    fn right_value(&self) -> Option<Value> {
        match self.st.right.front().map(|t| &t.kind)? {
            TokKind::Val(Value::Proc(_)) => None,
            TokKind::Val(v) | TokKind::Nullary { value: v, .. } => Some(v.clone()),
            TokKind::Quoted(s) => Some(Value::Mot(s.clone())),
            TokKind::Word(w) if self.registry.find(w).is_none() => Some(Value::mot(w)),
            _ => None,
        }
    }

    fn take_with<T>(&mut self, conv: impl Fn(&Value) -> Option<T>) -> Option<T> {
        take_typed(self.st, self.registry, conv)
    }

    fn take_right_with<T>(&mut self, conv: impl Fn(&Value) -> Option<T>) -> Option<T> {
        let t = conv(&self.right_value()?)?;
        self.st.right.pop_front();
        Some(t)
    }

    /// Whether an argument of type T is there, pushed or on the right,
    /// without taking it (an operator whose form depends on which types
    /// are present, in any order).
    pub fn has_any<T: FromArg>(&self) -> bool {
        self.st.left.iter().any(|v| T::from_value(v).is_some())
            || self.st.right.iter().any(|t| match &t.kind {
                TokKind::Val(v) | TokKind::Nullary { value: v, .. } => T::from_value(v).is_some(),
                _ => false,
            })
    }

    /// An optional argument of type T: pushed operands first, then right.
    pub fn opt<T: FromArg>(&mut self) -> Option<T> {
        self.take_with(T::from_value)
    }

    /// An argument that `conv` accepts, found like [`opt`](Self::opt). An
    /// operator that takes one of several types reads them in one go (a
    /// POINT or a MAILLAGE: whichever comes first), never one type after
    /// the other, which would reach past the other type to a later
    /// argument.
    pub fn opt_with<T>(&mut self, conv: impl Fn(&Value) -> Option<T>) -> Option<T> {
        self.take_with(conv)
    }

    /// A required argument of type T.
    pub fn req<T: FromArg>(&mut self) -> Result<T> {
        match self.opt::<T>() {
            Some(t) => Ok(t),
            None => Err(self.missing(T::EXPECT)),
        }
    }

    /// Only from the right (for arguments that must follow the operator).
    pub fn opt_right<T: FromArg>(&mut self) -> Option<T> {
        self.take_right_with(T::from_value)
    }

    /// A 1-based ENTIER index into an object of `len` items, returned
    /// 0-based (EXTR on lists and words).
    pub fn req_index(&mut self, len: usize) -> Result<usize> {
        let i = self.req::<i64>()?;
        if i < 1 || i as usize > len {
            return Err(self.err(match len {
                0 => format!("index {} is out of range: the object is empty", i),
                _ => format!("index {} is outside 1..{}", i, len),
            }));
        }
        Ok(i as usize - 1)
    }

    /// A number (ENTIER or FLOTTANT) as f64.
    pub fn opt_num(&mut self) -> Option<f64> {
        self.take_with(Num::accept).map(|n| n.0)
    }
    pub fn req_num(&mut self) -> Result<f64> {
        self.opt_num().ok_or_else(|| self.missing("FLOTTANT"))
    }
    pub fn opt_num_right(&mut self) -> Option<f64> {
        self.take_right_with(Num::accept).map(|n| n.0)
    }

    /// The most recently pushed operand, if it has type T (binary
    /// operators take their left operand this way: `1 + 2 * 3` is 9).
    pub fn left_top<T: FromArg>(&mut self) -> Option<T> {
        let t = T::from_value(self.st.left.last()?)?;
        self.st.left.pop();
        Some(t)
    }

    /// Give back an operand taken too early: it is pushed as the newest
    /// left operand, where the next read finds it.
    pub fn unread(&mut self, v: Value) {
        self.st.left.push(v);
    }

    /// Left operand of an infix operator: the newest pushed value.
    pub fn left_value(&mut self) -> Option<Value> {
        self.st.left.pop()
    }

    /// The next right value, whatever its type.
    pub fn right_any(&mut self) -> Option<Value> {
        let v = self.right_value()?;
        self.st.right.pop_front();
        Some(v)
    }

    /// The next right token if it is a procedure (which no other reader
    /// takes: a procedure runs where it is reached).
    pub fn right_proc(&mut self) -> Option<Rc<crate::syntax::ast::ProcDef>> {
        match self.st.right.front().map(|t| &t.kind)? {
            TokKind::Val(Value::Proc(p)) => {
                let p = p.clone();
                self.st.right.pop_front();
                Some(p)
            }
            _ => None,
        }
    }

    /// Peek at the next right value without consuming it.
    pub fn peek_right(&self) -> Option<Value> {
        self.right_value()
    }

    /// Every remaining value on the right, up to the next operator.
    pub fn rest(&mut self) -> Vec<Value> {
        let mut out = Vec::new();
        while let Some(v) = self.right_any() {
            out.push(v);
        }
        out
    }

    /// Number of operands pushed on the left (not yet consumed).
    pub fn left_len(&self) -> usize {
        self.st.left.len()
    }

    // ---- words ---------------------------------------------------------

    /// The raw next right token as a word: quoted text, any unquoted word
    /// (operator names included), a MOT object, or a symbol (`RELA` reads
    /// `+`/`-` this way).
    fn right_word(&self) -> Option<String> {
        match self.st.right.front().map(|t| &t.kind)? {
            TokKind::Quoted(s) => Some(s.to_string()),
            TokKind::Word(w) | TokKind::Nullary { word: w, .. } => Some(w.clone()),
            TokKind::Val(Value::Mot(s)) => Some(s.to_string()),
            TokKind::Sym(s) => Some(s.to_string()),
            _ => None,
        }
    }

    /// One of `choices` (4-letter match), consumed, as written in the
    /// table: the next token, else the first word of the window past the
    /// objects written before it (`MINI L 'ABS'`, `MAXI (LECT 1 4)
    /// 'ABSOLU'`, `MAXI L ABS`: a matching operator word is a keyword
    /// here). Another word there is not passed: keywords keep their place
    /// among words. What followed a keyword found further right is brought
    /// to the front, so that the keyword's own value is read next
    /// (`P1 D 10 P2 'DINI' 0.1` reads 0.1 for DINI, not 10).
    pub fn keyword(&mut self, choices: &[&'static str]) -> Option<&'static str> {
        if let Some(c) = self.keyword_next(choices) {
            return Some(c);
        }
        let right = &self.st.right;
        let mut found = None;
        for (i, t) in right.iter().enumerate() {
            let word = match &t.kind {
                TokKind::Quoted(s) | TokKind::Val(Value::Mot(s)) => s.to_string(),
                TokKind::Word(w) | TokKind::Nullary { word: w, .. } => w.clone(),
                TokKind::Val(Value::Proc(_)) | TokKind::Sym(_) => break,
                TokKind::Val(_) => continue,
            };
            if let Some(c) = choices.iter().find(|c| keyword_matches(&word, c)) {
                found = Some((i, *c));
            }
            if found.is_some() || !matches!(t.kind, TokKind::Nullary { .. }) {
                break;
            }
        }
        let (i, c) = found?;
        let right = &mut self.st.right;
        right.remove(i);
        // A quoted operator name also ends it: it runs where it stands
        // (`MAXI ch 'ABS' '/' x` divides the maximum), as in `take_typed`.
        let ends = |t: &Tok| {
            ends_window(t, self.registry)
                || matches!(&t.kind, TokKind::Quoted(s) if !s.contains(char::is_whitespace) && self.registry.find(s).is_some())
        };
        let end = (i..right.len()).find(|&j| ends(&right[j])).unwrap_or(right.len());
        right.make_contiguous()[..end].rotate_left(i);
        Some(c)
    }

    /// Like [`keyword`](Self::keyword), but only the next token (a keyword
    /// at a fixed place of a sequence: `PROG 0. PAS 0.5 2.`).
    pub fn keyword_next(&mut self, choices: &[&'static str]) -> Option<&'static str> {
        let w = self.right_word()?;
        let c = choices.iter().find(|c| keyword_matches(&w, c))?;
        self.st.right.pop_front();
        Some(c)
    }

    /// Like [`keyword`](Self::keyword) but the word must be there.
    pub fn req_keyword(&mut self, choices: &[&'static str]) -> Result<&'static str> {
        self.keyword(choices).ok_or_else(|| self.missing(&format!("one of {}", choices.join(" "))))
    }

    /// The next right token as a word, not consumed: quoted text, a MOT,
    /// or an unquoted word even when it names an operator (`CHAI FORMAT`).
    pub fn peek_word(&self) -> Option<String> {
        self.right_word()
    }

    /// Any word on the right (not a symbol), consumed.
    pub fn word(&mut self) -> Option<String> {
        match self.st.right.front().map(|t| &t.kind)? {
            TokKind::Sym(_) => None,
            _ => {
                let w = self.right_word()?;
                self.st.right.pop_front();
                Some(w)
            }
        }
    }

    /// A symbol or word `+`/`-` on the right (RELA's signs).
    pub fn sign(&mut self) -> Option<f64> {
        match self.right_word()?.as_str() {
            "+" => {
                self.st.right.pop_front();
                Some(1.0)
            }
            "-" => {
                self.st.right.pop_front();
                Some(-1.0)
            }
            _ => None,
        }
    }

    /// A MOT among the pushed operands (for operators written after their
    /// operands), else on the right.
    pub fn opt_mot(&mut self) -> Option<String> {
        self.opt::<String>()
    }
}

/// The error of an operator: `OP: message`, with its usage as a note. The
/// evaluator's fast path words the errors of `+ - * / **` through it too.
pub fn operator_error(op: &OpSpec, msg: impl std::fmt::Display) -> Error {
    Error::runtime(format!("{}: {}", op.name, msg)).note(format!("usage: {}", op.signature))
}

/// Whether a right token ends an operator's window: a symbol, an operator
/// word or a procedure, which run on their own when they are reached.
pub fn ends_window(t: &Tok, registry: &Registry) -> bool {
    match &t.kind {
        TokKind::Sym(_) | TokKind::Val(Value::Proc(_)) => true,
        TokKind::Val(v) if super::objet::is_bound(v) => true,
        TokKind::Word(w) => registry.find(w).is_some(),
        TokKind::Val(_) | TokKind::Nullary { .. } | TokKind::Quoted(_) => false,
    }
}

/// Call `f` on the value a right token stands for as an argument.
fn with_value<R>(t: &Tok, f: impl FnOnce(&Value) -> R) -> R {
    match &t.kind {
        TokKind::Val(v) | TokKind::Nullary { value: v, .. } => f(v),
        TokKind::Quoted(s) => f(&Value::Mot(s.clone())),
        TokKind::Word(w) => f(&Value::mot(w)),
        TokKind::Sym(s) => f(&Value::mot(s)),
    }
}

/// One argument that `conv` accepts: among the pushed operands first
/// (oldest first), else the first one in the right window. Operators and
/// procedures read their typed arguments this way.
///
/// While pushed operands are still waiting, only the next token is
/// looked at on the right: the operator was written after its first
/// arguments (`GEO ROTA 12 90. CENTRE`), and an operator that accepts one
/// of several types (a POINT or a MAILLAGE) must find the one waiting on
/// the left before it looks far to the right.
pub fn take_typed<T>(st: &mut GroupState, registry: &Registry, conv: impl Fn(&Value) -> Option<T>) -> Option<T> {
    take_typed_before(st, registry, conv, |_| false)
}

/// [`take_typed`], but the right window also ends at a token `stop`
/// accepts (that token is not read).
pub fn take_typed_before<T>(
    st: &mut GroupState,
    registry: &Registry,
    conv: impl Fn(&Value) -> Option<T>,
    stop: impl Fn(&Tok) -> bool,
) -> Option<T> {
    if let Some(i) = st.left.iter().position(|v| conv(v).is_some()) {
        return conv(&st.left.remove(i));
    }
    let reach = if st.left.is_empty() { st.right.len() } else { st.right.len().min(1) };
    for i in 0..reach {
        let t = &st.right[i];
        if ends_window(t, registry) || (stop(t) && with_value(t, &conv).is_none()) {
            return None;
        }
        if let Some(x) = with_value(t, &conv) {
            st.right.remove(i);
            return Some(x);
        }
        // A quoted operator name that is not the argument sought runs as
        // that operator where it stands (`P1 'DROI' 1 P2 'DROI' 1 P3`):
        // the search must not take the arguments that follow it.
        if matches!(&t.kind, TokKind::Quoted(s) if !s.contains(char::is_whitespace) && registry.find(s).is_some()) {
            return None;
        }
    }
    None
}

/// Whether an operator takes no argument at all (its signature is its
/// name alone, like `PI`): such an operator is evaluated wherever it is
/// met, so it can stand where a value is expected.
pub fn takes_no_argument(op: &OpSpec) -> bool {
    op.signature.split_whitespace().nth(1).is_none_or(|t| t == "->")
}

fn article(ty: &str) -> &'static str {
    if ty.starts_with(['E', 'A', 'I', 'O', 'U']) {
        "an"
    } else {
        "a"
    }
}

impl Args<'_> {
    /// A `*` on the right (the `n*value` repeat of PROG, LECT, MOTS).
    pub fn sign_like_star(&mut self) -> bool {
        if matches!(self.st.right.front().map(|t| &t.kind), Some(TokKind::Sym("*"))) {
            self.st.right.pop_front();
            true
        } else {
            false
        }
    }

    /// A word on the right that is not an unquoted operator name. Such
    /// words name components and options: Cast3M pads names to 4
    /// characters, so trailing blanks (`'NU  '`) are dropped.
    pub fn word_not_operator(&mut self) -> Option<String> {
        match self.st.right.front().map(|t| &t.kind)? {
            TokKind::Word(w) if self.registry.find(w).is_some() => None,
            TokKind::Sym(_) => None,
            _ => self.word().map(|w| w.trim_end().to_string()),
        }
    }

    /// A word on the right, even an operator's name, when a value (not a
    /// word) follows it: a label before its data, which Cast3M reads as
    /// a word wherever the operator expects one.
    pub fn word_before_value(&mut self) -> Option<String> {
        match self.st.right.get(1).map(|t| &t.kind)? {
            TokKind::Val(v) if !matches!(v, Value::Mot(_) | Value::Proc(_)) => self.word(),
            _ => None,
        }
    }

    /// An unquoted word (even an operator's name) followed by a text or by
    /// nothing, consumed: a name never assigned, which Cast3M reads as a
    /// word where a text is expected (`CHAINE 'a' TRESCA ' b'`).
    pub fn word_before_text(&mut self) -> Option<String> {
        let w = match self.st.right.front().map(|t| &t.kind)? {
            TokKind::Word(w) => w.clone(),
            _ => return None,
        };
        match self.st.right.get(1).map(|t| &t.kind) {
            None | Some(TokKind::Quoted(_)) | Some(TokKind::Val(Value::Mot(_))) => {
                self.st.right.pop_front();
                Some(w)
            }
            _ => None,
        }
    }

    /// If the next right token is a name that is bound to nothing (an
    /// unassigned word), consume it and return it (EXIS, OUBL).
    pub fn unbound_word(&mut self) -> Option<String> {
        match self.st.right.front().map(|t| &t.kind)? {
            TokKind::Word(w) => {
                let w = w.clone();
                self.st.right.pop_front();
                Some(w)
            }
            _ => None,
        }
    }

    /// A word written against the group that follows it, with no blank
    /// (`F(T)`: a label with its argument, as decks name a curve's
    /// ordinate): the word and the group's word as one text, both consumed.
    /// `None` (nothing consumed) when the next word stands alone.
    pub fn word_with_glued_group(&mut self) -> Option<(String, String)> {
        let (w, g) = (self.st.right.front()?, self.st.right.get(1)?);
        let glued = w.span.end == g.span.start && g.span.end > g.span.start + 1;
        let inner = match (&w.kind, &g.kind) {
            (TokKind::Word(_) | TokKind::Quoted(_), TokKind::Val(Value::Mot(m))) if glued => m.to_string(),
            _ => return None,
        };
        let word = self.right_word()?;
        self.st.right.pop_front();
        self.st.right.pop_front();
        Some((word, inner))
    }

    /// Where the next right token was written, when it was a name (the
    /// caller reads the name back from the source).
    pub fn next_name_span(&self) -> Option<Span> {
        self.st.right.front().filter(|t| t.named).map(|t| t.span)
    }
}

impl Args<'_> {
    /// Consume every remaining token of the instruction (COMM).
    pub fn drain(&mut self) {
        self.st.right.clear();
    }

    /// Take every remaining token of the instruction, unread (ASSI runs
    /// them as an instruction of its own).
    pub fn take_rest(&mut self) -> Vec<Tok> {
        self.st.right.drain(..).collect()
    }
}

impl Args<'_> {
    /// The same as [`opt`](Self::opt), which looks through the whole
    /// window: `EXCO 'UX' u` reads the field after the component, as the
    /// notices write it.
    pub fn find<T: FromArg>(&mut self) -> Option<T> {
        self.opt::<T>()
    }

    /// A required argument found by [`find`](Self::find).
    pub fn req_find<T: FromArg>(&mut self) -> Result<T> {
        self.find::<T>().ok_or_else(|| self.missing(T::EXPECT))
    }
}
