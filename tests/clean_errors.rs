//! Mistakes that used to end the process or slip through silently are
//! ordinary runtime errors (exit 70 from the CLI): every size a deck asks
//! for is checked before it is allocated, and floating results that would
//! be inf or NaN are refused.

use gibi::Interpreter;

fn fails_cleanly(src: &str, want: &str) {
    let mut g = Interpreter::new();
    let e = g.run_str("t", src).expect_err(src);
    assert!(e.message.contains(want), "{}: {}", src, e.message);
}

#[test]
fn list_counts_are_capped() {
    for src in [
        "a = prog 100000000000 * 1. ;",
        "a = lect 100000000000 * 1 ;",
        "a = prog 1. pas 1. npas 100000000000 ;",
        "a = lect 1 pas 1 npas 100000000000 ;",
        "a = lect 1 pas 1 1000000000 ;",
        "a = prog 0. pas 1.e-12 1. ;",
        "a = mots 100000000000 * UX ;",
        "a = prog 60000000 * 1. 60000000 * 1. ;",
    ] {
        fails_cleanly(src, "too many values");
    }
}

#[test]
fn joins_that_double_are_capped() {
    fails_cleanly("l = lect 1 ; repeter b 40 ; l = l et l ; fin b ;", "too many values");
    fails_cleanly("m = mot 'ab' ; repeter b 40 ; m = m et m ; fin b ;", "too many values");
}

#[test]
fn mesh_products_are_capped() {
    let pts = "opti dime 2 elem qua4 ; p1 = 0 0 ; p2 = 1 0 ; p3 = 1 1 ; p4 = 0 1 ;";
    fails_cleanly(&format!("{pts} l = droi 100000000 p1 p2 ;"), "allowed");
    fails_cleanly(&format!("{pts} l = droi 100000 p1 p2 ; s = l tran 100000 (0 1) ;"), "allowed");
    fails_cleanly(&format!("{pts} l = droi 100000 p1 p2 ; s = l rota 100000 90. p4 ;"), "allowed");
    fails_cleanly(
        &format!(
            "{pts} l1 = droi 100000 p1 p2 ; l2 = droi 100000 p2 p3 ; l3 = droi 100000 p3 p4 ; \
             l4 = droi 100000 p4 p1 ; s = dall l1 l2 l3 l4 ;"
        ),
        "allowed",
    );
}

#[test]
fn float_division_by_zero_and_nan_powers() {
    // Prefix forms go through the operators (numeric infix instructions
    // take eval's fast path).
    fails_cleanly("x = '/' 7 0. ;", "division of 7 by zero");
    fails_cleanly("x = '/' 0. 0 ;", "by zero");
    fails_cleanly("x = (prog 1. 2.) / 0. ;", "division of a LISTREEL by zero");
    fails_cleanly("x = (prog 1. 2.) / (prog 1. 0.) ;", "divides by zero");
    fails_cleanly("x = '**' (-8.) 0.5 ;", "no finite real value");
    fails_cleanly("x = (prog 4. -1.) ** 0.5 ;", "no finite real value");
    fails_cleanly("x = log (prog 1. 0.) ;", "no finite result");
    fails_cleanly("x = asin 2. ;", "no finite result");
    let mut g = Interpreter::new();
    g.run_str("t", "x = '**' (-8.) 2. ; y = (prog 4. 9.) ** 0.5 ; z = '/' 1 2. ;").unwrap();
    assert_eq!(g.get_f64("x"), Some(64.0));
    assert_eq!(g.get_f64("z"), Some(0.5));
}

/// The evaluator's fast path (purely numeric instructions) and the
/// operators (the same instruction with an operator call in it) give the
/// same error: same message and notes, at the same operator.
#[test]
fn fast_path_and_operators_give_the_same_errors() {
    for (fast, machine) in [
        ("x = 1.e308 * 10. ;", "x = 1.e308 * (flot 10) ;"),
        ("x = 7. / 0. ;", "x = 7. / (flot 0) ;"),
        ("x = 7 / 0 ;", "x = 7 / (enti 0) ;"),
        ("x = (-8.) ** 0.5 ;", "x = (-8.) ** (flot 0.5) ;"),
        ("x = 1.e309 ; y = x - x ;", "x = 1.e309 ; y = x - (flot x) ;"),
        ("x = 2 ** 5000 ;", "x = 2 ** (enti 5000) ;"),
    ] {
        let err = |src: &str| Interpreter::new().run_str("t", src).expect_err(src);
        let (f, m) = (err(fast), err(machine));
        assert_eq!(f.message, m.message, "{fast}");
        assert_eq!(f.notes, m.notes, "{fast}");
        let at = |src: &str, e: &gibi::Error| {
            let s = e.span.unwrap();
            src[s.start as usize..s.end as usize].to_string()
        };
        assert_eq!(at(fast, &f), at(machine, &m), "{fast}");
    }
}
