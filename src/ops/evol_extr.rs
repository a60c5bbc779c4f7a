//! EXTR on an EVOLUTIO (extr.notice): a curve's lists, by keyword
//! (`'ABSC'`, `'ORDO'`) or by their name; its legends (`'LEGE'`, `'LEGX'`,
//! `'LEGY'`); some of its curves (`'COUR'` by number, name or LISTENTI);
//! some of its couples (`'PAS'`, `'AVAN'`, `'APRE'`, `'COMP'`).

use super::Args;
use crate::error::Result;
use crate::value::model::Curve;
use crate::value::{Evolution, Value};
use std::rc::Rc;

pub(crate) fn extr(a: &mut Args, ev: &Evolution) -> Result<Vec<Value>> {
    let keys = ["ABSC", "ORDO", "LEGE", "LEGX", "LEGY", "COUR", "PAS", "AVAN", "APRE", "COMP"];
    let Some(k) = a.keyword(&keys) else {
        // A list named by the title given to EVOL (`EXTR ev 'TEMPS'`).
        let name = a.word().ok_or_else(|| a.missing(&format!("one of {} or a list's name", keys.join(" "))))?;
        return by_name(a, ev, &name);
    };
    match k {
        "COUR" => return Ok(vec![curves(a, ev)?]),
        "PAS" | "AVAN" | "APRE" | "COMP" => return Ok(vec![couples(a, ev, k)?]),
        _ => {}
    }
    let n = a.opt::<i64>().unwrap_or(1);
    let c = curve(a, ev, n)?;
    Ok(vec![match k {
        "ABSC" => Value::ListReel(Rc::new(c.x.clone())),
        "ORDO" => Value::ListReel(Rc::new(c.y.clone())),
        "LEGE" => Value::mot(&c.legend),
        "LEGX" => Value::mot(&c.x_name),
        _ => Value::mot(&c.y_name),
    }])
}

fn curve<'e>(a: &Args, ev: &'e Evolution, n: i64) -> Result<&'e Curve> {
    usize::try_from(n)
        .ok()
        .and_then(|i| i.checked_sub(1))
        .and_then(|i| ev.curves.get(i))
        .ok_or_else(|| a.err(format!("curve {} does not exist (the object has {})", n, ev.curves.len())))
}

/// Names compare without their trailing blanks (Cast3M pads words).
fn same_name(p: &str, q: &str) -> bool {
    p.trim() == q.trim()
}

/// The first list, abscissae or ordinates, with this name.
fn by_name(a: &Args, ev: &Evolution, name: &str) -> Result<Vec<Value>> {
    for c in &ev.curves {
        if same_name(&c.x_name, name) {
            return Ok(vec![Value::ListReel(Rc::new(c.x.clone()))]);
        }
        if same_name(&c.y_name, name) {
            return Ok(vec![Value::ListReel(Rc::new(c.y.clone()))]);
        }
    }
    Err(a.err(format!("no list of the EVOLUTIO is named {}", name.trim())))
}

/// `'COUR' N|LISTENTI|MOT`: curve N, the curves at the places listed, or
/// every curve one of whose lists has the name.
fn curves(a: &mut Args, ev: &Evolution) -> Result<Value> {
    let chosen: Vec<Curve> = if let Some(n) = a.opt::<i64>() {
        vec![curve(a, ev, n)?.clone()]
    } else if let Some(l) = a.opt::<Rc<Vec<i64>>>() {
        l.iter().map(|&n| curve(a, ev, n).cloned()).collect::<Result<_>>()?
    } else {
        let name = a.word().ok_or_else(|| a.missing("ENTIER, LISTENTI or MOT (the curves to keep)"))?;
        let found: Vec<Curve> =
            ev.curves.iter().filter(|c| same_name(&c.x_name, &name) || same_name(&c.y_name, &name)).cloned().collect();
        if found.is_empty() {
            return Err(a.err(format!("no curve of the EVOLUTIO has a list named {}", name.trim())));
        }
        found
    };
    Ok(Value::Evol(Rc::new(Evolution { curves: chosen })))
}

