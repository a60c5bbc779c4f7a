//! The procedure library: Cast3M procedures loaded from files on first use
//! (`InterpreterBuilder::procedures`), in both of Cast3M's formats: a
//! folder of `*.procedur` files and a file of `$$$$ NAME` procedures.
//! The files are gibi's own, in tests/data/procedures.

use gibi::{Capture, Interpreter};
use std::path::PathBuf;

fn data(p: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/data/procedures").join(p)
}

fn session(paths: &[&str]) -> (Interpreter, Capture) {
    let out = Capture::default();
    let g = Interpreter::builder().output(out.clone()).procedures(paths.iter().map(|p| data(p))).build();
    (g, out)
}

#[test]
fn a_folder_of_procedur_files_loads_on_first_use() {
    let (mut g, _) = session(&["folder"]);
    g.run_str("t", "a = carre 3. ; b = hypot 3. 4. ;").unwrap();
    assert_eq!(g.get_f64("a"), Some(9.0));
    // HYPOT (a file without $$$$ lines) calls CARRE: loaded in turn.
    assert_eq!(g.get_f64("b"), Some(5.0));
    // CASSEE holds a syntax error: never read, since no deck named it.
    g.run_str("t2", "c = carre 0.5 ;").unwrap();
    assert_eq!(g.get_f64("c"), Some(0.25));
}

#[test]
fn arguments_argu_respro_comments_and_continued_lines_in_a_library_procedure() {
    let (mut g, _) = session(&["folder"]);
    // The keyword comes after the numbers: an optional argument is not
    // looked for past a word of the call (Cast3M's @POINTIR relies on it).
    g.run_str("t", "n s = cumul 1. 2. 3.5 ; m t = cumul 2. 4. 'OPPOSE' ; p = cumul 4. ;").unwrap();
    assert_eq!(g.get_f64("n"), Some(3.0));
    assert_eq!(g.get_f64("s"), Some(6.5));
    assert_eq!(g.get_f64("m"), Some(2.0));
    assert_eq!(g.get_f64("t"), Some(-6.0));
    // One name for two results: the procedure's extra result is dropped.
    assert_eq!(g.get_f64("p"), Some(1.0));
}

#[test]
fn a_dollar_file_holds_several_procedures() {
    let (mut g, _) = session(&["utilproc.txt"]);
    g.run_str("t", "a = double 2.5 ; b = triple 2. ; c = carre 3. ;").unwrap();
    assert_eq!(g.get_f64("a"), Some(5.0));
    assert_eq!(g.get_f64("b"), Some(6.0));
    assert_eq!(g.get_f64("c"), Some(-9.0));
}

#[test]
fn the_first_path_that_has_a_name_wins() {
    let (mut g, _) = session(&["folder", "utilproc.txt"]);
    g.run_str("t", "a = carre 3. ; b = double 1. ;").unwrap();
    assert_eq!(g.get_f64("a"), Some(9.0));
    assert_eq!(g.get_f64("b"), Some(2.0));
    let (mut g, _) = session(&["utilproc.txt", "folder"]);
    g.run_str("t", "a = carre 3. ;").unwrap();
    assert_eq!(g.get_f64("a"), Some(-9.0));
    // HYPOT comes from the folder and calls the file's CARRE.
    let e = g.run_str("t", "b = hypot 3. 4. ;").unwrap_err();
    assert!(e.message.contains("-2.50000E+01 ** 5.00000E-01"), "{}", e.message);
}

#[test]
fn native_operators_win_over_library_procedures_of_their_name_and_deck_procedures_win_over_both() {
    let (mut g, _) = session(&["folder"]);
    // JEU is gibi's operator: the library's JEU is not called.
    let e = g.run_str("t", "x = jeu ;").unwrap_err();
    assert!(e.message.starts_with("JEU:"), "{}", e.message);
    // TRANS is a form of TRANSLATION (TRAN): gibi's operator too.
    let e = g.run_str("t", "x = trans ;").unwrap_err();
    assert!(e.message.starts_with("TRAN:"), "{}", e.message);
    // TRANSFO only begins like TRAN: the library's procedure.
    g.run_str("t", "y = transfo 1. ;").unwrap();
    assert_eq!(g.get_f64("y"), Some(101.0));
    // A procedure of the deck hides the library's.
    g.run_str("t", "debproc carre x*flottant ; finproc (x + 1.) ; z = carre 3. ;").unwrap();
    assert_eq!(g.get_f64("z"), Some(4.0));
}

