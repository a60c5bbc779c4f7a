//! OSCI, SPO and SPON: one-degree-of-freedom oscillators driven by a
//! signal (an EVOLUTIO), `x'' + 2 xi w x' + r(x) = signal(t)`: the time
//! response, the linear response spectra, and the spectra of a bilinear
//! hysteretic oscillator. Numerics in `value::signal::oscillator`.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::model::Curve;
use crate::value::signal::oscillator::{self as osc, Signal, Spring};
use crate::value::{Evolution, Value};
use std::f64::consts::PI;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "OSCI",
        signature: "OSCI EVOLUTIO 'AMOR' XI 'FREQ' F ('TEMP' LISTREEL) ('DEPL' X0) ('VITE' V0) ('COUL' colour)",
        doc: "Response x(t) of the oscillator x'' + 2 XI w x' + w² x = signal(t), w = 2π F, from x = X0, x' = V0 (default 0) at the first time. Exact for a signal linear between its samples (zero outside them). Times: those of the LISTREEL, by default the signal's. A curve 'DEPL' against 'TEMPS'.",
        example: "x = osci (evol 'MANU' (prog 0. 10.) (prog 1. 1.)) 'AMOR' 0. 'FREQ' 1. ;",
        f: osci,
    },
    OpDef {
        name: "SPO",
        signature: "SPO EVOLUTIO 'AMOR' LISTREEL ('FREQ' LISTREEL) ('TEMP' LISTREEL) ('COUL' colour) 'DEPL'|'VITE'|'ACCE'|'ACCA'",
        doc: "Response spectra of the signal: for each damping XI of 'AMOR', a curve against frequency of max|x| ('DEPL'), w·max|x| ('VITE', pseudo-velocity), w²·max|x| ('ACCE', pseudo-acceleration) or max|2 XI w x' + w² x| ('ACCA', absolute acceleration) of the oscillator x'' + 2 XI w x' + w² x = signal(t). Default frequencies from 1/T by 1/T up to 1/(XI T), then by steps XI·f up to 1/(2 dt) (T the duration, dt the mean step); default times the signal's followed by half a period of free motion.",
        example: "s = spo (evol 'MANU' (prog 0. 1. 2.) (prog 0. 1. 0.)) 'AMOR' (prog 0.05) 'FREQ' (prog 1. 2.) 'ACCE' ;",
        f: spo,
    },
    OpDef {
        name: "SPON",
        signature: "SPON ('DEMA') 'SIGN' EVOLUTIO ('SPEL' EVOLUTIO 'DEPL'|'VITE'|'ACCE') 'AMOR' LISTREEL 'CINE'|'ISOT'|'ELAS' LISTREEL ('COUL' colour) 'DEPL'|'VITE'|'ACCE'|'EPSE'",
        doc: "Spectra of a bilinear oscillator (stiffness w², then THETA·w² past the yield displacement uy; kinematic 'CINE' or isotropic 'ISOT' hardening, or non-linear elastic 'ELAS'), properties (MU THETA): ductility and stiffness ratio. At the frequencies of the linear spectrum 'SPEL' (computed if absent). With 'DEMA', uy is the yield giving a largest |x| of MU·uy and the ordinates are uy, w·uy or w²·uy; without, uy is the linear peak over MU and the ordinates are max|x|, w·max|x|, w²·max|x|. 'EPSE': the cumulated plastic displacement.",
        example: "s = spon 'DEMA' 'SIGN' (evol 'MANU' (prog 0. pas 0.01 1.) (prog 101 * 1.)) 'AMOR' (prog 0.05) 'CINE' (prog 1. 0.) 'ACCE' ;",
        f: spon,
    },
];

/// The signal: the one curve of an EVOLUTIO.
fn signal(a: &Args, ev: &Evolution) -> Result<(Vec<f64>, Vec<f64>)> {
    let Some(c) = ev.curves.first() else { return Err(a.err("the signal EVOLUTIO has no curve")) };
    if c.x.len() < 2 {
        return Err(a.err("the signal needs at least two samples"));
    }
    if c.x.windows(2).any(|p| p[1].is_nan() || p[1] < p[0]) {
        return Err(a.err("the times of the signal must increase"));
    }
    Ok((c.x.clone(), c.y.clone()))
}

