//! Thin wrappers over faer's sparse factorisations: "symbolic once, numeric
//! many".
//!
//! * [`SymFactor`]: supernodal LDLᵀ without pivoting and without
//!   regularisation, in an elimination order we choose
//!   (`SymmetricOrdering::Custom`). It is always supernodal so that the
//!   factor can be read block by block (condensation, partial solves).
//! * [`LuFactor`]: sparse LU with partial pivoting for non-symmetric
//!   matrices.
//!
//! **Same-structure contract.** A factor is analysed for one CSC pattern
//! (`col_ptr`, `row_idx`, upper triangle for [`SymFactor`]). Every later
//! [`SymFactor::factor`] / [`LuFactor::refactor`] must pass values laid out
//! on exactly that pattern; only the numbers may change. The caller
//! ([`super::lagrange::Doubled`]) guarantees it by scattering new values
//! through a fixed map instead of rebuilding the pattern.
//!
//! A pivot with |d_k| ≤ [`PIVOT_TOL`] · (largest |entry| of row k) is treated
//! as zero: faer only rejects exact zeros, and a free rigid mode leaves a
//! round-off pivot, not an exact one.

use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::cholesky::ldlt::factor::LdltRegularization;
use faer::linalg::solvers::SolveCore;
use faer::prelude::{Reborrow, ReborrowMut};
use faer::sparse::linalg::cholesky::{
    factorize_symbolic_cholesky, supernodal::SupernodalLdltRef, supernodal::SymbolicSupernodalCholesky,
    CholeskySymbolicParams, LdltRef, SymbolicCholesky, SymbolicCholeskyRaw, SymmetricOrdering,
};
use faer::sparse::linalg::solvers::{Lu, SymbolicLu};
use faer::sparse::linalg::SupernodalThreshold;
use faer::sparse::{SparseColMatRef, SymbolicSparseColMatRef};
use faer::{Conj, Mat, MatMut, Par};

use crate::solve::error::SolveError;

/// Relative size under which a pivot counts as zero.
pub const PIVOT_TOL: f64 = 1e-12;

/// A failed numeric factorisation: the position (natural numbering) of the
/// first pivot that vanished.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ZeroPivot {
    pub index: usize,
}

fn oom() -> SolveError {
    SolveError::Other("out of memory in the sparse factorisation".into())
}

/// Flops per factor entry above which threads pay for the numeric
/// factorisation. Measured on 2 cores: 2D meshes (≈ 200–700 flops per
/// entry, many small supernodes) run faster sequentially (0.27–0.47 s
/// against 0.32–0.61 s at n = 262k), 3D ones (≈ 2,500) 1.4–1.6× faster with
/// threads (solver-notes §1.1 saw the same).
const PAR_FLOPS_PER_ENTRY: f64 = 1000.0;

/// faer's global parallelism for factors dense enough to use it, else
/// sequential.
fn choose_par(symbolic: &SymbolicCholesky<usize>) -> Par {
    let SymbolicCholeskyRaw::Supernodal(sup) = symbolic.raw() else {
        return Par::Seq;
    };
    let mut flops = 0.0_f64;
    for s in 0..sup.n_supernodes() {
        let w = sup.supernode_end()[s] - sup.supernode_begin()[s];
        let r = (w + sup.supernode(s).pattern().len()) as f64;
        // Σ_k (r − k)² over the w columns, in closed form.
        let w = w as f64;
        flops += w * r * r - r * w * (w - 1.0) + (w - 1.0) * w * (2.0 * w - 1.0) / 6.0;
    }
    let nnz = symbolic.len_val().max(1) as f64;
    if flops / nnz >= PAR_FLOPS_PER_ENTRY {
        faer::get_global_parallelism()
    } else {
        Par::Seq
    }
}

/// Supernodal LDLᵀ in a fixed elimination order.
#[derive(Debug)]
pub struct SymFactor {
    symbolic: SymbolicCholesky<usize>,
    l: Vec<f64>,
    fwd: Vec<usize>,
    inv: Vec<usize>,
    n: usize,
    par: Par,
    factored: bool,
}

