//! Arithmetic on transforms: an EVOLUTIO of two curves that TFR gives (real
//! and imaginary parts PREE/PIMA, or modulus and phase in degrees MODU/PHAS)
//! is one complex curve, so `*` and `/` of two of them are the complex
//! product and quotient (a transfer function is `TFR out / TFR in`), and
//! `+ -` of two MOPH curves add the complex values, not the phases.

use crate::value::arith::Bin;
use crate::value::model::{Curve, Evolution};

#[derive(Clone, Copy, PartialEq)]
enum Form {
    ReIm,
    ModPhase,
}

fn form(e: &Evolution) -> Option<Form> {
    match e.curves.as_slice() {
        [a, b] if a.y_name == "PREE" && b.y_name == "PIMA" => Some(Form::ReIm),
        [a, b] if a.y_name == "MODU" && b.y_name == "PHAS" => Some(Form::ModPhase),
        _ => None,
    }
}

fn to_reim(f: Form, p: f64, q: f64) -> (f64, f64) {
    match f {
        Form::ReIm => (p, q),
        Form::ModPhase => (p * q.to_radians().cos(), p * q.to_radians().sin()),
    }
}

/// `e op g` as complex curves, in the form of `e`; `None` when either is
/// not a transform (then the curves combine value by value). Both must be
/// sampled at the same frequencies.
pub fn combine(e: &Evolution, g: &Evolution, op: Bin) -> Option<Result<Evolution, String>> {
    let (fe, fg) = (form(e)?, form(g)?);
    if op == Bin::Pow || (op != Bin::Mul && op != Bin::Div && fe == Form::ReIm && fg == Form::ReIm) {
        return None;
    }
    let x = &e.curves[0].x;
    if g.curves.iter().chain(&e.curves).any(|c| c.x != *x || c.y.len() != x.len()) {
        return Some(Err("the two transforms must be sampled at the same frequencies".into()));
    }
    let (mut y1, mut y2) = (Vec::with_capacity(x.len()), Vec::with_capacity(x.len()));
    for i in 0..x.len() {
        let (a, b) = to_reim(fe, e.curves[0].y[i], e.curves[1].y[i]);
        let (c, d) = to_reim(fg, g.curves[0].y[i], g.curves[1].y[i]);
        let (re, im) = match op {
            Bin::Add => (a + c, b + d),
            Bin::Sub => (a - c, b - d),
            Bin::Mul => (a * c - b * d, a * d + b * c),
            _ => {
                let n = c * c + d * d;
                ((a * c + b * d) / n, (b * c - a * d) / n)
            }
        };
        match fe {
            Form::ReIm => {
                y1.push(re);
                y2.push(im);
            }
            Form::ModPhase => {
                let m = re.hypot(im);
                y1.push(m);
                y2.push(if m > 1e-20 {
                    im.atan2(re).to_degrees()
                } else if m.is_finite() {
                    0.0
                } else {
                    f64::NAN
                });
            }
        }
    }
    let curve = |c: &Curve, y: Vec<f64>| Curve { y, ..c.clone() };
    Some(Ok(Evolution { curves: vec![curve(&e.curves[0], y1), curve(&e.curves[1], y2)] }))
}

/// RIMP: the same complex curve in the other form (PREE/PIMA ↔ MODU/PHAS,
/// phases in degrees); `None` when `e` is not a transform.
pub fn switch_form(e: &Evolution) -> Option<Evolution> {
    let f = form(e)?;
    let (names, legends) =
        if f == Form::ReIm { (["MODU", "PHAS"], ["Amp", "Phase"]) } else { (["PREE", "PIMA"], ["Re", "Im"]) };
    let (mut y1, mut y2) = (vec![], vec![]);
    for (p, q) in e.curves[0].y.iter().zip(&e.curves[1].y) {
        let (re, im) = to_reim(f, *p, *q);
        if f == Form::ReIm {
            y1.push(re.hypot(im));
            y2.push(if re == 0.0 && im == 0.0 { 0.0 } else { im.atan2(re).to_degrees() });
        } else {
            y1.push(re);
            y2.push(im);
        }
    }
    let curve = |k: usize, y: Vec<f64>| {
        let c = &e.curves[k];
        // A legend TFR or EVOL 'COMP' chose follows the form; a deck's own stays.
        let legend = if ["Amp", "Phase", "Re", "Im"].contains(&c.legend.as_str()) {
            legends[k].into()
        } else {
            c.legend.clone()
        };
        Curve { legend, y_name: names[k].into(), y, ..c.clone() }
    };
    Some(Evolution { curves: vec![curve(0, y1), curve(1, y2)] })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn moph(m: f64, p: f64) -> Evolution {
        let c = |n: &str, y| Curve { y_name: n.into(), x: vec![1.0], y: vec![y], ..Curve::default() };
        Evolution { curves: vec![c("MODU", m), c("PHAS", p)] }
    }

    #[test]
    fn quotient_divides_moduli_and_subtracts_phases() {
        let r = combine(&moph(6.0, 50.0), &moph(2.0, 20.0), Bin::Div).unwrap().unwrap();
        assert!((r.curves[0].y[0] - 3.0).abs() < 1e-12);
        assert!((r.curves[1].y[0] - 30.0).abs() < 1e-9);
        // a zero phase in the divisor is not a division by zero
        let r = combine(&moph(6.0, 0.0), &moph(2.0, 0.0), Bin::Div).unwrap().unwrap();
        assert!((r.curves[0].y[0] - 3.0).abs() < 1e-12 && r.curves[1].y[0] == 0.0);
    }

    #[test]
    fn switch_and_back() {
        let r = switch_form(&moph(2.0, 90.0)).unwrap();
        assert_eq!(r.curves[0].y_name, "PREE");
        assert!(r.curves[0].y[0].abs() < 1e-12 && (r.curves[1].y[0] - 2.0).abs() < 1e-12);
        let b = switch_form(&r).unwrap();
        assert!((b.curves[0].y[0] - 2.0).abs() < 1e-12 && (b.curves[1].y[0] - 90.0).abs() < 1e-9);
    }
}
