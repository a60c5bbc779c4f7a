//! Fortran edit descriptors, for `CHAI 'FORMAT' '(F8.3)' …`: Fw.d, Ew.d
//! (with a kP scale factor and an Ee exponent width), Dw.d, ESw.d, Gw.d,
//! Iw(.m) and A(w), written as Fortran writes them: right-justified in w
//! characters, and w asterisks when the value does not fit.

/// One edit descriptor.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Edit {
    /// Fixed point: w wide (0: as narrow as possible), d decimals.
    F { w: usize, d: usize },
    /// Exponent form: `scale` digits before the point (0: `0.ddd`),
    /// `letter` E or D, exponent of `e` digits (None: 2, or 3 without the
    /// letter past 99).
    E { w: usize, d: usize, scale: usize, e: Option<usize>, letter: char },
    /// Fixed point when the magnitude suits d significant digits, else E.
    G { w: usize, d: usize },
    /// Integer: w wide, at least m digits.
    I { w: usize, m: usize },
    /// Text, w wide when given.
    A { w: Option<usize> },
}

/// Parse `(1PE12.5)`, `(F8.3)`, `(I5)`, `(A10)`, … (one descriptor; the
/// parentheses may be left out).
pub(crate) fn parse(text: &str) -> Result<Edit, String> {
    let bad = || {
        format!("unsupported format '{}': give one of (Fw.d) (Ew.d) (1PEw.d) (ESw.d) (Dw.d) (Gw.d) (Iw) (A) (Aw)", text)
    };
    let t: String = text.trim().to_uppercase().chars().filter(|c| !c.is_whitespace()).collect();
    let t = match t.strip_prefix('(') {
        Some(inner) => inner.strip_suffix(')').ok_or_else(bad)?,
        None => t.as_str(),
    };
    // Optional scale factor kP (only before E or D).
    let (scale, t) = match t.find('P') {
        Some(i) if i > 0 && t[..i].chars().all(|c| c.is_ascii_digit()) => {
            (Some(t[..i].parse::<usize>().map_err(|_| bad())?), &t[i + 1..])
        }
        _ => (None, t),
    };
    let num = |s: &str| s.parse::<usize>().map_err(|_| bad());
    // "w.d" and an optional "Ee".
    let width_dec = |s: &str| -> Result<(usize, usize, Option<usize>), String> {
        let (wd, e) = match s.split_once('E') {
            Some((wd, e)) => (wd, Some(num(e)?)),
            None => (s, None),
        };
        let (w, d) = wd.split_once('.').ok_or_else(bad)?;
        Ok((num(w)?, num(d)?, e))
    };
    let edit = if let Some(r) = t.strip_prefix("ES") {
        let (w, d, e) = width_dec(r)?;
        Edit::E { w, d, scale: 1, e, letter: 'E' }
    } else if let Some(r) = t.strip_prefix('E').or_else(|| t.strip_prefix('D')) {
        let (w, d, e) = width_dec(r)?;
        let letter = t.chars().next().unwrap_or('E');
        let scale = scale.unwrap_or(0);
        if scale > d + 1 {
            return Err(bad());
        }
        Edit::E { w, d, scale, e, letter }
    } else if scale.is_some() {
        return Err(bad());
    } else if let Some(r) = t.strip_prefix('F') {
        let (w, d, e) = width_dec(r)?;
        if e.is_some() {
            return Err(bad());
        }
        Edit::F { w, d }
    } else if let Some(r) = t.strip_prefix('G') {
        let (w, d, _) = width_dec(r)?;
        Edit::G { w, d }
    } else if let Some(r) = t.strip_prefix('I') {
        match r.split_once('.') {
            Some((w, m)) => Edit::I { w: num(w)?, m: num(m)? },
            None => Edit::I { w: num(r)?, m: 1 },
        }
    } else if let Some(r) = t.strip_prefix('A') {
        Edit::A { w: if r.is_empty() { None } else { Some(num(r)?) } }
    } else {
        return Err(bad());
    };
    // F0.d is "as narrow as possible"; E and G need a width.
    if let Edit::E { w: 0, .. } | Edit::G { w: 0, .. } = edit {
        return Err(bad());
    }
    Ok(edit)
}

/// Right-justify in `w` (0: no padding), or `w` asterisks if too long.
fn fit(s: String, w: usize) -> String {
    match w {
        0 => s,
        w if s.len() > w => "*".repeat(w),
        w => format!("{:>w$}", s),
    }
}

/// Fortran may drop the leading zero of `0.ddd` to fit the width.
fn fit_number(s: String, w: usize) -> String {
    if w > 0 && s.len() > w {
        let short = s.replacen("0.", ".", 1);
        if short.len() <= w && (s.starts_with("0.") || s.starts_with("-0.")) {
            return fit(short, w);
        }
    }
    fit(s, w)
}

pub(crate) fn real(edit: &Edit, x: f64) -> String {
    match *edit {
        Edit::F { w, d } => fixed(x, w, d),
        Edit::E { w, d, scale, e, letter } => exponent(x, w, d, scale, e, letter),
        Edit::G { w, d } => general(x, w, d),
        // A real under an integer or text descriptor: Fortran would stop;
        // the FLOTTANT keeps its own format (the caller does not ask).
        _ => crate::value::fmt_float(x),
    }
}

fn fixed(x: f64, w: usize, d: usize) -> String {
    if !x.is_finite() {
        return fit(format!("{}", x), w);
    }
    let s = format!("{:.*}", d, x);
    // No "-0.000": Fortran writes the sign of a value that rounds to zero
    // only on some compilers; gibi never does.
    let s = if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') { s[1..].to_string() } else { s };
    fit_number(s, w)
}

