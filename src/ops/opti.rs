//! OPTI and VALE: Cast3M's general options (opti.notice, vale.notice).
//!
//! Every option of the notices is accepted, read with the type the notice
//! gives it, and kept, so that VALE returns it. An option acts where gibi
//! has the matching feature: DIME, ELEM, MODE, DENS, ECHO, RESO and ERRE
//! drive the evaluator and the operators; SORT and FTRA name the files
//! SORT 'VTK', TRAC and DESS write; TRAC picks the picture format; EPTR is
//! the line width of TRAC's drawings. The others (graphics fonts, logical
//! units, parallelism, memory) only keep their value. An option the
//! notices do not know is an error.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::Value;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "OPTI",
        signature: "OPTI KEY VALUE (KEY VALUE …), KEY one of ACQU ASSI CADR COSC COUL DEBU DENS DIME DONN ECHO \
                    ELEM EPSI EPTR ERRE FTRA GRAN IMPI IMPR INCO ISOV LANG LECT LOCA MODE NAVI NBP NGMA NIVE NORM \
                    OEIL OMBR PARA PETI PLAC POIN POLI POTR PREC RESO REST SAUV SORT SURV TRAC VERI ZERO",
        doc: "Set general options. Every Cast3M option is accepted and kept for VALE; DIME, ELEM, MODE, DENS, ECHO, \
              RESO, ERRE, SORT, FTRA, TRAC and EPTR act on gibi.",
        example: "opti dime 2 elem qua4 mode plan cont ;",
        f: opti,
    },
    OpDef {
        name: "VALE",
        signature: "VALE KEY (a KEY of OPTI, and ERMA) | VALE 'MODE' 'FOUR' | VALE 'POIN' OBJ1 …",
        doc: "The value of an option (as OPTI set it, else its default); VALE 'POIN' gives an identity number per \
              object (-3 for numbers, words and logicals).",
        example: "tol = (vale prec) ** 0.5 ;",
        f: vale,
    },
];

/// How an option's value is read.
#[derive(Clone, Copy)]
enum Arg {
    /// An ENTIER in a range.
    Int(i64, i64),
    /// A FLOTTANT (an ENTIER is accepted).
    Num,
    Bool,
    /// One of these words (4-letter match), kept as the table writes it.
    Choice(&'static [&'static str]),
    /// Any word.
    Word,
    /// A logical unit (ENTIER) or a file name; then 'NOUV' or 'SUIT'.
    Unit,
    /// Handled by its own code below.
    Own,
}

