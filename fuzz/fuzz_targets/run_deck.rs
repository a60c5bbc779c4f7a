//! Long fuzzing runs: `cargo +nightly fuzz run run_deck` from the repository
//! root. Any text must parse-or-fail and run-or-fail without panicking; the
//! interpreter's own loops are bounded by its instruction budget below.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Ok(text) = std::str::from_utf8(data) {
        // Skip inputs that would legitimately run for long (huge REPETER).
        if text.len() > 4096 {
            return;
        }
        let _ = gibi::syntax::check_complete(text);
        let mut g = gibi::Interpreter::new();
        let _ = g.run_str("fuzz", text);
    }
});
