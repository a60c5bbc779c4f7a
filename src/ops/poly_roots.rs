//! RACPOL: roots of a polynomial given by its coefficients, lowest
//! degree first.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::args::Num;
use crate::eval::Interp;
use crate::solve::poly_roots;
use crate::value::Value;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "RACPOL",
    signature: "RACPOL ('IMAG'|'BAIR') LISTREEL ('IMAG'|'BAIR') | RACPOL A0 A1 (A2 …) | RACPOL 'INTE' X1 X2 LISTREEL",
    doc: "Roots of A0 + A1 X + A2 X**2 + …: the real roots in increasing order (a LISTREEL); with 'IMAG' every root, real parts then imaginary parts (two LISTREEL, by increasing real part); with 'INTE' the first real root between X1 and X2 (a FLOTTANT), or the word 'VIDE' if there is none.",
    example: "r = racpol (prog 2. -3. 1.) ;",
    f: racpol,
}];

fn list(v: Vec<f64>) -> Value {
    Value::ListReel(Rc::new(v))
}

fn racpol(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mut key = a.keyword(&["IMAGINAIRE", "BAIRSTOW", "INTE"]);
    if key == Some("INTE") {
        let x1 = a.req::<Num>()?.0;
        let x2 = a.req::<Num>()?.0;
        let c = coefficients(a)?;
        let (lo, hi) = (x1.min(x2), x1.max(x2));
        let r = real(a, &c)?;
        return Ok(vec![match r.into_iter().find(|x| (lo..=hi).contains(x)) {
            Some(x) => Value::Float(x),
            None => Value::mot("VIDE"),
        }]);
    }
    let c = coefficients(a)?;
    if key.is_none() {
        key = a.keyword(&["IMAGINAIRE", "BAIRSTOW"]);
    }
    if key == Some("IMAGINAIRE") {
        check(a, &c)?;
        let r = poly_roots::roots(&c).ok_or_else(|| a.err(no_roots(&c)))?;
        return Ok(vec![list(r.iter().map(|z| z.0).collect()), list(r.iter().map(|z| z.1).collect())]);
    }
    // BAIRSTOW names another method for the same roots.
    Ok(vec![list(real(a, &c)?)])
}

/// A LISTREEL of coefficients, or the numbers A0 A1 … written in line.
fn coefficients(a: &mut Args) -> Result<Vec<f64>> {
    if let Some(l) = a.opt::<Rc<Vec<f64>>>() {
        return Ok(l.to_vec());
    }
    let mut c = Vec::new();
    while let Some(x) = a.opt::<Num>() {
        c.push(x.0);
    }
    if c.len() < 2 {
        return Err(a.missing("a LISTREEL of coefficients, or at least two numbers A0 A1"));
    }
    Ok(c)
}

fn check(a: &Args, c: &[f64]) -> Result<()> {
    match c.iter().find(|x| !x.is_finite()) {
        Some(x) => Err(a.err(format!("coefficient {x} is not a finite number"))),
        None => Ok(()),
    }
}

fn no_roots(c: &[f64]) -> String {
    if c.iter().all(|&x| x == 0.0) {
        "the polynomial is zero: every number is a root".into()
    } else if c.iter().skip(1).all(|&x| x == 0.0) {
        "the polynomial is a non-zero constant: it has no root".into()
    } else {
        "the root computation did not converge".into()
    }
}

fn real(a: &Args, c: &[f64]) -> Result<Vec<f64>> {
    check(a, c)?;
    poly_roots::real_roots(c).ok_or_else(|| a.err(no_roots(c)))
}
