//! ITER: the condensed method without a factorisation (unilateral.md §6,
//! 'OPTI RESO ITER'). G is formed column by column, one IC(0)-
//! preconditioned conjugate-gradient solve with the slave operator
//! H = K + C_UᵀWC_U per unilateral condition; the status loop is the one of
//! CONDENSE; u is recovered by one more solve.
//!
//! Bilateral conditions (BLOQ and RELA) are eliminated by substitution
//! ([`crate::solve::bilateral::eliminate`]): each gets a slave unknown expressed over the
//! others, and H = TᵀKT + C_UᵀWC_U on the masters is SPD whenever the
//! problem is well posed, which CG needs (doubled multipliers would make
//! it indefinite). Their multipliers come back from the residual forces.
//!
//! **When it pays.** m + 1 iterative solves against one factorisation for
//! CONDENSE: it pays only when a factorisation is out of reach (memory, 3D
//! meshes of millions of unknowns), with few conditions (m of a few tens),
//! and when a good preconditioner makes one solve much cheaper than one
//! factorisation. Re-solving the full system at every status with a
//! rebuilt preconditioner (Cast3M 2024's choice) pays when m exceeds the
//! number of status iterations times that cost ratio. With a direct solver
//! available, CONDENSE is always cheaper.

use super::backend::{to_global, Job, Outcome, StatusError, Trace};
use super::condensed::{operator, Condensed};
use super::status::{IterRecord, StatusOptions};
use crate::solve::bilateral::eliminate::Elimination;
use crate::solve::bilateral::lagrange;
use crate::solve::error::SolveError;
use crate::solve::problem::{Problem, Solution};

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
}

/// Incomplete Cholesky IC(0) of an SPD CSR matrix (Cast3M's iterative
/// solver uses ILU(0), its non-symmetric twin): L has the pattern of the
/// lower triangle, each row's diagonal last. Where the incomplete
/// elimination breaks down (a non-positive pivot, possible for matrices
/// that are not M-matrices), the factorisation is redone on A + s·diag(A)
/// with a growing shift s (Manteuffel).
struct Ic0 {
    ptr: Vec<usize>,
    col: Vec<usize>,
    val: Vec<f64>,
}

impl Ic0 {
    fn new(a: &Csr) -> Ic0 {
        let (ptr, col, base) = Self::lower(a);
        let mut shift = 0.0;
        loop {
            if let Some(val) = Self::factor(&ptr, &col, &base, shift) {
                return Ic0 { ptr, col, val };
            }
            shift = if shift == 0.0 { 1e-3 } else { 4.0 * shift };
        }
    }

    /// The lower triangle of `a` (pattern and values), each row's diagonal
    /// last, kept even where A has no entry.
    fn lower(a: &Csr) -> (Vec<usize>, Vec<usize>, Vec<f64>) {
        let n = a.ptr.len() - 1;
        let mut ptr = vec![0usize; n + 1];
        let (mut col, mut val) = (Vec::new(), Vec::new());
        for r in 0..n {
            for k in a.ptr[r]..a.ptr[r + 1] {
                if a.col[k] < r {
                    col.push(a.col[k]);
                    val.push(a.val[k]);
                }
            }
            col.push(r);
            val.push((a.ptr[r]..a.ptr[r + 1]).find(|&k| a.col[k] == r).map_or(0.0, |k| a.val[k]));
            ptr[r + 1] = col.len();
        }
        (ptr, col, val)
    }

    /// The factor of A + shift·diag(A), or None on a breakdown.
    fn factor(ptr: &[usize], col: &[usize], base: &[f64], shift: f64) -> Option<Vec<f64>> {
        let n = ptr.len() - 1;
        let mut val = base.to_vec();
        for i in 0..n {
            let (ri, di) = (ptr[i], ptr[i + 1] - 1);
            for p in ri..di {
                let k = col[p];
                // L[i,k] = (A[i,k] − Σ_j L[i,j] L[k,j]) / L[k,k], j < k, by a
                // merge of the two sorted rows.
                let (mut a, mut b, kd) = (ri, ptr[k], ptr[k + 1] - 1);
                let mut dot = 0.0;
                while a < p && b < kd {
                    match col[a].cmp(&col[b]) {
                        std::cmp::Ordering::Less => a += 1,
                        std::cmp::Ordering::Greater => b += 1,
                        std::cmp::Ordering::Equal => {
                            dot += val[a] * val[b];
                            a += 1;
                            b += 1;
                        }
                    }
                }
                val[p] = (val[p] - dot) / val[kd];
            }
            let sq: f64 = val[ri..di].iter().map(|v| v * v).sum();
            let d = val[di] * (1.0 + shift) - sq;
            if !(d > 0.0 && d.is_finite()) {
                return None;
            }
            val[di] = d.sqrt();
        }
        Some(val)
    }