/// The default value VALE gives before any OPTI.
#[derive(Clone, Copy)]
enum Dflt {
    Int(i64),
    Num(f64),
    Mot(&'static str),
    Bool(bool),
}

struct Opt {
    key: &'static str,
    arg: Arg,
    default: Dflt,
}

const fn opt(key: &'static str, arg: Arg, default: Dflt) -> Opt {
    Opt { key, arg, default }
}

const DEVICES: &[&str] = &["BENS", "X", "IBM", "GKS", "PHIG", "OPEN", "PS", "MIF", "PSC", "SVG", "PNG"];
const COLOURS: &[&str] = &[
    "DEFA", "BLEU", "ROUG", "ROSE", "JAUN", "VERT", "TURQ", "BLAN", "NOIR", "AZUR", "ORAN", "VIOL", "OCEA", "CYAN",
    "OLIV", "GRIS",
];
const STRAINS: &[&str] = &["LINEAIRE", "QUADRATIQUE", "TRUESDELL", "JAUMANN", "UTILISATEUR"];
const FONTS: &[&str] = &["8_BY_13", "9_BY_15", "TIMES_10", "TIMES_24", "HELV_10", "HELV_12", "HELV_18"];
const PS_FONTS: &[&str] = &[
    "COURIER_12",
    "HELVETICA_12",
    "TIMES_12",
    "COURIER_14",
    "HELVETICA_14",
    "TIMES_14",
    "COURIER_16",
    "HELVETICA_16",
    "TIMES_16",
    "COURIER_18",
    "HELVETICA_18",
    "TIMES_18",
];
const NAVIER: &[&str] = &["LICE", "LIMS", "LBMS", "MCCE", "MCP1", "MCMS", "QFCE", "QFP1", "QFMS"];

/// Cast3M's options (opti.notice), in the notice's order.
const OPTIONS: &[Opt] = &[
    opt("ACQU", Arg::Unit, Dflt::Int(9)),
    opt("ASSI", Arg::Int(0, 64), Dflt::Int(0)),
    opt("CADR", Arg::Num, Dflt::Num(30.0)),
    opt("COSC", Arg::Choice(&["NOIR", "BLAN", "JAUN"]), Dflt::Mot("NOIR")),
    opt("COUL", Arg::Choice(COLOURS), Dflt::Mot("DEFA")),
    opt("DEBU", Arg::Int(i64::MIN, i64::MAX), Dflt::Int(0)),
    opt("DENS", Arg::Own, Dflt::Num(0.0)),
    opt("DIME", Arg::Own, Dflt::Int(0)),
    opt("DONN", Arg::Unit, Dflt::Int(5)),
    opt("ECHO", Arg::Own, Dflt::Int(0)),
    opt("ELEM", Arg::Own, Dflt::Mot("")),
    opt("EPSI", Arg::Choice(STRAINS), Dflt::Mot("QUADRATIQUE")),
    opt("EPTR", Arg::Int(0, i64::MAX), Dflt::Int(1)),
    opt("ERRE", Arg::Own, Dflt::Mot("NORMAL")),
    opt("ERMA", Arg::Own, Dflt::Int(0)),
    opt("FTRA", Arg::Own, Dflt::Mot("")),
    opt("GRAN", Arg::Own, Dflt::Num(1e300)),
    opt("IMPI", Arg::Int(i64::MIN, i64::MAX), Dflt::Int(0)),
    opt("IMPR", Arg::Unit, Dflt::Int(6)),
    opt("INCO", Arg::Own, Dflt::Int(0)),
    opt("ISOV", Arg::Choice(&["LIGNE", "SURFACE", "SULI"]), Dflt::Mot("SURFACE")),
    opt("LANG", Arg::Word, Dflt::Mot("FRAN")),
    opt("LECT", Arg::Unit, Dflt::Int(4)),
    opt("LOCA", Arg::Bool, Dflt::Bool(false)),
    opt("MODE", Arg::Own, Dflt::Mot("")),
    opt("NAVI", Arg::Choice(NAVIER), Dflt::Mot("LICE")),
    opt("NBP", Arg::Own, Dflt::Int(0)),
    opt("NGMA", Arg::Int(0, i64::MAX), Dflt::Int(100000)),
    opt("NIVE", Arg::Int(i64::MIN, i64::MAX), Dflt::Int(9)),
    opt("NORM", Arg::Own, Dflt::Int(0)),
    opt("OEIL", Arg::Own, Dflt::Int(0)),
    opt("OMBR", Arg::Bool, Dflt::Bool(true)),
    opt("PARA", Arg::Bool, Dflt::Bool(false)),
    opt("PLAC", Arg::Int(i64::MIN, i64::MAX), Dflt::Int(0)),
    opt("POLI", Arg::Choice(FONTS), Dflt::Mot("8_BY_13")),
    opt("POTR", Arg::Choice(PS_FONTS), Dflt::Mot("COURIER_14")),
    opt("RESO", Arg::Own, Dflt::Mot("DIRECTE")),
    opt("REST", Arg::Own, Dflt::Int(2)),
    opt("SAUV", Arg::Own, Dflt::Int(8)),
    opt("SORT", Arg::Unit, Dflt::Int(7)),
    opt("SURV", Arg::Int(i64::MIN, i64::MAX), Dflt::Int(0)),
    opt("TRAC", Arg::Choice(DEVICES), Dflt::Mot("BENS")),
    opt("VERI", Arg::Int(i64::MIN, i64::MAX), Dflt::Int(0)),
    opt("ZERO", Arg::Int(i64::MIN, i64::MAX), Dflt::Int(4)),
    opt("PETI", Arg::Own, Dflt::Num(1e-300)),
    opt("PREC", Arg::Own, Dflt::Num(f64::EPSILON)),
    opt("POIN", Arg::Own, Dflt::Int(0)),
];

fn keys() -> Vec<&'static str> {
    OPTIONS.iter().map(|o| o.key).collect()
}

fn find(key: &str) -> &'static Opt {
    OPTIONS.iter().find(|o| o.key == key).expect("a key of the table")
}

fn opti(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let keys = keys();
    while let Some(k) = a.keyword(&keys) {
        let o = find(k);
        match o.arg {
            Arg::Own => super::opti_own::set(it, a, k)?,
            arg => {
                let v = read(a, k, arg)?;
                it.opts.kept.insert(k, v);
            }
        }
    }
    if a.peek_right().is_some() {
        return Err(a.err(format!("unknown option: {}", a.describe_next())));
    }
    Ok(vec![])
}