fn omega(a: &Args, f: f64) -> Result<f64> {
    if !(f > 0.0 && f.is_finite()) {
        return Err(a.err(format!("the frequency of an oscillator must be positive, found {}", f)));
    }
    Ok(2.0 * PI * f)
}

fn curve(x_name: &str, y_name: &str, x: Vec<f64>, y: Vec<f64>) -> Curve {
    Curve { legend: String::new(), x_name: x_name.into(), y_name: y_name.into(), x, y }
}

fn osci(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let ev = a.req::<Rc<Evolution>>()?;
    let (t, f) = signal(a, &ev)?;
    let (mut xi, mut freq, mut times, mut x0, mut v0) = (None, None, None, 0.0, 0.0);
    while let Some(k) = a.keyword_next(&["AMOR", "FREQ", "TEMP", "DEPL", "VITE", "COUL"]) {
        match k {
            "AMOR" => xi = Some(a.req_num()?),
            "FREQ" => freq = Some(a.req_num()?),
            "TEMP" => times = Some(a.req::<Rc<Vec<f64>>>()?),
            "DEPL" => x0 = a.req_num()?,
            "VITE" => v0 = a.req_num()?,
            _ => {
                a.keyword_next(super::evol::COLOURS);
            }
        }
    }
    let xi = xi.ok_or_else(|| a.missing("'AMOR' and the damping"))?;
    let w = omega(a, freq.ok_or_else(|| a.missing("'FREQ' and the frequency"))?)?;
    let times = times.map_or_else(|| t.clone(), |l| l.to_vec());
    let r = osc::linear(&Signal { t: &t, f: &f }, w, xi, &times, x0, v0).map_err(|e| a.err(e))?;
    Ok(vec![Value::Evol(Rc::new(Evolution { curves: vec![curve("TEMPS", "DEPL", times, r.x)] }))])
}

fn spo(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let ev = a.req::<Rc<Evolution>>()?;
    let (t, f) = signal(a, &ev)?;
    let (mut damp, mut freqs, mut times, mut out) = (None, None, None, None);
    while let Some(k) = a.keyword_next(&["AMOR", "FREQ", "TEMP", "COUL", "DEPL", "VITE", "ACCE", "ACCA"]) {
        match k {
            "AMOR" => damp = Some(a.req::<Rc<Vec<f64>>>()?),
            "FREQ" => freqs = Some(a.req::<Rc<Vec<f64>>>()?),
            "TEMP" => times = Some(a.req::<Rc<Vec<f64>>>()?),
            "COUL" => {
                a.keyword_next(super::evol::COLOURS);
            }
            o => out = Some(o),
        }
    }
    let damp = damp.ok_or_else(|| a.missing("'AMOR' and a LISTREEL of dampings"))?;
    let out = out.ok_or_else(|| a.missing("one of DEPL VITE ACCE ACCA (the spectrum's kind)"))?;
    let sig = Signal { t: &t, f: &f };
    let mut curves = Vec::new();
    for &xi in damp.iter() {
        let fl = freqs.as_ref().map_or_else(|| osc::spectrum_frequencies(&t, xi), |l| l.to_vec());
        let mut y = Vec::with_capacity(fl.len());
        for &fr in &fl {
            let w = omega(a, fr)?;
            let tt = times.as_ref().map_or_else(|| osc::spectrum_times(&t, w), |l| l.to_vec());
            let r = osc::linear(&sig, w, xi, &tt, 0.0, 0.0).map_err(|e| a.err(e))?;
            y.push(match out {
                "DEPL" => r.max_x,
                "VITE" => w * r.max_x,
                "ACCE" => w * w * r.max_x,
                _ => r.max_acc,
            });
        }
        let mut c = curve("FREQ", out, fl, y);
        c.legend = format!("AMOR {}", xi);
        curves.push(c);
    }
    Ok(vec![Value::Evol(Rc::new(Evolution { curves }))])
}

