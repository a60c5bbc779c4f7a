//! Long fuzzing runs: `cargo +nightly fuzz run run_deck -- -jobs=1` from the
//! repository root (seeds in fuzz/corpus/run_deck: deep tables, huge
//! numbers, long lines, control bytes). Any bytes must parse-or-fail and
//! run-or-fail without panicking, overflowing the stack or hanging; the
//! interpreter's loops are bounded by a step limit. The text is read as the
//! CLI reads decks (Latin-1 where not UTF-8) and run in two parts on one
//! session, split at the first blank line, as REPL entries are. The
//! evaluator turns a panic into an `Internal` error (the session survives
//! it): that is a bug too, so it is turned back into a panic for the fuzzer.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if data.len() > 65_536 {
        return;
    }
    let text = gibi::source::decode(data);
    let _ = gibi::syntax::check_complete(&text);
    let mut g = gibi::Interpreter::builder().step_limit(500_000).build();
    let (first, second) = text.split_once("\n\n").unwrap_or((&text, ""));
    for (name, part) in [("fuzz#1", first), ("fuzz#2", second)] {
        if let Err(e) = g.run_str(name, part) {
            // Rendering is part of the contract: clipped, escaped, no panic.
            let rendered = e.render();
            assert!(e.kind != gibi::ErrorKind::Internal, "{}", rendered);
        }
    }
});
