//! The options of OPTI/VALE that need their own reading: the ones the
//! evaluator and the operators use (DIME, ELEM, MODE, ECHO, DENS, ERRE,
//! RESO), and the ones whose value is not a single word or number (MODE,
//! SAUV/REST formats, INCO, NORM, OEIL, FTRA, the number limits).

use super::opti::{choose, default_of, pointer};
use super::{Args, PointId};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::Value;
use std::rc::Rc;

/// OPTI `key` …: read the option's value and apply it.
pub(super) fn set(it: &mut Interp, a: &mut Args, key: &'static str) -> Result<()> {
    match key {
        "DIME" => {
            let d = a.req::<i64>()?;
            if !(1..=3).contains(&d) {
                return Err(a.err(format!("DIME must be 1, 2 or 3, found {}", d)));
            }
            it.opts.dime = d as usize;
            it.opts.mode = match d {
                3 => "TRID",
                2 => "PLAN CONT",
                _ => "UNID PLAN DYDZ",
            }
            .into();
        }
        "ELEM" => it.opts.elem = a.word().ok_or_else(|| a.missing("an element type"))?.to_uppercase(),
        "MODE" => it.opts.mode = mode(a)?,
        "ECHO" => {
            let n = a.req::<i64>()?;
            if !(-1..=2).contains(&n) {
                return Err(a.err(format!("ECHO is -1, 0, 1 or 2, found {}", n)));
            }
            it.opts.echo = n;
            // Kept as given: the messages Cast3M prints by default
            // (PASAPAS's step lines) stay silent only under an explicit
            // OPTI ECHO 0, gibi's default being 0 too.
            it.opts.kept.insert(key, Value::Int(n));
        }
        // As Cast3M does, a negative density counts by its size.
        "DENS" => it.opts.dens = a.req_num()?.abs(),
        "ERRE" => it.opts.erre = word_of(a, key, &["FATAL", "NORMAL", "IGNORE", "CONTROLE", "CONTINUER"])?.into(),
        "RESO" => it.opts.reso = word_of(a, key, &["DIRECTE", "ITERATIVE"])?.into(),
        "ERMA" => return Err(a.err("ERMA (the highest error level reached) is read with VALE, never set")),
        "FTRA" => {
            let file = a.word().ok_or_else(|| a.missing("a file name"))?;
            a.keyword_next(&["NOUV", "SUIT"]);
            it.opts.kept.insert(key, Value::mot(&file));
        }
        "PETI" | "GRAN" | "PREC" => {
            let x = a.req_num()?.abs();
            let ok = match key {
                "PETI" => x > 0.0 && x / 10.0 < x,
                "GRAN" => x.is_finite() && x * 10.0 > x,
                _ => 1.0 + x > 1.0 && x.is_finite(),
            };
            if !ok {
                return Err(a.err(format!("{} {:e} is not a usable value on this machine", key, x)));
            }
            it.opts.kept.insert(key, Value::Float(x));
        }
        "NBP" => {
            let n = a.req::<i64>()?;
            if n < it.nodes.len() as i64 {
                return Err(a.err(format!(
                    "NBP {} would drop points that exist ({} of them): gibi keeps every point",
                    n,
                    it.nodes.len()
                )));
            }
        }
        "INCO" => inco(it, a)?,
        "NORM" => {
            let v = match a.keyword_next(&["AUTO", "ANNU"]) {
                Some(w) => Value::mot(w),
                None => {
                    let names = a.req::<Rc<Vec<String>>>()?;
                    let factors = a.req::<Rc<Vec<f64>>>()?;
                    if names.len() != factors.len() {
                        return Err(a.err("NORM: the LISTMOTS and the LISTREEL must have the same length"));
                    }
                    if let Some(duals) = a.opt::<Rc<Vec<String>>>() {
                        let f = a.req::<Rc<Vec<f64>>>()?;
                        if duals.len() != f.len() {
                            return Err(a.err("NORM: the LISTMOTS and the LISTREEL must have the same length"));
                        }
                    }
                    Value::ListMots(names)
                }
            };
            it.opts.kept.insert(key, v);
        }
        "OEIL" => {
            let p = a.req::<PointId>()?;
            it.opts.kept.insert(key, Value::Point(p.0));
        }
        "SAUV" | "REST" => {
            while let Some(w) = a.keyword_next(&["FORM", "TAIL", "XDR", "BINA"]) {
                if w == "TAIL" {
                    a.req_num()?;
                }
            }
            let v = match a.opt_right::<i64>() {
                Some(n) if n <= 0 => return Err(a.err(format!("{}: a logical unit is positive, found {}", key, n))),
                Some(n) => Value::Int(n),
                None => Value::mot(&a.word().ok_or_else(|| a.missing("a logical unit or a file name"))?),
            };
            it.opts.kept.insert(key, v);
        }
        // Cast3M accepts OPTI POIN and does nothing with it.
        "POIN" => {}
        _ => unreachable!("{} has no code of its own", key),
    }
    Ok(())
}