    /// z = (L Lᵀ)⁻¹ r.
    fn apply(&self, r: &[f64], z: &mut [f64]) {
        let n = r.len();
        for i in 0..n {
            let (ri, di) = (self.ptr[i], self.ptr[i + 1] - 1);
            let s: f64 = (ri..di).map(|p| self.val[p] * z[self.col[p]]).sum();
            z[i] = (r[i] - s) / self.val[di];
        }
        for i in (0..n).rev() {
            let (ri, di) = (self.ptr[i], self.ptr[i + 1] - 1);
            z[i] /= self.val[di];
            let zi = z[i];
            for p in ri..di {
                z[self.col[p]] -= self.val[p] * zi;
            }
        }
    }
}

/// IC(0)-preconditioned CG for the SPD `a`. Errors when CG breaks down
/// or stalls: H is then singular (a rigid mode held by nothing).
fn pcg(a: &Csr, pre: &Ic0, b: &[f64]) -> Result<Vec<f64>, SolveError> {
    let n = b.len();
    let mut x = vec![0.0; n];
    let bn = b.iter().map(|v| v * v).sum::<f64>().sqrt();
    if bn == 0.0 {
        return Ok(x);
    }
    let mut r = b.to_vec();
    let mut z = vec![0.0; n];
    pre.apply(&r, &mut z);
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
        pre.apply(&r, &mut z);
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
pub(super) fn solve(job: &Job, trace: &mut Trace) -> Outcome {
    let Job { p, load, uni, sopts } = *job;
    let Trace { on_iter, phases } = trace;
    let g = StatusError::Global;
    let t0 = std::time::Instant::now();
    lagrange::validate(p).map_err(g)?;
    crate::solve::bilateral::direct::check_structure(p).map_err(g)?;
    if !p.k.symmetric {
        return Err(g(SolveError::Other("method ITER needs a symmetric stiffness".into())));
    }
    let (n, m) = (p.k.n, p.conditions.len());
    // Bilateral rows (BLOQ and RELA) are eliminated by substitution: H
    // stays positive definite on the masters, which CG needs.
    let el = Elimination::new(p, &load.d).map_err(g)?;
    let nf = el.masters.len();
    let local = &el.local;
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
    let all_uni = uni;
    // Unilateral rows over the masters; the eliminated part shifts d.
    // A row the eliminated conditions fix entirely (a RELA 'MINI' between
    // two blocked nodes) has a constant value: it holds or it conflicts,
    // and never acts (as the status loop drops such rows).
    let mut kept: Vec<usize> = Vec::with_capacity(uni.len());
    let mut rows: Vec<Vec<(usize, f64)>> = Vec::with_capacity(uni.len());
    let mut d = Vec::with_capacity(uni.len());
    for &i in uni {
        let (r, k0) = el.reduce(&p.conditions[i].terms);
        if r.is_empty() {
            let c = &p.conditions[i];
            let chat = c.terms.iter().fold(1.0_f64, |a, t| a.max(t.1.abs()));
            if c.kind.sense() * (k0 - load.d[i]) < -1e-10 * chat.max(load.d[i].abs()).max(k0.abs()) {
                return Err(g(SolveError::Conflicting { conditions: vec![i] }));
            }
            continue;
        }
        kept.push(i);
        rows.push(r);
        d.push(load.d[i] - k0);
    }
    let uni = &kept[..];
    let uni_p = Problem { k: Default::default(), conditions: uni.iter().map(|&i| p.conditions[i].clone()).collect() };
    let sc = lagrange::scaling(&uni_p, &row_max);
    let w: Vec<f64> = (0..uni.len()).map(|q| sc.sigma[q] * sc.sigma[q] / sc.alpha[q]).collect();
    // H = TᵀKT + C_UᵀWC_U on the masters; F_eff = Tᵀ(F − K g).
    let mut ht: Vec<(usize, usize, f64)> = Vec::with_capacity(kt.len());
    let mut f_eff = vec![0.0; nf];
    let mut ti: Vec<(usize, f64)> = Vec::new();
    for &(i, j, v) in &kt {
        if local[i] != usize::MAX && local[j] != usize::MAX {
            ht.push((local[i], local[j], v));
            continue;
        }
        ti.clear();
        el.expand(i, |a, t| ti.push((a, t)));
        let cj = el.expand(j, |b, t| {
            for &(a, s) in &ti {
                ht.push((local[a], local[b], v * s * t));
            }
        });
        for &(a, s) in &ti {
            f_eff[local[a]] -= v * s * cj;
        }
    }
    for (i, &fi) in load.f.iter().enumerate() {
        el.expand(i, |a, t| f_eff[local[a]] += t * fi);
    }
    for (q, r) in rows.iter().enumerate() {
        for &(a, va) in r {
            for &(b, vb) in r {
                ht.push((local[a], local[b], w[q] * va * vb));
            }
        }
    }
    let h = Csr::from_triplets(nf, &ht);
    let pre = Ic0::new(&h);
    let sc_row = |q: usize, y: &[f64]| sc.sigma[q] * rows[q].iter().map(|&(j, v)| v * y[local[j]]).sum::<f64>();
    let mu = uni.len();
    let mut gm = faer::Mat::<f64>::zeros(mu, mu);
    for q in 0..mu {
        let mut b = vec![0.0; nf];
        for &(j, v) in &rows[q] {
            b[local[j]] += sc.sigma[q] * v;
        }
        let y = pcg(&h, &pre, &b).map_err(g)?;
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
    let uf = pcg(&h, &pre, &rhs).map_err(g)?;
    let hf = pcg(&h, &pre, &f_eff).map_err(g)?;
    let cd = Condensed {
        g: std::rc::Rc::new(gm),
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
    // Positions among the kept rows ↔ among all unilateral rows.
    let pos: Vec<usize> = uni.iter().map(|i| all_uni.iter().position(|j| j == i).expect("kept from all")).collect();
    let local_opts =
        StatusOptions { start: sopts.start.as_ref().map(|s| pos.iter().map(|&q| s[q]).collect()), ..sopts.clone() };
    let remap = |v: &[usize]| v.iter().map(|&q| pos[q]).collect::<Vec<_>>();
    let res = operator::run(&cd, &local_opts, &mut |r: &IterRecord| {
        on_iter(&IterRecord { activated: remap(&r.activated), released: remap(&r.released), ..r.clone() })
    })
    .map_err(|e| StatusError::Local(to_global(e, &pos)))?;
    phases.push(("status", t1.elapsed().as_secs_f64()));

    // §3.3: u = H⁻¹(F + CᵀWd − 2CᵀΣx).
    let t2 = std::time::Instant::now();
    for (q, r) in rows.iter().enumerate() {
        for &(j, v) in r {
            rhs[local[j]] -= 2.0 * v * sc.sigma[q] * res.x[q];
        }
    }
    let uf = pcg(&h, &pre, &rhs).map_err(g)?;
    let u = el.unknowns(&uf);
    let mut lambda = vec![0.0; m];
    let mut active = vec![true; m];
    for &i in all_uni {
        active[i] = false;
    }
    // The eliminated rows supply what K u and the unilateral reactions
    // leave unbalanced: F − K u − C_Uᵀλ_U.
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
    let unbalanced: Vec<f64> = load.f.iter().zip(&react).map(|(f, r)| f - r).collect();
    for (i, l) in el.multipliers(p, &unbalanced).map_err(g)? {
        lambda[i] = l;
    }
    phases.push(("recover", t2.elapsed().as_secs_f64()));
    let statuses = all_uni.iter().map(|&i| active[i]).collect();
    Ok((Solution { u, lambda, active }, statuses))
}

#[cfg(test)]
#[path = "tests/iterative.rs"]
mod tests;
