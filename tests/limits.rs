//! The README's "Limits and guarantees", through the library: deep
//! structures never overflow the stack, whether built in one run or
//! entry by entry as the REPL does.

use gibi::{Capture, Interpreter};

/// The REPL runs each entry with `run_str` on one session: a chain built
/// in one entry is released by a reassignment in a later one (the crash
/// used to come there, and took every object with it).
#[test]
fn deep_table_chain_across_entries() {
    let out = Capture::default();
    let mut g = Interpreter::builder().output(out.clone()).build();
    g.run_str("<repl#1>", "t = table ; t . 'FOND' = 1 ; k = 5 ;").unwrap();
    g.run_str("<repl#2>", "repeter b 100000 ; n = table ; n . 'X' = t ; t = n ; fin b ;").unwrap();
    g.run_str("<repl#3>", "c = copi 'RECU' t ; list t ;").unwrap();
    g.run_str("<repl#4>", "t = 1 ;").unwrap();
    g.run_str("<repl#5>", "c = 2 ; n = 3 ;").unwrap();
    assert_eq!(g.get_f64("k"), Some(5.0));
    assert_eq!(g.get_f64("c"), Some(2.0));
    assert!(out.text().contains("'X' -> <TABLE>"), "{}", out.text());
    // The session itself going away releases everything too.
    g.run_str("<repl#6>", "repeter b 100000 ; n = table ; n . t = 1 ; t = n ; fin b ;").unwrap();
    drop(g);
}

/// Operators that can overflow say so, by name, at their line: no
/// infinity or NaN reaches an object (a NaN passes every `SI (x > tol)`).
#[test]
fn overflowing_operators_are_named() {
    for (src, op) in [
        ("x = somm (prog 1.e308 1.e308) ;", "SOMM"),
        ("l = prog 1.e300 pas 1.e307 npas 30 ;", "PROG"),
        ("ev = evol manu 'X' (prog 0. 1.e308) 'Y' (prog 1.e308 1.e308) ; i = intg ev ;", "INTG"),
        ("opti dime 2 ; p = 1.e308 1.e308 ; d = dist p (-1.e308 -1.e308) ;", "DIST"),
        ("opti dime 2 elem seg2 ; l = droi 2 (0. 0.) (1.e308 0.) ;", "DROI"),
        (
            "opti dime 2 elem seg2 ; l = droi 2 (0. 0.) (1. 0.) ; m = l plus (1.e308 0.) ; n = m plus (1.e308 0.) ;",
            "PLUS",
        ),
    ] {
        let mut g = Interpreter::new();
        let e = g.run_str("t", src).expect_err(src);
        assert!(e.message.starts_with(&format!("{}: ", op)), "{}: {}", src, e.message);
        assert!(e.span.is_some(), "{}", src);
    }
}

