//! FONC (special functions of a LISTREEL) and AIDE (operators whose
//! description holds a word).

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::{fmt_float, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "FONC",
        signature: "FONC 'GAMMA' LISTREEL | FONC 'BESSEL' 'J0'|'J1'|'Y0'|'Y1' LISTREEL | FONC 'FRESNEL' 'CX'|'SX' LISTREEL",
        doc: "Special functions of each value of a list: Gamma; Bessel functions of the first (J0, J1) and second (Y0, Y1, x > 0) kind; the Fresnel integrals CX(x) = (2 pi)^-1/2 int_0^x cos(t)/sqrt(t) dt and SX with sin (x >= 0).",
        example: "g = fonc 'GAMMA' (prog 0.5 1. 5.) ;",
        f: fonc,
    },
    OpDef {
        name: "AIDE",
        signature: "AIDE MOT",
        doc: "The operators whose name, signature or description holds the word (any case), printed and returned as a LISTMOTS.",
        example: "l = aide 'PRESSURE' ;",
        f: aide,
    },
];

fn fonc(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let family = a.req_keyword(&["GAMMA", "BESSEL", "FRESNEL"])?;
    let f: fn(f64) -> std::result::Result<f64, &'static str> = match family {
        "GAMMA" => |x| Ok(libm::tgamma(x)),
        "BESSEL" => match a.req_keyword(&["J0", "J1", "Y0", "Y1"])? {
            "J0" => |x| Ok(libm::j0(x)),
            "J1" => |x| Ok(libm::j1(x)),
            "Y0" => |x| positive(x).map(libm::y0),
            _ => |x| positive(x).map(libm::y1),
        },
        _ => match a.req_keyword(&["CX", "SX"])? {
            "CX" => |x| not_negative(x).map(|x| fresnel(scaled(x)).0),
            _ => |x| not_negative(x).map(|x| fresnel(scaled(x)).1),
        },
    };
    let xs = a.req::<Rc<Vec<f64>>>()?;
    let mut out = Vec::with_capacity(xs.len());
    for (k, &x) in xs.iter().enumerate() {
        let y = f(x).map_err(|why| a.err(format!("value {} of the list, {}: {why}", k + 1, fmt_float(x))))?;
        if !y.is_finite() {
            return Err(a.err(format!("value {} of the list, {}, is a pole of the function", k + 1, fmt_float(x))));
        }
        out.push(y);
    }
    Ok(vec![Value::ListReel(Rc::new(out))])
}

fn positive(x: f64) -> std::result::Result<f64, &'static str> {
    if x > 0.0 {
        Ok(x)
    } else {
        Err("the second kind needs x > 0")
    }
}

fn not_negative(x: f64) -> std::result::Result<f64, &'static str> {
    if x >= 0.0 {
        Ok(x)
    } else {
        Err("the Fresnel integrals of FONC need x >= 0")
    }
}

/// FONC's integrals in t/sqrt(t) are the normalised C(z), S(z) (with
/// cos(pi s^2 / 2)) at z = sqrt(2 x / pi): put t = pi s^2 / 2.
fn scaled(x: f64) -> f64 {
    (2.0 * x / std::f64::consts::PI).sqrt()
}

