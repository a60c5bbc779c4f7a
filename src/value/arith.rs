//! The arithmetic of Gibiane numbers: the one definition of `+ - * / **`
//! that every operand type applies value by value, and the one rule that
//! a result must be a finite number.
//!
//! The operators (`ops::arith`) and the evaluator's fast path for numeric
//! instructions (`eval::fast`) both go through [`numbers`] and
//! [`ArithError`], so they give the same answers and the same errors. A
//! NaN or an infinity is never a value: it would pass every
//! `SI (err > tol)` check of a deck.

use super::{fmt_float, Value};
use std::fmt;

/// A binary arithmetic operator.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Bin {
    Add,
    Sub,
    Mul,
    Div,
    Pow,
}

impl Bin {
    pub fn symbol(self) -> &'static str {
        match self {
            Bin::Add => "+",
            Bin::Sub => "-",
            Bin::Mul => "*",
            Bin::Div => "/",
            Bin::Pow => "**",
        }
    }

    pub fn from_symbol(s: &str) -> Option<Bin> {
        Some(match s {
            "+" => Bin::Add,
            "-" => Bin::Sub,
            "*" => Bin::Mul,
            "/" => Bin::Div,
            "**" => Bin::Pow,
            _ => return None,
        })
    }
}

/// An ENTIER or a FLOTTANT.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Number {
    Int(i64),
    Float(f64),
}

impl Number {
    pub fn of(v: &Value) -> Option<Number> {
        match v {
            Value::Int(i) => Some(Number::Int(*i)),
            Value::Float(x) => Some(Number::Float(*x)),
            _ => None,
        }
    }
    pub fn f64(self) -> f64 {
        match self {
            Number::Int(i) => i as f64,
            Number::Float(x) => x,
        }
    }
    pub fn value(self) -> Value {
        match self {
            Number::Int(i) => Value::Int(i),
            Number::Float(x) => Value::Float(x),
        }
    }
}

/// The operation on two FLOTTANTs, unchecked: containers apply it value by
/// value, then the result is checked once ([`check`]).
pub fn float_op(op: Bin, x: f64, y: f64) -> f64 {
    match op {
        Bin::Add => x + y,
        Bin::Sub => x - y,
        Bin::Mul => x * y,
        Bin::Div => x / y,
        Bin::Pow => power(x, y),
    }
}

/// `x ** y`, with the real odd root of a negative number: `(-8.) ** (1./3.)`
/// is -2 when 1/y is an odd integer (to rounding), as Cast3M gives it.
/// Any other fractional power of a negative number has no real value.
fn power(x: f64, y: f64) -> f64 {
    if x < 0.0 && y.fract() != 0.0 && y.is_finite() {
        let n = 1.0 / y;
        let k = n.round();
        if (n - k).abs() <= 1e-9 * k.abs() && k % 2.0 != 0.0 {
            return -(-x).powf(y);
        }
    }
    x.powf(y)
}

/// Why an operation has no value.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Why {
    /// ENTIER / 0.
    IntegerDivisionByZero,
    /// Anything divided by the number 0.
    DivisionByZero,
    /// Some value divided by a zero value of a container.
    DividesByZero,
    /// A finite result beyond the largest FLOTTANT.
    Overflow,
    /// A power with no finite real value ((-8.) ** 0.5, 10. ** 400).
    NoRealValue,
    /// An operand that is itself not a finite number.
    NotFinite,
}

/// An arithmetic error: the operation and its operands as messages show
/// them. Its text is the same whichever path computed it.
#[derive(Debug, Clone, PartialEq)]
pub struct ArithError {
    pub op: Bin,
    pub x: String,
    pub y: String,
    pub why: Why,
}

impl fmt::Display for ArithError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (x, s, y) = (&self.x, self.op.symbol(), &self.y);
        match self.why {
            Why::IntegerDivisionByZero => write!(f, "division of an ENTIER by zero"),
            Why::DivisionByZero => write!(f, "division of {} by zero", x),
            Why::DividesByZero => write!(f, "{} / {} divides by zero", x, y),
            Why::Overflow => write!(f, "{} {} {} overflows: the result is beyond the largest FLOTTANT", x, s, y),
            Why::NoRealValue => write!(f, "{} ** {} has no finite real value", x, y),
            Why::NotFinite => write!(f, "{} {} {} has no value: an operand is not a finite number", x, s, y),
        }
    }
}

impl ArithError {
    fn new(op: Bin, x: &Value, y: &Value, why: Why) -> Self {
        ArithError { op, x: describe(x), y: describe(y), why }
    }
}