/// VALE `key` (…): the option's value.
pub(super) fn get(it: &mut Interp, a: &mut Args, key: &'static str) -> Result<Vec<Value>> {
    let kept = |it: &Interp| it.opts.kept.get(key).cloned().unwrap_or_else(|| default_of(key));
    Ok(vec![match key {
        "DIME" => Value::Int(it.opts.dime as i64),
        "ELEM" => Value::mot(&it.opts.elem),
        "MODE" => {
            let m = it.opts.mode.clone();
            match (m.strip_prefix("FOUR "), a.keyword_next(&["FOUR"])) {
                (Some(n), Some(_)) => n.parse::<i64>().map(Value::Int).unwrap_or_else(|_| Value::mot(n)),
                (None, Some(_)) => return Err(a.err("VALE MODE FOUR: the mode is not FOUR")),
                // VALE gives the words of the mode run together: PLANCONT.
                (_, None) => {
                    Value::mot(m.split_whitespace().take(if m.starts_with("FOUR") { 1 } else { 3 }).collect::<String>())
                }
            }
        }
        "ECHO" => Value::Int(it.opts.echo),
        "DENS" => Value::Float(it.opts.dens),
        "ERRE" => Value::mot(&it.opts.erre),
        "RESO" => Value::mot(&it.opts.reso),
        "ERMA" => Value::Int(0),
        "NBP" => Value::Int(it.nodes.len() as i64),
        "FTRA" => match it.opts.kept.get(key) {
            Some(v) => v.clone(),
            None => return Err(a.err("VALE FTRA: no picture file was named with OPTI FTRA")),
        },
        "OEIL" => match it.opts.kept.get(key) {
            Some(v) => v.clone(),
            None => return Err(a.err("VALE OEIL: no point of view was given with OPTI OEIL")),
        },
        "NORM" => return Err(a.err("the NORM option cannot be read back (as in Cast3M)")),
        "INCO" => {
            let (primal, dual) = incos(it);
            return Ok(vec![Value::ListMots(Rc::new(primal)), Value::ListMots(Rc::new(dual))]);
        }
        "POIN" => {
            let mut out = Vec::new();
            while let Some(v) = a.opt::<Value>() {
                out.push(Value::Int(pointer(&v)));
            }
            if out.is_empty() {
                return Err(a.missing("the objects whose pointers VALE 'POIN' gives"));
            }
            return Ok(out);
        }
        // A unit option given a file name reports its unit.
        "SAUV" | "REST" => match kept(it) {
            Value::Mot(_) => default_of(key),
            v => v,
        },
        _ => kept(it),
    }])
}

