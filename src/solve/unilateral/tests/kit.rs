//! Test helpers for the status iteration: a small dense problem condensed
//! exactly as unilateral.md §2.2/§3.2 says (without the sparse layer), the
//! recovery of §3.3, 2D Hermite beams, a brute-force reference over all
//! statuses, and a tiny deterministic PRNG.

use crate::solve::unilateral::condensed::operator;
use crate::solve::unilateral::dense_ldlt::DenseLdlt;
use crate::solve::unilateral::guyan::reduced::{self, ReducedProblem, ReducedResult};
use crate::solve::unilateral::status::{IterRecord, StatusOptions, StatusResult};
use crate::solve::{unilateral::Condensed, SolveError};
use faer::linalg::solvers::Solve;
use faer::Mat;

/// K u + Cᵀλ = F with s_i (c_i u − d_i) ≥ 0.
#[derive(Debug, Clone)]
pub struct Dense {
    pub k: Mat<f64>,
    pub rows: Vec<Vec<(usize, f64)>>,
    pub sense: Vec<f64>,
    pub d: Vec<f64>,
    pub f: Vec<f64>,
}

/// The condensed data plus what the recovery needs.
pub struct Built {
    pub c: Condensed,
    h: DenseLdlt,
    w: Vec<f64>,
}

/// u and the physical multipliers λ of a status solution.
#[derive(Debug, Clone)]
pub struct Answer {
    pub u: Vec<f64>,
    pub lambda: Vec<f64>,
    pub active: Vec<bool>,
    pub iterations: usize,
}

pub const MINI: f64 = 1.0;
pub const MAXI: f64 = -1.0;

impl Dense {
    pub fn new(k: Mat<f64>, f: Vec<f64>) -> Self {
        Dense { k, rows: Vec::new(), sense: Vec::new(), d: Vec::new(), f }
    }
    /// Adds `row ⋈ d` with s = MINI or MAXI.
    pub fn cond(mut self, row: &[(usize, f64)], s: f64, d: f64) -> Self {
        self.rows.push(row.to_vec());
        self.sense.push(s);
        self.d.push(d);
        self
    }
    pub fn n(&self) -> usize {
        self.f.len()
    }
    pub fn dot(&self, i: usize, u: &[f64]) -> f64 {
        self.rows[i].iter().map(|&(j, v)| v * u[j]).sum()
    }
    /// The reactions R = −Cᵀλ.
    pub fn reactions(&self, lambda: &[f64]) -> Vec<f64> {
        let mut r = vec![0.0; self.n()];
        for (i, row) in self.rows.iter().enumerate() {
            for &(j, v) in row {
                r[j] -= v * lambda[i];
            }
        }
        r
    }
}

/// §2.2 scaling and §3.2 condensation, densely.
pub fn build(p: &Dense) -> Built {
    let (n, m) = (p.n(), p.rows.len());
    let kmax = (0..n).flat_map(|j| (0..n).map(move |i| (i, j))).fold(0.0_f64, |a, (i, j)| a.max(p.k[(i, j)].abs()));
    let (mut sigma, mut alpha, mut w) = (vec![0.0; m], vec![0.0; m], vec![0.0; m]);
    for (i, r) in p.rows.iter().enumerate() {
        let mut k = r
            .iter()
            .flat_map(|&(j, _)| (0..n).map(move |l| (j, l)))
            .fold(0.0_f64, |a, (j, l)| a.max(p.k[(j, l)].abs()));
        if k.is_nan() || k <= 1e-12 * kmax {
            k = if kmax > 0.0 { kmax } else { 1.0 };
        }
        let chat = r.iter().fold(1.0_f64, |a, &(_, v)| a.max(v.abs()));
        sigma[i] = 1.5 * k / chat;
        alpha[i] = 3.0 * k;
        w[i] = sigma[i] * sigma[i] / alpha[i];
    }
    let mut hm = p.k.clone();
    for (i, r) in p.rows.iter().enumerate() {
        for &(a, va) in r {
            for &(b, vb) in r {
                hm[(a, b)] += w[i] * va * vb;
            }
        }
    }
    let h = DenseLdlt::factor(hm.as_ref());
    // X = H⁻¹CᵀΣ column by column, u_F = H⁻¹(F + CᵀWd), H⁻¹F.
    let mut x = vec![vec![0.0; n]; m];
    for i in 0..m {
        for &(j, v) in &p.rows[i] {
            x[i][j] += sigma[i] * v;
        }
        h.solve_in_place(&mut x[i]);
    }
    let mut rhs = p.f.clone();
    for (i, row) in p.rows.iter().enumerate() {
        for &(j, v) in row {
            rhs[j] += v * w[i] * p.d[i];
        }
    }
    let mut uf = rhs.clone();
    h.solve_in_place(&mut uf);
    let mut hf = p.f.clone();
    h.solve_in_place(&mut hf);
    let g = Mat::<f64>::from_fn(m, m, |a, b| sigma[a] * p.dot(a, &x[b]));
    let hv = (0..m).map(|i| 0.5 * (sigma[i] * p.dot(i, &uf) - sigma[i] * p.d[i])).collect();
    let xtf = (0..m).map(|i| sigma[i] * p.dot(i, &hf)).collect();
    let c = Condensed {
        g: g.into(),
        g_factor: None,
        h: hv,
        alpha,
        sigma,
        sense: p.sense.clone(),
        xtf,
        rows: p.rows.clone(),
        d: p.d.clone(),
    };
    Built { c, h, w }
}