/// Checks the result `r` of `x op y`, computed value by value: a result
/// that is not finite is the error of the operation, named by why it
/// happened.
pub fn check(op: Bin, x: &Value, y: &Value, r: Value) -> Result<Value, ArithError> {
    if finite(&r) {
        return Ok(r);
    }
    let why = if !finite(x) || !finite(y) {
        Why::NotFinite
    } else {
        match op {
            Bin::Pow => Why::NoRealValue,
            Bin::Div if has_zero(y) => Why::DividesByZero,
            _ => Why::Overflow,
        }
    };
    Err(ArithError::new(op, x, y, why))
}

/// The division of anything by the number zero, refused before it is
/// computed (ENTIER / ENTIER has its own error, from [`numbers`]).
pub fn divides_by_zero(op: Bin, x: &Value, y: &Value) -> Option<ArithError> {
    let by_zero = op == Bin::Div && y.as_f64() == Some(0.0) && !matches!((x, y), (Value::Int(_), Value::Int(_)));
    by_zero.then(|| ArithError::new(op, x, y, Why::DivisionByZero))
}

/// `x op y` on two numbers. ENTIER op ENTIER is an ENTIER when it fits
/// (`/` truncates), a FLOTTANT when it overflows, and a FLOTTANT for a
/// negative power; every result is checked.
pub fn numbers(op: Bin, x: Number, y: Number) -> Result<Number, ArithError> {
    let (vx, vy) = (x.value(), y.value());
    if let Some(e) = divides_by_zero(op, &vx, &vy) {
        return Err(e);
    }
    let r = match (x, y) {
        (Number::Int(i), Number::Int(j)) => {
            let exact = match op {
                Bin::Add => i.checked_add(j),
                Bin::Sub => i.checked_sub(j),
                Bin::Mul => i.checked_mul(j),
                Bin::Div if j == 0 => return Err(ArithError::new(op, &vx, &vy, Why::IntegerDivisionByZero)),
                Bin::Div => i.checked_div(j),
                Bin::Pow if j < 0 => None,
                Bin::Pow => u32::try_from(j).ok().and_then(|e| i.checked_pow(e)),
            };
            match exact {
                Some(v) => return Ok(Number::Int(v)),
                None => float_op(op, i as f64, j as f64),
            }
        }
        _ => float_op(op, x.f64(), y.f64()),
    };
    match check(op, &vx, &vy, Value::Float(r)) {
        Ok(_) => Ok(Number::Float(r)),
        Err(e) => Err(e),
    }
}

/// Whether every number of `v` is finite (objects without numbers are).
pub fn finite(v: &Value) -> bool {
    let ok = |x: &f64| x.is_finite();
    match v {
        Value::Float(x) => x.is_finite(),
        Value::ListReel(l) => l.iter().all(ok),
        Value::Chpo(c) => c.entries().all(|(_, _, x)| x.is_finite()),
        Value::ListChpo(l) => l.iter().all(|c| c.entries().all(|(_, _, x)| x.is_finite())),
        Value::Mchaml(m) => {
            m.zones.iter().all(|z| z.constants.values().all(ok) && z.values.iter().flatten().flatten().all(ok))
        }
        Value::Evol(e) => e.curves.iter().all(|c| c.x.iter().chain(&c.y).all(ok)),
        _ => true,
    }
}

/// Whether `v` holds a zero among its numbers.
fn has_zero(v: &Value) -> bool {
    let zero = |x: &f64| *x == 0.0;
    match v {
        Value::Int(i) => *i == 0,
        Value::Float(x) => *x == 0.0,
        Value::ListReel(l) => l.iter().any(zero),
        Value::ListEnti(l) => l.contains(&0),
        Value::Chpo(c) => c.entries().any(|(_, _, x)| x == 0.0),
        Value::Mchaml(m) => {
            m.zones.iter().any(|z| z.constants.values().any(zero) || z.values.iter().flatten().flatten().any(zero))
        }
        Value::Evol(e) => e.curves.iter().any(|c| c.y.iter().any(zero)),
        _ => false,
    }
}

/// A number as messages show it; other operands by their type.
pub fn describe(v: &Value) -> String {
    match v {
        Value::Int(i) => i.to_string(),
        Value::Float(x) => fmt_float(*x),
        other => {
            let t = other.type_name();
            format!("{} {}", if t.starts_with(['A', 'E', 'I', 'O', 'U']) { "an" } else { "a" }, t)
        }
    }
}

#[cfg(test)]
mod power_tests {
    #[test]
    fn odd_roots_of_negative_numbers_are_real() {
        assert!((super::power(-8.0, 1.0 / 3.0) + 2.0).abs() < 1e-12);
        assert!((super::power(-512.0, 1.0 / 9.0) + 2.0).abs() < 1e-12);
        assert!(super::power(-4.0, 0.5).is_nan());
        assert!(super::power(-4.0, 0.25).is_nan());
    }
}
