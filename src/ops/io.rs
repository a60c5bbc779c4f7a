//! Directives that talk to the user: DENS, MESS, LIST, SAUT, TITR, ERRE
//! (OPTI and VALE are in opti.rs, TEMP in temps.rs). Output goes to the injected sink.

use super::{Args, OpDef};
use crate::error::{Error, ErrorKind, Result};
use crate::eval::Interp;
use crate::value::{fmt_float, list_value, Value};

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "DENS",
        signature: "DENS x",
        doc: "Set the density (element size) given to new points, like OPTI DENS.",
        example: "dens 0.1 ;",
        f: dens,
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
        name: "ERRE",
        signature: "ERRE n | ERRE 'text'",
        doc: "Raise an error: ERRE 0 does nothing, ERRE 5 aborts the run.",
        example: "si (err > 1.e-6) ; erre 5 ; finsi ;",
        f: erre,
    },
];

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
    // 'RESUME' asks for a shorter listing (list.notice): it is a keyword
    // here even unquoted, where it would otherwise run the RESU operator.
    // gibi's listings are already short, so it changes nothing.
    a.keyword_next(&["RESUME"]);
    let name = a.next_name_span().map(|sp| it.source.slice(sp).to_uppercase());
    match a.opt::<Value>() {
        Some(v) => {
            let text = list_value(&it.nodes, it.opts.dime, name.as_deref(), &v);
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
