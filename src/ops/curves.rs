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

/// INTG of a curve (the INTG entry, in `integrate.rs`, dispatches here):
/// a LISTREEL, the trapezoidal integral of every curve (between the
/// points of numbers ENT1 and ENT2 when given), or of the one curve over
/// each interval of two LISTENTI; with 'ABS', of the absolute value.
pub(crate) fn intg_curve(a: &mut Args, e: Rc<Evolution>) -> Result<Vec<Value>> {
    let abs = a.keyword(&["ABS"]).is_some();
    let ranges: Option<Vec<(i64, i64)>> = if let Some(l1) = a.opt::<Rc<Vec<i64>>>() {
        let l2 = a.req::<Rc<Vec<i64>>>()?;
        if l1.len() != l2.len() {
            return Err(a.err(format!("the bounds are lists of {} and {} numbers", l1.len(), l2.len())));
        }
        if e.curves.len() != 1 {
            return Err(a.err(format!("intervals as LISTENTI need a curve alone (the object has {})", e.curves.len())));
        }
        Some(l1.iter().copied().zip(l2.iter().copied()).collect())
    } else if let Some(i1) = a.opt::<i64>() {
        Some(vec![(i1, a.req::<i64>()?)])
    } else {
        None
    };
    let mut out = Vec::new();
    for (k, c) in e.curves.iter().enumerate() {
        if k > 0 && ranges.as_ref().is_some_and(|r| r.len() > 1) {
            break;
        }
        let n = c.x.len().min(c.y.len());
        let spans = ranges.clone().unwrap_or(vec![(1, n as i64)]);
        for (i1, i2) in spans {
            let ok = |i: i64| i >= 1 && i as usize <= n;
            if !ok(i1) || !ok(i2) || i1 > i2 {
                return Err(a.err(format!("the interval {i1} {i2} is not within the {n} points of the curve")));
            }
            let (lo, hi) = (i1 as usize - 1, i2 as usize);
            out.push(trapezoid(&c.x[lo..hi], &c.y[lo..hi], abs));
        }
    }
    Ok(vec![Value::ListReel(Rc::new(out))])
}

/// The integral of the piecewise linear curve (of its absolute value,
/// exactly, when `abs`: a segment crossing zero is cut there).
fn trapezoid(x: &[f64], y: &[f64], abs: bool) -> f64 {
    x.windows(2)
        .zip(y.windows(2))
        .map(|(x, y)| {
            let dx = x[1] - x[0];
            if !abs {
                dx * (y[0] + y[1]) / 2.0
            } else if y[0] * y[1] < 0.0 {
                dx * (y[0] * y[0] + y[1] * y[1]) / (2.0 * (y[0].abs() + y[1].abs()))
            } else {
                dx * (y[0].abs() + y[1].abs()) / 2.0
            }
        })
        .sum()
}
