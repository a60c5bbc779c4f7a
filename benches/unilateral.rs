//! Unilateral RESO against one plain faer factorisation F (solver-notes §4,
//! targets T4a–c and T5): `cargo bench --bench unilateral`.
//!
//! * `mini*` (2D): a membrane (5-point Laplacian, 512×512 grid, n = 262,144)
//!   held only by MINI supports under a downward load, cos-shaped gaps tuned
//!   so that about half of the supports end active. m ≤ 512 supports sit on
//!   the bottom edge; m = 2000 are spread over the whole perimeter.
//! * `mini*_3d`: the same on a 47³ grid (7-point Laplacian, n = 103,823),
//!   supports spread over the bottom face.
//! * `mini50_ancien`, `mini500_ancien`, `mini50_iter`: the same with the
//!   old method and with ITER (one IC(0)-preconditioned CG solve per
//!   condition), for comparison; the ITER case runs only when named in
//!   `GIBI_BENCH_ONLY` (it takes minutes).
//! * `obstacle`: the 512×512 membrane fixed on its perimeter (bilateral)
//!   above a flat obstacle, one MINI per interior node (m ≈ n), solved by
//!   CREUX with its defaults (from all conditions inactive, mixed rule).
//!
//! F is measured in the same run, on K with the supported (or fixed)
//! unknowns eliminated; both are medians of `GIBI_BENCH_REPEAT` (default 3)
//! interleaved runs (F of 3 runs and one solve for the obstacle; its line
//! adds the time per iteration). The detail line `F_seq` is F with faer's
//! parallelism off, faster in 2D on 2 cores: the stricter reference there. `GIBI_BENCH_ONLY=name,name` runs a subset.

mod common;

use std::time::Instant;

use gibi::solve::unilateral::{solve_unilateral, Method, Rule, UnilCache, UnilOptions};
use gibi::solve::{Condition, Kind, Load, Matrix, Problem};

fn wanted(name: &str) -> bool {
    match std::env::var("GIBI_BENCH_ONLY") {
        Ok(list) => list.split(',').any(|w| w == name),
        // ITER takes minutes here (m CG solves on an operator held only by
        // its supports): opt-in.
        Err(_) => !name.ends_with("_iter"),
    }
}

