//! What the machine reads: the tokens of one parenthesised group, and
//! the state an operator reads its arguments from (operands already
//! pushed on the left, tokens not yet read on the right).

use crate::source::Span;
use crate::value::Value;
use std::collections::VecDeque;
use std::rc::Rc;

#[derive(Debug, Clone)]
pub enum TokKind {
    /// A value: literal number, object, group result, loop counter.
    Val(Value),
    /// Quoted text: a MOT, unless it names an operator in operator position.
    Quoted(Rc<str>),
    /// An unquoted word that names no object: an operator, else a MOT.
    Word(String),
    /// An operator that takes no argument (`PI`), already evaluated: a
    /// value for whoever reads an operand, still a word for whoever reads
    /// a keyword.
    Nullary { word: String, value: Value },
    /// `+ - * / ** < > <EG >EG %`.
    Sym(&'static str),
}

#[derive(Debug, Clone)]
pub struct Tok {
    pub kind: TokKind,
    pub span: Span,
    /// Whether the token was written as a name (OUBL and LIST recover the
    /// name from the source text at `span`; no copy on the hot path).
    pub named: bool,
}

/// Operands already pushed (left) and tokens not yet read (right).
#[derive(Debug, Default)]
pub struct GroupState {
    pub left: Vec<Value>,
    pub right: VecDeque<Tok>,
}
