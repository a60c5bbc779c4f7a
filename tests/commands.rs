//! EXTE and the host's command policy: programs run only where allowed.

use gibi::{Capture, CommandPolicy, ErrorKind, Interpreter};

fn with(policy: CommandPolicy) -> (Interpreter, Capture) {
    let out = Capture::default();
    (Interpreter::builder().output(out.clone()).commands(policy).build(), out)
}

#[test]
fn an_allowed_program_gets_the_values_and_gives_back_its_words() {
    let (mut gibi, _) = with(CommandPolicy::Only(vec!["cat".into()]));
    let deck = "l = lect 3 4 ; tt = tabl ; tt . 1 = 'x' ; tt . 2 = 8 ;
        t = exte 'cat' 1 2.5 'RC' 'abc' l tt ;
        si (neg t . 1 1) ; erre 5 ; finsi ;
        si ((abs (t . 2 - 2.5)) > 1.e-12) ; erre 5 ; finsi ;
        si (neg t . 3 'abc') ; erre 5 ; finsi ;
        si (neg t . 5 4) ; erre 5 ; finsi ;
        si (neg t . 6 'x') ; erre 5 ; finsi ;
        si (neg (dime t) 7) ; erre 5 ; finsi ;";
    gibi.run_str("t", deck).unwrap();
}

#[test]
fn arguments_are_not_given_to_a_shell() {
    let (mut gibi, _) = with(CommandPolicy::Anything);
    gibi.run_str(
        "t",
        "t = exte 'echo a;b $HOME' ; si (neg t . 1 'a;b') ; erre 5 ; finsi ; si (neg t . 2 '$HOME') ; erre 5 ; finsi ;",
    )
    .unwrap();
}

#[test]
fn a_program_not_allowed_is_refused_and_nothing_runs() {
    let (mut gibi, _) = with(CommandPolicy::Only(vec!["cat".into()]));
    let e = gibi.run_str("t", "t = exte 'echo' 1 ;").unwrap_err();
    assert_eq!(e.kind, ErrorKind::Denied);
    assert!(e.message.contains("'echo'"), "{}", e.message);
    let (mut gibi, _) = with(CommandPolicy::default());
    assert_eq!(gibi.run_str("t", "t = exte 'cat' ;").unwrap_err().kind, ErrorKind::Denied);
}

#[test]
fn a_missing_program_gives_an_empty_table() {
    let (mut gibi, out) = with(CommandPolicy::Anything);
    gibi.run_str("t", "t = exte 'gibi-no-such-program-here' 1 ; si (exis t 1) ; erre 5 ; finsi ;").unwrap();
    assert!(out.text().contains("no program 'gibi-no-such-program-here'"), "{}", out.text());
}