impl SymFactor {
    /// Symbolic analysis of the upper-triangle pattern in the order `fwd`
    /// (`fwd[new] = old`).
    pub fn analyse(col_ptr: &[usize], row_idx: &[usize], fwd: Vec<usize>) -> Result<Self, SolveError> {
        let n = col_ptr.len() - 1;
        let inv = super::ordering::inverse(&fwd);
        let a = SymbolicSparseColMatRef::new_checked(n, n, col_ptr, None, row_idx);
        let perm = faer::perm::PermRef::new_checked(&fwd, &inv, n);
        let params = CholeskySymbolicParams {
            supernodal_flop_ratio_threshold: SupernodalThreshold::FORCE_SUPERNODAL,
            ..Default::default()
        };
        let symbolic = factorize_symbolic_cholesky(a, faer::Side::Upper, SymmetricOrdering::Custom(perm), params)
            .map_err(|e| SolveError::Other(format!("symbolic analysis failed: {e:?}")))?;
        let l = vec![0.0; symbolic.len_val()];
        let par = choose_par(&symbolic);
        Ok(SymFactor { symbolic, l, fwd, inv, n, par, factored: false })
    }

    pub fn dim(&self) -> usize {
        self.n
    }

    /// Marks the factor unusable (after a failed or perturbed factorisation).
    pub fn invalidate(&mut self) {
        self.factored = false;
    }
    pub fn fwd(&self) -> &[usize] {
        &self.fwd
    }
    pub fn inv(&self) -> &[usize] {
        &self.inv
    }

    /// The supernodal structure (always supernodal: see the module doc).
    pub fn supernodal(&self) -> &SymbolicSupernodalCholesky<usize> {
        match self.symbolic.raw() {
            SymbolicCholeskyRaw::Supernodal(s) => s,
            // FORCE_SUPERNODAL makes this unreachable; n == 0 aside.
            SymbolicCholeskyRaw::Simplicial(_) => unreachable!("forced supernodal"),
        }
    }

    /// The factor values, for block access with
    /// `SupernodalLdltRef::new(self.supernodal(), self.values())`.
    pub fn values(&self) -> &[f64] {
        &self.l
    }