fn exponent(x: f64, w: usize, d: usize, scale: usize, e: Option<usize>, letter: char) -> String {
    if !x.is_finite() {
        return fit(format!("{}", x), w);
    }
    // Significant digits: d after `0.`, or d + 1 with a scale factor.
    let sig = if scale == 0 { d.max(1) } else { d + 1 };
    let sci = format!("{:.*e}", sig - 1, x.abs());
    let (m, p) = sci.split_once('e').unwrap_or((&sci, "0"));
    let p: i32 = p.parse().unwrap_or(0);
    let digits: String = m.chars().filter(|c| c.is_ascii_digit()).collect();
    let (mant, exp) = if x == 0.0 {
        let zeros = "0".repeat(sig);
        if scale == 0 {
            (format!("0.{}", zeros), 0)
        } else {
            (format!("{}.{}", &zeros[..scale], &zeros[scale..]), 0)
        }
    } else if scale == 0 {
        (format!("0.{}", digits), p + 1)
    } else {
        (format!("{}.{}", &digits[..scale], &digits[scale..]), p - scale as i32 + 1)
    };
    let sign = if x < 0.0 { "-" } else { "" };
    let es = if exp < 0 { '-' } else { '+' };
    let exp_text = match e {
        Some(n) => {
            let t = format!("{:0n$}", exp.unsigned_abs());
            if t.len() > n {
                return "*".repeat(w);
            }
            format!("{}{}{}", letter, es, t)
        }
        None if exp.abs() <= 99 => format!("{}{}{:02}", letter, es, exp.abs()),
        None if exp.abs() <= 999 => format!("{}{:03}", es, exp.abs()),
        None => return "*".repeat(w),
    };
    fit_number(format!("{}{}{}", sign, mant, exp_text), w)
}

/// Gw.d: F with d significant digits (and 4 trailing blanks) when
/// 0.1 <= |x| < 10^d, else Ew.d.
fn general(x: f64, w: usize, d: usize) -> String {
    let a = x.abs();
    if x.is_finite() && (x == 0.0 || (a >= 0.1 && a < 10f64.powi(d as i32))) {
        let k = if x == 0.0 { 1 } else { (a.log10().floor() as i32 + 1).max(0) as usize };
        let decimals = d.saturating_sub(k);
        return format!("{}    ", fixed(x, w.saturating_sub(4), decimals));
    }
    exponent(x, w, d, 0, None, 'E')
}

pub(crate) fn int(edit: &Edit, i: i64) -> String {
    match *edit {
        Edit::I { w, m } => {
            let digits = format!("{:0m$}", i.unsigned_abs());
            let s = if i < 0 { format!("-{}", digits) } else { digits };
            fit(s, w)
        }
        _ => i.to_string(),
    }
}

pub(crate) fn text(edit: &Edit, s: &str) -> String {
    match *edit {
        // Fortran's Aw takes the first w characters, or right-justifies.
        Edit::A { w: Some(w) } => {
            let n = s.chars().count();
            if n >= w {
                s.chars().take(w).collect()
            } else {
                format!("{}{}", " ".repeat(w - n), s)
            }
        }
        _ => s.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn r(f: &str, x: f64) -> String {
        real(&parse(f).unwrap(), x)
    }

    #[test]
    fn reals_as_fortran_writes_them() {
        assert_eq!(r("(F8.3)", std::f64::consts::PI), "   3.142");
        assert_eq!(r("(F8.3)", -0.5), "  -0.500");
        assert_eq!(r("(F4.3)", 0.5), ".500");
        assert_eq!(r("(F4.1)", 12345.0), "****");
        assert_eq!(r("(F0.2)", 2.0), "2.00");
        assert_eq!(r("(1PE12.5)", 1.0), " 1.00000E+00");
        assert_eq!(r("(1PE12.5)", -123.456), "-1.23456E+02");
        assert_eq!(r("(E12.4)", std::f64::consts::PI), "  0.3142E+01");
        assert_eq!(r("(E12.4)", 0.0), "  0.0000E+00");
        assert_eq!(r("(ES10.3)", 0.00123), " 1.230E-03");
        assert_eq!(r("(D10.3)", 2.5), " 0.250D+01");
        assert_eq!(r("(2PE12.4)", std::f64::consts::PI), "  31.416E-01");
        assert_eq!(r("(E12.4E3)", 1.0e-120), " 0.1000E-119");
        assert_eq!(r("(1PE11.4)", 1.0e150), " 1.0000+150");
        assert_eq!(r("(G12.4)", std::f64::consts::PI), "   3.142    ");
        assert_eq!(r("(G12.4)", 1.0e6), "  0.1000E+07");
    }

    #[test]
    fn integers_and_text() {
        assert_eq!(int(&parse("(I5)").unwrap(), -42), "  -42");
        assert_eq!(int(&parse("(I5.3)").unwrap(), 7), "  007");
        assert_eq!(int(&parse("(I2)").unwrap(), 123), "**");
        assert_eq!(text(&parse("(A6)").unwrap(), "abc"), "   abc");
        assert_eq!(text(&parse("(A2)").unwrap(), "abc"), "ab");
        assert_eq!(text(&parse("(a)").unwrap(), "abc"), "abc");
    }

    #[test]
    fn unsupported_formats_are_named() {
        for f in ["(F8.3", "(X)", "(F8)", "(3PE8.1)", "(1PF8.3)", "(E0.3)", "(2X,F8.3)"] {
            assert!(parse(f).is_err(), "{}", f);
        }
        assert_eq!(parse("( 1p e12.5 )").unwrap(), Edit::E { w: 12, d: 5, scale: 1, e: None, letter: 'E' });
        assert_eq!(parse("F8.3").unwrap(), Edit::F { w: 8, d: 3 });
    }
}