/// The value of a table-driven option, checked.
fn read(a: &mut Args, key: &str, arg: Arg) -> Result<Value> {
    Ok(match arg {
        Arg::Int(lo, hi) => {
            let n = a.req::<i64>()?;
            if !(lo..=hi).contains(&n) {
                return Err(a.err(format!("{} {} is out of range", key, n)));
            }
            Value::Int(n)
        }
        Arg::Num => Value::Float(a.req_num()?),
        Arg::Bool => Value::Bool(a.req::<bool>()?),
        Arg::Choice(choices) => {
            let w = a.word().ok_or_else(|| a.missing(&format!("one of {}", choices.join(" "))))?.to_uppercase();
            match choose(&w, choices) {
                Some(c) => Value::mot(c),
                None => return Err(a.err(format!("{} {}: expected one of {}", key, w, choices.join(" ")))),
            }
        }
        Arg::Word => Value::mot(&a.word().ok_or_else(|| a.missing("a word"))?),
        Arg::Unit => match a.opt_right::<i64>() {
            Some(n) if n <= 0 => return Err(a.err(format!("{}: a logical unit is positive, found {}", key, n))),
            Some(n) => Value::Int(n),
            None => {
                let file = a.word().ok_or_else(|| a.missing("a logical unit or a file name"))?;
                a.keyword_next(&["NOUV", "SUIT"]);
                Value::mot(&file)
            }
        },
        Arg::Own => unreachable!("read by opti_own"),
    })
}

/// The choice a word names: itself, else a choice that it begins or that
/// begins it, 4 letters at least ('SURF' and 'SURFACES' for SURFACE), else
/// a short choice by its 4 letters. Long choices differ past their 4th
/// letter (HELVETICA_12, HELVETICA_14): neither begins the other.
pub(super) fn choose(word: &str, choices: &[&'static str]) -> Option<&'static str> {
    let long = |c: &&&str| word.len() >= 4 && c.len() >= 4 && (c.starts_with(word) || word.starts_with(**c));
    choices
        .iter()
        .find(|c| **c == word)
        .or_else(|| choices.iter().find(long))
        .or_else(|| choices.iter().find(|c| c.len() <= 4 && super::args::keyword_matches(word, c)))
        .copied()
}

fn vale(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let keys = keys();
    let k = a.req_keyword(&keys)?;
    let o = find(k);
    if let Arg::Own = o.arg {
        return super::opti_own::get(it, a, k);
    }
    let v = match (it.opts.kept.get(k), o.arg) {
        // A unit option given a file name still reports its unit.
        (Some(Value::Mot(_)), Arg::Unit) | (None, _) => default(o.default),
        (Some(v), _) => v.clone(),
    };
    Ok(vec![v])
}

fn default(d: Dflt) -> Value {
    match d {
        Dflt::Int(i) => Value::Int(i),
        Dflt::Num(x) => Value::Float(x),
        Dflt::Mot(m) => Value::mot(m),
        Dflt::Bool(b) => Value::Bool(b),
    }
}

/// The default of an option handled by its own code.
pub(super) fn default_of(key: &str) -> Value {
    default(find(key).default)
}

/// VALE 'POIN': an identity number per object (Cast3M gives the pointer
/// of its memory segment; numbers, words and logicals have none: -3).
pub(super) fn pointer(v: &Value) -> i64 {
    fn addr<T: ?Sized>(r: &Rc<T>) -> i64 {
        (Rc::as_ptr(r) as *const () as usize as i64) & i64::MAX
    }
    match v {
        Value::Int(_) | Value::Float(_) | Value::Mot(_) | Value::Bool(_) => -3,
        Value::Point(p) => *p as i64 + 1,
        Value::ListReel(r) => addr(r),
        Value::ListEnti(r) => addr(r),
        Value::ListMots(r) => addr(r),
        Value::Table(r) => addr(r),
        Value::Proc(r) => addr(r),
        Value::Bloc(r) => addr(r),
        Value::Mesh(r) => addr(r),
        Value::Chpo(r) => addr(r),
        Value::ListChpo(r) => addr(r),
        Value::Rigi(r) => addr(r),
        Value::Model(r) => addr(r),
        Value::Mchaml(r) => addr(r),
        Value::Evol(r) => addr(r),
        Value::Charge(r) => addr(r),
        Value::Nuage(r) => addr(r),
        Value::Host(r) => addr(r),
    }
}
