//! ACQUERIR: read values from the file named by OPTI ACQU into named
//! objects (acqu.notice).
//!
//! Each ACQU starts at the next record (line) of the file, as a Fortran
//! read does: what is left of the line before is skipped, and a list may
//! run over several lines. Values are separated by blanks or commas; a
//! MOT may be quoted to hold blanks. `ACQU 'BRUT'` gives the next line
//! itself, as a MOT.

use super::{Args, OpDef};
use crate::error::{Error, Result};
use crate::eval::tokens::TokKind;
use crate::eval::Interp;
use crate::value::Value;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "ACQU",
    signature: "ACQU NAME1(*TYPE1) (N1) (NAME2(*TYPE2) …), TYPE one of ENTIER FLOTTANT MOT LISTENTI LISTREEL | \
                ACQU 'BRUT'",
    doc: "Read objects from the file named by OPTI ACQU, starting at its next line, and name them: an ENTIER, a \
          FLOTTANT, a MOT (quoted if it holds blanks), or N1 numbers for a LISTENTI or LISTREEL; without a type, a \
          number or a word as written. 'BRUT': the next line as a MOT.",
    example: "opti acqu 'data.txt' ; acqu n*entier l*listreel 3 ;",
    f: acqu,
}];

/// How one object is read.
#[derive(Clone, Copy, PartialEq)]
enum Kind {
    Any,
    Int,
    Float,
    Word,
    Ints(usize),
    Floats(usize),
}

fn acqu(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let raw = a.keyword_next(&["BRUT"]).is_some();
    let mut wanted: Vec<(String, Kind)> = Vec::new();
    if !raw {
        let mut toks = a.take_rest().into_iter().peekable();
        while let Some(t) = toks.next() {
            let name = match &t.kind {
                TokKind::Word(w) => w.to_uppercase(),
                TokKind::Val(_) | TokKind::Nullary { .. } if t.named => it.source.slice(t.span).trim().to_uppercase(),
                _ => return Err(a.err("expected the name of an object to read")),
            };
            let mut kind = Kind::Any;
            if matches!(toks.peek().map(|t| &t.kind), Some(TokKind::Sym("*"))) {
                toks.next();
                let ty = match toks.next().map(|t| t.kind) {
                    Some(TokKind::Word(w) | TokKind::Nullary { word: w, .. }) => w.to_uppercase(),
                    Some(TokKind::Quoted(s)) => s.to_uppercase(),
                    Some(TokKind::Val(Value::Mot(s))) => s.to_uppercase(),
                    _ => return Err(a.err(format!("expected the type of {} after '*'", name))),
                };
                let count = |toks: &mut std::iter::Peekable<std::vec::IntoIter<crate::eval::tokens::Tok>>| match toks
                    .next()
                    .map(|t| t.kind)
                {
                    Some(TokKind::Val(Value::Int(n))) if n >= 0 => Ok(n as usize),
                    _ => Err(a.err(format!("{} is a list: give the number of values to read (ENTIER)", name))),
                };
                kind = match ty.get(..4).unwrap_or(&ty) {
                    "ENTI" => Kind::Int,
                    "FLOT" => Kind::Float,
                    "MOT" => Kind::Word,
                    "LIST" if ty.starts_with("LISTENTI") => Kind::Ints(count(&mut toks)?),
                    "LIST" if ty.starts_with("LISTREEL") => Kind::Floats(count(&mut toks)?),
                    _ => {
                        return Err(a.err(format!(
                            "{}: cannot read a {} (ENTIER, FLOTTANT, MOT, LISTENTI or LISTREEL)",
                            name, ty
                        )))
                    }
                };
            }
            wanted.push((name, kind));
        }
        if wanted.is_empty() {
            return Err(a.missing("the names of the objects to read, or 'BRUT'"));
        }
    }
    let file = match it.opts.kept.get("ACQU") {
        Some(Value::Mot(s)) => s.trim().to_string(),
        Some(Value::Int(n)) => {
            return Err(a.err(format!("OPTI ACQU names logical unit {}: gibi reads from a file named by OPTI ACQU", n)))
        }
        _ => return Err(a.err("no file to read: name it first with OPTI ACQU 'file'")),
    };
    let start = match &it.exports.acqu_read {
        Some((f, line)) if *f == file => *line,
        _ => 0,
    };
    let path = it.files.check_read(&file)?;
    let bytes = crate::io::read_file(&path).map_err(|e| Error::io(e.0))?;
    let text = crate::source::decode(&bytes);
    let lines: Vec<&str> = text.lines().collect();
    let mut r = Records { lines: &lines, line: start, col: 0, file: &file };
    if raw {
        let l = *lines.get(start).ok_or_else(|| a.err(format!("'{}' has no line {} to read", file, start + 1)))?;
        it.exports.acqu_read = Some((file.clone(), start + 1));
        return Ok(vec![Value::mot(l)]);
    }
    let mut read: Vec<(String, Value)> = Vec::new();
    for (name, kind) in wanted {
        let v = match kind {
            Kind::Ints(n) => Value::ListEnti(Rc::new((0..n).map(|_| r.int(a)).collect::<Result<_>>()?)),
            Kind::Floats(n) => Value::ListReel(Rc::new((0..n).map(|_| r.float(a)).collect::<Result<_>>()?)),
            Kind::Int => Value::Int(r.int(a)?),
            Kind::Float => Value::Float(r.float(a)?),
            Kind::Word => Value::mot(r.next(a)?),
            Kind::Any => {
                let w = r.next(a)?;
                match (w.parse::<i64>(), number(&w)) {
                    (Ok(i), _) => Value::Int(i),
                    (_, Some(x)) => Value::Float(x),
                    _ => Value::mot(w),
                }
            }
        };
        read.push((name, v));
    }
    it.exports.acqu_read = Some((file.clone(), r.line + 1));
    for (name, v) in read {
        it.store.set(&name, v);
    }
    Ok(vec![])
}

