//! Mathematical functions, applied value by value to lists, node and
//! element fields and curve ordinates. Angles are in degrees, as in Cast3M.

use super::{pointwise, Args, FromArg, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::{fmt_float, Chpoint, Mchaml, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "ABS",
        signature: "ABS NUM|LISTREEL|LISTENTI|CHPOINT|MCHAML|EVOLUTIO",
        doc: "Absolute value (of every value of a list or field; of the ordinates of a curve).",
        example: "e = abs (x - 1.) ;",
        f: abs,
    },
    OpDef {
        name: "SIN",
        signature: "SIN NUM|LISTREEL|LISTENTI|CHPOINT|MCHAML|EVOLUTIO",
        doc: "Sine of an angle in degrees, value by value on lists and fields.",
        example: "s = sin 30. ;",
        f: sin,
    },
    OpDef {
        name: "COS",
        signature: "COS NUM|LISTREEL|LISTENTI|CHPOINT|MCHAML|EVOLUTIO",
        doc: "Cosine of an angle in degrees, value by value on lists and fields.",
        example: "c = cos 60. ;",
        f: cos,
    },
    OpDef {
        name: "TAN",
        signature: "TAN NUM|LISTREEL|LISTENTI|CHPOINT|MCHAML|EVOLUTIO",
        doc: "Tangent of an angle in degrees, value by value on lists and fields.",
        example: "t = tan 45. ;",
        f: tan,
    },
    OpDef {
        name: "ASIN",
        signature: "ASIN NUM|LISTREEL|LISTENTI|CHPOINT|MCHAML|EVOLUTIO",
        doc: "Arc sine, in degrees.",
        example: "a = asin 0.5 ;",
        f: asin,
    },
    OpDef {
        name: "ACOS",
        signature: "ACOS NUM|LISTREEL|LISTENTI|CHPOINT|MCHAML|EVOLUTIO",
        doc: "Arc cosine, in degrees.",
        example: "a = acos 0.5 ;",
        f: acos,
    },
    OpDef {
        name: "ATG",
        signature: "ATG NUM (NUM2) | ATG LISTREEL (LISTREEL2) | ATG CHPOINT (CHPOINT2) | ATG MCHAML (MCHAML2) | ATG EVOLUTIO",
        doc: "Arc tangent in degrees; with two numbers, lists or node fields, atan2(Y, X) item by item (a field X of one component pairs with every component of Y).",
        example: "a = atg 1. ;",
        f: atg,
    },
    OpDef {
        name: "EXP",
        signature: "EXP NUM|LISTREEL|LISTENTI|CHPOINT|MCHAML|EVOLUTIO",
        doc: "Exponential, value by value on lists and fields.",
        example: "e = exp 1. ;",
        f: exp,
    },
    OpDef {
        name: "LOG",
        signature: "LOG NUM|LISTREEL|LISTENTI|CHPOINT|MCHAML|EVOLUTIO",
        doc: "Natural logarithm, value by value on lists and fields.",
        example: "l = log 10. ;",
        f: log,
    },
    OpDef {
        name: "ENTI",
        signature: "ENTI ('TRON'|'INFE'|'SUPE'|'PROC') NUM|LISTREEL|LISTENTI|CHPOINT|MOT|LISTMOTS",
        doc: "Integer part (TRON truncation, the default; INFE floor, SUPE ceiling, PROC nearest); a LISTREEL gives a LISTENTI, a CHPOINT a CHPOINT of whole values, a MOT holding a number its value, a LISTMOTS of such words a LISTENTI.",
        example: "i = enti 3.7 ;",
        f: enti,
    },
    OpDef {
        name: "FLOT",
        signature: "FLOT NUM|LISTENTI|LISTREEL|MOT|LISTMOTS",
        doc: "Conversion to FLOTTANT (a LISTENTI gives a LISTREEL, a MOT holding a number its value, a LISTMOTS of such words a LISTREEL).",
        example: "x = flot 3 ;",
        f: flot,
    },
    OpDef {
        name: "MULT",
        signature: "MULT I J",
        doc: "VRAI when the ENTIER I is a multiple of J (unilater.procedur: `'MULT' &BOUCL1 100`).",
        example: "si (mult &b 10) ; mess &b ; finsi ;",
        f: mult,
    },
    OpDef { name: "PI", signature: "PI", doc: "The number pi.", example: "l = 2. * pi ;", f: pi },
    OpDef {
        name: "MAXI",
        signature: "MAXI (ABS) LISTREEL|LISTENTI|NUM1 NUM2 ...|CHPOINT|MCHAML|EVOLUTIO",
        doc: "Largest value of a list, of several numbers or of a field (ENTIER when every value is); of several lists or fields, the largest value by value.",
        example: "m = maxi (prog 3. 8. 1.) ;",
        f: maxi,
    },
    OpDef {
        name: "MINI",
        signature: "MINI (ABS) LISTREEL|LISTENTI|NUM1 NUM2 ...|CHPOINT|MCHAML|EVOLUTIO",
        doc: "Smallest value of a list, of several numbers or of a field (ENTIER when every value is); of several lists or fields, the smallest value by value.",
        example: "m = mini (prog 3. 8. 1.) ;",
        f: mini,
    },
];

