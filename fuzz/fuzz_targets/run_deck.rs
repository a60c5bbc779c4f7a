//! Long fuzzing runs: `cargo +nightly fuzz run run_deck` from the repository
//! root. Any text must parse-or-fail and run-or-fail without panicking; the
//! interpreter's loops are bounded by a step limit. The evaluator turns an
//! operator's panic into an `Internal` error (the session survives it):
//! that is a bug too, so it is turned back into a panic for the fuzzer.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        if text.len() > 4096 {
            return;
        }
        let _ = gibi::syntax::check_complete(text);
        let mut g = gibi::Interpreter::builder().step_limit(100_000).build();
        if let Err(e) = g.run_str("fuzz", text) {
            assert!(e.kind != gibi::ErrorKind::Internal, "{}", e.render());
        }
    }
});
