//! Shared set-up of the RESO benchmarks: a 2D 5-point Laplacian on an
//! N×N grid (the plane-strain stand-in of solver-notes §4) and the
//! reference factorisation F of the notes.

use std::time::Instant;

use faer::sparse::{SparseColMat, Triplet};
use gibi::solve::Matrix;

/// Graph Laplacian of the N×N grid (singular: pure Neumann), both
/// triangles, as elementary blocks would give it.
pub fn laplacian(nx: usize) -> Matrix {
    let id = |i: usize, j: usize| i * nx + j;
    let mut entries = Vec::with_capacity(8 * nx * nx);
    for i in 0..nx {
        for j in 0..nx {
            for (a, b) in [(i + 1, j), (i, j + 1)] {
                if a < nx && b < nx {
                    let (p, q) = (id(i, j), id(a, b));
                    entries.extend([(p, p, 1.0), (q, q, 1.0), (p, q, -1.0), (q, p, -1.0)]);
                }
            }
        }
    }
    Matrix { n: nx * nx, entries, symmetric: true }
}

/// Graph Laplacian of the N×N×N grid (7-point, pure Neumann), both
/// triangles: the 3D stand-in of solver-notes §3.3.
#[allow(dead_code)]
pub fn laplacian3d(nx: usize) -> Matrix {
    let id = |i: usize, j: usize, k: usize| (k * nx + j) * nx + i;
    let mut entries = Vec::with_capacity(12 * nx * nx * nx);
    for k in 0..nx {
        for j in 0..nx {
            for i in 0..nx {
                for (a, b, c) in [(i + 1, j, k), (i, j + 1, k), (i, j, k + 1)] {
                    if a < nx && b < nx && c < nx {
                        let (p, q) = (id(i, j, k), id(a, b, c));
                        entries.extend([(p, p, 1.0), (q, q, 1.0), (p, q, -1.0), (q, p, -1.0)]);
                    }
                }
            }
        }
    }
    Matrix { n: nx * nx * nx, entries, symmetric: true }
}

/// Boundary nodes of the grid, counter-clockwise from the origin.
#[allow(dead_code)]
pub fn perimeter(nx: usize) -> Vec<usize> {
    let mut v: Vec<usize> = (0..nx).collect();
    v.extend((1..nx).map(|i| i * nx + nx - 1));
    v.extend((0..nx - 1).rev().map(|j| (nx - 1) * nx + j));
    v.extend((1..nx - 1).rev().map(|i| i * nx));
    v
}

/// The upper triangle of K with the unknowns `fixed` eliminated
/// (Dirichlet), renumbered. Laplacian rows lose their eliminated
/// neighbours: still SPD.
fn reduced(k: &Matrix, fixed: &[usize]) -> SparseColMat<usize, f64> {
    let mut keep = vec![true; k.n];
    for &j in fixed {
        keep[j] = false;
    }
    let mut new = vec![usize::MAX; k.n];
    let mut nn = 0;
    for j in 0..k.n {
        if keep[j] {
            new[j] = nn;
            nn += 1;
        }
    }
    let trip: Vec<Triplet<usize, usize, f64>> = k
        .entries
        .iter()
        .filter(|&&(i, j, _)| keep[i] && keep[j] && i <= j)
        .map(|&(i, j, v)| Triplet::new(new[i], new[j], v))
        .collect();
    SparseColMat::<usize, f64>::try_new_from_triplets(nn, nn, &trip).expect("valid")
}

/// Seconds of one plain faer factorisation (AMD, symbolic + numeric LLᵀ,
/// supernodal by the automatic rule) of K with the unknowns `fixed`
/// eliminated (Dirichlet).
pub fn reference_f(k: &Matrix, fixed: &[usize]) -> f64 {
    let a = reduced(k, fixed);
    let t = Instant::now();
    let llt = a.as_ref().sp_cholesky(faer::Side::Upper).expect("SPD");
    let s = t.elapsed().as_secs_f64();
    std::hint::black_box(&llt);
    s
}

/// [`reference_f`] with faer's global parallelism set to `Seq` (restored
/// after): on 2 cores a 2D factorisation is faster without threads, so this
/// is the stricter reference there.
#[allow(dead_code)]
pub fn reference_f_seq(k: &Matrix, fixed: &[usize]) -> f64 {
    let before = faer::get_global_parallelism();
    faer::set_global_parallelism(faer::Par::Seq);
    let f = reference_f(k, fixed);
    faer::set_global_parallelism(before);
    f
}

#[allow(dead_code)]
/// Grid size, from `GIBI_BENCH_N` (default 500, n = 250,000).
pub fn grid() -> usize {
    std::env::var("GIBI_BENCH_N").ok().and_then(|s| s.parse().ok()).unwrap_or(500)
}

/// Repeats per timing, from `GIBI_BENCH_REPEAT` (default 3).
#[allow(dead_code)]
pub fn repeats() -> usize {
    std::env::var("GIBI_BENCH_REPEAT").ok().and_then(|s| s.parse().ok()).unwrap_or(3).max(1)
}

/// Median of a non-empty sample.
#[allow(dead_code)]
pub fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// [`reference_f`] and S, the seconds of one forward and backward solve
/// (one right-hand side) with that factor (median of 5), and S_seq, the
/// same solve with faer's parallelism off (the step solver's partial
/// substitutions run sequentially).
#[allow(dead_code)]
pub fn reference_f_s(k: &Matrix, fixed: &[usize]) -> (f64, f64, f64) {
    use faer::linalg::solvers::Solve;
    let a = reduced(k, fixed);
    let nn = a.nrows();
    let t = Instant::now();
    let llt = a.as_ref().sp_cholesky(faer::Side::Upper).expect("SPD");
    let f = t.elapsed().as_secs_f64();
    let time_solves = || {
        let mut s = Vec::new();
        for r in 0..5 {
            let mut rhs = faer::Mat::<f64>::from_fn(nn, 1, |i, _| ((i + r) % 7) as f64 - 3.0);
            let t = Instant::now();
            llt.solve_in_place(rhs.as_mut());
            s.push(t.elapsed().as_secs_f64());
            std::hint::black_box(&rhs);
        }
        median(&mut s)
    };
    let s = time_solves();
    let before = faer::get_global_parallelism();
    faer::set_global_parallelism(faer::Par::Seq);
    let s_seq = time_solves();
    faer::set_global_parallelism(before);
    (f, s, s_seq)
}
