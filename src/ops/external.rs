//! EXTE: run a program of the host, feed it values, read back its results
//! (exte.notice).
//!
//! The host decides whether the program may run ([`CommandPolicy`]; the
//! library and the CLI run none unless told). The command is split on
//! blanks and started directly, never through a shell: its first word is
//! the program the policy checks, the others are its arguments. The
//! values after the command are written on its standard input, separated
//! by blanks, 'RC' starting a new line; every blank-separated word of its
//! standard output is a result (ENTIER, FLOTTANT or MOT), in a TABLE
//! indexed from 1. A program that cannot be found gives an empty TABLE,
//! as the notice says.
//!
//! [`CommandPolicy`]: crate::eval::CommandPolicy

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::tokens::TokKind;
use crate::eval::{interrupted, FilePolicy, Interp};
use crate::value::{Key, Table, Value};
use std::cell::RefCell;
use std::io::{Read, Write};
use std::process::{Command, Stdio};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "EXTE",
    signature: "EXTE MOT (ENTIER | FLOTTANT | MOT | LISTENTI | LISTREEL | TABLE | 'RC') …",
    doc: "Run the program the MOT names (with its arguments; no shell) if the host allows it, write the values that \
          follow on its standard input ('RC' starts a new line, a TABLE gives its entries 1, 2, …), and return its \
          standard output as a TABLE of numbers and words indexed from 1 (empty when the program does not exist).",
    example: "opti erre 'IGNORE' ; t = exte 'bc' 1 + 2 'RC' ;",
    f: exte,
}];

fn exte(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mut toks = a.take_rest().into_iter();
    let command = match toks.next().map(|t| t.kind) {
        Some(TokKind::Val(Value::Mot(s))) | Some(TokKind::Quoted(s)) => s.to_string(),
        Some(TokKind::Val(v)) => return Err(a.err(format!("expected the command (MOT), found {}", v.type_name()))),
        _ => return Err(a.missing("the command to run (MOT)")),
    };
    let mut words = command.split_whitespace();
    let program = words.next().ok_or_else(|| a.err("the command is empty"))?.to_string();
    let arguments: Vec<String> = words.map(String::from).collect();
    let mut input = String::new();
    for t in toks {
        let piece = match t.kind {
            TokKind::Quoted(s) if s.eq_ignore_ascii_case("RC") => {
                input.push('\n');
                continue;
            }
            TokKind::Quoted(s) => s.to_string(),
            TokKind::Word(w) | TokKind::Nullary { word: w, .. } => w,
            TokKind::Sym(s) => s.to_string(),
            TokKind::Val(v) => {
                as_text(&v).ok_or_else(|| a.err(format!("cannot send a {} to a command", v.type_name())))?
            }
        };
        if !(input.is_empty() || input.ends_with('\n')) {
            input.push(' ');
        }
        input.push_str(&piece);
    }
    if !(input.is_empty() || input.ends_with('\n')) {
        input.push('\n');
    }
    it.commands.check(&program)?;
    let mut cmd = Command::new(&program);
    cmd.args(&arguments).stdin(Stdio::piped()).stdout(Stdio::piped()).stderr(Stdio::piped());
    if let FilePolicy::Under(root) = &it.files {
        cmd.current_dir(root);
    }
    let mut child = match cmd.spawn() {
        Ok(c) => c,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            it.println(&format!(
                "warning: EXTE: no program '{}' on this machine: the result is an empty TABLE",
                program
            ));
            return Ok(vec![table(Table::new())]);
        }
        Err(e) => return Err(a.err(format!("cannot run '{}': {}", program, e))),
    };
    // Input and output go through threads, so that a program that writes
    // before it has read everything cannot block against us.
    let stdin = child.stdin.take();
    let feed = std::thread::spawn(move || {
        if let Some(mut s) = stdin {
            let _ = s.write_all(input.as_bytes());
        }
    });
    let drain = |pipe: Option<Box<dyn Read + Send>>| {
        std::thread::spawn(move || {
            let mut b = Vec::new();
            if let Some(mut p) = pipe {
                let _ = p.read_to_end(&mut b);
            }
            b
        })
    };
    let out = drain(child.stdout.take().map(|p| Box::new(p) as Box<dyn Read + Send>));
    let err = drain(child.stderr.take().map(|p| Box::new(p) as Box<dyn Read + Send>));
    let status = loop {
        match child.try_wait() {
            Ok(Some(s)) => break s,
            Ok(None) if it.interrupt.is_pending() => {
                let _ = child.kill();
                let _ = child.wait();
                return Err(interrupted());
            }
            Ok(None) => std::thread::sleep(std::time::Duration::from_millis(5)),
            Err(e) => return Err(a.err(format!("waiting for '{}': {}", program, e))),
        }
    };
    let _ = feed.join();
    let out = out.join().unwrap_or_default();
    let err = err.join().unwrap_or_default();
    if !status.success() {
        let why = String::from_utf8_lossy(&err);
        let first = why.lines().next().unwrap_or("").trim();
        it.println(&format!(
            "warning: EXTE: '{}' ended with {}{}{}",
            program,
            status,
            if first.is_empty() { "" } else { ": " },
            first
        ));
    }
    let mut t = Table::new();
    for (i, w) in String::from_utf8_lossy(&out).split_whitespace().enumerate() {
        t.set(Key::Int(i as i64 + 1), word_value(w));
    }
    Ok(vec![table(t)])
}

fn table(t: Table) -> Value {
    Value::Table(Rc::new(RefCell::new(t)))
}

/// A word of the program's output as Gibiane reads it.
fn word_value(w: &str) -> Value {
    if let Ok(i) = w.parse::<i64>() {
        return Value::Int(i);
    }
    match w.parse::<f64>() {
        Ok(x) if x.is_finite() && w.chars().any(|c| c.is_ascii_digit()) => Value::Float(x),
        _ => Value::mot(w),
    }
}

/// A value as the text written on the program's input.
fn as_text(v: &Value) -> Option<String> {
    let join = |items: Vec<String>| items.join(" ");
    Some(match v {
        Value::Int(i) => i.to_string(),
        Value::Float(x) => x.to_string(),
        Value::Mot(s) => s.to_string(),
        Value::Bool(b) => if *b { "VRAI" } else { "FAUX" }.into(),
        Value::ListReel(l) => join(l.iter().map(|x| x.to_string()).collect()),
        Value::ListEnti(l) => join(l.iter().map(|x| x.to_string()).collect()),
        Value::ListMots(l) => join(l.iter().map(|x| x.to_string()).collect()),
        Value::Table(t) => {
            let t = t.borrow();
            let mut items = Vec::new();
            let mut k = 1;
            while let Some(v) = t.get(&Key::Int(k)) {
                items.push(as_text(v)?);
                k += 1;
            }
            join(items)
        }
        _ => return None,
    })
}
