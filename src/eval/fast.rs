//! A fast path for purely numeric instructions (`s = s + (&b * 2.) ;`).
//!
//! Loops in decks are dominated by such instructions, and the general stack
//! machine allocates token and operand buffers per group. Here an
//! instruction made only of numbers, names bound to numbers, loop counters,
//! `+ - * / **` written infix, and parenthesised groups of the same, is
//! evaluated directly, left to right without precedence: the same rule as
//! the machine, through the same numeric core (`value::arith`), so the
//! answers and the errors are the same, worded by the same operator.
//! Anything else (an operator word, a prefix operator, two operands side by
//! side that would make a POINT) returns `None` before any side effect, and
//! the general machine runs the instruction instead.

use super::args::operator_error;
use super::Interp;
use crate::error::{Error, Result};
use crate::source::Span;
use crate::syntax::ast::{Item, ItemKind};
use crate::value::arith::{numbers, ArithError, Bin, Number};
use crate::value::Value;

impl Interp {
    fn fast_operand(&self, it: &Item) -> Option<Result<Number>> {
        Some(Ok(match &it.kind {
            ItemKind::Int(i) => Number::Int(*i),
            ItemKind::Float(f) => Number::Float(*f),
            ItemKind::Counter(n) => Number::Int(self.store.counter(n)?),
            ItemKind::Word(w) => Number::of(self.store.get(w)?)?,
            ItemKind::Group(g) => return self.fast_num(g),
            _ => return None,
        }))
    }

    /// `operand (op operand)*`, or None. Every operand is read (groups
    /// evaluated) before any operator runs, as the machine does: a group's
    /// error comes before an error of the operators around it.
    fn fast_num(&self, items: &[Item]) -> Option<Result<Number>> {
        if items.len().is_multiple_of(2) {
            return None;
        }
        let mut operands = Vec::with_capacity(items.len() / 2 + 1);
        let mut ops: Vec<(Bin, Span)> = Vec::with_capacity(items.len() / 2);
        for (k, it) in items.iter().enumerate() {
            if k % 2 == 0 {
                operands.push(self.fast_operand(it)?);
            } else {
                let ItemKind::Sym(s) = &it.kind else { return None };
                ops.push((Bin::from_symbol(s)?, it.span));
            }
        }
        let mut values = Vec::with_capacity(operands.len());
        for o in operands {
            match o {
                Ok(n) => values.push(n),
                Err(e) => return Some(Err(e)),
            }
        }
        let mut acc = values[0];
        for (&(op, span), &y) in ops.iter().zip(&values[1..]) {
            acc = match numbers(op, acc, y) {
                Ok(n) => n,
                Err(e) => return Some(Err(self.arith_error(op, e, span)?)),
            };
        }
        Some(Ok(acc))
    }

    /// The error the operator itself gives, at the operator (None when the
    /// symbol names no operator: the machine then says so).
    fn arith_error(&self, op: Bin, e: ArithError, span: Span) -> Option<Error> {
        let spec = self.registry.find(op.symbol())?;
        Some(operator_error(&spec, e).with_span_if_missing(span, &self.source))
    }

    /// The value of a numeric instruction, its error, or None to take the
    /// general path.
    pub(super) fn fast_value(&self, items: &[Item]) -> Option<Result<Value>> {
        // A single operand alone goes through the machine (it may be a
        // procedure call or an operator with no argument).
        if items.len() < 2 && !matches!(items.first().map(|i| &i.kind), Some(ItemKind::Group(_))) {
            return None;
        }
        Some(self.fast_num(items)?.map(Number::value))
    }
}
