//! The REPL in a real (pseudo-)terminal, as a user drives it: Ctrl-C stops
//! a running entry and keeps every object, errors and deep structures do
//! not end the session, history is saved entry by entry, `:help` matches
//! operators like decks do.
#![cfg(unix)]

use rexpect::process::signal::Signal;
use rexpect::session::{spawn_command, PtySession};
use std::path::PathBuf;
use std::process::Command;
use std::time::{Duration, Instant};

fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("gibi-repl-{}-{}", name, std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// gibi's REPL on a terminal, with its history in `dir`, at its first prompt.
fn repl(dir: &std::path::Path) -> PtySession {
    let mut c = Command::new(env!("CARGO_BIN_EXE_gibi"));
    c.current_dir(dir).env("GIBI_HISTORY", dir.join("history")).env("TERM", "xterm");
    let mut p = spawn_command(c, Some(30_000)).expect("spawn gibi in a pty");
    p.exp_string("gibi> ").expect("first prompt");
    p
}

/// Type an entry, wait for `expect` in what it prints, then for the next
/// prompt (rustyline drops what is typed before the prompt is back).
fn enter(p: &mut PtySession, line: &str, expect: &str) {
    p.send_line(line).unwrap();
    if !expect.is_empty() {
        p.exp_string(expect).unwrap_or_else(|e| panic!("{}: {}", line, e));
    }
    p.exp_string("gibi> ").unwrap_or_else(|e| panic!("{}: no prompt after: {}", line, e));
}

#[test]
fn ctrl_c_stops_the_entry_and_keeps_the_objects() {
    let dir = scratch("ctrlc");
    let mut p = repl(&dir);
    enter(&mut p, "x = 42 ;", "");
    // 2e9 passes: minutes of work, unless Ctrl-C stops it.
    p.send_line("repeter c 20 ; repeter b 100000000 ; y = &b ; fin b ; fin c ;").unwrap();
    std::thread::sleep(Duration::from_millis(400));
    let t = Instant::now();
    p.send_control('c').unwrap();
    p.exp_string("interrupted").unwrap();
    let took = t.elapsed();
    assert!(took < Duration::from_millis(1500), "Ctrl-C took {:?}", took);
    p.exp_string("gibi> ").unwrap();
    enter(&mut p, "mess 'kept' x (y > 0) ;", "kept 42 VRAI");
    // The next entry runs normally (the interrupt was used up).
    enter(&mut p, "repeter b 1000 ; z = &b ; fin b ; mess 'z =' z ;", "z = 1000");
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}

#[test]
fn errors_and_deep_tables_do_not_end_the_session() {
    let dir = scratch("errors");
    let mut p = repl(&dir);
    enter(&mut p, "a = 7 ;", "");
    enter(&mut p, "b = extr a 'x' ;", "error:");
    enter(&mut p, "t = table ; repeter b 100000 ; n = table ; n . 'X' = t ; t = n ; fin b ;", "");
    // Releasing the chain used to overflow the stack and kill the session.
    enter(&mut p, "t = 0 ; n = 0 ;", "");
    enter(&mut p, "mess 'still' a ;", "still 7");
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}

#[test]
fn history_is_saved_per_entry_and_help_matches_like_operators() {
    let dir = scratch("history");
    let mut p = repl(&dir);
    enter(&mut p, ":help reso", "usage: RESO RIGIDITE");
    enter(&mut p, ":HELP Resolution", "usage: RESO RIGIDITE");
    enter(&mut p, "h1 = 1 ;", "");
    enter(&mut p, "mess 'second' h1 ;", "second 1");
    // A kill, not a clean exit: what was typed is in the file already.
    p.process_mut().kill(Signal::SIGKILL).unwrap();
    let h = std::fs::read_to_string(dir.join("history")).unwrap();
    assert!(h.contains("h1 = 1 ;") && h.contains("mess 'second' h1 ;"), "{}", h);
    // And a new session offers it (H1 is gone with the old session: the
    // recalled line prints the word).
    let mut p = repl(&dir);
    p.send("\x1b[A").unwrap(); // up arrow: the last entry
    p.send_line("").unwrap();
    p.exp_string("second H1").unwrap();
    p.send_control('d').unwrap();
    p.exp_eof().unwrap();
}