/// An operand holding numbers: a number, a list, a field or a curve.
pub(crate) struct Numeric(pub(crate) Value);
impl FromArg for Numeric {
    const EXPECT: &'static str = "a number, a list, a field or a curve";
    fn from_value(v: &Value) -> Option<Self> {
        let ok = matches!(
            v,
            Value::Int(_)
                | Value::Float(_)
                | Value::ListReel(_)
                | Value::ListEnti(_)
                | Value::Chpo(_)
                | Value::Mchaml(_)
                | Value::Evol(_)
        );
        ok.then(|| Numeric(v.clone()))
    }
}

/// The operand of a one-argument function: the newest pushed value when
/// it holds numbers (`(x - 1.) abs`), else the next one on the right.
pub(crate) fn operand(a: &mut Args) -> Result<Value> {
    match a.left_top::<Numeric>().or_else(|| a.opt::<Numeric>()) {
        Some(n) => Ok(n.0),
        None => Err(a.missing(Numeric::EXPECT)),
    }
}

/// `f` value by value; a NaN or an infinity made from a finite value is
/// an error, since it would slip through every `SI (err > tol)` check.
pub(crate) fn unary(a: &mut Args, f: fn(f64) -> f64) -> Result<Vec<Value>> {
    let v = operand(a)?;
    let g = |x: f64| {
        let y = f(x);
        if x.is_finite() && !y.is_finite() {
            f64::NAN
        } else {
            y
        }
    };
    match pointwise::map_checked(&v, &g) {
        Some(Ok(r)) => Ok(vec![r]),
        Some(Err(x)) => Err(a.err(format!("no finite result for {}", fmt_float(x)))),
        None => Err(a.err(format!("no value by value function of a {}", v.type_name()))),
    }
}

fn abs(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    Ok(vec![match operand(a)? {
        Value::Int(i) => Value::Int(i.abs()),
        Value::ListEnti(l) => Value::ListEnti(Rc::new(l.iter().map(|x| x.abs()).collect())),
        other => pointwise::map(&other, &f64::abs).unwrap_or(other),
    }])
}

fn sin(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    unary(a, sin_deg)
}
fn cos(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    unary(a, cos_deg)
}
fn tan(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    unary(a, tan_deg)
}

/// tan of an angle in degrees. At an odd multiple of 90 the exact cosine is
/// 0; Cast3M, converting to radians first, gets the large finite tangent of
/// the rounded angle there, which decks print and go on with: give the same.
pub(crate) fn tan_deg(x: f64) -> f64 {
    let c = cos_deg(x);
    if c == 0.0 {
        x.to_radians().tan()
    } else {
        sin_deg(x) / c
    }
}

