//! Calculus on sampled curves: IPOL (linear or cubic spline
//! interpolation, from an EVOLUTIO or from two lists, held at the end
//! values outside the abscissae) and INTG of an EVOLUTIO (trapezoidal
//! integral, exact for the piecewise linear curve IPOL reads; the INTG
//! entry itself is in `integrate.rs`, with the field integrals).

use super::math::Numeric;
use super::{pointwise, Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::props::spline::{End, Spline};
use crate::value::model::Curve;
use crate::value::{fmt_float, Evolution, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "IPOL",
        signature: "IPOL X EVOLUTIO | IPOL X LISTREEL_X LISTREEL_Y ('SPLI' ('DGAU' D1) ('DDRO' D2))   (X: NUM|LISTREEL|CHPOINT|MCHAML) | IPOL NUAGE FIELD ('GAUS'|'RATI'|'PID' (P)|'GRIL')",
        doc: "Interpolation of a curve at X (value by value for lists and fields): linear (monotonic abscissae; a repeated abscissa is a jump), or a cubic spline with 'SPLI' (natural ends, or the slopes DGAU at the smallest abscissa and DDRO at the largest). Outside the abscissae the end values hold. With a NUAGE, a function of the field's components (the NUAGE's components the field names) giving the others: a first-order fit weighted around each point ('GAUS', the default, or 'RATI'), inverse distance weighting ('PID', power P, 1 by default), or multilinear on a grid ('GRIL': one tuple of a LISTREEL per axis and the values, first axis fastest).",
        example: "y = ipol 1.5 (prog 0. 1. 2.) (prog 0. 10. 40.) ;",
        f: ipol,
    },
];

fn ipol(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if let Some(nu) = a.opt_with(|v| if let Value::Nuage(n) = v { Some(n.clone()) } else { None }) {
        return super::nuage::ipol(a, &nu);
    }
    // Up to three operands, in the order written: X then the curve (one
    // EVOLUTIO, or the abscissae and ordinates lists).
    let mut vals: Vec<Value> = Vec::new();
    let (mut spline, mut left, mut right) = (false, End::Natural, End::Natural);
    loop {
        match a.keyword(&["SPLI", "DGAU", "DDRO"]) {
            Some("SPLI") => spline = true,
            Some(k) => {
                let d = a.opt_num_right().ok_or_else(|| a.missing(&format!("the slope after '{}'", k)))?;
                *(if k == "DGAU" { &mut left } else { &mut right }) = End::Slope(d);
            }
            None if vals.len() < 3 && !(vals.len() == 2 && vals.iter().any(|v| matches!(v, Value::Evol(_)))) => {
                let Some(v) = a.opt::<Numeric>() else { break };
                vals.push(v.0);
                continue;
            }
            None => break,
        }
    }
    if !spline && (left != End::Natural || right != End::Natural) {
        return Err(a.err("'DGAU' and 'DDRO' go with 'SPLI'"));
    }
    let (x, xs, ys) = match vals.iter().position(|v| matches!(v, Value::Evol(_))) {
        Some(k) => {
            let Value::Evol(e) = &vals[k] else { unreachable!() };
            let c = single_curve(a, e)?;
            let x = vals.iter().enumerate().find(|(i, _)| *i != k).map(|(_, v)| v.clone());
            (x, c.x.clone(), c.y.clone())
        }
        None => {
            let lists: Vec<(usize, Rc<Vec<f64>>)> = vals
                .iter()
                .enumerate()
                .filter_map(|(i, v)| if let Value::ListReel(l) = v { Some((i, l.clone())) } else { None })
                .collect();
            if lists.len() < 2 {
                return Err(a.missing("EVOLUTIO, or the LISTREELs of abscissae and ordinates"));
            }
            // Three lists: X is the first one written.
            let (xs, ys) = (&lists[lists.len() - 2], &lists[lists.len() - 1]);
            let x = vals.iter().enumerate().find(|(i, _)| *i != xs.0 && *i != ys.0).map(|(_, v)| v.clone());
            (x, xs.1.to_vec(), ys.1.to_vec())
        }
    };
    let x = x.ok_or_else(|| a.missing("the value to interpolate at"))?;
    check_curve(a, &xs, &ys, spline)?;
    let s = spline.then(|| Spline::new(&xs, &ys, left, right));
    let f = |t: f64| match &s {
        Some(s) => s.eval(t),
        None => interpolate(&xs, &ys, t),
    };
    match pointwise::map_checked(&x, &f) {
        Some(Ok(Value::Evol(_))) | None => Err(a.err(format!("cannot interpolate at a {}", x.type_name()))),
        Some(Ok(r)) => Ok(vec![r]),
        Some(Err(t)) => Err(a.err(format!("cannot interpolate at {}", fmt_float(t)))),
    }
}

