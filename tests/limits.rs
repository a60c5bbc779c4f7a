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
