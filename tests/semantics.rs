//! The semantics a Cast3M user relies on (language.md §2, §10), each
//! asserted on real values.

use gibi::{Capture, Interpreter, Value};

fn run(src: &str) -> Interpreter {
    let mut g = Interpreter::new();
    if let Err(e) = g.run_str("t", src) {
        panic!("{}\n{}", src, e.render());
    }
    g
}

fn num(g: &Interpreter, n: &str) -> f64 {
    g.get_f64(n).unwrap_or_else(|| panic!("{} is not a number: {:?}", n, g.get(n)))
}

#[test]
fn no_precedence() {
    let g = run("a = 1 + 2 * 3 ; b = 10 - 4 / 2 ; c = 2 ** 3 - 1 ;");
    assert_eq!(num(&g, "a"), 9.0);
    assert_eq!(num(&g, "b"), 3.0);
    assert_eq!(num(&g, "c"), 7.0);
}

#[test]
fn integer_division_truncates_and_mixing_gives_float() {
    let g = run("a = 7 / 2 ; b = 7 / 2. ; c = -7 / 2 ;");
    assert!(matches!(g.get("a"), Some(Value::Int(3))));
    assert!(matches!(g.get("b"), Some(Value::Float(f)) if f == 3.5));
    assert!(matches!(g.get("c"), Some(Value::Int(-3))));
}

#[test]
fn arguments_on_either_side() {
    let g = run("a = (2. - 5.) abs ; b = abs (2. - 5.) ; c = '-' 10 4 ; l = prog 3. 8. 1. ; d = l maxi ;");
    assert_eq!(num(&g, "a"), 3.0);
    assert_eq!(num(&g, "b"), 3.0);
    assert_eq!(num(&g, "c"), 6.0);
    assert_eq!(num(&g, "d"), 8.0);
}

#[test]
fn leftover_numbers_make_a_point() {
    let g = run("opti dime 2 ; p = 1. 2. ; x y = coor p ; q = (3 4) ;");
    assert_eq!((num(&g, "x"), num(&g, "y")), (1.0, 2.0));
    assert_eq!(g.point_coords(&g.get("q").unwrap()), Some([3.0, 4.0, 0.0]));
    let mut g = Interpreter::new();
    let e = g.run_str("t", "p = 1. 2. ;").unwrap_err();
    assert!(e.message.contains("OPTI DIME"), "{}", e.message);
}

#[test]
fn word_versus_object() {
    let g = run("m = toto ; toto = 3 ; n = toto ; q = 'toto' ;");
    assert_eq!(g.get("m").unwrap().as_mot(), Some("TOTO"));
    assert_eq!(num(&g, "n"), 3.0);
    assert_eq!(g.get("q").unwrap().as_mot(), Some("toto"));
}

#[test]
fn four_letter_matching() {
    let g = run("a = maximum (prog 1. 5.) ; b = MAXI (prog 1. 5.) ; opti dimension 2 ; c = vale dime ;");
    assert_eq!(num(&g, "a"), 5.0);
    assert_eq!(num(&g, "b"), 5.0);
    assert_eq!(num(&g, "c"), 2.0);
}

#[test]
fn sign_rule_in_evaluation() {
    let g = run("a = 5 ; b = a-1 ; c = a - 1 ; crit = 2. ; d = crit*-1 ; l = prog 1. -2. ;");
    assert_eq!(num(&g, "b"), 4.0);
    assert_eq!(num(&g, "c"), 4.0);
    assert_eq!(num(&g, "d"), -2.0);
    assert!(matches!(g.get("l"), Some(Value::ListReel(l)) if *l == vec![1.0, -2.0]));
    let mut g = Interpreter::new();
    // `a -1` is two operands: two results for one name.
    assert!(g.run_str("t", "a = 5 ; b = a -1 ;").is_err());
}

#[test]
fn procedure_scope_is_read_only() {
    let g = run("a = 9 ; debproc f x*flottant ; a = 1000 ; y = x + a ; finproc y ;\n\
         r = f 1. ; s = a ;");
    assert_eq!(num(&g, "r"), 1001.0);
    assert_eq!(num(&g, "s"), 9.0);
}

