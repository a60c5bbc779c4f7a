//! TFR and TFRI: the Fourier transform of a sampled curve and back
//! (numerics in `value::signal::fourier`). The transform is an EVOLUTIO
//! of two curves against frequency: real and imaginary parts ('REIM', the
//! default; y names PREE and PIMA) or modulus and phase in degrees
//! ('MOPH'; MODU and PHAS). TFRI reads those names to know which.

use super::{limits, Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::model::Curve;
use crate::value::signal::fourier;
use crate::value::{Evolution, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "TFR",
        signature: "TFR N EVOLUTIO ('REIM'|'MOPH') ('FMIN' F1) ('FMAX' F2) (colour1) (colour2)",
        doc: "Fourier transform of a curve sampled at a constant step dt, on 2**N points (the signal is cut or padded with zeros): dt·Σ x_j exp(-2iπ jk/2**N) at the frequencies k/(2**N dt) from 0 (or FMIN) to the Nyquist frequency (or FMAX). Two curves: real and imaginary parts ('REIM'), or modulus and phase in degrees ('MOPH').",
        example: "tf = tfr 3 (evol 'MANU' (prog 0. pas 1. 7.) (prog 1. 0. 0. 0. 0. 0. 0. 0.)) ;",
        f: tfr,
    },
    OpDef {
        name: "TFRI",
        signature: "TFRI EVOLUTIO",
        doc: "Inverse of TFR: the real signal whose one-sided transform (from frequency 0 at a constant step df, as TFR gives it) is the curve pair; 2(m-1) samples for m frequencies, at the step 1/(2(m-1)df).",
        example: "s = tfri (tfr 3 (evol 'MANU' (prog 0. pas 1. 7.) (prog 1. 0. 0. 0. 0. 0. 0. 0.))) ;",
        f: tfri,
    },
];

fn tfr(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let p = a.req::<i64>()?;
    if !(0..=40).contains(&p) {
        return Err(a.err(format!("the transform has 2**N points: N must be between 0 and 40, found {}", p)));
    }
    let n = limits::room(a, 0, 2f64.powi(p as i32))?;
    let ev = a.req::<Rc<Evolution>>()?;
    let [c] = ev.curves.as_slice() else {
        return Err(a.err(format!("the signal must be one curve, the EVOLUTIO has {}", ev.curves.len())));
    };
    let moph = a.keyword(&["REIM", "MOPH"]) == Some("MOPH");
    let fmin = freq_bound(a, "FMIN")?;
    let fmax = freq_bound(a, "FMAX")?;
    a.keyword(super::evol::COLOURS);
    a.keyword(super::evol::COLOURS);
    if c.x.len() < 2 {
        return Err(a.err("the signal needs at least two samples (the time step is their distance)"));
    }
    let dt = c.x[1] - c.x[0];
    if dt.is_nan() || dt <= 0.0 {
        return Err(a.err(format!("the times must increase (first step {})", dt)));
    }
    let df = 1.0 / (dt * n as f64);
    let half = n / 2;
    let first = fmin.map_or(0, |f| ((f / df).floor() as usize).min(half));
    let last = fmax.map_or(half, |f| ((f / df).floor() as usize).min(half));
    if last < first {
        return Err(a.err(format!("no frequency between FMIN and FMAX (the step is {})", df)));
    }
    let s = fourier::forward(&c.y, dt, n, first, last);
    let (y1, y2, names) = if moph {
        let modu: Vec<f64> = s.re.iter().zip(&s.im).map(|(r, i)| r.hypot(*i)).collect();
        let phase =
            s.re.iter()
                .zip(&s.im)
                .zip(&modu)
                .map(|((r, i), m)| if *m > 1e-20 { i.atan2(*r).to_degrees() } else { 0.0 })
                .collect();
        (modu, phase, ["MODU", "PHAS", "Amp", "Phase"])
    } else {
        (s.re, s.im, ["PREE", "PIMA", "Re", "Im"])
    };
    let curve = |y: Vec<f64>, name: &str, part: &str| Curve {
        legend: format!("{} TF({})", part, c.legend),
        x_name: "FREQ".into(),
        y_name: name.into(),
        x: s.freq.clone(),
        y,
    };
    let curves = vec![curve(y1, names[0], names[2]), curve(y2, names[1], names[3])];
    Ok(vec![Value::Evol(Rc::new(Evolution { curves }))])
}

/// `'FMIN' F` or `'FMAX' F`: a frequency, its sign dropped as Cast3M does.
fn freq_bound(a: &mut Args, key: &'static str) -> Result<Option<f64>> {
    if a.keyword(&[key]).is_none() {
        return Ok(None);
    }
    let f = a.req_num()?.abs();
    Ok(Some(f))
}

fn tfri(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let ev = a.req::<Rc<Evolution>>()?;
    let moph = match ev.curves.as_slice() {
        [c1, c2] if c1.y_name == "PREE" && c2.y_name == "PIMA" => false,
        [c1, c2] if c1.y_name == "MODU" && c2.y_name == "PHAS" => true,
        _ => {
            return Err(
                a.err("the EVOLUTIO must be a transform as TFR gives it: two curves PREE and PIMA, or MODU and PHAS")
            )
        }
    };
    let (c1, c2) = (&ev.curves[0], &ev.curves[1]);
    let f = &c1.x;
    if f.len() < 2 || c2.x.len() != f.len() {
        return Err(a.err("the transform needs at least two frequencies, the same on both curves"));
    }
    if f[0] != 0.0 {
        return Err(a.err(format!("the first frequency must be 0, found {}", f[0])));
    }
    let df = f[1] - f[0];
    if df.is_nan() || df <= 0.0 {
        return Err(a.err(format!("the frequencies must increase (first step {})", df)));
    }
    let (re, im): (Vec<f64>, Vec<f64>) = if moph {
        c1.y.iter().zip(&c2.y).map(|(m, p)| (m * p.to_radians().cos(), m * p.to_radians().sin())).unzip()
    } else {
        (c1.y.clone(), c2.y.clone())
    };
    let (t, y) = fourier::inverse(&re, &im, df);
    let curve = Curve { legend: "TF^{-1}".into(), x_name: "TEMPS".into(), y_name: "REEL".into(), x: t, y };
    Ok(vec![Value::Evol(Rc::new(Evolution { curves: vec![curve] }))])
}
