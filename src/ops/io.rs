//! Directives that talk to the user or set options: OPTI, VALE, MESS,
//! LIST, SAUT, TITR, TEMP, ERRE. Output goes to the injected sink.

use super::{Args, OpDef};
use crate::error::{Error, ErrorKind, Result};
use crate::eval::Interp;
use crate::value::{fmt_float, list_value, Key, Table, Value};
use std::cell::RefCell;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "DENS",
        signature: "DENS x",
        doc: "Set the density (element size) given to new points, like OPTI DENS.",
        example: "dens 0.1 ;",
        f: dens,
    },
    OpDef {
        name: "OPTI",
        signature:
            "OPTI (DIME n) (ELEM type) (MODE mode) (ECHO n) (DENS x) (ERRE w) (TRAC w) (NORM w) (IMPI n) (RESO w) …",
        doc: "Set options: space dimension, element type, analysis mode, echo, density, …",
        example: "opti dime 2 elem qua4 mode plan cont ;",
        f: opti,
    },
    OpDef {
        name: "VALE",
        signature: "VALE ('PREC'|'DIME'|'MODE'|'ELEM'|'DENS'|'ECHO'|'RESO'|'EPSI')",
        doc: "The value of an option (PREC: machine precision).",
        example: "tol = (vale prec) ** 0.5 ;",
        f: vale,
    },
    OpDef {
        name: "MESS",
        signature: "MESS OBJ1 OBJ2 …",
        doc: "Print words and numbers on one line.",
        example: "mess 'u =' u ;",
        f: mess,
    },
    OpDef {
        name: "LIST",
        signature: "LIST (OBJ) | LIST ;",
        doc: "Print an object; alone, list every object.",
        example: "list u ;",
        f: list,
    },
    OpDef {
        name: "SAUT",
        signature: "SAUT (n) (LIGN|PAGE)",
        doc: "Print blank lines.",
        example: "saut 2 lign ;",
        f: saut,
    },
    OpDef {
        name: "TITR",
        signature: "TITR OBJ1 …",
        doc: "Set the title (72 characters at most).",
        example: "titr 'Cantilever' ;",
        f: titr,
    },
    OpDef {
        name: "TEMP",
        signature: "TEMP ('IMPR'|'ZERO'|'NOEC'|'SGAC')",
        doc: "Print the time spent per operator and per solver phase ('NOEC': print nothing). Also returns a TABLE: \
              'TEMPS_CPU' and 'TEMPS_HORLOGE', each a TABLE with 'INITIAL' (milliseconds since the start or the last \
              'ZERO') and 'ECOULE' (since the previous TEMP), ENTIERs. gibi has no CPU clock of its own: both are wall-clock times.",
        example: "t = temp 'NOEC' ; mess (t . 'TEMPS_HORLOGE' . 'INITIAL') ;",
        f: temp,
    },
    OpDef {
        name: "ERRE",
        signature: "ERRE n | ERRE 'text'",
        doc: "Raise an error: ERRE 0 does nothing, ERRE 5 aborts the run.",
        example: "si (err > 1.e-6) ; erre 5 ; finsi ;",
        f: erre,
    },
];

const OPTI_KEYS: &[&str] = &[
    "DIME", "ELEM", "MODE", "ECHO", "DENS", "ERRE", "TRAC", "NORM", "IMPI", "RESO", "EPSI", "SORT", "LOCA", "SAUV",
    "REST", "DONN", "LECT", "IMPR", "VERI", "PARA", "ACQU", "POTR", "CALC", "INCO", "COUL", "DEBU", "FTRA",
];