    pub fn ldlt_ref(&self) -> SupernodalLdltRef<'_, usize, f64> {
        SupernodalLdltRef::new(self.supernodal(), &self.l)
    }

    /// Numeric LDLᵀ of the values laid out on the analysed pattern.
    /// `row_scale` (natural numbering) is the reference of the tiny-pivot
    /// test, applied to the pivots before position `limit` of the
    /// elimination order only (a trailing block being condensed may be
    /// singular without harm). `regularise = Some((signs, delta, eps))` replaces small or
    /// wrong-sign pivots (diagnostics only: the answer is perturbed).
    pub fn factor(
        &mut self,
        col_ptr: &[usize],
        row_idx: &[usize],
        values: &[f64],
        row_scale: &[f64],
        limit: usize,
        regularise: Option<(&[i8], f64, f64)>,
    ) -> Result<(), ZeroPivot> {
        self.factored = false;
        let n = self.n;
        if n == 0 {
            self.factored = true;
            return Ok(());
        }
        let a = SparseColMatRef::new(SymbolicSparseColMatRef::new_checked(n, n, col_ptr, None, row_idx), values);
        let reg = match regularise {
            Some((signs, delta, eps)) => LdltRegularization {
                dynamic_regularization_signs: Some(signs),
                dynamic_regularization_delta: delta,
                dynamic_regularization_epsilon: eps,
            },
            None => LdltRegularization::default(),
        };
        let req = self.symbolic.factorize_numeric_ldlt_scratch::<f64>(self.par, Default::default());
        let Ok(mut mem) = MemBuffer::try_new(req) else {
            return Err(ZeroPivot { index: usize::MAX });
        };
        let res = self.symbolic.factorize_numeric_ldlt(
            &mut self.l,
            a,
            faer::Side::Upper,
            reg,
            self.par,
            MemStack::new(&mut mem),
            Default::default(),
        );
        if let Err(e) = res {
            let faer::linalg::cholesky::ldlt::factor::LdltError::ZeroPivot { index } = e;
            return Err(ZeroPivot { index: self.fwd[index.min(n - 1)] });
        }
        if regularise.is_none() {
            if let Some(k) = self.first_tiny_pivot(row_scale, limit) {
                return Err(ZeroPivot { index: self.fwd[k] });
            }
        }
        self.factored = true;
        Ok(())
    }

    /// Position (elimination order) of the first pivot below the threshold.
    fn first_tiny_pivot(&self, row_scale: &[f64], limit: usize) -> Option<usize> {
        let f = self.ldlt_ref();
        let sym = self.supernodal();
        for s in 0..sym.n_supernodes() {
            let sn = f.supernode(s);
            let v = sn.val();
            for c in 0..v.ncols() {
                let k = sn.start() + c;
                if k >= limit {
                    return None;
                }
                let d = v[(c, c)];
                let scale = row_scale[self.fwd[k]];
                if !d.is_finite() || d.abs() <= PIVOT_TOL * scale || d == 0.0 {
                    return Some(k);
                }
            }
        }
        None
    }

    /// The pivots d_k in elimination order.
    pub fn pivots(&self) -> Vec<f64> {
        let f = self.ldlt_ref();
        let mut d = Vec::with_capacity(self.n);
        for s in 0..self.supernodal().n_supernodes() {
            let v = f.supernode(s).val();
            d.extend((0..v.ncols()).map(|c| v[(c, c)]));
        }
        d
    }

    /// Solves in place for several right-hand sides (natural numbering).
    pub fn solve_in_place(&self, rhs: MatMut<'_, f64>) -> Result<(), SolveError> {
        if !self.factored {
            return Err(SolveError::Other("solve without a valid factor".into()));
        }
        if self.n == 0 {
            return Ok(());
        }
        let req = self.symbolic.solve_in_place_scratch::<f64>(rhs.ncols(), self.par);
        let mut mem = MemBuffer::try_new(req).map_err(|_| oom())?;
        LdltRef::new(&self.symbolic, &self.l).solve_in_place_with_conj(
            Conj::No,
            rhs,
            self.par,
            MemStack::new(&mut mem),
        );
        Ok(())
    }

    /// Scratch for the partial substitutions: the tallest supernode panel
    /// times the number of right-hand sides (allocated once per call, not
    /// once per supernode).
    fn scratch(&self, k: usize) -> Mat<f64> {
        let f = self.ldlt_ref();
        let rows = (0..self.supernodal().n_supernodes()).map(|s| f.supernode(s).val().nrows()).max().unwrap_or(0);
        Mat::zeros(rows, k)
    }

    // The partial substitutions run sequentially: they are memory-bound,
    // and most supernodes are so small that spawning threads for each
    // panel costs more than the arithmetic (measured 15× slower).

    /// Forward substitution `x ← L⁻¹ x` restricted to the columns `< cut`
    /// of the elimination order (x in elimination order). Rows `≥ cut`
    /// receive the updates, so afterwards they hold the right-hand side of
    /// the Schur complement system on the trailing block.
    pub fn forward_partial(&self, mut x: MatMut<'_, f64>, cut: usize) {
        let f = self.ldlt_ref();
        let k = x.ncols();
        let mut scratch = self.scratch(k);
        for s in 0..self.supernodal().n_supernodes() {
            let sn = f.supernode(s);
            let start = sn.start();
            if start >= cut {
                break;
            }
            let v = sn.val();
            let ncols = v.ncols();
            let w = ncols.min(cut - start);
            let top = v.submatrix(0, 0, w, w);
            faer::linalg::triangular_solve::solve_unit_lower_triangular_in_place(
                top,
                x.rb_mut().subrows_mut(start, w),
                Par::Seq,
            );
            let rest = v.submatrix(w, 0, v.nrows() - w, w);
            let nr = rest.nrows();
            let mut tmp = scratch.as_mut().submatrix_mut(0, 0, nr, k);
            faer::linalg::matmul::matmul(
                tmp.rb_mut(),
                faer::Accum::Replace,
                rest,
                x.rb().subrows(start, w),
                1.0,
                Par::Seq,
            );
            let pattern = sn.pattern();
            for j in 0..k {
                for r in 0..nr {
                    let row = if r + w < ncols { start + w + r } else { pattern[r + w - ncols] };
                    x[(row, j)] -= tmp[(r, j)];
                }
            }
        }
    }

    /// Divides the rows `< cut` by their pivot.
    pub fn diagonal_partial(&self, mut x: MatMut<'_, f64>, cut: usize) {
        let d = self.pivots();
        for (k, &dk) in d.iter().enumerate().take(cut) {
            for j in 0..x.ncols() {
                x[(k, j)] /= dk;
            }
        }
    }

    /// Back substitution `x ← L⁻ᵀ x` on the columns `< cut`, with the rows
    /// `≥ cut` taken as already known (the trailing unknowns).
    pub fn backward_partial(&self, mut x: MatMut<'_, f64>, cut: usize) {
        let f = self.ldlt_ref();
        let k = x.ncols();
        let mut scratch = self.scratch(k);
        for s in (0..self.supernodal().n_supernodes()).rev() {
            let sn = f.supernode(s);
            let start = sn.start();
            if start >= cut {
                continue;
            }
            let v = sn.val();
            let ncols = v.ncols();
            let w = ncols.min(cut - start);
            let rest = v.submatrix(w, 0, v.nrows() - w, w);
            let nr = rest.nrows();
            let pattern = sn.pattern();
            let mut gathered = scratch.as_mut().submatrix_mut(0, 0, nr, k);
            for j in 0..k {
                for r in 0..nr {
                    let row = if r + w < ncols { start + w + r } else { pattern[r + w - ncols] };
                    gathered[(r, j)] = x[(row, j)];
                }
            }
            faer::linalg::matmul::matmul(
                x.rb_mut().subrows_mut(start, w),
                faer::Accum::Add,
                rest.transpose(),
                gathered.rb(),
                -1.0,
                Par::Seq,
            );
            let top = v.submatrix(0, 0, w, w);
            faer::linalg::triangular_solve::solve_unit_upper_triangular_in_place(
                top.transpose(),
                x.rb_mut().subrows_mut(start, w),
                Par::Seq,
            );
        }
    }
}

