//! Bounded "no panic on random input" tests (run in CI). Longer runs use
//! the cargo-fuzz target in `fuzz/`.
//!
//! The evaluator turns an operator's panic into an error of kind
//! `Internal` so that a session survives it; these tests fail on any such
//! error, as on a panic that escapes. `a_panicking_operator_fails_both_checks`
//! shows that they can fail.

use gibi::{ErrorKind, FilePolicy, Interpreter, OpSpec};

/// A tiny deterministic generator (xorshift): no dependency, same inputs
/// on every run.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
    fn pick<'a>(&mut self, xs: &[&'a str]) -> &'a str {
        xs[(self.next() % xs.len() as u64) as usize]
    }
}

const PIECES: &[&str] = &[
    "a",
    "b",
    "t",
    "=",
    ";",
    "(",
    ")",
    "'",
    "''",
    "'x'",
    ".",
    "+",
    "-",
    "*",
    "/",
    "**",
    "<",
    ">EG",
    "1",
    "-2",
    "3.5",
    "1e400",
    "0",
    "prog",
    "lect",
    "mots",
    "extr",
    "dime",
    "et",
    "ou",
    "non",
    "si",
    "sinon",
    "finsi",
    "repeter",
    "fin",
    "quitter",
    "iterer",
    "debproc",
    "finproc",
    "argu",
    "respro",
    "table",
    "opti",
    "dime",
    "2",
    "3",
    "mess",
    "list",
    "coor",
    "abs",
    "maxi",
    "mini",
    "enti",
    "chai",
    "exis",
    "oubl",
    "type",
    "erre",
    "&b",
    "\n",
    "\n*",
    " ",
    "pas",
    "npas",
    "vale",
    "prec",
    "tabl",
    "log",
    "-1",
    "/0",
    "9999999999",
    "vrai",
    "faux",
    "ega",
    "neg",
    "nbno",
    "sin",
];

/// Runs one text: Ok whether it ran or failed cleanly; Err names a panic
/// or an internal error, with the input.
fn run_cleanly(g: &mut Interpreter, src: &str) -> Result<bool, String> {
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| g.run_str("fuzz", src))) {
        Err(_) => Err(format!("panic on input: {src:?}")),
        Ok(Err(e)) if e.kind == ErrorKind::Internal => Err(format!("internal error on input {src:?}: {}", e.message)),
        Ok(r) => Ok(r.is_ok()),
    }
}

/// Random texts from the pieces of Gibiane, run on fresh interpreters
/// made by `new`.
fn random_programs(new: &dyn Fn() -> Interpreter, pieces: &[&str], count: usize) -> Result<(), String> {
    let mut rng = Rng(0x9E3779B97F4A7C15);
    for _ in 0..count {
        let n = 1 + rng.next() % 40;
        let mut src = String::new();
        for _ in 0..n {
            src.push_str(rng.pick(pieces));
            src.push(' ');
        }
        run_cleanly(&mut new(), &src)?;
        let _ = gibi::syntax::check_complete(&src);
    }
    Ok(())
}

#[test]
fn random_programs_never_panic() {
    let new = || Interpreter::builder().step_limit(10_000).build();
    random_programs(&new, PIECES, 3000).unwrap_or_else(|e| panic!("{e}"));
}

// Every registered operator, called with random arguments drawn from a
// pool of objects of every type (and keywords, numbers, words), must
// answer with a value or an error, never a panic: this fuzzes the
// operators rather than the language.

/// Objects of every type, in a 2D plane-stress setting with a contact pair.
const SETUP: &str = "
opti echo 0 dime 2 elem qua4 mode plan cont ;
p1 = 0. 0. ; p2 = 1. 0. ; p3 = 1. 1. ; p4 = 0. 1. ;
l1 = droi 2 p1 p2 ; l2 = droi 2 p2 p3 ; l3 = droi 2 p3 p4 ; l4 = droi 2 p4 p1 ;
s = dall l1 l2 l3 l4 ;
mo = mode s mecanique elastique ;
ma = mate mo youn 100. nu 0.3 ;
k = rigi mo ma ;
cl = bloq 'UX' 'UY' l4 ;
cu = bloq 'MINI' 'UY' l1 ;
u = reso (k et cl) (forc 'FX' 1. p3) ;
sg = sigm mo ma u ;
ep = epsi mo ma u ;
lr = prog 1. 2. 3. ; le = lect 1 2 3 ; lm = mots 'UX' 'UY' ;
t = table ; t . 1 = 2. ;
ev = evol manu lr lr ;
ch = char 'MECA' (forc 'FX' 1. p3) ev ;
moc = mode (impo 'MAIL' l1 l3) 'CONTACT' ;
tp = tabl ; tp . 'MODELE' = mo et moc ; tp . 'CARACTERISTIQUES' = ma ;
tp . 'BLOCAGES_MECANIQUES' = cl ; tp . 'CHARGEMENT' = ch ; tp . 'TEMPS_CALCULES' = lr ;
n = 3 ; x = 2.5 ; w = 'ABCD' ; b = vrai ;
";