#[allow(clippy::too_many_arguments)]
fn run(name: &str, k: &Matrix, nodes: &[usize], gap: f64, load: f64, method: Method, fixed: &[usize]) {
    // GIBI_BENCH_ONLY=name,name runs some cases (the obstacle takes a while).
    if !wanted(name) {
        return;
    }
    let n = k.n;
    let m = nodes.len();
    let gap = gap * std::env::var("GIBI_BENCH_GAP").ok().and_then(|s| s.parse().ok()).unwrap_or(1.0);
    let mut conditions: Vec<Condition> =
        nodes.iter().map(|&j| Condition { terms: vec![(j, 1.0)], kind: Kind::Mini, dual: None }).collect();
    conditions.extend(fixed.iter().map(|&j| Condition { terms: vec![(j, 1.0)], kind: Kind::Equal, dual: None }));
    let p = Problem { k: k.clone(), conditions };
    let mut d: Vec<f64> = (0..m)
        .map(|q| {
            if method == Method::Creux {
                gap
            } else {
                -gap * (1.0 - (std::f64::consts::TAU * q as f64 / m as f64).cos())
            }
        })
        .collect();
    d.extend(fixed.iter().map(|_| 0.0));
    let l = Load { f: vec![load; n], d };
    let eliminated: Vec<usize> = if fixed.is_empty() { nodes.to_vec() } else { fixed.to_vec() };
    // The obstacle runs with CREUX's defaults (all inactive, mixed rule).
    // GIBI_OBSTACLE_RULE=pdas|damped picks another rule from the same start,
    // GIBI_OBSTACLE_COLD=1 Cast3M's cold start (all active, damped rule).
    let rule = match std::env::var("GIBI_OBSTACLE_RULE").as_deref() {
        Ok("pdas") => Rule::Pdas,
        Ok("damped") => Rule::Damped,
        _ => Rule::Auto,
    };
    let opts = if method == Method::Creux && std::env::var("GIBI_OBSTACLE_COLD").is_ok() {
        UnilOptions { method, rule: Rule::Damped, initial: Some(vec![true; m]), ..Default::default() }
    } else {
        UnilOptions { method, rule, ..Default::default() }
    };
    let verbose = std::env::var("GIBI_BENCH_VERBOSE").is_ok();
    // Medians of interleaved repeats: single timings vary by ±30 % on the
    // shared 2-core machines. The long obstacle run is timed once.
    let repeats = if method == Method::Creux { 1 } else { common::repeats() };
    let (mut fs, mut ts, mut fq) = (Vec::new(), Vec::new(), Vec::new());
    let mut rep = None;
    for _ in 0..repeats {
        fs.push(common::reference_f(&p.k, &eliminated));
        fq.push(common::reference_f_seq(&p.k, &eliminated));
        let t0 = Instant::now();
        let mut on_iter = |r: &gibi::solve::unilateral::IterRecord| {
            if verbose {
                println!(
                    "#     it {} at {:.3}s: active {} +{} -{} {}",
                    r.iteration,
                    t0.elapsed().as_secs_f64(),
                    r.active_count,
                    r.activated.len(),
                    r.released.len(),
                    r.mode
                );
            }
        };
        // The cache (factor, symbolic analysis) outlives the timing, as it
        // outlives a RESO inside its RIGIDITE; F's factor is not freed
        // inside its timing either.
        let mut cache = UnilCache::default();
        let t = Instant::now();
        let (_, r) = solve_unilateral(&p, &l, &opts, &mut cache, &mut on_iter).expect("solves");
        ts.push(t.elapsed().as_secs_f64());
        drop(cache);
        rep = Some(r);
    }
    if method == Method::Creux {
        fs.push(common::reference_f(&p.k, &eliminated));
        fs.push(common::reference_f(&p.k, &eliminated));
    }
    let rep = rep.expect("at least one run");
    let (f, s, fseq) = (common::median(&mut fs), common::median(&mut ts), common::median(&mut fq));
    println!(
        "case={name} n={n} m={m} method={} F_s={f:.3} reso_s={s:.3} ratio={:.3} iterations={}",
        rep.method,
        s / f,
        rep.iterations
    );
    println!("#   F_seq_s={fseq:.3} ratio_seq={:.3}", s / fseq);
    if method == Method::Creux {
        println!("#   per iteration: {:.3} s = {:.3} F", s / rep.iterations as f64, s / rep.iterations as f64 / f);
    }
    let phases: Vec<String> = rep.phase_seconds.iter().map(|(k, v)| format!("{k}:{v:.3}")).collect();
    println!("#   active={} phases={}", rep.active_count, phases.join(","));
}

/// `m` of the `pool` nodes, evenly spaced.
fn spread(pool: &[usize], m: usize) -> Vec<usize> {
    (0..m).map(|q| pool[q * pool.len() / m]).collect()
}

fn main() {
    let nx = std::env::var("GIBI_BENCH_N").ok().and_then(|s| s.parse().ok()).unwrap_or(512);
    let k = common::laplacian(nx);
    let per = common::perimeter(nx);
    let bottom: Vec<usize> = (0..nx).collect();
    let load = -1.0 / nx as f64;
    for (m, gap, method) in [
        (50, 200.0, Method::Condense),
        (500, 150.0, Method::Condense),
        (2000, 200.0, Method::Condense),
        (50, 200.0, Method::Ancien),
        (500, 150.0, Method::Ancien),
        (50, 200.0, Method::Iter),
    ] {
        let pool = if m <= nx { &bottom } else { &per };
        let suffix = match method {
            Method::Ancien => "_ancien",
            Method::Iter => "_iter",
            _ => "",
        };
        let name = format!("mini{m}{suffix}");
        run(&name, &k, &spread(pool, m), gap, load, method, &[]);
    }

    let n3 = std::env::var("GIBI_BENCH_N3").ok().and_then(|s| s.parse().ok()).unwrap_or(47);
    let k3 = common::laplacian3d(n3);
    let face: Vec<usize> = (0..n3 * n3).collect();
    for (m, gap) in [(50, 4.0), (500, 1.0), (2000, 0.5)] {
        run(&format!("mini{m}_3d"), &k3, &spread(&face, m), gap, -1.0 / (n3 * n3) as f64, Method::Condense, &[]);
    }

    let interior: Vec<usize> =
        (0..nx * nx).filter(|&j| j % nx != 0 && j % nx != nx - 1 && j >= nx && j < nx * (nx - 1)).collect();
    let h2 = 1.0 / ((nx - 1) * (nx - 1)) as f64;
    run("obstacle", &k, &interior, -0.3, -8.0 * h2, Method::Creux, &per);
}