#[test]
fn procedure_arguments_by_type_on_both_sides() {
    let g = run("debproc modulo a*entier b*entier ; r = a - (a / b * b) ; finproc r ;\n\
         k = 8 modulo 3 ; l = modulo 8 3 ;\n\
         debproc opt x*flottant n/entier ; si (non (exis n)) ; n = 2 ; finsi ; finproc (x * n) ;\n\
         m = opt 3. ; o = opt 3. 5 ;");
    assert_eq!(num(&g, "k"), 2.0);
    assert_eq!(num(&g, "l"), 2.0);
    assert_eq!(num(&g, "m"), 6.0);
    assert_eq!(num(&g, "o"), 15.0);
}

#[test]
fn respro_argu_and_quitter_out_of_a_procedure() {
    let g =
        run("debproc p ; argu x*entier ; respro (x + 1) ; si (x > 0) ; quitter p ; finsi ; respro 99 ; finproc ;\n\
         a = p 5 ; b c = p -1 ;");
    assert_eq!(num(&g, "a"), 6.0);
    assert_eq!((num(&g, "b"), num(&g, "c")), (0.0, 99.0));
}

#[test]
fn tables_alias_and_keys_of_several_types() {
    let g = run("t = table ; t . 'K' = 2.5 ; t . 1 = 'UN' ; t2 = t ; t2 . 2 = 7 ; t3 = tabl t ; t3 . vrai = 1 ;\n\
         a = t . 2 ; b = t.1 ; i = 2 ; c = t . i ; d = dime t ; s = tabl 'VECTEUR' ; e = s . 'SOUSTYPE' ;\n\
         u = table ; u . 'A' = table ; u . 'A' . 3 = 4. ; f = u . 'A' . 3 ;");
    assert_eq!(num(&g, "a"), 7.0);
    assert_eq!(g.get("b").unwrap().as_mot(), Some("UN"));
    assert_eq!(num(&g, "c"), 7.0);
    assert_eq!(num(&g, "d"), 4.0);
    assert_eq!(g.get("e").unwrap().as_mot(), Some("VECTEUR"));
    assert_eq!(num(&g, "f"), 4.0);
}

#[test]
fn loop_forms() {
    let g = run("s = 0 ; repeter b 4 ; s = s + &b ; fin b ;\n\
         t = 0 ; repeter 3 c ; t = t + 1 ; fin c ;\n\
         n = 0 ; repeter d ; n = n + 1 ; si (n >eg 5) ; quitter d ; finsi ; fin d ;\n\
         z = 0 ; repeter e 0 ; z = 1 ; fin e ;\n\
         k = 0 ; repeter o 3 ; repeter i 3 ; si (&i ega 2) ; iterer i ; finsi ; k = k + 1 ; fin i ; fin o ;");
    assert_eq!(num(&g, "s"), 10.0);
    assert_eq!(num(&g, "t"), 3.0);
    assert_eq!(num(&g, "n"), 5.0);
    assert_eq!(num(&g, "z"), 0.0);
    assert_eq!(num(&g, "k"), 6.0);
}

#[test]
fn fin_ends_the_run() {
    let mut g = Interpreter::new();
    let r = g.run_str("t", "a = 1 ; si (a ega 1) ; fin ; finsi ; a = 2 ;").unwrap();
    assert_eq!(r, gibi::Outcome::Finished);
    assert_eq!(g.get_f64("a"), Some(1.0));
}

#[test]
fn erre_severities() {
    let mut g = Interpreter::new();
    assert!(g.run_str("t", "erre 0 ; a = 1 ;").is_ok());
    let e = g.run_str("t", "erre 5 ;").unwrap_err();
    assert_eq!(e.kind, gibi::ErrorKind::Abort);
    let e = g.run_str("t", "erre 'bad value' ;").unwrap_err();
    assert!(e.message.contains("bad value"));
}