/// An angle in degrees brought into [-180, 180] and its sign folded into
/// [0, 180], exactly: `%` is exact, and so are the subtractions (Sterbenz).
/// Converting a large angle to radians first would lose the digits that
/// matter near the zeros (sin 36000.0001 degrees), and 180 would not give
/// exactly 0.
fn reduce_deg(x: f64) -> f64 {
    let mut r = x % 360.0;
    if r > 180.0 {
        r -= 360.0;
    } else if r < -180.0 {
        r += 360.0;
    }
    r
}

/// sin of an angle in degrees, exact at multiples of 90.
pub(crate) fn sin_deg(x: f64) -> f64 {
    let r = reduce_deg(x);
    let (s, r) = if r < 0.0 { (-1.0, -r) } else { (1.0, r) };
    // sin(r) = sin(180 - r), exact for r in [90, 180]
    let r = if r > 90.0 { 180.0 - r } else { r };
    s * r.to_radians().sin()
}

/// cos of an angle in degrees, exact at multiples of 90.
pub(crate) fn cos_deg(x: f64) -> f64 {
    let r = reduce_deg(x).abs();
    let (s, r) = if r > 90.0 { (-1.0, 180.0 - r) } else { (1.0, r) };
    // cos(r) = sin(90 - r), exact for r in [45, 90]
    s * if r <= 45.0 { r.to_radians().cos() } else { (90.0 - r).to_radians().sin() }
}
fn asin(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    unary(a, |x| x.asin().to_degrees())
}
fn acos(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    unary(a, |x| x.acos().to_degrees())
}
fn atg(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let y = operand(a)?;
    match &y {
        Value::Int(_) | Value::Float(_) => {
            let yv = y.as_f64().unwrap_or(0.0);
            Ok(vec![Value::Float(match a.opt_num_right() {
                Some(x) => yv.atan2(x).to_degrees(),
                None => yv.atan().to_degrees(),
            })])
        }
        Value::ListReel(l) => match a.opt_right::<Rc<Vec<f64>>>() {
            Some(m) if m.len() == l.len() => Ok(vec![Value::ListReel(Rc::new(
                l.iter().zip(m.iter()).map(|(p, q)| p.atan2(*q).to_degrees()).collect(),
            ))]),
            Some(m) => Err(a.err(format!("lists of different lengths ({} and {})", l.len(), m.len()))),
            None => Ok(vec![pointwise::map(&y, &|x| x.atan().to_degrees()).unwrap_or(y)]),
        },
        Value::Chpo(c) => match a.opt_right::<Rc<Chpoint>>() {
            Some(x) => Ok(vec![Value::Chpo(Rc::new(atan2_fields(a, c, &x)?))]),
            None => Ok(vec![pointwise::map(&y, &|x| x.atan().to_degrees()).unwrap_or(y)]),
        },
        Value::Mchaml(m) => match a.opt_right::<Rc<Mchaml>>() {
            Some(x) => Ok(vec![Value::Mchaml(Rc::new(atan2_elements(a, m, &x)?))]),
            None => Ok(vec![pointwise::map(&y, &|x| x.atan().to_degrees()).unwrap_or(y)]),
        },
        _ => Ok(vec![pointwise::map(&y, &|x| x.atan().to_degrees()).unwrap_or(y)]),
    }
}

