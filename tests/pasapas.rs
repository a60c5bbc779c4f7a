//! PASAPAS through the embedding API: what a refusal leaves in the table
//! (nothing), and the progress a host is told of.

use gibi::{Capture, Interpreter, Value};
use std::cell::RefCell;
use std::rc::Rc;

/// A block on a clamped base under a load ramp: the table of a PASAPAS
/// run, with the model given by `model`.
fn deck(model: &str) -> String {
    format!(
        "opti dime 2 elem qua4 mode plan cont ;
         bas = (0. 0.) droi 2 (1. 0.) ; s = bas tran 2 (0. 1.) ;
         sup = (2. -0.01) droi 2 (-1. -0.01) ; mc = impo 'MAIL' bas sup ;
         mo = {model} ;
         t = tabl ; t . 'MODELE' = mo ;
         t . 'CARACTERISTIQUES' = mate mo 'YOUN' 2.e5 'NU' 0.3 ;
         t . 'BLOCAGES_MECANIQUES' = (bloq sup 'DEPL') et (bloq (s cote 4) 'UX') ;
         t . 'CHARGEMENT' = char 'MECA' (forc (0. -1.) (s cote 3)) (evol manu (prog 0. 2.) (prog 0. 2.)) ;
         t . 'TEMPS_CALCULES' = prog 0.5 1. ;
         n0 = dime t ;
         pasapas t ;"
    )
}

fn keys(g: &Interpreter) -> Vec<String> {
    match g.get("t") {
        Some(Value::Table(t)) => t
            .borrow()
            .iter()
            .map(|(k, _)| match k.to_value() {
                Value::Mot(s) => s.to_string(),
                v => format!("{v:?}"),
            })
            .collect(),
        other => panic!("no table: {other:?}"),
    }
}

#[test]
fn refusals_leave_the_table_untouched() {
    for model in [
        "(mode s mecanique elastique plastique parfait) et (mode mc 'CONTACT')",
        "(mode s mecanique elastique) et (mode mc 'CONTACT' 'FROTTANT' 'COULOMB')",
    ] {
        let mut g = Interpreter::new();
        let e = g.run_str("deck", &deck(model)).unwrap_err();
        assert!(e.message.starts_with("PASAPAS:"), "{}", e.message);
        let k = keys(&g);
        assert_eq!(k, ["MODELE", "CARACTERISTIQUES", "BLOCAGES_MECANIQUES", "CHARGEMENT", "TEMPS_CALCULES"], "{model}");
    }
}

#[test]
fn a_run_fills_the_results_and_reports_progress() {
    let seen = Rc::new(RefCell::new(Vec::new()));
    let s = seen.clone();
    let out = Capture::default();
    let mut g = Interpreter::builder()
        .output(out.clone())
        .progress(move |done, total| s.borrow_mut().push((done, total)))
        .build();
    g.run_str("deck", &deck("(mode s mecanique elastique) et (mode mc 'CONTACT')")).unwrap();
    let k = keys(&g);
    for want in
        ["TEMPS", "DEPLACEMENTS", "CONTRAINTES", "DEFORMATIONS", "REACTIONS", "STATUTS_CONTACT", "PRESSIONS_CONTACT"]
    {
        assert!(k.iter().any(|x| x == want), "{want} missing from {k:?}");
    }
    assert_eq!(*seen.borrow(), vec![(1, 2), (2, 2)]);
    // One line per step, silent under OPTI ECHO 0.
    assert_eq!(out.text().lines().filter(|l| l.starts_with("PASAPAS step")).count(), 2);
    out.clear();
    g.run_str("again", "opti echo 0 ; t . 'TEMPS_CALCULES' = prog 1.5 2. ; pasapas t ; n = dime t . 'TEMPS' ;")
        .unwrap();
    assert_eq!(out.text(), "");
    assert_eq!(g.get_f64("n"), Some(5.0));
}
