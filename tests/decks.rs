//! Every deck under `scripts/` and `tests/decks/` is run and its transcript
//! snapshotted (insta). Decks named `err_*` must fail: the snapshot holds
//! the rendered error. Other decks must run without error — their numbers
//! are checked inside the deck by `SI (err > tol) ; ERRE 5 ; FINSI ;`.

use gibi::{Capture, FilePolicy, Interpreter};
use std::path::Path;

fn run_deck(path: &Path) -> String {
    let out = Capture::default();
    let dir = path.parent().unwrap().canonicalize().unwrap();
    let mut gibi = Interpreter::builder().output(out.clone()).files(FilePolicy::Under(dir)).build();
    let name = path.file_name().unwrap().to_string_lossy().to_string();
    let text = gibi::source::decode(&std::fs::read(path).unwrap());
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

/// The example decks users run (`scripts/<theme>/*.dgibi`).
#[test]
fn script_decks() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("scripts");
    let mut decks = Vec::new();
    for theme in std::fs::read_dir(&root).unwrap().flatten() {
        if let Ok(files) = std::fs::read_dir(theme.path()) {
            decks.extend(files.flatten().map(|f| f.path()).filter(|p| p.extension().is_some_and(|e| e == "dgibi")));
        }
    }
    decks.sort();
    assert!(!decks.is_empty());
    for deck in decks {
        let theme = deck.parent().unwrap().file_name().unwrap().to_string_lossy().to_string();
        let name = format!("{}__{}", theme, deck.file_stem().unwrap().to_string_lossy());
        let mut settings = insta::Settings::clone_current();
        settings.set_snapshot_suffix(name);
        settings.set_input_file(&deck);
        settings.bind(|| insta::assert_snapshot!(run_deck(&deck)));
    }
}

/// Every committed snapshot belongs to a deck that still exists, so a
/// renamed or deleted deck cannot leave a stale transcript behind.
#[test]
fn no_stale_snapshots() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    for f in std::fs::read_dir(root.join("tests/snapshots")).unwrap().flatten() {
        let name = f.file_name().to_string_lossy().to_string();
        let deck = if let Some(rest) = name.strip_prefix("decks__decks@") {
            root.join("tests/decks").join(rest.trim_end_matches(".snap").replace("__", "/"))
        } else if let Some(rest) = name.strip_prefix("decks__script_decks@") {
            root.join("scripts").join(format!("{}.dgibi", rest.trim_end_matches(".snap").replacen("__", "/", 1)))
        } else {
            continue;
        };
        assert!(deck.exists(), "snapshot {} has no deck ({})", name, deck.display());
    }
}