/// The one curve of an EVOLUTIO that IPOL reads.
fn single_curve<'e>(a: &Args, e: &'e Evolution) -> Result<&'e Curve> {
    match e.curves.as_slice() {
        [c] => Ok(c),
        cs => Err(a.err(format!("the EVOLUTIO has {} curves: take one with EXTR ev 'COUR' n", cs.len()))),
    }
}

/// One ordinate per abscissa; abscissae increasing or decreasing, and
/// strictly so for a spline (a repeated abscissa is a jump of the
/// polyline, which a spline cannot follow).
fn check_curve(a: &Args, xs: &[f64], ys: &[f64], strict: bool) -> Result<()> {
    if xs.len() != ys.len() {
        return Err(a.err(format!("{} abscissae for {} ordinates", xs.len(), ys.len())));
    }
    if xs.is_empty() {
        return Err(a.err("the curve is empty"));
    }
    if xs.iter().chain(ys).any(|v| !v.is_finite()) {
        return Err(a.err("the curve has a value that is not a finite number"));
    }
    let up = xs.windows(2).all(|w| w[1] > w[0] || (!strict && w[1] == w[0]));
    let down = xs.windows(2).all(|w| w[1] < w[0] || (!strict && w[1] == w[0]));
    if !(up || down) {
        let how = if strict { "strictly " } else { "" };
        return Err(a.err(format!("the abscissae must be {how}increasing or {how}decreasing")));
    }
    Ok(())
}

/// y(t) on the polyline (xs, ys), held at the end values outside it (a
/// NaN t gives NaN, which the caller reports).
fn interpolate(xs: &[f64], ys: &[f64], t: f64) -> f64 {
    let n = xs.len();
    let up = xs[n - 1] >= xs[0];
    let key = |x: f64| if up { x } else { -x };
    let (tk, first, last) = (key(t), key(xs[0]), key(xs[n - 1]));
    if t.is_nan() {
        return t;
    }
    if tk <= first {
        return ys[0];
    }
    if tk >= last {
        return ys[n - 1];
    }
    // First segment whose right end is at or past t; a vertical one (a
    // repeated abscissa) is a jump, and t on it takes the value after.
    let j = xs.partition_point(|x| key(*x) < tk).clamp(1, n - 1);
    let (x0, x1, y0, y1) = (xs[j - 1], xs[j], ys[j - 1], ys[j]);
    if x1 == x0 {
        return y1;
    }
    y0 + (y1 - y0) * (t - x0) / (x1 - x0)
}

/// INTG of a curve (the INTG entry, in `integrate.rs`, dispatches here).
pub(crate) fn intg_curve(a: &mut Args, e: Rc<Evolution>) -> Result<Vec<Value>> {
    let n = a.opt::<i64>().unwrap_or(1);
    let c = usize::try_from(n)
        .ok()
        .and_then(|i| i.checked_sub(1))
        .and_then(|i| e.curves.get(i))
        .ok_or_else(|| a.err(format!("curve {} does not exist (the object has {})", n, e.curves.len())))?;
    let s: f64 = c.x.windows(2).zip(c.y.windows(2)).map(|(x, y)| (x[1] - x[0]) * (y[0] + y[1]) / 2.0).sum();
    Ok(vec![Value::Float(s)])
}