/// The normalised Fresnel integrals C(z) = int_0^z cos(pi s^2/2) ds and
/// S(z). Below 1.5 their power series (alternating terms of at most e^3.5,
/// so no digit is lost); above, the continued fraction of the
/// complementary error function they are the real and imaginary parts of
/// (Lentz's method), which converges fast there.
fn fresnel(z: f64) -> (f64, f64) {
    use std::f64::consts::{FRAC_PI_2, PI};
    let ax = z.abs();
    let (c, s) = if ax < 1e-150 {
        (ax, 0.0)
    } else if ax <= 1.5 {
        // C = sum (-1)^k (pi/2)^2k z^(4k+1) / ((2k)! (4k+1)), S likewise
        // with the odd powers: one running term t_n = (pi/2 z^2)^n / n! z.
        let fact = FRAC_PI_2 * ax * ax;
        let (mut c, mut s, mut term) = (ax, 0.0, ax);
        for n in 1..200 {
            term *= fact / n as f64;
            let sign = if (n / 2) % 2 == 0 { 1.0 } else { -1.0 };
            let piece = sign * term / (2 * n + 1) as f64;
            if n % 2 == 0 {
                c += piece;
            } else {
                s += piece;
            }
            if term < 1e-17 * c.abs().max(s.abs()) {
                break;
            }
        }
        (c, s)
    } else {
        let pix2 = PI * ax * ax;
        let mut b = Cx(1.0, -pix2);
        let mut cc = Cx(1e300, 0.0);
        let mut d = b.inv();
        let mut h = d;
        let mut n = -1.0;
        for _ in 2..300 {
            n += 2.0;
            let an = -n * (n + 1.0);
            b = Cx(b.0 + 4.0, b.1);
            d = (d.scale(an).add(b)).inv();
            cc = b.add(cc.inv().scale(an));
            let del = cc.mul(d);
            h = h.mul(del);
            if (del.0 - 1.0).abs() + del.1.abs() < 1e-16 {
                break;
            }
        }
        h = h.mul(Cx(ax, -ax));
        let e = Cx((0.5 * pix2).cos(), (0.5 * pix2).sin());
        let one_minus = Cx(1.0 - e.mul(h).0, -e.mul(h).1);
        let cs = Cx(0.5, 0.5).mul(one_minus);
        (cs.0, cs.1)
    };
    if z < 0.0 {
        (-c, -s)
    } else {
        (c, s)
    }
}

/// Just the complex arithmetic the continued fraction needs.
#[derive(Clone, Copy)]
struct Cx(f64, f64);

impl Cx {
    fn add(self, o: Cx) -> Cx {
        Cx(self.0 + o.0, self.1 + o.1)
    }
    fn mul(self, o: Cx) -> Cx {
        Cx(self.0 * o.0 - self.1 * o.1, self.0 * o.1 + self.1 * o.0)
    }
    fn scale(self, k: f64) -> Cx {
        Cx(self.0 * k, self.1 * k)
    }
    fn inv(self) -> Cx {
        let n = self.0 * self.0 + self.1 * self.1;
        Cx(self.0 / n, -self.1 / n)
    }
}

fn aide(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    // `AIDE ELEM`: the word is often an operator's own name, unquoted.
    let word = match a.opt::<String>() {
        Some(w) => w,
        None => a.word().ok_or_else(|| a.missing("MOT"))?,
    }
    .to_uppercase();
    let mut names: Vec<String> = it
        .registry
        .all()
        .iter()
        .filter(|op| {
            op.name.contains(&word)
                || op.signature.to_uppercase().contains(&word)
                || op.doc.to_uppercase().contains(&word)
        })
        .map(|op| op.name.to_string())
        .collect();
    names.sort();
    names.dedup();
    if !names.is_empty() {
        it.println(&names.join(" "));
    }
    Ok(vec![Value::ListMots(Rc::new(names))])
}

#[cfg(test)]
mod tests {
    use super::fresnel;

    #[test]
    fn fresnel_integrals_match_tabulated_values() {
        // Abramowitz & Stegun table 7.7, and the limits 1/2 at infinity.
        for (z, c, s) in [
            (0.5, 0.492_344_225_871_446_3, 0.064_732_432_859_999_29),
            (1.0, 0.779_893_400_376_822_8, 0.438_259_147_390_354_8),
            (1.5, 0.445_261_176_039_821_4, 0.697_504_960_082_093_1),
            (2.0, 0.488_253_406_075_340_8, 0.343_415_678_363_698_2),
            (5.0, 0.563_631_188_704_012_8, 0.499_191_381_917_117_6),
        ] {
            let (fc, fs) = fresnel(z);
            assert!((fc - c).abs() < 1e-13 && (fs - s).abs() < 1e-13, "z = {z}: {fc} {fs}");
        }
        let (fc, fs) = fresnel(1e4);
        assert!((fc - 0.5).abs() < 1e-4 && (fs - 0.5).abs() < 1e-4);
    }
}
