//! ITER: the condensed method without a factorisation (unilateral.md §6,
//! 'OPTI RESO ITER'). G is formed column by column, one Jacobi-
//! preconditioned conjugate-gradient solve with the slave operator
//! H = K + C_UᵀWC_U per unilateral condition; the status loop is the one of
//! CONDENSE; u is recovered by one more solve.
//!
//! Bilateral conditions on one unknown (BLOQ) are eliminated (the unknown
//! is imposed, its multiplier is the reaction); H is then SPD on the free
//! unknowns whenever the problem is well posed, which CG needs. Bilateral
//! rows over several unknowns (RELA) would make the operator indefinite:
//! they are refused with a clear error.
//!
//! **When it pays.** m + 1 iterative solves against one factorisation for
//! CONDENSE: it pays only when a factorisation is out of reach (memory, 3D
//! meshes of millions of unknowns), with few conditions (m of a few tens),
//! and when a good preconditioner makes one solve much cheaper than one
//! factorisation. Re-solving the full system at every status with a
//! rebuilt preconditioner (Cast3M 2024's choice) pays when m exceeds the
//! number of status iterations times that cost ratio. With a direct solver
//! available, CONDENSE is always cheaper.

use super::error::SolveError;
use super::lagrange;
use super::problem::{Condensed, Load, Problem, Solution};
use super::status::{self, IterRecord, StatusOptions};
use super::unilateral::StatusError;

/// Relative residual at which a CG solve stops: G must match the direct
/// condensation to ≈ 1e-10.
const CG_TOL: f64 = 1e-14;

/// A symmetric matrix in CSR (both triangles).
struct Csr {
    ptr: Vec<usize>,
    col: Vec<usize>,
    val: Vec<f64>,
}

impl Csr {
    fn from_triplets(n: usize, t: &[(usize, usize, f64)]) -> Csr {
        let mut count = vec![0usize; n + 1];
        for &(r, _, _) in t {
            count[r + 1] += 1;
        }
        for r in 0..n {
            count[r + 1] += count[r];
        }
        let mut next = count.clone();
        let mut bucket = vec![(0usize, 0.0f64); t.len()];
        for &(r, c, v) in t {
            bucket[next[r]] = (c, v);
            next[r] += 1;
        }
        let (mut ptr, mut col, mut val) = (vec![0usize; n + 1], Vec::new(), Vec::new());
        for r in 0..n {
            let b = &mut bucket[count[r]..count[r + 1]];
            b.sort_unstable_by_key(|e| e.0);
            for &(c, v) in b.iter() {
                if col.len() > ptr[r] && col.last() == Some(&c) {
                    *val.last_mut().expect("non-empty") += v;
                } else {
                    col.push(c);
                    val.push(v);
                }
            }
            ptr[r + 1] = col.len();
        }
        Csr { ptr, col, val }
    }

    fn apply(&self, x: &[f64], y: &mut [f64]) {
        for (r, yr) in y.iter_mut().enumerate() {
            *yr = (self.ptr[r]..self.ptr[r + 1]).map(|k| self.val[k] * x[self.col[k]]).sum();
        }
    }

    fn diag(&self) -> Vec<f64> {
        (0..self.ptr.len() - 1)
            .map(|r| (self.ptr[r]..self.ptr[r + 1]).find(|&k| self.col[k] == r).map_or(0.0, |k| self.val[k]))
            .collect()
    }
}

/// Jacobi-preconditioned CG for the SPD `a`. Errors when CG breaks down
/// or stalls: H is then singular (a rigid mode held by nothing).
fn pcg(a: &Csr, inv_diag: &[f64], b: &[f64]) -> Result<Vec<f64>, SolveError> {
    let n = b.len();
    let mut x = vec![0.0; n];
    let bn = b.iter().map(|v| v * v).sum::<f64>().sqrt();
    if bn == 0.0 {
        return Ok(x);
    }
    let mut r = b.to_vec();
    let mut z: Vec<f64> = r.iter().zip(inv_diag).map(|(a, b)| a * b).collect();
    let mut p = z.clone();
    let mut rz: f64 = r.iter().zip(&z).map(|(a, b)| a * b).sum();
    let mut ap = vec![0.0; n];
    for _ in 0..(10 * n + 100) {
        a.apply(&p, &mut ap);
        let pap: f64 = p.iter().zip(&ap).map(|(a, b)| a * b).sum();
        if !(pap > 0.0 && pap.is_finite()) {
            break;
        }
        let step = rz / pap;
        for k in 0..n {
            x[k] += step * p[k];
            r[k] -= step * ap[k];
        }
        if r.iter().map(|v| v * v).sum::<f64>().sqrt() <= CG_TOL * bn {
            return Ok(x);
        }
        for k in 0..n {
            z[k] = r[k] * inv_diag[k];
        }
        let rz2: f64 = r.iter().zip(&z).map(|(a, b)| a * b).sum();
        let beta = rz2 / rz;
        rz = rz2;
        for k in 0..n {
            p[k] = z[k] + beta * p[k];
        }
    }
    Err(SolveError::Singular { dofs: Vec::new() })
}

