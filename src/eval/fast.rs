//! A fast path for purely numeric instructions (`s = s + (&b * 2.) ;`).
//!
//! Loops in decks are dominated by such instructions, and the general stack
//! machine allocates token and operand buffers per group. Here an
//! instruction made only of numbers, names bound to numbers, loop counters,
//! `+ - * / **` written infix, and parenthesised groups of the same, is
//! evaluated directly, left to right without precedence — the same rule as
//! the machine. Anything else (an operator word, a prefix operator, two
//! operands side by side that would make a POINT, a division by zero that
//! must raise an error) returns `None` before any side effect, and the
//! general machine runs the instruction instead.

use super::Interp;
use crate::syntax::ast::{Item, ItemKind};
use crate::value::Value;

#[derive(Clone, Copy)]
enum Num {
    Int(i64),
    Float(f64),
}

impl Num {
    fn f(self) -> f64 {
        match self {
            Num::Int(i) => i as f64,
            Num::Float(x) => x,
        }
    }
}

fn apply(op: &str, x: Num, y: Num) -> Option<Num> {
    Some(match (x, y) {
        (Num::Int(i), Num::Int(j)) => {
            let r = match op {
                "+" => i.checked_add(j),
                "-" => i.checked_sub(j),
                "*" => i.checked_mul(j),
                // Division by zero must raise the general error.
                "/" if j == 0 => return None,
                "/" => i.checked_div(j),
                _ if j < 0 => return Some(Num::Float((i as f64).powf(j as f64))),
                _ => u32::try_from(j).ok().and_then(|e| i.checked_pow(e)),
            };
            match r {
                Some(v) => Num::Int(v),
                None => Num::Float(float(op, i as f64, j as f64)),
            }
        }
        _ => {
            let (a, b) = (x.f(), y.f());
            let r = float(op, a, b);
            // A non-finite result of finite operands (x / 0., (-8.) ** 0.5)
            // is the operator's error: the fast path does not decide it.
            if !r.is_finite() && a.is_finite() && b.is_finite() {
                return None;
            }
            Num::Float(r)
        }
    })
}

fn float(op: &str, x: f64, y: f64) -> f64 {
    match op {
        "+" => x + y,
        "-" => x - y,
        "*" => x * y,
        "/" => x / y,
        _ => x.powf(y),
    }
}

impl Interp {
    fn fast_operand(&self, it: &Item) -> Option<Num> {
        match &it.kind {
            ItemKind::Int(i) => Some(Num::Int(*i)),
            ItemKind::Float(f) => Some(Num::Float(*f)),
            ItemKind::Counter(n) => self.store.counter(n).map(Num::Int),
            ItemKind::Word(w) => match self.store.get(w)? {
                Value::Int(i) => Some(Num::Int(*i)),
                Value::Float(f) => Some(Num::Float(*f)),
                _ => None,
            },
            ItemKind::Group(g) => self.fast_num(g),
            _ => None,
        }
    }

    fn fast_num(&self, items: &[Item]) -> Option<Num> {
        let (first, rest) = items.split_first()?;
        let mut acc = self.fast_operand(first)?;
        let mut it = rest.iter();
        while let Some(op) = it.next() {
            let ItemKind::Sym(s @ ("+" | "-" | "*" | "/" | "**")) = &op.kind else { return None };
            let y = self.fast_operand(it.next()?)?;
            acc = apply(s, acc, y)?;
        }
        Some(acc)
    }

    /// The value of a numeric instruction, or None to take the general path.
    pub(super) fn fast_value(&self, items: &[Item]) -> Option<Value> {
        // A single operand alone goes through the machine (it may be a
        // procedure call or an operator with no argument).
        if items.len() < 2 && !matches!(items.first().map(|i| &i.kind), Some(ItemKind::Group(_))) {
            return None;
        }
        Some(match self.fast_num(items)? {
            Num::Int(i) => Value::Int(i),
            Num::Float(f) => Value::Float(f),
        })
    }
}
