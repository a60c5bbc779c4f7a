//! Elimination order for the doubled system (unilateral.md §2.3).
//!
//! Primal unknowns are ordered by AMD on the pattern of K + CᵀC (the fill
//! the first multipliers create is that of CᵀC), or by METIS nested
//! dissection when AMD's fill is that of a 3D mesh ([`primal_best`]). Then each λ1_i goes
//! immediately before the first of its unknowns and each λ2_i immediately
//! after the last, which is Cast3M's `optnum` rule: with it, LDLᵀ without
//! pivoting meets no zero pivot when the problem is well posed. Conditions
//! listed in `last` have their λ2 put at the very end instead, in the given
//! order, so that the trailing block of the factor is their condensed
//! operator (§3).
//!
//! The result is `fwd[new] = old` in the natural numbering of
//! [`super::lagrange`] (u, λ1, λ2).

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::sparse::linalg::amd;
use faer::sparse::linalg::cholesky::simplicial;
use faer::sparse::SymbolicSparseColMatRef;

use crate::solve::error::SolveError;
use crate::solve::problem::Problem;

/// Fill-reducing algorithm for the primal unknowns.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Algo {
    /// faer's approximate minimum degree.
    Amd,
    /// METIS nested dissection ([`super::nd`]).
    Nd,
}

/// AMD order of the primal unknowns on K + CᵀC: `perm[new] = old`.
/// `k_upper` may give the already assembled upper pattern of K (the first
/// n columns of the doubled matrix); it is used as is when no condition has
/// several terms and nothing is kept last, which saves rebuilding a
/// pattern from the raw entries.
pub fn primal_amd(
    p: &Problem,
    extra_last: &[usize],
    k_upper: Option<(&[usize], &[usize])>,
) -> Result<Vec<usize>, SolveError> {
    primal_order(p, extra_last, k_upper, Algo::Amd)
}

/// [`primal_amd`] with the choice of algorithm.
pub fn primal_order(
    p: &Problem,
    extra_last: &[usize],
    k_upper: Option<(&[usize], &[usize])>,
    algo: Algo,
) -> Result<Vec<usize>, SolveError> {
    primal_order_counted(p, extra_last, k_upper, algo).map(|r| r.0)
}

/// [`primal_order`], with AMD's own estimate of the factor's flops
/// (Σ column count², as [`factor_flops`]) when AMD ran.
fn primal_order_counted(
    p: &Problem,
    extra_last: &[usize],
    k_upper: Option<(&[usize], &[usize])>,
    algo: Algo,
) -> Result<(Vec<usize>, Option<f64>), SolveError> {
    let n = p.k.n;
    let run = |nf: usize, cp: &[usize], ri: &[usize]| match algo {
        Algo::Amd => amd_order(nf, cp, ri).map(|(perm, f)| (perm, Some(f))),
        Algo::Nd => super::nd::order(nf, cp, ri).map(|perm| (perm, None)),
    };
    let single = p.conditions.iter().all(|c| c.terms.len() <= 1);
    if let (Some((cp, ri)), true, true) = (k_upper, single, extra_last.is_empty()) {
        return run(n, &cp[..=n], &ri[..cp[n]]);
    }
    // Upper-triangle pairs of K + CᵀC (AMD symmetrises itself).
    let mut pairs: Vec<(usize, usize)> = Vec::with_capacity(p.k.entries.len() + n);
    for &(i, j, _) in &p.k.entries {
        pairs.push((i.min(j), i.max(j)));
    }
    for c in &p.conditions {
        for &(a, _) in &c.terms {
            for &(b, _) in &c.terms {
                if a < b {
                    pairs.push((a, b));
                }
            }
        }
    }
    let is_last = {
        let mut v = vec![false; n];
        for &j in extra_last {
            v[j] = true;
        }
        v
    };
    // Kept-last unknowns are taken out of the AMD graph and appended.
    let free: Vec<usize> = (0..n).filter(|&j| !is_last[j]).collect();
    let mut local = vec![usize::MAX; n];
    for (k, &j) in free.iter().enumerate() {
        local[j] = k;
    }
    let nf = free.len();
    let mut count = vec![0usize; nf + 1];
    let mut kept = Vec::with_capacity(pairs.len());
    for &(a, b) in &pairs {
        let (la, lb) = (local[a], local[b]);
        if la != usize::MAX && lb != usize::MAX {
            let (r, c) = (la.min(lb), la.max(lb));
            kept.push((r, c));
            count[c + 1] += 1;
        }
    }
    for c in 0..nf {
        count[c + 1] += count[c];
    }
    let mut next = count.clone();
    let mut rows = vec![0usize; kept.len()];
    for &(r, c) in &kept {
        rows[next[c]] = r;
        next[c] += 1;
    }
    let mut col_ptr = vec![0usize; nf + 1];
    let mut row_idx = Vec::with_capacity(rows.len());
    for c in 0..nf {
        let b = &mut rows[count[c]..count[c + 1]];
        b.sort_unstable();
        let mut last = usize::MAX;
        for &r in b.iter() {
            if r != last {
                row_idx.push(r);
                last = r;
            }
        }
        col_ptr[c + 1] = row_idx.len();
    }
    let (perm, flops) = run(nf, &col_ptr, &row_idx)?;
    let mut out: Vec<usize> = perm.iter().map(|&k| free[k]).collect();
    out.extend_from_slice(extra_last);
    Ok((out, flops))
}