/// §3.3: u = H⁻¹(F + CᵀWd − 2CᵀΣx), λ_i = 2σ_i x_i when active.
pub fn recover(p: &Dense, b: &Built, r: &StatusResult) -> Answer {
    let mut rhs = p.f.clone();
    for (i, row) in p.rows.iter().enumerate() {
        for &(j, v) in row {
            rhs[j] += v * (b.w[i] * p.d[i] - 2.0 * b.c.sigma[i] * r.x[i]);
        }
    }
    b.h.solve_in_place(&mut rhs);
    let lambda = (0..r.x.len()).map(|i| if r.active[i] { 2.0 * b.c.sigma[i] * r.x[i] } else { 0.0 }).collect();
    Answer { u: rhs, lambda, active: r.active.clone(), iterations: r.records.len() }
}

/// One spring k to the ground on one dof, loaded by f.
pub fn spring(k: f64, f: f64) -> Dense {
    Dense::new(Mat::from_fn(1, 1, |_, _| k), vec![f])
}

/// Condenses, runs the status iteration and recovers.
pub fn solve(p: &Dense, opts: &StatusOptions) -> Result<Answer, SolveError> {
    let b = build(p);
    let r = operator::run(&b.c, opts, &mut |_| {})?;
    Ok(recover(p, &b, &r))
}

/// The status iteration's records, whatever the outcome.
pub fn solve_recording(p: &Dense, opts: &StatusOptions) -> (Result<Answer, SolveError>, Vec<IterRecord>) {
    let b = build(p);
    let mut recs = Vec::new();
    let r = operator::run(&b.c, opts, &mut |r| recs.push(r.clone()));
    (r.map(|r| recover(p, &b, &r)), recs)
}

/// The number of solves, whatever the outcome.
pub fn solve_counting(p: &Dense, opts: &StatusOptions) -> (Result<Answer, SolveError>, usize) {
    let (r, recs) = solve_recording(p, opts);
    (r, recs.len())
}

/// The old method with K_c = K (every dof in P).
pub fn solve_ancien(p: &Dense, opts: &StatusOptions) -> Result<ReducedResult, SolveError> {
    let pb = ReducedProblem {
        kc: &p.k,
        fc: &p.f,
        rows: &p.rows,
        sense: &p.sense,
        d: &p.d,
        k_ref: None,
        eq_rows: &[],
        eq_d: &[],
    };
    reduced::run(&pb, opts, &mut |_| {})
}

/// 2D Euler–Bernoulli beam over nodes at `x`, dofs (v, θ) per node.
pub fn beam(x: &[f64], ei: f64) -> Mat<f64> {
    let n = 2 * x.len();
    let mut k = Mat::<f64>::zeros(n, n);
    for e in 0..x.len() - 1 {
        let l = x[e + 1] - x[e];
        let c = ei / (l * l * l);
        let ke = [
            [12.0, 6.0 * l, -12.0, 6.0 * l],
            [6.0 * l, 4.0 * l * l, -6.0 * l, 2.0 * l * l],
            [-12.0, -6.0 * l, 12.0, -6.0 * l],
            [6.0 * l, 2.0 * l * l, -6.0 * l, 4.0 * l * l],
        ];
        for a in 0..4 {
            for b in 0..4 {
                k[(2 * e + a, 2 * e + b)] += c * ke[a][b];
            }
        }
    }
    k
}

