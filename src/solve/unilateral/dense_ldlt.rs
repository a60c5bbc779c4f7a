//! Dense LDLᵀ without pivoting, with diagonal rank-one updates.
//!
//! Used for the condensed operator T = G − A·P_I (unilateral.md §3.5), which
//! is symmetric quasi-definite for every regular status: its LDLᵀ exists in
//! any ordering and the sign of pivot k is known in advance (+ for an active
//! condition, − for an inactive one). So no pivoting is needed, and a pivot of
//! the wrong sign or of negligible size is a free singularity test.
//!
//! A status change is T ± α_i e_i e_iᵀ. Only the trailing block from row i
//! of the factor depends on T_ii, so the update runs faer's rank-one LDLᵀ
//! update on that block alone (cost ≈ 2(m − i)² instead of m³/3).

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::cholesky::ldlt;
use faer::{Col, Mat, MatRef, Par};

/// Order from which the dense factorisation uses faer's global parallelism.
const PAR_MIN: usize = 300;

/// A packed LDLᵀ factor: D on the diagonal, the unit lower factor L strictly
/// below it. The strict upper triangle is never read.
#[derive(Debug, Clone)]
pub struct DenseLdlt {
    ld: Mat<f64>,
    /// Rank-one updates applied since the last factorisation from scratch.
    updates: usize,
}

impl DenseLdlt {
    /// Factors the symmetric matrix `a` (only its lower triangle is read).
    /// Never fails: a zero pivot leaves the later pivots as NaN so that
    /// [`DenseLdlt::first_bad_pivot`] points at the first failure.
    pub fn factor(a: MatRef<'_, f64>) -> Self {
        Self::factor_owned(a.to_owned())
    }

    /// [`DenseLdlt::factor`] in the storage of `a` (no copy of m² entries).
    pub fn factor_owned(a: Mat<f64>) -> Self {
        let n = a.nrows();
        let mut ld = a;
        // Threads only where they pay (m³/3 flops at m ≳ 300), as the
        // embedder set faer's global parallelism (Seq for none). The blocked
        // factorisation is deterministic for a given thread count.
        let par = if n >= PAR_MIN { faer::get_global_parallelism() } else { Par::Seq };
        let mut mem = MemBuffer::new(ldlt::factor::cholesky_in_place_scratch::<f64>(n, par, Default::default()));
        let stack = MemStack::new(&mut mem);
        let res = ldlt::factor::cholesky_in_place(ld.as_mut(), Default::default(), par, stack, Default::default());
        if let Err(ldlt::factor::LdltError::ZeroPivot { index }) = res {
            for k in index + 1..n {
                ld[(k, k)] = f64::NAN;
            }
        }
        DenseLdlt { ld, updates: 0 }
    }

    /// A factor computed elsewhere, packed as this type keeps it.
    pub fn from_packed(ld: Mat<f64>) -> Self {
        DenseLdlt { ld, updates: 0 }
    }

    /// The m² storage, for reuse by a later factorisation.
    pub fn into_storage(self) -> Mat<f64> {
        self.ld
    }

    pub fn dim(&self) -> usize {
        self.ld.nrows()
    }

    pub fn pivot(&self, k: usize) -> f64 {
        self.ld[(k, k)]
    }

    /// Number of rank-one updates since the last full factorisation.
    pub fn updates(&self) -> usize {
        self.updates
    }

    /// The first pivot that is not finite, has the wrong sign
    /// (`positive[k]` says which sign pivot k must have) or is negligible:
    /// `|d_k| ≤ eps·scale[k]`.
    pub fn first_bad_pivot(&self, positive: &[bool], scale: &[f64], eps: f64) -> Option<usize> {
        (0..self.dim()).find(|&k| {
            let d = self.pivot(k);
            let right_sign = if positive[k] { d > 0.0 } else { d < 0.0 };
            !d.is_finite() || !right_sign || d.abs() <= eps * scale[k]
        })
    }

    /// Turns the factor of A into the factor of A + delta·e_i e_iᵀ.
    pub fn update_diag(&mut self, i: usize, delta: f64) {
        let n = self.dim();
        if i >= n {
            return;
        }
        let k = n - i;
        // Rows and columns before i of the factor depend only on the leading
        // columns of A, which do not change.
        let sub = self.ld.as_mut().submatrix_mut(i, i, k, k);
        let mut w = Mat::<f64>::zeros(k, 1);
        w[(0, 0)] = 1.0;
        let mut alpha = Col::<f64>::from_fn(1, |_| delta);
        ldlt::update::rank_r_update_clobber(sub, w.as_mut(), alpha.as_diagonal_mut());
        self.updates += 1;
    }

    /// Turns the factor of A into the factor of `A + Σ_k deltas[k]·e_i e_iᵀ`
    /// (`i = idx[k]`, distinct) in one rank-r update of the trailing block
    /// from the smallest index: ≈ 2(m − i₀)²·r flops. Counts as one update.
    pub fn update_diags(&mut self, idx: &[usize], deltas: &[f64]) {
        let n = self.dim();
        let Some(&i0) = idx.iter().min() else { return };
        if idx.len() != deltas.len() || idx.iter().any(|&i| i >= n) {
            return;
        }
        let k = n - i0;
        let sub = self.ld.as_mut().submatrix_mut(i0, i0, k, k);
        let mut w = Mat::<f64>::zeros(k, idx.len());
        for (c, &i) in idx.iter().enumerate() {
            w[(i - i0, c)] = 1.0;
        }
        let mut alpha = Col::<f64>::from_fn(idx.len(), |c| deltas[c]);
        ldlt::update::rank_r_update_clobber(sub, w.as_mut(), alpha.as_diagonal_mut());
        self.updates += 1;
    }

    /// Solves A y = rhs in place (faer's blocked triangular solves).
    pub fn solve_in_place(&self, rhs: &mut [f64]) {
        let n = self.dim();
        if rhs.len() != n || n == 0 {
            return;
        }
        let y = faer::MatMut::from_column_major_slice_mut(rhs, n, 1);
        let mut stack = MemBuffer::new(ldlt::solve::solve_in_place_scratch::<f64>(n, 1, Par::Seq));
        ldlt::solve::solve_in_place_with_conj(
            self.ld.as_ref(),
            self.ld.diagonal(),
            faer::Conj::No,
            y,
            Par::Seq,
            MemStack::new(&mut stack),
        );
    }
}

#[cfg(test)]
#[path = "tests/dense_ldlt.rs"]
mod tests;
