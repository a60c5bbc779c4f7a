//! The embedding API: sinks, typed reads, custom operators, file policy.

use gibi::{Capture, FilePolicy, Interpreter, OpSpec, Value};
use std::rc::Rc;

#[test]
fn library_prints_nothing_by_default_and_objects_persist() {
    let mut g = Interpreter::new();
    g.run_str("a", "mess 'hidden' ; x = 2 ;").unwrap();
    g.run_str("b", "y = x * 3 ;").unwrap();
    assert_eq!(g.get_f64("y"), Some(6.0));
}

#[test]
fn typed_reads_and_writes() {
    let mut g = Interpreter::new();
    g.set("n", Value::Int(4));
    g.set("w", "UX");
    g.run_str("t", "l = prog 1. pas 1. n ; m = w et 'Y' ;").unwrap();
    let l: Rc<Vec<f64>> = g.get_as("l").unwrap();
    assert_eq!(*l, vec![1.0, 2.0, 3.0, 4.0]);
    let m: String = g.get_as("m").unwrap();
    assert_eq!(m, "UXY");
    let e = g.get_as::<f64>("m").unwrap_err();
    assert!(e.message.contains("MOT"));
}

#[test]
fn custom_operator_reads_arguments_by_type_on_both_sides() {
    let out = Capture::default();
    let mut g = Interpreter::builder()
        .output(out.clone())
        .operator(OpSpec::host("SCAL", "SCAL LISTREEL FLOTTANT", "Scale a list.", |a| {
            let l: Rc<Vec<f64>> = a.req()?;
            let s = a.req_num()?;
            Ok(vec![Value::ListReel(Rc::new(l.iter().map(|x| x * s).collect()))])
        }))
        .build();
    g.run_str("t", "a = scal (prog 1. 2.) 3 ; b = (prog 1.) scal 2. ; c = extr a 2 ;").unwrap();
    assert_eq!(g.get_f64("c"), Some(6.0));
    let e = g.run_str("t", "d = scal 2. ;").unwrap_err();
    assert!(e.render().contains("SCAL: expected LISTREEL"), "{}", e.render());
    assert!(e.render().contains("usage: SCAL LISTREEL FLOTTANT"));
}

#[test]
fn file_policy_defaults_to_nothing() {
    assert!(FilePolicy::Nothing.check_read("a.txt").is_err());
    let root = std::env::temp_dir();
    assert!(FilePolicy::Under(root.clone()).check_write("sub/a.txt").is_ok());
    assert!(FilePolicy::Under(root).check_write("../a.txt").is_err());
}

#[test]
fn a_panicking_operator_becomes_an_error_and_objects_survive() {
    let mut g =
        Interpreter::builder().operator(OpSpec::host("BOOM", "BOOM", "Always panics.", |_| panic!("kaboom"))).build();
    let prev = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    g.run_str("t", "a = 1 ;").unwrap();
    let e = g.run_str("t", "b = boom ;").unwrap_err();
    std::panic::set_hook(prev);
    assert!(e.message.contains("BOOM: internal error (kaboom)"), "{}", e.message);
    assert_eq!(g.get_f64("a"), Some(1.0));
}

#[test]
fn a_listchpo_reads_back_as_a_list_of_fields() {
    let mut g = Interpreter::new();
    g.run_str("t", "opti dime 2 ; p = 0. 0. ; l = suit (forc 'FX' 1. p) (forc 'FY' 2. p) ;").unwrap();
    let l: Rc<Vec<Rc<gibi::value::Chpoint>>> = g.get_as("l").unwrap();
    assert_eq!(l.len(), 2);
    assert_eq!(l[1].components(), vec!["FY".to_string()]);
    assert_eq!(g.get("l").unwrap().type_name(), "LISTCHPO");
}

/// An embedder stops a run from another thread: the error is at the
/// instruction reached (here inside a procedure), objects stay, and the
/// next run is not affected.
#[test]
fn interrupt_handle_stops_a_run_from_another_thread() {
    let mut g = Interpreter::new();
    let stop = g.interrupt_handle();
    let t = std::thread::spawn(move || {
        std::thread::sleep(std::time::Duration::from_millis(100));
        stop.interrupt();
    });
    let deck = "a = 1 ;\ndebproc f ;\n  repeter b ; x = &b ; fin b ;\nfinproc ;\nf ;\n";
    let e = g.run_str("host", deck).unwrap_err();
    t.join().unwrap();
    assert_eq!(e.kind, gibi::ErrorKind::Interrupted);
    assert_eq!(e.location().map(|l| l.1), Some(3), "{}", e.render());
    assert!(e.render().contains("in procedure F"), "{}", e.render());
    assert_eq!(g.get_f64("a"), Some(1.0));
    g.run_str("next", "b = a + 1 ;").unwrap();
    assert_eq!(g.get_f64("b"), Some(2.0));
}