#[test]
fn lists_words_and_math() {
    let g = run(
        "l = prog 0. pas 0.5 2. ; a = dime l ; m = prog 3 * 2. ; b = extr m 3 ; li = lect 1 pas 2 7 ; c = extr li 4 ;\n\
         w = mots 'UX' 'UY' ; d = extr w 2 ; e = extr 'abcdef' 2 4 ; f = 'ab' et 'cd' ;\n\
         g1 = sin 30. ; g2 = atg 1. ; g3 = enti 3.7 ; g4 = exp 0. ; n = l + 1. ; h = extr n 5 ;\n\
         q = prog 0. pas 0.5 npas 2 ; r = dime q ;",
    );
    assert_eq!(num(&g, "a"), 5.0);
    assert_eq!(num(&g, "b"), 2.0);
    assert_eq!(num(&g, "c"), 7.0);
    assert_eq!(g.get("d").unwrap().as_mot(), Some("UY"));
    assert_eq!(g.get("e").unwrap().as_mot(), Some("bcd"));
    assert_eq!(g.get("f").unwrap().as_mot(), Some("abcd"));
    assert!((num(&g, "g1") - 0.5).abs() < 1e-15);
    assert!((num(&g, "g2") - 45.0).abs() < 1e-12);
    assert_eq!(num(&g, "g3"), 3.0);
    assert_eq!(num(&g, "g4"), 1.0);
    assert_eq!(num(&g, "h"), 3.0);
    assert_eq!(num(&g, "r"), 3.0);
}

#[test]
fn comparisons_and_logic() {
    let g = run(
        "a = (1 < 2) et (2 >eg 2) ; b = non ((3 <eg 2) ou faux) ; c = 'AB  ' ega 'AB' ; d = 1 ega 1.0000001 1.e-3 ;",
    );
    for n in ["a", "b", "c", "d"] {
        assert!(matches!(g.get(n), Some(Value::Bool(true))), "{}", n);
    }
}

#[test]
fn type_exis_oubl() {
    let g = run("x = 1. ; t = type x ; e1 = exis x ; oubl x ; e2 = exis x ; l = mots 'A' 'B' ; e3 = exis l 'B' ;");
    assert_eq!(g.get("t").unwrap().as_mot(), Some("FLOTTANT"));
    assert!(matches!(g.get("e1"), Some(Value::Bool(true))));
    assert!(matches!(g.get("e2"), Some(Value::Bool(false))));
    assert!(matches!(g.get("e3"), Some(Value::Bool(true))));
}

#[test]
fn messages_go_to_the_sink() {
    let out = Capture::default();
    let mut g = Interpreter::builder().output(out.clone()).build();
    g.run_str("t", "mess 'x =' 1.5 2 vrai ; x = chai 'a' 1 ' ' 2.5 ;").unwrap();
    assert_eq!(out.text(), "x = 1.50000E+00 2 VRAI\n");
    assert_eq!(g.get("x").unwrap().as_mot(), Some("a1 2.50000E+00"));
}

#[test]
fn errors_point_at_the_operator_with_usage() {
    let mut g = Interpreter::new();
    let e = g.run_str("deck.dgibi", "a = 1 ;\nb = 2 + 'x' ;\n").unwrap_err();
    let r = e.render();
    assert!(r.starts_with("deck.dgibi:2:7: error: +: cannot combine ENTIER and MOT"), "{}", r);
    assert!(r.contains("usage: OBJ1 + OBJ2"), "{}", r);
    // Objects defined before the error survive.
    assert_eq!(g.get_f64("a"), Some(1.0));
}

#[test]
fn statements_before_a_syntax_error_run() {
    let mut g = Interpreter::new();
    let e = g.run_str("t", "a = 1 ;\nb = 'open ;\nc = 3 ;").unwrap_err();
    assert_eq!(e.kind, gibi::ErrorKind::Syntax);
    assert_eq!(g.get_f64("a"), Some(1.0));
    assert!(g.get("c").is_none());
    // Nothing after a top-level FIN is read.
    let mut g = Interpreter::new();
    assert_eq!(g.run_str("t", "a = 2 ; fin ; ceci n'est pas ( du Gibiane").unwrap(), gibi::Outcome::Finished);
    assert_eq!(g.get_f64("a"), Some(2.0));
}