/// atan2(y, x) value by value of two element fields of one layout.
fn atan2_elements(a: &Args, y: &Mchaml, x: &Mchaml) -> Result<Mchaml> {
    let mismatch = || a.err("the two MCHAMLs must have the same zones, elements and points");
    if y.zones.len() != x.zones.len() {
        return Err(mismatch());
    }
    let mut out = y.clone();
    for (zo, zx) in out.zones.iter_mut().zip(&x.zones) {
        for (k, v) in zo.constants.iter_mut() {
            let w = zx
                .constants
                .get(k)
                .or_else(|| (zx.constants.len() == 1).then(|| zx.constants.values().next()).flatten());
            *v = v.atan2(*w.ok_or_else(mismatch)?).to_degrees();
        }
        if zo.values.len() != zx.values.len() {
            return Err(mismatch());
        }
        for (ey, ex) in zo.values.iter_mut().zip(&zx.values) {
            if ey.len() != ex.len() {
                return Err(mismatch());
            }
            for (py, px) in ey.iter_mut().zip(ex) {
                if py.len() != px.len() {
                    return Err(mismatch());
                }
                for (v, w) in py.iter_mut().zip(px) {
                    *v = v.atan2(*w).to_degrees();
                }
            }
        }
    }
    Ok(out)
}

/// atan2(y, x) node by node: the same component of `x`, or its only one
/// (`ATG y x` of the fields COOR gives, named Y and X).
fn atan2_fields(a: &Args, y: &Chpoint, x: &Chpoint) -> Result<Chpoint> {
    let only = (x.comps.len() == 1).then(|| x.comps[0].as_str());
    let mut out = Vec::new();
    for (n, c, yv) in y.entries() {
        let xv = x
            .get(n, c)
            .or_else(|| only.and_then(|o| x.get(n, o)))
            .ok_or_else(|| a.err(format!("the second field has no value for {} at node {}", c, n + 1)))?;
        out.push((n, c, yv.atan2(xv).to_degrees()));
    }
    Ok(Chpoint::from_entries(y.nature, out))
}
fn exp(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    unary(a, f64::exp)
}
fn log(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    // ln 0 is -inf and ln of a negative number NaN: both are errors.
    unary(a, |x| if x > 0.0 { x.ln() } else { f64::NAN })
}

/// A number written in a MOT, Fortran style (`'12'`, `'1.5D3'`).
fn parse_number(s: &str) -> Option<f64> {
    let t = s.trim().replace(['D', 'd', 'Q', 'q'], "E");
    t.parse::<f64>().ok().filter(|x| x.is_finite())
}

/// ENTI and FLOT also read a MOT holding a number.
struct NumericOrMot(Value);
impl FromArg for NumericOrMot {
    const EXPECT: &'static str = "a number, a list or a word holding a number";
    fn from_value(v: &Value) -> Option<Self> {
        let ok = matches!(
            v,
            Value::Int(_)
                | Value::Float(_)
                | Value::ListReel(_)
                | Value::ListEnti(_)
                | Value::Mot(_)
                | Value::ListMots(_)
                | Value::Chpo(_)
        );
        ok.then(|| NumericOrMot(v.clone()))
    }
}

fn numeric_or_mot(a: &mut Args) -> Result<Value> {
    match a.left_top::<NumericOrMot>().or_else(|| a.opt_right::<NumericOrMot>()) {
        Some(n) => Ok(n.0),
        None => Err(a.missing(NumericOrMot::EXPECT)),
    }
}

fn word_number(a: &Args, s: &str) -> Result<f64> {
    parse_number(s).ok_or_else(|| a.err(format!("the word '{}' is not a number", s)))
}