/// A library procedure runs where its name would run; where an operator
/// reads its arguments the name is a word, as in Cast3M, which loads a
/// library procedure only when it comes to run it (`VARI PSATT T` with
/// a PSATT procedure in the library).
#[test]
fn a_library_procedure_name_read_as_an_argument_is_a_word() {
    let (mut g, _) = session(&["folder"]);
    g.run_str("t", "p = vari psatt 373.15 ; q = psatt 2. ; w = mot psatt ;").unwrap();
    // IAPWS-IF97 saturation pressure at 373.15 K: 101 417.98 Pa.
    assert!((g.get_f64("p").unwrap() - 101_417.98).abs() < 0.1, "{:?}", g.get_f64("p"));
    assert_eq!(g.get_f64("q"), Some(4.0));
    assert!(matches!(g.get("W"), Some(gibi::Value::Mot(m)) if &*m == "PSATT"));
}

#[test]
fn errors_inside_a_library_procedure_point_into_its_file() {
    let (mut g, _) = session(&["folder", "utilproc.txt"]);
    let e = g.run_str("deck", "l = prog 1. 2. ;\nx = casse l ;").unwrap_err();
    let (file, line, col) = e.location().unwrap();
    assert!(file.ends_with("casse.procedur"), "{}", file);
    assert_eq!((line, col), (5, 7), "{}", e.render());
    assert!(e.trace.iter().any(|t| t.contains("in procedure CASSE called at deck:2:5")), "{:?}", e.trace);

    // In a $$$$ file, lines count from the top of the file.
    let e = g.run_str("deck", "x = echec ;").unwrap_err();
    let (file, line, _) = e.location().unwrap();
    assert!(file.ends_with("utilproc.txt"), "{}", file);
    assert_eq!(line, 18, "{}", e.render());

    // A syntax error is found when the procedure is first named.
    let e = g.run_str("deck", "x = cassee ;").unwrap_err();
    let (file, line, _) = e.location().unwrap();
    assert!(file.ends_with("cassee.procedur") && line == 4, "{}", e.render());
    assert_eq!(e.kind, gibi::ErrorKind::Syntax);

    // A method of the library (DEBMETH) is a procedure OBJET can run.
    g.run_str("deck", "o = objet methode ;").unwrap();
}

#[test]
fn a_cast3m_procedure_the_library_lacks_is_refused_by_name() {
    let (mut g, _) = session(&["folder"]);
    let e = g.run_str("t", "t = tabl ; dynamic t ;").unwrap_err();
    assert_eq!(
        e.message,
        "DYNAMIC is a Cast3M procedure that gibi does not implement, and the procedure library does not hold it"
    );
    let mut g = Interpreter::new();
    let e = g.run_str("t", "t = tabl ; dynamic t ;").unwrap_err();
    assert!(e.notes.iter().any(|n| n.contains("GIBI_PROCEDURES")), "{:?}", e.notes);
}

#[test]
fn library_procedures_echo_only_at_echo_2() {
    let (mut g, out) = session(&["folder"]);
    g.run_str("t", "opti echo 1 ; a = carre 2. ;").unwrap();
    assert!(!out.text().contains("y = x * x"), "{}", out.text());
    assert!(out.text().contains("a = carre 2."), "{}", out.text());
    g.run_str("t", "opti echo 2 ; a = carre 2. ;").unwrap();
    assert!(out.text().contains("y = x * x"), "{}", out.text());
}

#[test]
fn a_missing_library_path_is_an_error_when_a_procedure_is_looked_for() {
    let mut g = Interpreter::builder().procedures(["/nonexistent/gibi/procedures.txt"]).build();
    let e = g.run_str("t", "x = toto 1 ;").unwrap_err();
    assert!(e.message.contains("cannot read the procedure library"), "{}", e.message);
}