/// One of `choices`, by the word that follows.
fn word_of(a: &mut Args, key: &str, choices: &[&'static str]) -> Result<&'static str> {
    let w = a.word().ok_or_else(|| a.missing(&format!("one of {}", choices.join(" "))))?.to_uppercase();
    choose(&w, choices).ok_or_else(|| a.err(format!("{} {}: expected one of {}", key, w, choices.join(" "))))
}

/// OPTI MODE: the analysis mode, as gibi spells it internally (words
/// separated by blanks: `PLAN CONT`, `FOUR 2`, `UNID AXIS AXDZ`).
fn mode(a: &mut Args) -> Result<String> {
    let w = word_of(a, "MODE", &["PLAN", "AXIS", "FOUR", "TRID", "UNID", "FREQ"])?;
    Ok(match w {
        // PLAN alone is plane strain (option.eso: DEFO first).
        "PLAN" => format!("PLAN {}", a.keyword_next(&["DEFO", "CONT", "GENE"]).unwrap_or("DEFO")),
        "FOUR" => match a.opt_right::<i64>() {
            Some(n) => format!("FOUR {}", n),
            None => match a.keyword_next(&["NOHA"]) {
                Some(_) => "FOUR NOHA".into(),
                None => return Err(a.missing("the Fourier harmonic (ENTIER) or NOHA")),
            },
        },
        "UNID" => match a.keyword_next(&["PLAN", "AXIS", "SPHE"]) {
            None | Some("PLAN") => {
                let sub = ["DYDZ", "DYCZ", "CYDZ", "CYCZ", "GYDZ", "GYCZ", "DYGZ", "CYGZ", "GYGZ"];
                format!("UNID PLAN {}", a.keyword_next(&sub).unwrap_or("DYDZ"))
            }
            Some("AXIS") => format!("UNID AXIS {}", a.keyword_next(&["AXDZ", "AXCZ", "AXGZ"]).unwrap_or("AXDZ")),
            Some(_) => "UNID SPHE".into(),
        },
        w => w.into(),
    })
}

/// OPTI INCO: new primal/dual component names, as two LISTMOTS or two words.
fn inco(it: &mut Interp, a: &mut Args) -> Result<()> {
    let (primal, dual) = match a.opt::<Rc<Vec<String>>>() {
        Some(p) => (p.to_vec(), a.req::<Rc<Vec<String>>>()?.to_vec()),
        None => {
            let p = a.word().ok_or_else(|| a.missing("the primal name (MOT or LISTMOTS)"))?;
            let d = a.word().ok_or_else(|| a.missing("the dual name"))?;
            (vec![p], vec![d])
        }
    };
    if primal.is_empty() || primal.len() != dual.len() {
        return Err(a.err("INCO: the primal and dual names must be two non-empty lists of the same length"));
    }
    if let Some(n) = primal.iter().chain(&dual).find(|n| n.chars().count() > 4) {
        return Err(a.err(format!("INCO: component names have 4 characters at most, found {}", n)));
    }
    let (mut p0, mut d0) = user_incos(it);
    for (p, d) in primal.into_iter().zip(dual) {
        let (p, d) = (p.to_uppercase(), d.to_uppercase());
        if !p0.contains(&p) {
            p0.push(p);
            d0.push(d);
        }
    }
    it.opts.kept.insert("INCO", Value::ListMots(Rc::new(p0)));
    it.opts.kept.insert("INCO DUAL", Value::ListMots(Rc::new(d0)));
    Ok(())
}

fn user_incos(it: &Interp) -> (Vec<String>, Vec<String>) {
    let list = |k| match it.opts.kept.get(k) {
        Some(Value::ListMots(l)) => l.to_vec(),
        _ => Vec::new(),
    };
    (list("INCO"), list("INCO DUAL"))
}

/// Every primal name gibi knows with its dual, then those of OPTI INCO.
fn incos(it: &Interp) -> (Vec<String>, Vec<String>) {
    let mut primal: Vec<String> = super::dofs::known_primals().iter().map(|s| s.to_string()).collect();
    let mut dual: Vec<String> = primal.iter().map(|p| super::dofs::dual_of(p)).collect();
    let (p, d) = user_incos(it);
    primal.extend(p);
    dual.extend(d);
    (primal, dual)
}