fn enti(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    // The rounding word may come before the value (`ENTI 'PROC' 2.5`):
    // read it first there, or the MOT would be taken for the value.
    const ROUNDING: &[&str] = &["TRON", "INFE", "SUPE", "PROC"];
    let before = a.keyword_next(ROUNDING);
    let v = numeric_or_mot(a)?;
    let round: fn(f64) -> f64 = match before.or_else(|| a.keyword(ROUNDING)) {
        Some("INFE") => f64::floor,
        Some("SUPE") => f64::ceil,
        Some("PROC") => f64::round,
        _ => f64::trunc,
    };
    let to_int = |x: f64| -> Result<i64> {
        let r = round(x);
        if !r.is_finite() || r.abs() > 9.0e18 {
            return Err(a.err(format!("{} has no ENTIER value", fmt_float(x))));
        }
        Ok(r as i64)
    };
    Ok(vec![match v {
        Value::Int(i) => Value::Int(i),
        Value::Float(x) => Value::Int(to_int(x)?),
        Value::Mot(s) => Value::Int(to_int(word_number(a, &s)?)?),
        Value::ListEnti(l) => Value::ListEnti(l),
        Value::ListReel(l) => Value::ListEnti(Rc::new(l.iter().map(|x| to_int(*x)).collect::<Result<_>>()?)),
        Value::ListMots(l) => {
            Value::ListEnti(Rc::new(l.iter().map(|w| to_int(word_number(a, w)?)).collect::<Result<_>>()?))
        }
        // A field keeps FLOTTANT values, rounded as asked.
        Value::Chpo(c) => Value::Chpo(Rc::new(c.map(round))),
        other => return Err(a.err(format!("no integer part of a {}", other.type_name()))),
    }])
}

fn flot(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    Ok(vec![match numeric_or_mot(a)? {
        Value::Int(i) => Value::Float(i as f64),
        Value::Mot(s) => Value::Float(word_number(a, &s)?),
        Value::ListEnti(l) => Value::ListReel(Rc::new(l.iter().map(|i| *i as f64).collect())),
        Value::ListMots(l) => Value::ListReel(Rc::new(l.iter().map(|w| word_number(a, w)).collect::<Result<_>>()?)),
        other => other,
    }])
}

fn mult(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let i = a.req::<i64>()?;
    let j = a.req::<i64>()?;
    if j == 0 {
        return Err(a.err("MULT: no multiple of 0"));
    }
    Ok(vec![Value::Bool(i % j == 0)])
}

fn pi(_: &mut Interp, _: &mut Args) -> Result<Vec<Value>> {
    Ok(vec![Value::Float(std::f64::consts::PI)])
}