fn spon(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let (mut demand, mut sig_ev, mut spel, mut damp, mut law, mut out) = (false, None, None, None, None, None);
    let kinds =
        ["DEMA", "SIGN", "SPEL", "AMOR", "CINE", "ISOT", "ELAS", "TAKE", "COUL", "DEPL", "VITE", "ACCE", "EPSE"];
    while let Some(k) = a.keyword_next(&kinds) {
        match k {
            "DEMA" => demand = true,
            "SIGN" => sig_ev = Some(a.req::<Rc<Evolution>>()?),
            "SPEL" => {
                let e = a.req::<Rc<Evolution>>()?;
                let kind = a
                    .keyword_next(&["DEPL", "VITE", "ACCE"])
                    .ok_or_else(|| a.missing("DEPL, VITE or ACCE (the kind of the linear spectrum)"))?;
                spel = Some((e, kind));
            }
            "AMOR" => damp = Some(a.req::<Rc<Vec<f64>>>()?),
            "TAKE" => return Err(a.err("the Takeda law of SPON is not implemented; 'CINE', 'ISOT' and 'ELAS' are")),
            "CINE" | "ISOT" | "ELAS" => law = Some((k, a.req::<Rc<Vec<f64>>>()?)),
            "COUL" => {
                a.keyword_next(super::evol::COLOURS);
            }
            o => out = Some(o),
        }
    }
    let sig_ev = sig_ev.ok_or_else(|| a.missing("'SIGN' and the signal EVOLUTIO"))?;
    let (t, f) = signal(a, &sig_ev)?;
    let damp = damp.ok_or_else(|| a.missing("'AMOR' and a LISTREEL of dampings"))?;
    let (law, props) =
        law.ok_or_else(|| a.missing("'CINE', 'ISOT' or 'ELAS' and the LISTREEL (ductility, stiffness ratio)"))?;
    let out = out.ok_or_else(|| a.missing("one of DEPL VITE ACCE EPSE (the spectrum's kind)"))?;
    if props.len() < 2 {
        return Err(
            a.err(format!("the bilinear law needs 2 values (ductility, stiffness ratio), found {}", props.len()))
        );
    }
    let (mu, theta) = (props[0], props[1]);
    if !(mu >= 1.0 && mu.is_finite() && (0.0..=1.0).contains(&theta)) {
        return Err(a.err(format!(
            "the ductility must be at least 1 and the stiffness ratio between 0 and 1, found {} and {}",
            mu, theta
        )));
    }
    let spring = match law {
        "CINE" => Spring::Kinematic,
        "ISOT" => Spring::Isotropic,
        _ => Spring::Elastic,
    };
    let sig = Signal { t: &t, f: &f };
    let mut curves = Vec::new();
    for (ci, &xi) in damp.iter().enumerate() {
        // The linear peak displacement at each frequency: from SPEL, or computed.
        let (fl, lin): (Vec<f64>, Vec<f64>) = match &spel {
            Some((e, kind)) => {
                let c =
                    e.curves.get(ci).or(e.curves.first()).ok_or_else(|| a.err("the linear spectrum has no curve"))?;
                let mut d = Vec::with_capacity(c.x.len());
                for (&fr, &y) in c.x.iter().zip(&c.y) {
                    let w = omega(a, fr)?;
                    d.push(match *kind {
                        "DEPL" => y,
                        "VITE" => y / w,
                        _ => y / (w * w),
                    });
                }
                (c.x.clone(), d)
            }
            None => {
                let fl = osc::spectrum_frequencies(&t, xi);
                let mut d = Vec::with_capacity(fl.len());
                for &fr in &fl {
                    let w = omega(a, fr)?;
                    d.push(
                        osc::linear(&sig, w, xi, &osc::spectrum_times(&t, w), 0.0, 0.0).map_err(|e| a.err(e))?.max_x,
                    );
                }
                (fl, d)
            }
        };
        let mut y = Vec::with_capacity(fl.len());
        for (&fr, &lmax) in fl.iter().zip(&lin) {
            let w = omega(a, fr)?;
            let times = osc::spectrum_times(&t, w);
            let (peak, plastic) = if demand {
                let (uy, p) = osc::yield_for_ductility(&sig, w, xi, spring, theta, mu, lmax.abs(), &times)
                    .map_err(|e| a.err(e))?;
                (uy, p)
            } else if mu == 1.0 || lmax == 0.0 {
                (lmax.abs(), 0.0)
            } else {
                osc::bilinear(&sig, w, xi, spring, theta, lmax.abs() / mu, &times).map_err(|e| a.err(e))?
            };
            y.push(match out {
                "DEPL" => peak,
                "VITE" => w * peak,
                "ACCE" => w * w * peak,
                _ => plastic,
            });
        }
        let mut c = curve("FREQ", out, fl, y);
        c.legend = format!("AMOR {}", xi);
        curves.push(c);
    }
    Ok(vec![Value::Evol(Rc::new(Evolution { curves }))])
}