/// Tiny xorshift generator: deterministic across platforms.
pub struct Rng(pub u64);

impl Rng {
    pub fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    /// Uniform in [−1, 1).
    pub fn sym(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    }
    pub fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
}

/// KKT check of a candidate (u, λ): equilibrium, feasibility, signs,
/// complementarity, relative to the problem's scales.
pub fn kkt_ok(p: &Dense, u: &[f64], lambda: &[f64], tol: f64) -> bool {
    let n = p.n();
    let umax = u.iter().fold(1e-300_f64, |a, v| a.max(v.abs()));
    let fmax = p.f.iter().chain(lambda).fold(1e-300_f64, |a, v| a.max(v.abs()));
    let kmax = (0..n).flat_map(|j| (0..n).map(move |i| (i, j))).fold(0.0_f64, |a, (i, j)| a.max(p.k[(i, j)].abs()));
    let r = p.reactions(lambda);
    let eq = (0..n).all(|i| {
        let ku: f64 = (0..n).map(|j| p.k[(i, j)] * u[j]).sum();
        (ku - p.f[i] - r[i]).abs() <= tol * (fmax + kmax * umax)
    });
    let ok_rows = (0..p.rows.len()).all(|i| {
        let chat = p.rows[i].iter().fold(1.0_f64, |a, &(_, v)| a.max(v.abs()));
        let gap = p.sense[i] * (p.dot(i, u) - p.d[i]) / chat;
        let scale = tol * (umax + p.d[i].abs() / chat);
        gap >= -scale && p.sense[i] * lambda[i] <= tol * fmax && (lambda[i].abs() <= tol * fmax || gap.abs() <= scale)
    });
    eq && ok_rows
}

/// Brute force: every status whose KKT system is regular and whose
/// solution satisfies the KKT conditions. Returns the first such u.
pub fn brute_force(p: &Dense) -> Option<(Vec<f64>, Vec<f64>)> {
    let (n, m) = (p.n(), p.rows.len());
    for mask in 0u32..(1 << m) {
        let act: Vec<usize> = (0..m).filter(|&i| mask >> i & 1 == 1).collect();
        let a = act.len();
        let mut kkt = Mat::<f64>::zeros(n + a, n + a);
        for j in 0..n {
            for i in 0..n {
                kkt[(i, j)] = p.k[(i, j)];
            }
        }
        let mut rhs = p.f.clone();
        for (q, &i) in act.iter().enumerate() {
            for &(j, v) in &p.rows[i] {
                kkt[(n + q, j)] += v;
                kkt[(j, n + q)] += v;
            }
            rhs.push(p.d[i]);
        }
        let lu = kkt.full_piv_lu();
        let sol = lu.solve(Mat::<f64>::from_fn(n + a, 1, |i, _| rhs[i]));
        // Regularity: a singular KKT matrix leaves a free mode (no unique
        // u), which random data never needs.
        let res = &kkt * &sol - Mat::<f64>::from_fn(n + a, 1, |i, _| rhs[i]);
        let bad = (0..n + a).any(|i| !sol[(i, 0)].is_finite() || res[(i, 0)].abs() > 1e-9 * (1.0 + rhs[i].abs()));
        let sv = kkt.singular_values().unwrap_or_default();
        let smax = sv.iter().fold(0.0_f64, |x, v| x.max(*v));
        if bad || sv.iter().any(|&s| s <= 1e-9 * smax) {
            continue;
        }
        let u: Vec<f64> = (0..n).map(|i| sol[(i, 0)]).collect();
        let mut lambda = vec![0.0; m];
        for (q, &i) in act.iter().enumerate() {
            lambda[i] = sol[(n + q, 0)];
        }
        if kkt_ok(p, &u, &lambda, 1e-9) {
            return Some((u, lambda));
        }
    }
    None
}