fn opti(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mut any = false;
    while let Some(k) = a.keyword(OPTI_KEYS) {
        any = true;
        match k {
            "DIME" => {
                let d = a.req::<i64>()?;
                if !(1..=3).contains(&d) {
                    return Err(a.err(format!("DIME must be 1, 2 or 3, found {}", d)));
                }
                it.opts.dime = d as usize;
                it.opts.mode = if d == 3 {
                    "TRID".into()
                } else if d == 2 {
                    "PLAN CONT".into()
                } else {
                    "UNID".into()
                };
            }
            "ELEM" => {
                let e = a.word().ok_or_else(|| a.missing("an element type"))?;
                it.opts.elem = e.to_uppercase();
            }
            "MODE" => {
                let m = a.word().ok_or_else(|| a.missing("an analysis mode"))?.to_uppercase();
                let mode = if m.starts_with("PLAN") {
                    let sub = a.req_keyword(&["CONT", "DEFO", "GENE"])?;
                    format!("PLAN {}", sub)
                } else if m.starts_with("FOUR") {
                    format!("FOUR {}", a.opt_right::<i64>().unwrap_or(0))
                } else {
                    m.chars().take(4).collect()
                };
                it.opts.mode = mode;
            }
            "ECHO" => {
                it.opts.echo = a.req::<i64>()?;
                // Remembered as given: messages that Cast3M prints by default
                // (PASAPAS's step lines) stay silent only under an explicit
                // OPTI ECHO 0, gibi's default being 0 too.
                it.opts.other.insert("ECHO".into(), it.opts.echo.to_string());
            }
            "DENS" => it.opts.dens = a.req_num()?,
            "ERRE" => it.opts.erre = a.word().ok_or_else(|| a.missing("NORMAL, FATAL, CONTROLE or IGNORE"))?,
            "RESO" => it.opts.reso = a.word().ok_or_else(|| a.missing("DIRECTE or ITERATIVE"))?.to_uppercase(),
            other => {
                // Accepted for compatibility (graphics device, scaling,
                // debug level, …): keep the value for VALE.
                let v = match a.right_any() {
                    Some(Value::Mot(s)) => s.to_string(),
                    Some(Value::Int(i)) => i.to_string(),
                    Some(Value::Float(f)) => f.to_string(),
                    Some(Value::Bool(b)) => b.to_string(),
                    _ => String::new(),
                };
                it.opts.other.insert(other.to_string(), v);
            }
        }
    }
    if !any && a.peek_right().is_some() {
        return Err(a.err(format!("unknown option: {}", a.describe_next())));
    }
    Ok(vec![])
}

fn vale(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if let Some(k) = a.keyword(&["EPSI"]) {
        // The strain measure of OPTI EPSI; gibi computes small strains.
        return Ok(vec![Value::mot(it.opts.other.get(k).map_or("LINEAIRE", |s| s.as_str()))]);
    }
    let k = a.req_keyword(&["PREC", "DIME", "MODE", "ELEM", "DENS", "ECHO", "RESO", "ERRE"])?;
    Ok(vec![match k {
        "PREC" => Value::Float(f64::EPSILON),
        "DIME" => Value::Int(it.opts.dime as i64),
        "MODE" => Value::mot(&it.opts.mode),
        "ELEM" => Value::mot(&it.opts.elem),
        "DENS" => Value::Float(it.opts.dens),
        "ECHO" => Value::Int(it.opts.echo),
        "RESO" => Value::mot(&it.opts.reso),
        _ => Value::mot(&it.opts.erre),
    }])
}

/// How MESS shows one value.
pub(crate) fn show(it: &Interp, v: &Value) -> String {
    match v {
        Value::Int(i) => i.to_string(),
        Value::Float(f) => fmt_float(*f),
        Value::Mot(s) => s.to_string(),
        Value::Bool(b) => (if *b { "VRAI" } else { "FAUX" }).to_string(),
        Value::Point(p) => {
            let x = it.nodes.get(*p);
            let d = it.opts.dime.max(1);
            x[..d].iter().map(|c| fmt_float(*c)).collect::<Vec<_>>().join(" ")
        }
        other => format!("<{}>", other.type_name()),
    }
}

/// Every remaining argument as MESS shows it.
fn shown_args(it: &Interp, a: &mut Args) -> Vec<String> {
    let mut parts = Vec::new();
    while let Some(v) = a.opt::<Value>() {
        parts.push(show(it, &v));
    }
    parts
}