/// Deep nesting is an error at the offending line, never a stack overflow
/// (this runs on a test thread's 2 MB stack).
#[test]
fn deep_nesting_is_an_error_not_a_crash() {
    let mut g = Interpreter::new();
    let si = "si vrai ;\n".repeat(16_000) + &"finsi ;\n".repeat(16_000);
    let e = g.run_str("t", &si).unwrap_err();
    assert_eq!(e.kind, gibi::ErrorKind::Syntax);
    assert_eq!(e.location().unwrap().1, gibi::syntax::MAX_BLOCK_DEPTH + 1);
    let rep: String = (0..20_000).map(|i| format!("repeter b{} 1 ;\n", i)).collect();
    assert!(g.run_str("t", &rep).unwrap_err().message.contains("nested more than"));
    let parens = format!("x = {}1{} ;", "(".repeat(50_000), ")".repeat(50_000));
    assert!(g.run_str("t", &parens).unwrap_err().message.contains("nested more than"));
    // Nesting that piles up through a recursive procedure stops at the
    // runtime limit, at the line that goes one level too deep.
    let src = format!(
        "debproc f k*entier ;\n{}\nsi (k > 0) ; r = f (k - 1) ; sinon ; r = 0 ; finsi ;\n{}\nfinproc r ;\ny = f 1000 ;",
        "si vrai ; ".repeat(90),
        "finsi ; ".repeat(90)
    );
    let e = g.run_str("t", &src).unwrap_err();
    assert!(e.message.contains("nested more than 1000 deep"), "{}", e.render());
    assert_eq!(e.location().unwrap().1, 2);
}

#[test]
fn loop_counter_outlives_its_loop() {
    let g = run("repeter b1 10 ; si (&b1 ega 4) ; quitter b1 ; finsi ; fin b1 ; n = &b1 ;\n\
         debproc p ; finproc (&o * 2) ; repeter o 3 ; r = p ; fin o ;");
    assert_eq!(num(&g, "n"), 4.0);
    assert_eq!(num(&g, "r"), 6.0);
    let mut g = Interpreter::new();
    let e = g.run_str("t", "x = &zz ;").unwrap_err();
    assert!(e.message.contains("no REPETER ZZ has run"), "{}", e.message);
}

#[test]
fn quitter_without_its_loop_is_located() {
    let mut g = Interpreter::new();
    let e = g.run_str("t", "a = 1 ;\nquitter zz ;").unwrap_err();
    assert_eq!(e.location().map(|l| (l.1, l.2)), Some((2, 1)));
    let e = g.run_str("t", "debproc p ;\n  iterer b ;\nfinproc ;\nrepeter b 2 ; x = p ; fin b ;").unwrap_err();
    assert_eq!(e.location().map(|l| (l.1, l.2)), Some((2, 3)));
    assert!(e.message.contains("inside procedure P"), "{}", e.message);
}

/// An error in a procedure body points into the text that defined it,
/// even when the call comes from another file (a procedure library).
#[test]
fn procedure_errors_point_into_their_own_file() {
    let mut g = Interpreter::new();
    g.run_str("lib.dgibi", "debproc g x*flottant ;\n  y = x + 'a' ;\nfinproc y ;\n").unwrap();
    let e = g.run_str("deck.dgibi", "* deck\nr = g 2. ;\n").unwrap_err();
    let r = e.render();
    assert!(r.starts_with("lib.dgibi:2:9: error: +"), "{}", r);
    assert!(r.contains("2 |   y = x + 'a' ;"), "{}", r);
    assert!(r.contains("= in procedure G called at deck.dgibi:2:5"), "{}", r);
    assert_eq!(r.matches("objects:").count(), 1, "{}", r);
}