/// Below this many estimated factor flops AMD is always kept: METIS costs
/// about as much as a small factorisation.
const ND_MIN_FLOPS: f64 = 5.0e9;
/// AMD flops per pattern entry above which nested dissection is tried. A
/// 2D grid of 262k unknowns has ~3·10³ (AMD is good there and METIS would
/// cost twice the factorisation), a 3D grid of 10⁵ unknowns ~3·10⁵ (ND
/// divides the flops by 2.5–3).
const ND_MIN_DENSITY: f64 = 2.0e4;
/// ND is kept when it saves at least this fraction of AMD's flops.
const ND_GAIN: f64 = 0.8;

/// The primal order with the fewest factor flops among AMD and, when AMD
/// fills a lot (3D meshes), METIS nested dissection. Arguments as
/// [`primal_amd`].
pub fn primal_best(
    p: &Problem,
    extra_last: &[usize],
    k_upper: Option<(&[usize], &[usize])>,
) -> Result<Vec<usize>, SolveError> {
    let (amd, estimate) = primal_order_counted(p, extra_last, k_upper, Algo::Amd)?;
    let Some((cp, ri)) = k_upper else { return Ok(amd) };
    let n = p.k.n;
    let (cp, ri) = (&cp[..=n], &ri[..cp[n]]);
    // AMD counts its own fill exactly (checked against the etree count on
    // the bench grids), which saves that pass (≈ 0.06 F in 2D).
    let f_amd = estimate.unwrap_or_else(|| factor_flops(n, cp, ri, &amd));
    if f_amd < ND_MIN_FLOPS || f_amd < ND_MIN_DENSITY * ri.len() as f64 {
        return Ok(amd);
    }
    let nd = primal_order(p, extra_last, Some((cp, ri)), Algo::Nd)?;
    Ok(if factor_flops(n, cp, ri, &nd) < ND_GAIN * f_amd { nd } else { amd })
}

/// Σ (column count)² of the Cholesky factor of the upper pattern
/// (`col_ptr`, `row_idx`) in the order `perm` (`perm[new] = old`): the
/// multiply-adds of the factorisation, from faer's elimination tree and
/// column counts (near-linear time, no symbolic factorisation).
pub fn factor_flops(n: usize, col_ptr: &[usize], row_idx: &[usize], perm: &[usize]) -> f64 {
    if n == 0 {
        return 0.0;
    }
    let inv = inverse(perm);
    let mut count = vec![0usize; n + 1];
    for c in 0..n {
        for &r in &row_idx[col_ptr[c]..col_ptr[c + 1]] {
            count[inv[r].max(inv[c]) + 1] += 1;
        }
    }
    for k in 0..n {
        count[k + 1] += count[k];
    }
    let mut next = count.clone();
    let mut rows = vec![0usize; count[n]];
    for c in 0..n {
        for &r in &row_idx[col_ptr[c]..col_ptr[c + 1]] {
            let (a, b) = (inv[r].min(inv[c]), inv[r].max(inv[c]));
            rows[next[b]] = a;
            next[b] += 1;
        }
    }
    for k in 0..n {
        rows[count[k]..count[k + 1]].sort_unstable();
    }
    let a = SymbolicSparseColMatRef::new_checked(n, n, &count, None, &rows);
    let mut etree = vec![0isize; n];
    let mut cc = vec![0usize; n];
    let mut mem = MemBuffer::new(simplicial::prefactorize_symbolic_cholesky_scratch::<usize>(n, rows.len()));
    simplicial::prefactorize_symbolic_cholesky(&mut etree, &mut cc, a, MemStack::new(&mut mem));
    cc.iter().map(|&c| (c as f64) * (c as f64)).sum()
}