fn extremum(a: &mut Args, max: bool) -> Result<Vec<Value>> {
    let use_abs = a.keyword(&["ABS"]).is_some();
    let pick = |x: f64, y: f64| if max { x.max(y) } else { x.min(y) };
    let conv = |x: f64| if use_abs { x.abs() } else { x };
    // Third form (maxi.notice): several lists or fields of one kind give
    // their extremum value by value.
    let first =
        a.opt_with(|v| matches!(v, Value::ListReel(_) | Value::ListEnti(_) | Value::Chpo(_)).then(|| v.clone()));
    if let Some(first) = first {
        let same = |v: &Value| std::mem::discriminant(v) == std::mem::discriminant(&first);
        let mut acc: Option<Value> = None;
        while let Some(next) = a.peek_right().filter(same) {
            a.right_any();
            let prev = acc.as_ref().unwrap_or(&first);
            acc = Some(value_by_value(a, prev, &next, |p, q| pick(conv(p), conv(q)))?);
        }
        match acc {
            Some(v) => return Ok(vec![v]),
            None => a.unread(first),
        }
    }
    if let Some(l) = a.opt::<Rc<Vec<f64>>>() {
        let v = l.iter().copied().map(conv).reduce(pick).ok_or_else(|| a.err("empty list"))?;
        return Ok(vec![Value::Float(v)]);
    }
    if let Some(l) = a.opt::<Rc<Vec<i64>>>() {
        let v = l.iter().map(|i| if use_abs { i.abs() } else { *i });
        let v = if max { v.max() } else { v.min() };
        return Ok(vec![Value::Int(v.ok_or_else(|| a.err("empty list"))?)]);
    }
    if let Some(r) = super::evol_extremum::extremum(a, max, use_abs)? {
        return Ok(r);
    }
    if let Some(r) = super::fields::extremum(a, max, use_abs)? {
        return Ok(vec![r]);
    }
    // Numbers: ENTIER when every one is (as for a LISTENTI), else FLOTTANT.
    let mut nums = Vec::new();
    loop {
        if let Some(i) = a.opt::<i64>() {
            nums.push(Value::Int(i));
        } else if let Some(x) = a.opt::<f64>() {
            nums.push(Value::Float(x));
        } else {
            break;
        }
    }
    if nums.is_empty() {
        return Err(a.missing("a list, numbers or a field"));
    }
    if nums.iter().all(|v| matches!(v, Value::Int(_))) {
        let ints =
            nums.iter()
                .filter_map(|v| if let Value::Int(i) = v { Some(if use_abs { i.abs() } else { *i }) } else { None });
        let r = if max { ints.max() } else { ints.min() };
        return Ok(vec![Value::Int(r.unwrap_or(0))]);
    }
    Ok(vec![Value::Float(nums.iter().filter_map(Value::as_f64).map(conv).reduce(pick).unwrap_or(0.0))])
}
/// `f` applied value by value to two lists of one length or two fields on
/// the same nodes and components (MAXI/MINI of several objects, ATG of two
/// fields).
fn value_by_value(a: &Args, x: &Value, y: &Value, f: impl Fn(f64, f64) -> f64) -> Result<Value> {
    let lengths = |n: usize, m: usize| a.err(format!("lists of different lengths ({} and {})", n, m));
    Ok(match (x, y) {
        (Value::ListReel(l), Value::ListReel(m)) if l.len() == m.len() => {
            Value::ListReel(Rc::new(l.iter().zip(m.iter()).map(|(p, q)| f(*p, *q)).collect()))
        }
        (Value::ListEnti(l), Value::ListEnti(m)) if l.len() == m.len() => {
            Value::ListEnti(Rc::new(l.iter().zip(m.iter()).map(|(p, q)| f(*p as f64, *q as f64) as i64).collect()))
        }
        (Value::ListReel(l), Value::ListReel(m)) => return Err(lengths(l.len(), m.len())),
        (Value::ListEnti(l), Value::ListEnti(m)) => return Err(lengths(l.len(), m.len())),
        (Value::Chpo(p), Value::Chpo(q)) => {
            let covers = |p: &Chpoint, q: &Chpoint| p.entries().all(|(n, c, _)| q.get(n, c).is_some());
            if !covers(p, q) || !covers(q, p) {
                return Err(a.err("the fields must have the same components on the same nodes"));
            }
            Value::Chpo(Rc::new(p.combine(q, f)))
        }
        _ => return Err(a.err(format!("cannot combine {} and {} value by value", x.type_name(), y.type_name()))),
    })
}

fn maxi(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    extremum(a, true)
}
fn mini(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    extremum(a, false)
}

#[cfg(test)]
mod trig_tests {
    use super::{cos_deg, sin_deg};

    #[test]
    fn degrees_are_reduced_exactly() {
        assert_eq!(sin_deg(180.0), 0.0);
        assert_eq!(sin_deg(-540.0), 0.0);
        assert_eq!(cos_deg(90.0), 0.0);
        assert_eq!(cos_deg(360.0 * 1000.0 + 180.0), -1.0);
        assert_eq!(sin_deg(30.0 + 3600.0), sin_deg(30.0));
        // near a zero far out: sin(x) = sin(x - 36000) to full precision
        // (the subtraction is exact), where radians first lose 7 digits
        let x = 36000.0001f64;
        let want = (x - 36000.0).to_radians().sin();
        let got = sin_deg(x);
        assert!(((x.to_radians().sin() - want) / want).abs() > 1e-9);
        assert!(((got - want) / want).abs() < 1e-15, "{got} {want}");
        for k in 0..720 {
            let x = k as f64 * 0.5 - 180.0;
            assert!((sin_deg(x) - x.to_radians().sin()).abs() < 1e-15);
            assert!((cos_deg(x) - x.to_radians().cos()).abs() < 1e-15);
        }
    }
}
