//! Unilateral RESO by condensation against one plain faer factorisation F
//! (solver-notes §4, targets T4a–c): `cargo bench --bench unilateral`.
//!
//! A membrane (2D Laplacian) held only by MINI supports under a downward
//! load, with cos-shaped gaps so that part of the supports stay open.
//! m ≤ N supports sit on the bottom edge; m = 2000 exceeds one edge of the
//! 500×500 grid and uses the whole perimeter (1,996 nodes), as in
//! solver-notes §3.3.

mod common;

use std::time::Instant;

use gibi::solve::unilateral::{solve_unilateral, UnilCache, UnilOptions};
use gibi::solve::{Condition, Kind, Load, Problem};

fn main() {
    let nx = common::grid();
    let k = common::laplacian(nx);
    let n = k.n;
    let per = common::perimeter(nx);
    for m_want in [50usize, 500, 2000] {
        let nodes: Vec<usize> = if m_want <= nx { (0..m_want).map(|q| q * nx / m_want).collect() } else { per.clone() };
        let m = nodes.len();
        let conditions: Vec<Condition> =
            nodes.iter().map(|&j| Condition { terms: vec![(j, 1.0)], kind: Kind::Mini }).collect();
        let p = Problem { k: k.clone(), conditions };
        let gap = |q: usize| {
            let t = std::f64::consts::TAU * q as f64 / m as f64;
            -50.0 * (1.0 - t.cos())
        };
        let load = Load { f: vec![-1.0 / nx as f64; n], d: (0..m).map(gap).collect() };
        let f = common::reference_f(&p.k, &nodes);
        let t = Instant::now();
        let (_, rep) = solve_unilateral(&p, &load, &UnilOptions::default(), &mut UnilCache::default(), &mut |_| {})
            .expect("solves");
        let s = t.elapsed().as_secs_f64();
        println!(
            "case=mini{m_want} n={n} m={m} method=condense F_s={f:.3} reso_s={s:.3} ratio={:.3} iterations={} active={} phases={:?}",
            s / f,
            rep.iterations,
            rep.active_count,
            rep.phase_seconds
                .iter()
                .map(|(k, v)| format!("{k}:{v:.3}"))
                .collect::<Vec<_>>()
        );
    }
}