/// `'PAS' N` (every N-th couple from the first), `'AVAN'` (couples up to),
/// `'APRE'` (from) and `'COMP'` (between) an index (`'ENTI' I`) or an
/// abscissa, with `'ZERO'` moving the first abscissa kept to 0. Every
/// curve is cut the same way.
fn couples(a: &mut Args, ev: &Evolution, k: &str) -> Result<Value> {
    enum Bound {
        Index(i64),
        Absc(f64),
    }
    let step = if k == "PAS" {
        let s = a.req::<i64>()?;
        if s < 1 {
            return Err(a.err(format!("the step must be at least 1, found {}", s)));
        }
        Some(s as usize)
    } else {
        None
    };
    let mut bounds = Vec::new();
    if step.is_none() {
        let count = if k == "COMP" { 2 } else { 1 };
        let by_index = a.keyword(&["ENTI"]).is_some();
        for _ in 0..count {
            bounds.push(if by_index {
                Bound::Index(a.req::<i64>()?)
            } else {
                Bound::Absc(a.opt_num().ok_or_else(|| a.missing("FLOTTANT (an abscissa) or 'ENTI' and an index"))?)
            });
        }
    }
    let zero = a.keyword(&["ZERO"]).is_some();
    // Whether couple i (0-based) of a curve is kept.
    let keep = |c: &Curve, i: usize| -> bool {
        let inside = |b: &Bound, after: bool| match b {
            Bound::Index(n) => {
                if after {
                    (i as i64) + 1 >= *n
                } else {
                    (i as i64) < *n
                }
            }
            Bound::Absc(x) => {
                if after {
                    c.x[i] >= *x
                } else {
                    c.x[i] <= *x
                }
            }
        };
        match (k, bounds.as_slice()) {
            ("PAS", _) => i.is_multiple_of(step.unwrap_or(1)),
            ("AVAN", [b]) => inside(b, false),
            ("APRE", [b]) => inside(b, true),
            (_, [b1, b2]) => inside(b1, true) && inside(b2, false),
            _ => true,
        }
    };
    let mut out = Vec::with_capacity(ev.curves.len());
    for c in &ev.curves {
        let idx: Vec<usize> = (0..c.x.len()).filter(|&i| keep(c, i)).collect();
        let shift = match idx.first() {
            Some(&i) if zero => c.x[i],
            _ => 0.0,
        };
        out.push(Curve {
            legend: c.legend.clone(),
            x_name: c.x_name.clone(),
            y_name: c.y_name.clone(),
            x: idx.iter().map(|&i| c.x[i] - shift).collect(),
            y: idx.iter().map(|&i| c.y[i]).collect(),
        });
    }
    Ok(Value::Evol(Rc::new(Evolution { curves: out })))
}

/// `ORDO EVOLUTIO`: every curve's couples sorted by abscissa (stable:
/// equal abscissae keep their order).
pub(crate) fn sorted(ev: &Evolution, decr: bool, use_abs: bool) -> Evolution {
    let key = |x: f64| if use_abs { x.abs() } else { x };
    let curves = ev
        .curves
        .iter()
        .map(|c| {
            let mut perm: Vec<usize> = (0..c.x.len()).collect();
            perm.sort_by(|&i, &j| {
                let o = key(c.x[i]).total_cmp(&key(c.x[j]));
                if decr {
                    o.reverse()
                } else {
                    o
                }
            });
            Curve {
                legend: c.legend.clone(),
                x_name: c.x_name.clone(),
                y_name: c.y_name.clone(),
                x: perm.iter().map(|&i| c.x[i]).collect(),
                y: perm.iter().map(|&i| c.y[i]).collect(),
            }
        })
        .collect();
    Evolution { curves }
}
