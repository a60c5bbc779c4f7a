//! Bilateral RESO against one plain faer factorisation F (solver-notes §4,
//! targets T1–T3): `cargo bench --bench reso`.

mod common;

use std::time::Instant;

use gibi::solve::direct::{DirectOptions, Factorization};
use gibi::solve::{Condition, Kind, Load, Problem};

fn line(case: &str, n: usize, m: usize, f: f64, t: f64) {
    println!("case={case} n={n} m={m} method=direct F_s={f:.3} reso_s={t:.3} ratio={:.3}", t / f);
}

fn main() {
    let nx = common::grid();
    let k = common::laplacian(nx);
    let n = k.n;
    let fixed = common::perimeter(nx);
    let conditions: Vec<Condition> =
        fixed.iter().map(|&j| Condition { terms: vec![(j, 1.0)], kind: Kind::Equal, dual: None }).collect();
    let m = conditions.len();
    let p = Problem { k, conditions };
    let load = |s: f64| Load {
        f: (0..n).map(|i| s * (1.0 + (i % 7) as f64)).collect(),
        d: (0..m).map(|i| 0.01 * s * (i % 5) as f64).collect(),
    };
    // Medians of interleaved repeats (timings vary by ±30 % on the shared
    // machines); each repeat factorises afresh.
    let (mut fs, mut tb, mut tr, mut tf) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    let mut fq = Vec::new();
    for _ in 0..common::repeats() {
        fs.push(common::reference_f(&p.k, &fixed));
        fq.push(common::reference_f_seq(&p.k, &fixed));
        let t = Instant::now();
        let mut fac = Factorization::new(&p, &DirectOptions::default()).expect("factorises");
        let s = fac.solve(&[load(1.0)]).expect("solves");
        tb.push(t.elapsed().as_secs_f64());
        std::hint::black_box(&s);

        let t = Instant::now();
        let s = fac.solve(&[load(2.0)]).expect("solves");
        tr.push(t.elapsed().as_secs_f64());
        std::hint::black_box(&s);

        let mut q = p.clone();
        for e in &mut q.k.entries {
            e.2 *= 2.0;
        }
        let t = Instant::now();
        fac.refactor(&q).expect("refactors");
        tf.push(t.elapsed().as_secs_f64());
    }
    let f = common::median(&mut fs);
    line("bilateral", n, m, f, common::median(&mut tb));
    line("rhs", n, m, f, common::median(&mut tr));
    line("refactor", n, m, f, common::median(&mut tf));
    // F with faer's parallelism off: faster in 2D on 2 cores, the stricter
    // reference there.
    let fseq = common::median(&mut fq);
    println!(
        "#   F_seq_s={fseq:.3} ratios_seq: bilateral={:.3} rhs={:.3} refactor={:.3}",
        common::median(&mut tb) / fseq,
        common::median(&mut tr) / fseq,
        common::median(&mut tf) / fseq
    );
}