/// faer's AMD on a sorted upper-triangle pattern.
/// Returns the order and AMD's estimate of Σ (column count)² of the factor.
fn amd_order(nf: usize, col_ptr: &[usize], row_idx: &[usize]) -> Result<(Vec<usize>, f64), SolveError> {
    let mut perm = vec![0usize; nf];
    let mut perm_inv = vec![0usize; nf];
    let mut flops = 0.0;
    if nf > 0 {
        let a = SymbolicSparseColMatRef::new_checked(nf, nf, col_ptr, None, row_idx);
        let mut mem = MemBuffer::try_new(amd::order_scratch::<usize>(nf, row_idx.len()))
            .map_err(|_| SolveError::Other("out of memory in AMD".into()))?;
        let count = amd::order(&mut perm, &mut perm_inv, a, amd::Control::default(), MemStack::new(&mut mem))
            .map_err(|e| SolveError::Other(format!("AMD failed: {e:?}")))?;
        // AMD counts Σ l(l+2)/2 multiply-subtracts and Σ l divisions (l
        // the below-diagonal count): Σ (l + 1)² = 2·mult + divisions + n.
        flops = 2.0 * count.n_mult_subs_ldl + count.n_div + nf as f64;
    }
    Ok((perm, flops))
}

/// Full elimination order of the doubled system from a primal order:
/// every λ1 first, λ2 after the last unknown of its row, except the
/// conditions of `last`, whose λ2 close the order (in that order).
///
/// "λ1 before the first unknown of its row" is all the pivoting rule asks,
/// and the fill is the same wherever λ1 sits before it. Putting them all at
/// the front keeps chains of primal unknowns contiguous, so that they merge
/// into wide supernodes: a λ1 between two unknowns of a chain cuts it, and
/// on a 3D contact face that made the factorisation 1.9× slower for the
/// same flops (benches/profile).
pub fn doubled_order(p: &Problem, primal: &[usize], last: &[usize]) -> Vec<usize> {
    let n = p.k.n;
    let m = p.conditions.len();
    let mut fwd: Vec<usize> = (n..n + m).collect();
    fwd.extend(doubled_order_interleaved(p, primal, last).into_iter().filter(|&o| o < n || o >= n + m));
    fwd
}

/// [`doubled_order`] with each λ1 immediately before the first unknown of
/// its row (Cast3M's `optnum` layout): a condensation onto chosen unknowns
/// wants the λ1 of conditions on kept unknowns inside the trailing block.
pub fn doubled_order_interleaved(p: &Problem, primal: &[usize], last: &[usize]) -> Vec<usize> {
    let n = p.k.n;
    let m = p.conditions.len();
    let mut at = vec![0usize; n];
    for (k, &j) in primal.iter().enumerate() {
        at[j] = k;
    }
    let mut is_last = vec![false; m];
    for &c in last {
        is_last[c] = true;
    }
    // For each primal position, the conditions opening and closing there.
    let mut opens: Vec<Vec<usize>> = vec![Vec::new(); n];
    let mut closes: Vec<Vec<usize>> = vec![Vec::new(); n];
    for (ci, c) in p.conditions.iter().enumerate() {
        let first = c.terms.iter().map(|&(j, _)| at[j]).min().unwrap_or(0);
        let lastp = c.terms.iter().map(|&(j, _)| at[j]).max().unwrap_or(0);
        if n > 0 {
            opens[first].push(ci);
            if !is_last[ci] {
                closes[lastp].push(ci);
            }
        }
    }
    let mut fwd = Vec::with_capacity(n + 2 * m);
    for (k, &j) in primal.iter().enumerate() {
        fwd.extend(opens[k].iter().map(|&ci| n + ci));
        fwd.push(j);
        fwd.extend(closes[k].iter().map(|&ci| n + m + ci));
    }
    fwd.extend(last.iter().map(|&ci| n + m + ci));
    fwd
}

/// Inverse permutation: `inv[old] = new`.
pub fn inverse(fwd: &[usize]) -> Vec<usize> {
    let mut inv = vec![0usize; fwd.len()];
    for (k, &o) in fwd.iter().enumerate() {
        inv[o] = k;
    }
    inv
}

#[cfg(test)]
#[path = "tests/ordering.rs"]
mod tests;