/// A number as Fortran writes it (a `D` exponent too).
fn number(w: &str) -> Option<f64> {
    let s = w.replace(['D', 'd'], "E");
    s.parse::<f64>().ok().filter(|x| x.is_finite() && s.chars().any(|c| c.is_ascii_digit()))
}

/// The values of a file, read in order across its lines.
struct Records<'a> {
    lines: &'a [&'a str],
    line: usize,
    col: usize,
    file: &'a str,
}

impl Records<'_> {
    /// The next value's text (a quoted one without its quotes).
    fn next(&mut self, a: &Args) -> Result<String> {
        loop {
            let Some(l) = self.lines.get(self.line) else {
                return Err(a.err(format!("'{}' ends before every value is read", self.file)));
            };
            let rest: Vec<char> = l.chars().skip(self.col).collect();
            let skip = rest.iter().take_while(|c| c.is_whitespace() || **c == ',').count();
            if skip == rest.len() {
                self.line += 1;
                self.col = 0;
                continue;
            }
            let body = &rest[skip..];
            if body[0] == '\'' {
                let mut out = String::new();
                let mut i = 1;
                while i < body.len() {
                    if body[i] == '\'' {
                        if body.get(i + 1) == Some(&'\'') {
                            out.push('\'');
                            i += 2;
                            continue;
                        }
                        break;
                    }
                    out.push(body[i]);
                    i += 1;
                }
                self.col += skip + i + 1;
                return Ok(out);
            }
            let n = body.iter().take_while(|c| !(c.is_whitespace() || **c == ',')).count();
            self.col += skip + n;
            return Ok(body[..n].iter().collect());
        }
    }

    fn int(&mut self, a: &Args) -> Result<i64> {
        let w = self.next(a)?;
        w.parse::<i64>()
            .map_err(|_| a.err(format!("'{}' line {}: expected an ENTIER, found '{}'", self.file, self.line + 1, w)))
    }

    fn float(&mut self, a: &Args) -> Result<f64> {
        let w = self.next(a)?;
        number(&w)
            .ok_or_else(|| a.err(format!("'{}' line {}: expected a FLOTTANT, found '{}'", self.file, self.line + 1, w)))
    }
}