const POOL: &[&str] = &[
    "p1", "p3", "l1", "s", "mo", "ma", "k", "cl", "cu", "u", "sg", "ep", "lr", "le", "lm", "t", "ev", "n", "x", "w",
    "b", "ch", "moc", "tp", "'TEMP'", "'DIMP'", "0", "-1", "2", "0.", "1.e300", "'UX'", "'FX'", "'MINI'", "'MAXI'",
    "'MAIL'", "'TRAN'", "'COMP'", "'CONT'", "'CHPO'", "'ABS'", "'SOMM'", "'NOEC'", "'VALE'", "(0. 0.)", "(1. 2.)",
];

/// Operators that change the session itself (dimension, files, the end of
/// the run, object removal) rather than compute from their arguments.
const SKIP: &[&str] = &["OPTI", "FIN", "ERRE", "OUBL", "DETR", "SORT", "LIRE", "TEMP", "MENA"];

/// Each operator of `names` called 300 times with random arguments from
/// the pool; the number of calls that succeeded and of all calls.
fn random_calls(g: &mut Interpreter, names: &[String]) -> Result<(usize, usize), String> {
    let mut rng = Rng(0x2545_f491_4f6c_dd1d);
    let (mut calls, mut ok) = (0, 0);
    for name in names.iter().filter(|n| !SKIP.contains(&n.as_str())) {
        for _ in 0..300 {
            let mut src = format!("zz = {name}");
            for _ in 0..rng.below(5) {
                src.push(' ');
                src.push_str(POOL[rng.below(POOL.len())]);
            }
            src.push_str(" ;");
            ok += run_cleanly(g, &src)? as usize;
            calls += 1;
        }
    }
    Ok((ok, calls))
}

fn operator_session(extra: Option<OpSpec>) -> Interpreter {
    let mut b = Interpreter::builder().files(FilePolicy::Nothing).step_limit(100_000);
    if let Some(op) = extra {
        b = b.operator(op);
    }
    let mut g = b.build();
    g.run_str("setup", SETUP).expect("setup runs");
    g
}

#[test]
fn every_operator_survives_random_arguments() {
    let mut g = operator_session(None);
    let names: Vec<String> = g.registry().all().iter().map(|o| o.name.to_string()).collect();
    assert!(names.len() > 120, "only {} operators", names.len());
    let (ok, calls) = random_calls(&mut g, &names).unwrap_or_else(|e| panic!("{e}"));
    // The pool must make real calls, not only argument errors.
    assert!(ok * 50 > calls, "{ok} of {calls} calls succeeded");
    eprintln!("{ok} of {calls} calls succeeded");
}

/// The checks above fail when an operator panics: one that panics on a
/// FLOTTANT argument is caught by both.
#[test]
fn a_panicking_operator_fails_both_checks() {
    let boom = || {
        OpSpec::host("BOOM", "BOOM (FLOTTANT)", "Panics on a FLOTTANT.", |a| match a.opt_num() {
            Some(_) => panic!("kaboom"),
            None => Ok(vec![]),
        })
    };
    let prev = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    let new = || Interpreter::builder().step_limit(10_000).operator(boom()).build();
    let programs = random_programs(&new, &["boom", "1", "3.5", "x", ";"], 200);
    let mut g = operator_session(Some(boom()));
    let calls = random_calls(&mut g, &["BOOM".to_string()]);
    std::panic::set_hook(prev);
    let e = programs.expect_err("random programs must fail on BOOM");
    assert!(e.contains("internal error") && e.contains("kaboom"), "{e}");
    let e = calls.expect_err("random operator calls must fail on BOOM");
    assert!(e.contains("BOOM: internal error (kaboom)"), "{e}");
}