/// Sparse LU (COLAMD + partial pivoting) for non-symmetric matrices.
#[derive(Debug)]
pub struct LuFactor {
    symbolic: SymbolicLu<usize>,
    lu: Lu<usize, f64>,
}

impl LuFactor {
    /// Symbolic and numeric factorisation of a full CSC matrix.
    pub fn new(col_ptr: &[usize], row_idx: &[usize], values: &[f64]) -> Result<Self, SolveError> {
        let n = col_ptr.len() - 1;
        let sym = SymbolicSparseColMatRef::new_checked(n, n, col_ptr, None, row_idx);
        let symbolic = SymbolicLu::try_new(sym).map_err(|e| SolveError::Other(format!("LU analysis failed: {e:?}")))?;
        let lu = Self::numeric(&symbolic, col_ptr, row_idx, values)?;
        Ok(LuFactor { symbolic, lu })
    }

    fn numeric(
        symbolic: &SymbolicLu<usize>,
        col_ptr: &[usize],
        row_idx: &[usize],
        values: &[f64],
    ) -> Result<Lu<usize, f64>, SolveError> {
        let n = col_ptr.len() - 1;
        let a = SparseColMatRef::new(SymbolicSparseColMatRef::new_checked(n, n, col_ptr, None, row_idx), values);
        Lu::try_new_with_symbolic(symbolic.clone(), a).map_err(|e| match e {
            faer::sparse::linalg::LuError::SymbolicSingular { .. } => SolveError::Singular { dofs: vec![] },
            e => SolveError::Other(format!("LU failed: {e:?}")),
        })
    }

    /// New values on the same pattern: numeric factorisation only.
    pub fn refactor(&mut self, col_ptr: &[usize], row_idx: &[usize], values: &[f64]) -> Result<(), SolveError> {
        self.lu = Self::numeric(&self.symbolic, col_ptr, row_idx, values)?;
        Ok(())
    }

    pub fn solve_in_place(&self, rhs: MatMut<'_, f64>) {
        self.lu.solve_in_place_with_conj(Conj::No, rhs);
    }
}
