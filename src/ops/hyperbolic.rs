//! Hyperbolic functions, their inverses, the error function and the sign,
//! value by value on a number, a list, a field or a curve's ordinates
//! (cosh.notice and its neighbours, erf.notice, sign.notice).

use super::math::{operand, unary};
use super::{pointwise, Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::Value;
use std::rc::Rc;

macro_rules! row {
    ($name:literal, $ex:literal, $doc:literal, $f:expr) => {
        OpDef {
            name: $name,
            signature: concat!($name, " NUM|LISTREEL|LISTENTI|CHPOINT|MCHAML|EVOLUTIO"),
            doc: $doc,
            example: concat!("y = ", $name, " ", $ex, " ;"),
            f: $f,
        }
    };
}

pub(crate) const OPS: &[OpDef] = &[
    row!("COSH", "0.5", "Hyperbolic cosine.", |_, a| unary(a, f64::cosh)),
    row!("SINH", "0.5", "Hyperbolic sine.", |_, a| unary(a, f64::sinh)),
    row!("TANH", "0.5", "Hyperbolic tangent.", |_, a| unary(a, f64::tanh)),
    row!("ACOH", "2.", "Inverse hyperbolic cosine (values >= 1).", |_, a| unary(a, f64::acosh)),
    row!("ASIH", "0.5", "Inverse hyperbolic sine.", |_, a| unary(a, f64::asinh)),
    row!("ATAH", "0.5", "Inverse hyperbolic tangent (values in ]-1, 1[).", |_, a| unary(a, f64::atanh)),
    row!("ERF", "0.5", "Error function 2/sqrt(pi) int_0^x exp(-t^2) dt.", |_, a| unary(a, libm::erf)),
    row!("ERFC", "0.5", "Complementary error function 1 - erf(x).", |_, a| unary(a, libm::erfc)),
    row!(
        "SIGN",
        "0.5",
        "Sign of each value: -1 below zero, else 1 (Fortran's SIGN(1, x)); an ENTIER or LISTENTI stays one.",
        sign
    ),
];

fn sign(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let s = |x: f64| if x < 0.0 { -1.0 } else { 1.0 };
    Ok(vec![match operand(a)? {
        Value::Int(i) => Value::Int(if i < 0 { -1 } else { 1 }),
        Value::ListEnti(l) => Value::ListEnti(Rc::new(l.iter().map(|&i| if i < 0 { -1 } else { 1 }).collect())),
        other => pointwise::map(&other, &s).ok_or_else(|| a.err(format!("no sign of a {}", other.type_name())))?,
    }])
}
