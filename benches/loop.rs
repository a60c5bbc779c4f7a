//! The interpreter's loop speed against Lua 5.4 (issue 2): a REPETER of 10^6
//! passes of `s = s + (&b * 2.) ;` and the same loop in Lua, run side by
//! side. Prints `case=loop n=1000000 gibi_s=X lua_s=Y ratio=R` (ratio =
//! gibi / Lua; target ≤ 5). Lua comes from Debian's `lua5.4`; without it
//! the Lua time is reported as missing.

use std::time::Instant;

const N: u64 = 1_000_000;

fn best_of<F: FnMut() -> f64>(runs: usize, mut f: F) -> f64 {
    (0..runs).map(|_| f()).fold(f64::INFINITY, f64::min)
}

fn main() {
    let deck = format!("s = 0. ;\nrepeter b {} ;\n  s = s + (&b * 2.) ;\nfin b ;\n", N);
    let gibi_s = best_of(5, || {
        let mut g = gibi::Interpreter::new();
        let t = Instant::now();
        g.run_str("loop", &deck).expect("the loop deck runs");
        let dt = t.elapsed().as_secs_f64();
        assert_eq!(g.get_f64("S"), Some((N * (N + 1)) as f64));
        dt
    });
    let lua_src = format!("s = 0.0\nfor b = 1, {} do\n  s = s + (b * 2.0)\nend\n", N);
    let script = std::env::temp_dir().join("gibi_bench_loop.lua");
    std::fs::write(&script, lua_src).expect("write the Lua script");
    let startup = best_of(5, || {
        let t = Instant::now();
        let _ = std::process::Command::new("lua5.4").arg("-e").arg("").status();
        t.elapsed().as_secs_f64()
    });
    let lua = best_of(5, || {
        let t = Instant::now();
        match std::process::Command::new("lua5.4").arg(&script).status() {
            Ok(s) if s.success() => t.elapsed().as_secs_f64(),
            _ => f64::NAN,
        }
    });
    // Subtract Lua's process start-up so both times measure the loop.
    let lua_s = (lua - startup).max(1e-6);
    if lua.is_nan() {
        println!("case=loop n={} gibi_s={:.4} lua_s=missing (install lua5.4) ratio=missing", N, gibi_s);
    } else {
        println!("case=loop n={} gibi_s={:.4} lua_s={:.4} ratio={:.2}", N, gibi_s, lua_s, gibi_s / lua_s);
    }
}