fn mess(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mut parts = shown_args(it, a);
    while let Some(w) = a.word() {
        parts.push(w);
    }
    let line = parts.join(" ");
    it.println(&line);
    Ok(vec![])
}

fn list(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let name = a.next_name_span().map(|sp| it.source.slice(sp).to_uppercase());
    match a.opt::<Value>() {
        Some(v) => {
            let text = list_value(it, name.as_deref(), &v);
            it.println(&text);
        }
        None => {
            let objs = it.store.visible();
            it.println(&format!("{} object(s)", objs.len()));
            for (n, v) in objs {
                it.println(&format!("  {:<24} {}", n, v.type_name()));
            }
        }
    }
    Ok(vec![])
}

fn saut(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let n = a.opt::<i64>().unwrap_or(1).clamp(0, 1000);
    let page = a.keyword(&["LIGN", "PAGE"]) == Some("PAGE");
    let n = if page { 1 } else { n };
    for _ in 0..n {
        it.println("");
    }
    Ok(vec![])
}

fn titr(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let parts = shown_args(it, a);
    it.title = parts.join(" ").chars().take(72).collect();
    Ok(vec![])
}

fn temp(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if a.keyword(&["ZERO"]).is_some() {
        it.timers = Default::default();
        for op in it.registry.all() {
            op.reset_stats();
        }
        return Ok(vec![]);
    }
    let quiet = a.keyword(&["IMPR", "SGAC", "NOEC"]) == Some("NOEC");
    if !quiet {
        let mut lines = vec![format!("{:<10} {:>8} {:>12}", "operator", "calls", "seconds")];
        let mut ops: Vec<_> =
            it.registry.all().iter().map(|o| (o.name, o.stats())).filter(|(_, (n, _))| *n > 0).collect();
        ops.sort_by_key(|x| std::cmp::Reverse(x.1 .1));
        for (k, (n, d)) in ops {
            lines.push(format!("{:<10} {:>8} {:>12.6}", k, n, d.as_secs_f64()));
        }
        if !it.timers.phases.is_empty() {
            lines.push(format!("{:<24} {:>8} {:>12}", "solver phase", "count", "seconds"));
            for (k, (n, d)) in &it.timers.phases {
                lines.push(format!("{:<24} {:>8} {:>12.6}", k, n, d.as_secs_f64()));
            }
        }
        for l in lines {
            it.println(&l);
        }
    }
    // The clocks as a table, the form decks read timings from.
    let now = std::time::Instant::now();
    let ms = |d: std::time::Duration| Value::Int(d.as_millis() as i64);
    let clock = || {
        let mut c = Table::new();
        c.set(Key::Mot("INITIAL".into()), ms(now - it.timers.origin));
        c.set(Key::Mot("ECOULE".into()), ms(now - it.timers.last));
        Value::Table(Rc::new(RefCell::new(c)))
    };
    let mut t = Table::new();
    t.set(Key::Mot("TEMPS_CPU".into()), clock());
    t.set(Key::Mot("TEMPS_HORLOGE".into()), clock());
    it.timers.last = now;
    Ok(vec![Value::Table(Rc::new(RefCell::new(t)))])
}

/// Cast3M severities: message 0 is harmless; message 5 ("abnormal error")
/// has severity 3 and aborts. Any other number stops the deck as an error.
fn erre(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if let Some(n) = a.opt::<i64>() {
        return match n {
            0 => Ok(vec![]),
            5 => Err(Error::new(ErrorKind::Abort, "ERRE 5: the deck's own check failed (abnormal error, severity 3)")),
            n => Err(Error::runtime(format!("ERRE {}: error raised by the deck", n))),
        };
    }
    let parts = shown_args(it, a);
    if parts.is_empty() {
        return Err(a.missing("an error number or a text"));
    }
    Err(Error::runtime(format!("ERRE: {}", parts.join(" "))))
}

fn dens(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let d = a.req_num()?;
    if d < 0.0 {
        return Err(a.err(format!("a density must be positive, found {}", d)));
    }
    it.opts.dens = d;
    Ok(vec![])
}