/// ITER for `p` (unilateral conditions `uni`).
pub(super) fn solve(
    p: &Problem,
    load: &Load,
    uni: &[usize],
    sopts: &StatusOptions,
    on_iter: &mut dyn FnMut(&IterRecord),
    phases: &mut Vec<(&'static str, f64)>,
) -> Result<(Solution, Vec<bool>), StatusError> {
    let g = StatusError::Global;
    let t0 = std::time::Instant::now();
    lagrange::validate(p).map_err(g)?;
    super::direct::check_structure(p).map_err(g)?;
    if !p.k.symmetric {
        return Err(g(SolveError::Other("method ITER needs a symmetric stiffness".into())));
    }
    let (n, m) = (p.k.n, p.conditions.len());
    // Bilateral rows: each must fix one unknown.
    let mut fixed: Vec<Option<(usize, f64)>> = vec![None; n];
    let mut bil = Vec::new();
    for (i, c) in p.conditions.iter().enumerate() {
        if c.kind.is_unilateral() {
            continue;
        }
        let dof = c.terms[0].0;
        let coef: f64 = c.terms.iter().map(|e| e.1).sum();
        if c.terms.iter().any(|e| e.0 != dof) || coef == 0.0 {
            return Err(g(SolveError::Other(format!(
                "method ITER: bilateral condition {i} is a relation over several unknowns"
            ))));
        }
        fixed[dof] = Some((i, load.d[i] / coef));
        bil.push((i, dof, coef));
    }
    let mut local = vec![usize::MAX; n];
    let free: Vec<usize> = (0..n).filter(|&j| fixed[j].is_none()).collect();
    for (q, &j) in free.iter().enumerate() {
        local[j] = q;
    }
    let nf = free.len();
    // Assembled K (both triangles, read from one as the assembly does).
    let upper = p.k.entries.iter().any(|&(i, j, _)| i < j) || p.k.entries.is_empty();
    let mut kt = Vec::with_capacity(2 * p.k.entries.len());
    for &(i, j, v) in &p.k.entries {
        if if upper { i <= j } else { i >= j } {
            kt.push((i, j, v));
            if i != j {
                kt.push((j, i, v));
            }
        }
    }
    let k_full = Csr::from_triplets(n, &kt);
    let row_max: Vec<f64> =
        (0..n).map(|r| (k_full.ptr[r]..k_full.ptr[r + 1]).fold(0.0_f64, |a, k| a.max(k_full.val[k].abs()))).collect();
    let uni_p = Problem { k: Default::default(), conditions: uni.iter().map(|&i| p.conditions[i].clone()).collect() };
    let sc = lagrange::scaling(&uni_p, &row_max);
    // Unilateral rows on the free unknowns; imposed unknowns shift d.
    let mut rows: Vec<Vec<(usize, f64)>> = Vec::with_capacity(uni.len());
    let mut d = Vec::with_capacity(uni.len());
    for &i in uni {
        let mut r = Vec::new();
        let mut di = load.d[i];
        for &(j, v) in &p.conditions[i].terms {
            match fixed[j] {
                Some((_, gj)) => di -= v * gj,
                None => r.push((j, v)),
            }
        }
        if r.is_empty() {
            return Err(g(SolveError::DependentConditions { conditions: vec![i] }));
        }
        rows.push(r);
        d.push(di);
    }
    let w: Vec<f64> = (0..uni.len()).map(|q| sc.sigma[q] * sc.sigma[q] / sc.alpha[q]).collect();
    let mut ht: Vec<(usize, usize, f64)> = kt
        .iter()
        .filter(|e| local[e.0] != usize::MAX && local[e.1] != usize::MAX)
        .map(|&(i, j, v)| (local[i], local[j], v))
        .collect();
    for (q, r) in rows.iter().enumerate() {
        for &(a, va) in r {
            for &(b, vb) in r {
                ht.push((local[a], local[b], w[q] * va * vb));
            }
        }
    }
    let h = Csr::from_triplets(nf, &ht);
    let inv_diag: Vec<f64> = h.diag().iter().map(|&v| if v > 0.0 { 1.0 / v } else { 1.0 }).collect();
    // F on the free unknowns minus the imposed ones' forces.
    let mut ug = vec![0.0; n];
    for j in 0..n {
        if let Some((_, gj)) = fixed[j] {
            ug[j] = gj;
        }
    }
    let mut kug = vec![0.0; n];
    k_full.apply(&ug, &mut kug);
    let f_eff: Vec<f64> = free.iter().map(|&j| load.f[j] - kug[j]).collect();
    let sc_row = |q: usize, y: &[f64]| sc.sigma[q] * rows[q].iter().map(|&(j, v)| v * y[local[j]]).sum::<f64>();
    let mu = uni.len();
    let mut gm = faer::Mat::<f64>::zeros(mu, mu);
    for q in 0..mu {
        let mut b = vec![0.0; nf];
        for &(j, v) in &rows[q] {
            b[local[j]] += sc.sigma[q] * v;
        }
        let y = pcg(&h, &inv_diag, &b).map_err(g)?;
        for i in 0..mu {
            gm[(i, q)] = sc_row(i, &y);
        }
    }
    let mut rhs = f_eff.clone();
    for (q, r) in rows.iter().enumerate() {
        for &(j, v) in r {
            rhs[local[j]] += v * w[q] * d[q];
        }
    }
    let uf = pcg(&h, &inv_diag, &rhs).map_err(g)?;
    let hf = pcg(&h, &inv_diag, &f_eff).map_err(g)?;
    let cd = Condensed {
        g: gm,
        g_factor: None,
        h: (0..mu).map(|q| 0.5 * (sc_row(q, &uf) - sc.sigma[q] * d[q])).collect(),
        alpha: sc.alpha.clone(),
        sigma: sc.sigma.clone(),
        sense: uni.iter().map(|&i| p.conditions[i].kind.sense()).collect(),
        xtf: (0..mu).map(|q| sc_row(q, &hf)).collect(),
        rows: rows.clone(),
        d: d.clone(),
    };
    phases.push(("condense", t0.elapsed().as_secs_f64()));

    let t1 = std::time::Instant::now();
    let res = status::run(&cd, sopts, on_iter).map_err(StatusError::Local)?;
    phases.push(("status", t1.elapsed().as_secs_f64()));

    // §3.3: u = H⁻¹(F + CᵀWd − 2CᵀΣx).
    let t2 = std::time::Instant::now();
    for (q, r) in rows.iter().enumerate() {
        for &(j, v) in r {
            rhs[local[j]] -= 2.0 * v * sc.sigma[q] * res.x[q];
        }
    }
    let uf = pcg(&h, &inv_diag, &rhs).map_err(g)?;
    let mut u = ug;
    for (q, &j) in free.iter().enumerate() {
        u[j] = uf[q];
    }
    let mut lambda = vec![0.0; m];
    let mut active = vec![true; m];
    // Reactions at the imposed unknowns: F − K u − C_Uᵀλ_U.
    let mut react = vec![0.0; n];
    k_full.apply(&u, &mut react);
    for (q, &i) in uni.iter().enumerate() {
        active[i] = res.active[q];
        if res.active[q] {
            lambda[i] = 2.0 * sc.sigma[q] * res.x[q];
            for &(j, v) in &p.conditions[i].terms {
                react[j] += v * lambda[i];
            }
        }
    }
    for &(i, dof, coef) in &bil {
        lambda[i] = (load.f[dof] - react[dof]) / coef;
    }
    phases.push(("recover", t2.elapsed().as_secs_f64()));
    Ok((Solution { u, lambda, active }, res.active))
}
