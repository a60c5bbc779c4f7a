//! Phase timings of the condensation (development aid):
//! `cargo bench --bench profile`. `GIBI_BENCH_N` grid size, `GIBI_BENCH_M`
//! conditions, `GIBI_BENCH_3D` for the 3D grid, `GIBI_BENCH_FLOPS` to count
//! the factor's flops against K's alone, `GIBI_BENCH_SHORT` to skip the
//! Seq/Rayon comparison.

mod common;

use std::time::Instant;

use gibi::solve::bilateral::lagrange::Doubled;
use gibi::solve::bilateral::linear::SymFactor;
use gibi::solve::bilateral::ordering;
use gibi::solve::{Condition, Kind, Problem};

fn main() {
    let nx = common::grid();
    let three = std::env::var("GIBI_BENCH_3D").is_ok();
    let k = if three { common::laplacian3d(nx) } else { common::laplacian(nx) };
    let n = k.n;
    let m_want: usize = std::env::var("GIBI_BENCH_M").ok().and_then(|s| s.parse().ok()).unwrap_or(50);
    let nodes: Vec<usize> = if three {
        (0..m_want).map(|q| q * nx * nx / m_want).collect()
    } else if m_want <= nx {
        (0..m_want).map(|q| q * nx / m_want).collect()
    } else {
        common::perimeter(nx)
    };
    let conditions: Vec<Condition> =
        nodes.iter().map(|&j| Condition { terms: vec![(j, 1.0)], kind: Kind::Mini, dual: None }).collect();
    let m = conditions.len();
    let p = Problem { k, conditions };
    let f = common::reference_f(&p.k, &nodes);
    println!("F {f:.3}");
    let uni: Vec<usize> = (0..m).collect();
    let t = Instant::now();
    let tail: Vec<usize> = uni.iter().map(|&i| n + m + i).collect();
    let mut sys = Doubled::with_tail(&p, &tail, false).unwrap();
    println!("doubled {:.3}", t.elapsed().as_secs_f64());
    let t = Instant::now();
    let primal = match std::env::var("GIBI_BENCH_ORDER").as_deref() {
        Ok("nd") => ordering::primal_order(&p, &[], Some((&sys.col_ptr, &sys.row_idx)), ordering::Algo::Nd).unwrap(),
        _ => ordering::primal_amd(&p, &[], Some((&sys.col_ptr, &sys.row_idx))).unwrap(),
    };
    println!("amd {:.3}", t.elapsed().as_secs_f64());
    let t = Instant::now();
    let fwd = ordering::doubled_order(&p, &primal, &uni);
    println!("order {:.3}", t.elapsed().as_secs_f64());
    let t = Instant::now();
    let mut fac = SymFactor::analyse(&sys.col_ptr, &sys.row_idx, fwd).unwrap();
    println!("symbolic {:.3}", t.elapsed().as_secs_f64());
    let t = Instant::now();
    sys.fill(&p, 0.0).unwrap();
    println!("fill {:.3}", t.elapsed().as_secs_f64());
    let t = Instant::now();
    let _ = fac.factor(&sys.col_ptr, &sys.row_idx, &sys.values, &sys.row_scale, n, None);
    println!("numeric {:.3}", t.elapsed().as_secs_f64());
    let sup = fac.supernodal();
    let ns = sup.n_supernodes();
    let last = sup.supernode_end()[ns - 1] - sup.supernode_begin()[ns - 1];
    println!("nnz(L) {} supernodes {ns} last {last}", sup.len_val());
    let mut flops = 0.0f64;
    for q in 0..ns {
        let w = sup.supernode_end()[q] - sup.supernode_begin()[q];
        let r = w + sup.supernode(q).pattern().len();
        for k in 0..w {
            flops += ((r - k) as f64).powi(2);
        }
    }
    println!("flops {:.1} G", flops / 1e9);
    if std::env::var("GIBI_BENCH_TAIL").is_ok() {
        let cut = sup.nrows() - m;
        let (mut sflops, mut scat, mut solve, mut upd, mut nz, mut cnt) = (0.0f64, 0.0f64, 0.0f64, 0.0f64, 0.0f64, 0);
        let mut hist = [0usize; 12];
        let mut hist_f = [0.0f64; 12];
        for q in 0..ns {
            let b = sup.supernode_begin()[q];
            let w = (sup.supernode_end()[q] - b) as f64;
            if b >= cut {
                continue;
            }
            let pat = sup.supernode(q).pattern();
            let k = pat.iter().filter(|&&r| r >= cut).count() as f64;
            let pr = pat.len() as f64 - k;
            if k == 0.0 {
                continue;
            }
            cnt += 1;
            let f = w * k * k + w * w * k + 2.0 * pr * w * k;
            sflops += w * k * k;
            scat += k * k;
            solve += w * w * k;
            upd += 2.0 * pr * w * k;
            nz += w * k;
            let bin = (k.log2() as usize).min(11);
            hist[bin] += 1;
            hist_f[bin] += f;
        }
        println!(
            "tail: supernodes with lambda2 {cnt} nnzW {:.1}M S-flops {:.2}G scatter {:.1}M solve {:.2}G upd {:.2}G",
            nz / 1e6,
            sflops / 1e9,
            scat / 1e6,
            solve / 1e9,
            upd / 1e9
        );
        for (i, (h, f)) in hist.iter().zip(hist_f).enumerate() {
            println!("  k~2^{i}: {h} supernodes, {:.2} Gflop", f / 1e9);
        }
    }
    if std::env::var("GIBI_BENCH_FLOPS").is_ok() {
        // The same count for K alone with the supported unknowns eliminated.
        let keep: Vec<bool> = (0..n).map(|j| !nodes.contains(&j)).collect();
        let mut new = vec![usize::MAX; n];
        let mut nn = 0;
        for j in 0..n {
            if keep[j] {
                new[j] = nn;
                nn += 1;
            }
        }
        let trip: Vec<faer::sparse::Triplet<usize, usize, f64>> =
            p.k.entries
                .iter()
                .filter(|&&(i, j, _)| keep[i] && keep[j] && i <= j)
                .map(|&(i, j, v)| faer::sparse::Triplet::new(new[i], new[j], v))
                .collect();
        let a = faer::sparse::SparseColMat::<usize, f64>::try_new_from_triplets(nn, nn, &trip).unwrap();
        let sym = faer::sparse::linalg::cholesky::factorize_symbolic_cholesky(
            a.symbolic(),
            faer::Side::Upper,
            Default::default(),
            Default::default(),
        )
        .unwrap();
        if let faer::sparse::linalg::cholesky::SymbolicCholeskyRaw::Supernodal(s) = sym.raw() {
            let mut fl = 0.0f64;
            for q in 0..s.n_supernodes() {
                let w = s.supernode_end()[q] - s.supernode_begin()[q];
                let r = w + s.supernode(q).pattern().len();
                for k in 0..w {
                    fl += ((r - k) as f64).powi(2);
                }
            }
            println!("F flops {:.1} G nnz {}", fl / 1e9, s.len_val());
        }
    }
    let t = Instant::now();
    gibi::solve::direct::check_structure(&p).unwrap();
    println!("check_structure {:.3}", t.elapsed().as_secs_f64());
    let t = Instant::now();
    gibi::solve::bilateral::lagrange::validate(&p).unwrap();
    println!("validate {:.3}", t.elapsed().as_secs_f64());
    let t = Instant::now();
    let c = gibi::solve::unilateral::condensed::condenser::Condenser::new(&p).unwrap();
    println!("Condenser::new {:.3}", t.elapsed().as_secs_f64());
    let d: Vec<f64> = (0..m).map(|q| -200.0 * (1.0 - (std::f64::consts::TAU * q as f64 / m as f64).cos())).collect();
    let load = gibi::solve::Load { f: vec![-1.0 / nx as f64; n], d };
    let t = Instant::now();
    let cd = c.condensed(&load).unwrap();
    println!("condensed {:.3}", t.elapsed().as_secs_f64());
    let t = Instant::now();
    let _ = gibi::solve::unilateral::dense_ldlt::DenseLdlt::factor(cd.g.as_ref().as_ref());
    println!("dense ldlt {:.3}", t.elapsed().as_secs_f64());
    let t = Instant::now();
    let _ = gibi::solve::unilateral::dense_ldlt::DenseLdlt::factor(cd.g.as_ref().as_ref());
    println!("dense ldlt again {:.3}", t.elapsed().as_secs_f64());
    let t = Instant::now();
    let r = gibi::solve::unilateral::condensed::operator::run(&cd, &Default::default(), &mut |_| {});
    println!("status run {:.3} {:?}", t.elapsed().as_secs_f64(), r.map(|r| r.records.len()));
    if std::env::var("GIBI_BENCH_SHORT").is_ok() {
        return;
    }
    for par in [faer::Par::Seq, faer::Par::rayon(2)] {
        faer::set_global_parallelism(par);
        let mut fac2 = SymFactor::analyse(&sys.col_ptr, &sys.row_idx, fac.fwd().to_vec()).unwrap();
        let t = Instant::now();
        let _ = fac2.factor(&sys.col_ptr, &sys.row_idx, &sys.values, &sys.row_scale, n, None);
        println!("numeric {par:?} {:.3}", t.elapsed().as_secs_f64());
        let f = common::reference_f(&p.k, &nodes);
        println!("F {par:?} {f:.3}");
    }
}