/// Any operator that takes no argument is evaluated where it is met: a
/// value for an operand, still a word where an operator reads a keyword.
#[test]
fn operators_without_arguments_are_operands() {
    let mut g = Interpreter::new();
    g.register(gibi::OpSpec::host("UN", "UN", "One.", |_| Ok(vec![Value::Int(1)])));
    g.register(gibi::OpSpec::host("SUPE", "SUPE", "A name that is also a keyword of ENTI.", |_| {
        Ok(vec![Value::Int(99)])
    }));
    g.run_str("t", "x = 2 + un ; y = un + un ; i = enti 2.5 supe ; j = supe ; l = lect un 2 ;").unwrap();
    assert_eq!(num(&g, "x"), 3.0);
    assert_eq!(num(&g, "y"), 2.0);
    assert_eq!(num(&g, "i"), 3.0);
    assert_eq!(num(&g, "j"), 99.0);
    assert!(matches!(g.get("l"), Some(Value::ListEnti(l)) if *l == vec![1, 2]));
}

#[test]
fn a_mot_object_naming_an_operator_calls_it() {
    let out = Capture::default();
    let mut g = Interpreter::builder().output(out.clone()).build();
    g.run_str(
        "t",
        "ope = mot 'MESS' ; ope 'BONJOUR' ; op2 = mot 'MAXI' ; x = op2 (prog 1. 5.) ; w = mot 'UX' ; y = w ;",
    )
    .unwrap();
    assert_eq!(out.text(), "BONJOUR\n");
    assert_eq!(g.get_f64("x"), Some(5.0));
    assert_eq!(g.get("y").unwrap().as_mot(), Some("UX"));
}

/// A procedure may return more results than the caller names: the extra
/// ones are dropped (the acceptance deck 01_language relies on it:
/// `z3 = carre 2. 2 ;` with FINPROC y y2). An operator's extra result is
/// error 11 (language.md §4).
#[test]
fn extra_procedure_results_are_dropped_operator_results_are_not() {
    let g = run("debproc two2 ; finproc 1 2 ; x = two2 ;");
    assert_eq!(num(&g, "x"), 1.0);
    let mut g = Interpreter::new();
    let e = g.run_str("t", "x = 1 'a' ;").unwrap_err();
    assert!(e.message.contains("error 11"), "{}", e.message);
}

/// A MOT that names an operator, followed by an operator or by nothing,
/// is an operand: comparing a type name must not run the operator.
#[test]
fn a_mot_naming_an_operator_without_arguments_is_an_operand() {
    let g = run("opti dime 2 ; p = 0. 0. ; k = bloq 'UX' p ; ty = type k ; b = ty ega 'RIGIDITE' ; c = ty ;");
    assert!(matches!(g.get("b"), Some(Value::Bool(true))));
    assert_eq!(g.get("c").unwrap().as_mot(), Some("RIGIDITE"));
}

/// The evaluator's fast path for numeric instructions and the machine
/// agree, including the integer rules.
#[test]
fn fast_path_gives_the_answers_of_the_machine() {
    let src = "a = 7 ; b = 2. ; x1 = a / 2 * b + 1 ; x2 = (a - 10) / 2 ; x3 = 2 ** 10 ; x4 = 2 ** -1 ;\n\
               x5 = a * 1000000000 * 1000000000 * 1000 ; x6 = ((a)) ; x7 = a + b ** 2 ;";
    let mut g = Interpreter::new();
    g.run_str("t", src).unwrap();
    assert!(matches!(g.get("x1"), Some(Value::Float(f)) if f == 7.0));
    assert!(matches!(g.get("x2"), Some(Value::Int(-1))));
    assert!(matches!(g.get("x3"), Some(Value::Int(1024))));
    assert!(matches!(g.get("x4"), Some(Value::Float(f)) if f == 0.5));
    assert!(matches!(g.get("x5"), Some(Value::Float(_))));
    assert!(matches!(g.get("x6"), Some(Value::Int(7))));
    assert!(matches!(g.get("x7"), Some(Value::Float(f)) if f == 81.0));
    // A division by zero still raises the machine's error.
    assert!(g.run_str("t", "z = a / 0 ;").is_err());
}
