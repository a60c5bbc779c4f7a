//! Every deck under `scripts/` and `tests/decks/` is run and its transcript
//! snapshotted (insta). Decks named `err_*` must fail: the snapshot holds
//! the rendered error. Other decks must run without error — their numbers
//! are checked inside the deck by `SI (err > tol) ; ERRE 5 ; FINSI ;`.

use gibi::{Capture, FilePolicy, Interpreter};
use std::path::Path;

fn run_deck(path: &Path) -> String {
    let out = Capture::default();
    let dir = path.parent().unwrap().canonicalize().unwrap();
    let mut gibi = Interpreter::builder()
        .output(out.clone())
        .files(FilePolicy::Under(dir))
        .build();
    let name = path.file_name().unwrap().to_string_lossy().to_string();
    let text = std::fs::read_to_string(path).unwrap();
    let result = gibi.run_str(&name, &text);
    let expect_error = name.starts_with("err_");
    let mut transcript = out.text();
    match (result, expect_error) {
        (Ok(_), false) => {}
        (Err(e), true) => {
            transcript.push_str("--- error ---\n");
            transcript.push_str(&e.render());
        }
        (Ok(_), true) => panic!("{}: expected an error, the deck ran to its end", name),
        (Err(e), false) => panic!("{} failed:\n{}{}", name, transcript, e.render()),
    }
    transcript
}

#[test]
fn test_decks() {
    insta::glob!("decks/**/*.dgibi", |path| {
        insta::assert_snapshot!(run_deck(path));
    });
}

#[test]
fn script_decks() {
    insta::glob!("../scripts", "**/*.dgibi", |path| {
        insta::assert_snapshot!(run_deck(path));
    });
}
