//! RIGI against one faer factorisation F of the matrix it describes:
//! `cargo bench --bench assembly`.
//!
//! A unit square of NX × NX QUA4 in plane strain (NX = 706 by default, so
//! n ≈ 1.0e6 unknowns; `GIBI_BENCH_NX` changes it) is meshed and modelled
//! by running Gibiane through the library API. Then:
//! * `rigi_s` is the wall time of the single instruction `k = rigi mo ma ;`
//!   (element matrices of every element, stored per block as RIGI does);
//! * `F_s` is one faer symbolic + numeric Cholesky (AMD, supernodal by the
//!   automatic rule, as in solver-notes §4) of the same stiffness, read
//!   back from the RIGIDITE object, assembled here, with the bottom edge
//!   clamped (its unknowns eliminated) so that it is positive definite.
//!
//! The scatter of the element blocks into triplets is timed apart
//! (`scatter_s`): RESO does it, not RIGI. Target: ratio = rigi_s / F_s < 1.

use faer::sparse::{SparseColMat, Triplet};
use gibi::value::Rigidite;
use gibi::{Interpreter, Value};
use std::collections::HashMap;
use std::rc::Rc;
use std::time::Instant;

fn main() {
    let nx: usize = std::env::var("GIBI_BENCH_NX").ok().and_then(|s| s.parse().ok()).unwrap_or(706);
    let mut gibi = Interpreter::new();
    let deck = format!(
        "opti echo 0 dime 2 elem qua4 mode plan defo ;
         p1 = 0. 0. ; p2 = 1. 0. ; p3 = 1. 1. ; p4 = 0. 1. ;
         bas = droi {nx} p1 p2 ;
         s = dall bas (droi {nx} p2 p3) (droi {nx} p3 p4) (droi {nx} p4 p1) ;
         mo = mode s mecanique elastique ;
         ma = mate mo youn 2.e11 nu 0.3 ;"
    );
    let t = Instant::now();
    gibi.run_str("mesh", &deck).expect("the mesh deck runs");
    let mesh_s = t.elapsed().as_secs_f64();

    let t = Instant::now();
    gibi.run_str("rigi", "k = rigi mo ma ;").expect("RIGI runs");
    let rigi_s = t.elapsed().as_secs_f64();

    let k: Rc<Rigidite> = gibi.get_as("K").expect("K is a RIGIDITE");
    let fixed: Vec<usize> = match gibi.get("BAS") {
        Some(Value::Mesh(m)) => m.node_list(),
        _ => panic!("BAS is a mesh"),
    };

    // Number the unknowns (node, component), clamped ones left out.
    let t = Instant::now();
    let clamped: std::collections::HashSet<usize> = fixed.into_iter().collect();
    let mut index: HashMap<(usize, &str), usize> = HashMap::new();
    let mut trip = Vec::new();
    for b in &k.blocks {
        let nd = b.ndof();
        let mut ids = vec![usize::MAX; nd];
        for e in 0..b.n_elem() {
            let conn = &b.conn[e * b.nodes_per_elem..(e + 1) * b.nodes_per_elem];
            for (r, (l, c)) in b.dofs.iter().enumerate() {
                let node = conn[*l];
                ids[r] = if clamped.contains(&node) {
                    usize::MAX
                } else {
                    let next = index.len();
                    *index.entry((node, c.as_str())).or_insert(next)
                };
            }
            let m = b.mat(e);
            for r in 0..nd {
                for c in 0..nd {
                    let (i, j) = (ids[r], ids[c]);
                    if i != usize::MAX && j != usize::MAX && i <= j {
                        trip.push(Triplet::new(i, j, m[r * nd + c]));
                    }
                }
            }
        }
    }
    let n = index.len();
    let a = SparseColMat::<usize, f64>::try_new_from_triplets(n, n, &trip).expect("valid triplets");
    let scatter_s = t.elapsed().as_secs_f64();
    drop(trip);

    let t = Instant::now();
    let llt = a.as_ref().sp_cholesky(faer::Side::Upper).expect("the clamped stiffness is SPD");
    let f_s = t.elapsed().as_secs_f64();
    std::hint::black_box(&llt);

    let unknowns = 2 * (nx + 1) * (nx + 1);
    println!(
        "case=assembly n={unknowns} rigi_s={rigi_s:.3} F_s={f_s:.3} ratio={:.3} (mesh_s={mesh_s:.3} scatter_s={scatter_s:.3} n_free={n})",
        rigi_s / f_s
    );
}
