//! Bounded "no panic on random input" test (runs in CI). Longer runs use
//! the cargo-fuzz target in `fuzz/`.

use gibi::Interpreter;

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

#[test]
fn random_programs_never_panic() {
    let mut rng = Rng(0x9E3779B97F4A7C15);
    for _ in 0..3000 {
        let n = 1 + rng.next() % 40;
        let mut src = String::new();
        for _ in 0..n {
            src.push_str(rng.pick(PIECES));
            src.push(' ');
        }
        let mut g = Interpreter::builder().step_limit(10_000).build();
        let _ = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| g.run_str("fuzz", &src)))
            .unwrap_or_else(|_| panic!("panic on input: {:?}", src));
        let _ = gibi::syntax::check_complete(&src);
    }
}