/// RESO refuses non-finite data. No operator makes any, so they can only
/// come from the host (`Interpreter::set`).
#[test]
fn reso_refuses_non_finite_data_from_the_host() {
    use gibi::value::{Chpoint, Nature};
    use gibi::Value;
    use std::rc::Rc;
    let deck = "opti dime 2 elem seg2 mode plan cont ; p0 = 0. 0. ; p1 = 2. 0. ; l = droi 4 p0 p1 ;
        mo = mode l mecanique elastique barr ; cl = (bloq 'UX' p0) et (bloq 'UY' l) ;
        k = (rigi mo (mate mo youn 1. nu 0.3 sect 1.)) et cl ; d = depi cl 0.5 ;";
    let session = || {
        let mut g = Interpreter::new();
        g.run_str("setup", deck).unwrap();
        g
    };
    let tip = |g: &Interpreter| match g.get("P1") {
        Some(Value::Point(n)) => n,
        v => panic!("{:?}", v),
    };
    // A load of +infinity.
    let mut g = session();
    let f = Chpoint::from_entries(Nature::Discret, [(tip(&g), "FX", f64::INFINITY)]);
    g.set("F", Value::Chpo(Rc::new(f)));
    let e = g.run_str("t", "u = reso k f ;").unwrap_err();
    assert!(e.message.contains("RESO: the loads hold an overflow"), "{}", e.message);
    // An imposed value that is NaN.
    let mut g = session();
    let d: Rc<Chpoint> = g.get_as("D").unwrap();
    let nan = Chpoint::from_entries(Nature::Discret, d.entries().map(|(n, c, _)| (n, c, f64::NAN)));
    g.set("D", Value::Chpo(Rc::new(nan)));
    let e = g.run_str("t", "u = reso k d ;").unwrap_err();
    assert!(e.message.contains("RESO: the imposed values hold an undefined value (NaN)"), "{}", e.message);
    // A matrix term that is NaN.
    let mut g = session();
    let k: Rc<gibi::value::Rigidite> = g.get_as("K").unwrap();
    let mut k = (*k).clone();
    k.cache = Default::default();
    k.blocks[0].mats[0] = f64::NAN;
    g.set("K", Value::Rigi(Rc::new(k)));
    let e = g.run_str("t", "u = reso k d ;").unwrap_err();
    assert!(e.message.contains("RESO: the matrix holds an undefined value (NaN)"), "{}", e.message);
}

/// No literal or operator makes an infinity, but a host can hand one in
/// (`Interpreter::set`): arithmetic refuses it and names the operation,
/// on the evaluator's fast path (numbers only) as through the operator.
#[test]
fn arithmetic_refuses_an_infinite_operand_from_the_host() {
    for src in ["y = x - x ;", "y = (prog 1.) * (x - x) ;"] {
        let mut g = Interpreter::new();
        g.set("X", f64::INFINITY);
        let e = g.run_str("t", src).unwrap_err();
        assert!(e.message.starts_with("-: inf - inf has no value: an operand is not a finite number"), "{}", e.message);
        assert!(e.span.is_some(), "{}", src);
        assert!(g.get("Y").is_none(), "{}", src);
    }
}

/// A syntax error on a 1.3 MB line shows a window around the column, not
/// the line and a caret line as long; control characters are escaped.
#[test]
fn error_excerpts_are_clipped_and_escaped() {
    let line = format!("x = {} (2 ;", "1 + ".repeat(330_000));
    let mut g = Interpreter::new();
    let e = g.run_str("long", &format!("y = 1 ;\n{}\n", line)).unwrap_err();
    let r = e.render();
    assert!(r.starts_with(&format!("long:2:{}: syntax error", line.len())), "{}", &r[..100]);
    assert!(r.len() < 1000, "{} bytes", r.len());
    assert!(r.contains("… + 1 + 1"), "{}", r);
    // The caret is under the ';' that closes nothing.
    let lines: Vec<&str> = r.lines().collect();
    let (shown, marks) = (lines[2], lines[3]);
    assert_eq!(marks.find('^').and_then(|i| shown.chars().nth(i)), Some(';'), "{}", r);

    // Text from the deck in the message, the line and the file name.
    let mut g = Interpreter::new();
    let e = g.run_str("deck\x07.dgibi", "w = extr 'a\x1b]0;T\x07' \x1b[2J ;").unwrap_err();
    let r = e.render();
    assert!(!r.chars().any(|c| c.is_control() && c != '\n'), "{:?}", r);
    assert!(r.contains("deck\\x07.dgibi:1:") && r.contains("\\x1B[2J"), "{}", r);
    // The caret still points at the operator, after escaped characters too.
    let e = g.run_str("t", "w = '\x1b\x1b' ; x = extr w 'a' ;").unwrap_err();
    let r = e.render();
    let lines: Vec<&str> = r.lines().collect();
    let at = lines[3].find('^').map(|i| lines[2].chars().skip(i).take(4).collect::<String>());
    assert_eq!(at.as_deref(), Some("extr"), "{}", r);
    assert!(!format!("{}", e).chars().any(|c| c.is_control()));
}
