//! Scalar functions. Angles are in degrees, as in Cast3M.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::Value;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "ABS",
        signature: "ABS NUM|LISTREEL|LISTENTI|CHPOINT",
        doc: "Absolute value.",
        example: "e = abs (x - 1.) ;",
        f: abs,
    },
    OpDef { name: "SIN", signature: "SIN NUM", doc: "Sine of an angle in degrees.", example: "s = sin 30. ;", f: sin },
    OpDef {
        name: "COS",
        signature: "COS NUM",
        doc: "Cosine of an angle in degrees.",
        example: "c = cos 60. ;",
        f: cos,
    },
    OpDef {
        name: "TAN",
        signature: "TAN NUM",
        doc: "Tangent of an angle in degrees.",
        example: "t = tan 45. ;",
        f: tan,
    },
    OpDef { name: "ASIN", signature: "ASIN NUM", doc: "Arc sine, in degrees.", example: "a = asin 0.5 ;", f: asin },
    OpDef { name: "ACOS", signature: "ACOS NUM", doc: "Arc cosine, in degrees.", example: "a = acos 0.5 ;", f: acos },
    OpDef {
        name: "ATG",
        signature: "ATG NUM (NUM2)",
        doc: "Arc tangent in degrees; with two numbers, atan2(NUM, NUM2).",
        example: "a = atg 1. ;",
        f: atg,
    },
    OpDef { name: "EXP", signature: "EXP NUM", doc: "Exponential.", example: "e = exp 1. ;", f: exp },
    OpDef { name: "LOG", signature: "LOG NUM", doc: "Natural logarithm.", example: "l = log 10. ;", f: log },
    OpDef {
        name: "ENTI",
        signature: "ENTI NUM ('INFE'|'SUPE'|'PROC')",
        doc: "Integer part (truncation; INFE floor, SUPE ceiling, PROC nearest).",
        example: "i = enti 3.7 ;",
        f: enti,
    },
    OpDef { name: "PI", signature: "PI", doc: "The number pi.", example: "l = 2. * pi ;", f: pi },
    OpDef {
        name: "MAXI",
        signature: "MAXI (ABS) LISTREEL|LISTENTI|NUM1 NUM2 ...|CHPOINT",
        doc: "Largest value of a list, of several numbers or of a field.",
        example: "m = maxi (prog 3. 8. 1.) ;",
        f: maxi,
    },
    OpDef {
        name: "MINI",
        signature: "MINI (ABS) LISTREEL|LISTENTI|NUM1 NUM2 ...|CHPOINT",
        doc: "Smallest value of a list, of several numbers or of a field.",
        example: "m = mini (prog 3. 8. 1.) ;",
        f: mini,
    },
];

/// The one numeric operand of a unary function: left (newest), else the
/// first number of the window (`ENTI 'PROC' 2.5`).
fn num_arg(a: &mut Args) -> Result<f64> {
    if let Some(v) = a.left_top::<crate::ops::args::Num>() {
        return Ok(v.0);
    }
    if let Some(i) = a.left_top::<i64>() {
        return Ok(i as f64);
    }
    a.req_num()
}

fn unary(a: &mut Args, f: fn(f64) -> f64) -> Result<Vec<Value>> {
    let x = num_arg(a)?;
    let y = f(x);
    if y.is_nan() {
        return Err(a.err(format!("undefined for {}", x)));
    }
    Ok(vec![Value::Float(y)])
}

fn abs(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let v = match a.left_value() {
        Some(v) => v,
        None => a.right_any().ok_or_else(|| a.missing("a number, list or field"))?,
    };
    Ok(vec![match v {
        Value::Int(i) => Value::Int(i.abs()),
        Value::Float(f) => Value::Float(f.abs()),
        Value::ListReel(l) => Value::ListReel(Rc::new(l.iter().map(|x| x.abs()).collect())),
        Value::ListEnti(l) => Value::ListEnti(Rc::new(l.iter().map(|x| x.abs()).collect())),
        other => match crate::ops::fieldfn::abs(it, &other) {
            Some(v) => v,
            None => return Err(a.err(format!("no absolute value of a {}", other.type_name()))),
        },
    }])
}

fn sin(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    unary(a, |x| x.to_radians().sin())
}
fn cos(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    unary(a, |x| x.to_radians().cos())
}
fn tan(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    unary(a, |x| x.to_radians().tan())
}
fn asin(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    unary(a, |x| x.asin().to_degrees())
}
fn acos(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    unary(a, |x| x.acos().to_degrees())
}
fn atg(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let y = num_arg(a)?;
    Ok(vec![Value::Float(match a.opt_num_right() {
        Some(x) => y.atan2(x).to_degrees(),
        None => y.atan().to_degrees(),
    })])
}
fn exp(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    unary(a, f64::exp)
}
fn log(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let x = num_arg(a)?;
    if x <= 0.0 {
        return Err(a.err(format!("logarithm of a non-positive number ({})", x)));
    }
    Ok(vec![Value::Float(x.ln())])
}
fn enti(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let x = num_arg(a)?;
    let r = match a.keyword(&["INFE", "SUPE", "PROC"]) {
        Some("INFE") => x.floor(),
        Some("SUPE") => x.ceil(),
        Some(_) => x.round(),
        None => x.trunc(),
    };
    if !r.is_finite() || r.abs() > 9.0e18 {
        return Err(a.err(format!("{} has no ENTIER value", x)));
    }
    Ok(vec![Value::Int(r as i64)])
}
fn pi(_: &mut Interp, _: &mut Args) -> Result<Vec<Value>> {
    Ok(vec![Value::Float(std::f64::consts::PI)])
}

fn extremum(it: &mut Interp, a: &mut Args, max: bool) -> Result<Vec<Value>> {
    let use_abs = a.keyword(&["ABS"]).is_some();
    let pick = |x: f64, y: f64| if max { x.max(y) } else { x.min(y) };
    let conv = |x: f64| if use_abs { x.abs() } else { x };
    if let Some(l) = a.opt::<Rc<Vec<f64>>>() {
        let v = l.iter().copied().map(conv).reduce(pick).ok_or_else(|| a.err("empty list"))?;
        return Ok(vec![Value::Float(v)]);
    }
    if let Some(l) = a.opt::<Rc<Vec<i64>>>() {
        let v = l.iter().map(|i| if use_abs { i.abs() } else { *i });
        let v = if max { v.max() } else { v.min() };
        return Ok(vec![Value::Int(v.ok_or_else(|| a.err("empty list"))?)]);
    }
    if let Some(r) = crate::ops::fieldfn::extremum(it, a, max, use_abs)? {
        return Ok(vec![r]);
    }
    let mut nums = Vec::new();
    while let Some(x) = a.opt_num() {
        nums.push(x);
    }
    if nums.is_empty() {
        return Err(a.missing("a list, numbers or a field"));
    }
    Ok(vec![Value::Float(nums.into_iter().map(conv).reduce(pick).unwrap_or(0.0))])
}
fn maxi(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    extremum(it, a, true)
}
fn mini(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    extremum(it, a, false)
}
