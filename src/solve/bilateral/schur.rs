//! The Schur complement of a trailing block by an interrupted
//! factorisation (unilateral.md §3, solver-notes §3.3).
//!
//! The unknowns to condense onto are ordered last and made one dense
//! trailing supernode; one supernodal LDLᵀ of the whole doubled matrix then
//! holds, in that supernode, the LDLᵀ of the Schur complement S of the
//! trailing block. We read S = L₂₂D₂₂L₂₂ᵀ from it. Building S from one solve
//! per condensed unknown was measured 25–100× slower and is never done.
//!
//! Two users: the static condensation onto chosen primal unknowns
//! ([`schur_onto`], Cast3M's SUPER and the old unilateral method), and the
//! whole-matrix path of the unilateral condenser
//! (`unilateral::condensed::condenser`), onto the second multipliers of the
//! unilateral conditions.
//!
//! The trailing block's own factorisation is only a means to read S, and S
//! may be singular (a MINI and a MAXI on the same dof give a singular G).
//! So a diagonal shift that makes the trailing block safely definite is
//! added before factorising and taken off S afterwards: S is the same
//! (Schur complements are additive in the trailing diagonal) and no tiny
//! pivot ever appears there. For the unilateral λ2 the shift is −4α, so the
//! factor holds −4(G + A), with G + A between A and 2A; once the shift is
//! removed, S = −4G (the active baseline of §3.2).
//!
//! Without proportional rows G is usually regular, and the condensed tail
//! is first factorised *unshifted* (`plain`): the trailing supernode then
//! holds the LDLᵀ of −4G itself, handed to the status loop as the factor of
//! its first (all-active) status, one dense m³/3 factorisation saved. A
//! tiny tail pivot (rows dependent in a non-proportional way) sends it back
//! to the shifted factorisation.
//!
//! The first block of the factor (everything but the tail) does not depend
//! on the tail's values, so one factorisation serves every status
//! iteration; right-hand sides and the recovery use partial forward and
//! back substitutions through that block only.

use faer::linalg::matmul::triangular::{matmul as tri_matmul, BlockStructure};
use faer::{Accum, Mat};

use super::direct::{check_structure, diagnose};
use super::lagrange::Doubled;
use super::linear::SymFactor;
use super::ordering;
use crate::solve::error::SolveError;
use crate::solve::problem::{Load, Problem, Solution};
/// A doubled system factorised with a condensed tail.
#[derive(Debug)]
pub(crate) struct Interrupted {
    pub(crate) sys: Doubled,
    pub(crate) factor: SymFactor,
    /// First position of the tail in the elimination order.
    pub(crate) cut: usize,
    /// The tail's unknowns (natural numbering), in elimination order.
    pub(crate) tail: Vec<usize>,
    /// The Schur complement of the tail (shift removed), tail order.
    pub(crate) schur: Mat<f64>,
    /// Factorise the tail of condensed λ2 without the shift (see
    /// [`Interrupted::numeric`]); cleared when that meets a tiny pivot.
    pub(crate) plain: bool,
    /// With `plain` (only the condensation onto the λ2 uses it): the packed
    /// LDLᵀ of G = −S/4 (D on the diagonal, unit L strictly below), read
    /// from the factor, shared with every [`Condensed`] without a copy.
    pub(crate) tail_factor: Option<std::rc::Rc<Mat<f64>>>,
    /// Primal unknowns from this one on are multipliers written as
    /// unknowns ([`super::mult_masters`]): shifted like multipliers.
    pub(crate) negative_from: usize,
}

/// A plain tail pivot smaller than this fraction of its 4α is taken as
/// singular: the tail is then factorised with the shift.
const PLAIN_PIVOT_TOL: f64 = 1e-10;

impl Interrupted {
    /// `sys`, if given, must have been built with the tail `fwd[cut..]`.
    pub(crate) fn new(
        p: &Problem,
        fwd: Vec<usize>,
        cut: usize,
        sys: Option<Doubled>,
        plain: bool,
    ) -> Result<Self, SolveError> {
        Self::try_new(p, fwd, cut, sys, plain)?
            .ok_or_else(|| SolveError::Other("the condensed block does not form one trailing supernode".into()))
    }

    /// [`Interrupted::new`], or `None` when the tail is not one trailing
    /// supernode (a pattern without the explicit tail pairs whose tail the
    /// elimination does not connect).
    pub(crate) fn try_new(
        p: &Problem,
        fwd: Vec<usize>,
        cut: usize,
        sys: Option<Doubled>,
        plain: bool,
    ) -> Result<Option<Self>, SolveError> {
        Self::try_new_signed(p, fwd, cut, sys, plain, usize::MAX)
    }

    /// [`Interrupted::try_new`] with the primal unknowns from
    /// `negative_from` on shifted as multipliers.
    fn try_new_signed(
        p: &Problem,
        fwd: Vec<usize>,
        cut: usize,
        sys: Option<Doubled>,
        plain: bool,
        negative_from: usize,
    ) -> Result<Option<Self>, SolveError> {
        check_structure(p)?;
        if !p.k.symmetric {
            return Err(SolveError::Other("condensation needs a symmetric stiffness".into()));
        }
        let tail = fwd[cut..].to_vec();
        let sys = match sys {
            Some(s) => s,
            None => Doubled::new(p, &tail)?,
        };
        let factor = SymFactor::analyse(&sys.col_ptr, &sys.row_idx, fwd)?;
        let sup = factor.supernodal();
        let n_sup = sup.n_supernodes();
        if tail.is_empty() || n_sup == 0 || sup.supernode_begin()[n_sup - 1] > cut {
            return Ok(None);
        }
        let mut it =
            Interrupted { sys, factor, cut, tail, schur: Mat::zeros(0, 0), plain, tail_factor: None, negative_from };
        // The system was just built: it already holds the values of `p`.
        it.numeric(p, false)?;
        Ok(Some(it))
    }

    /// Shift of each tail unknown: −4α on a λ2 of a condensed condition,
    /// −(row scale) on other multipliers and +(row scale) on primal
    /// unknowns, which keeps the shifted tail quasi-definite.
    fn shifts(&self) -> Vec<f64> {
        let (n, m) = (self.sys.n, self.sys.m);
        self.tail
            .iter()
            .map(|&t| {
                if t >= n + m {
                    if self.plain {
                        0.0
                    } else {
                        -4.0 * self.sys.scaling.alpha[t - n - m]
                    }
                } else if t >= n || t >= self.negative_from {
                    -self.sys.row_scale[t]
                } else {
                    self.sys.row_scale[t].max(f64::MIN_POSITIVE)
                }
            })
            .collect()
    }

    /// Numeric factorisation of the values of `p` and extraction of S.
    pub(crate) fn numeric(&mut self, p: &Problem, refill: bool) -> Result<(), SolveError> {
        if refill {
            self.sys.fill(p, 0.0)?;
        }
        let shift = self.shifts();
        for (&t, &s) in self.tail.iter().zip(&shift) {
            self.sys.add_diag(t, s);
        }
        let sys = &self.sys;
        if let Err(z) = self.factor.factor(&sys.col_ptr, &sys.row_idx, &sys.values, &sys.row_scale, self.cut, None) {
            if self.plain && self.tail.contains(&z.index) {
                // An exactly zero pivot in the unshifted tail: G is singular
                // (a row fixed by the others); the shifted tail has none.
                // The plain shifts are 0 on the λ2: nothing to take off.
                self.plain = false;
                self.tail_factor = None;
                return self.numeric(p, false);
            }
            return Err(diagnose(sys, &mut self.factor, z));
        }
        let f = self.factor.ldlt_ref();
        let last = f.supernode(self.factor.supernodal().n_supernodes() - 1);
        let v = last.val();
        let mt = self.tail.len();
        let o = self.cut - last.start();
        let lt = v.submatrix(o, o, mt, mt);
        if self.plain {
            // Unshifted, the tail holds the LDLᵀ of S = −4G itself, negative
            // definite for independent rows: its pivots say whether it is
            // usable; if not, factorise again with the shift.
            let (n, m) = (self.sys.n, self.sys.m);
            let bad = self.tail.iter().enumerate().any(|(k, &t)| {
                let d = lt[(k, k)];
                let scale = if t >= n + m { 4.0 * self.sys.scaling.alpha[t - n - m] } else { 1.0 };
                !(d < 0.0 && d.abs() > PLAIN_PIVOT_TOL * scale)
            });
            if bad {
                self.plain = false;
                self.tail_factor = None;
                return self.numeric(p, false);
            }
        }
        // S = L D Lᵀ over the tail, from the packed factor (its strict lower
        // part is L, unit diagonal implied) and L·D, both copied column by
        // column from contiguous slices (an indexed copy of 2000² entries
        // costs as much as the product).
        let mut packed = Mat::<f64>::zeros(mt, mt);
        let mut ld = Mat::<f64>::zeros(mt, mt);
        for j in 0..mt {
            let src = lt.col(j).subrows(j, mt - j);
            let src = src.try_as_col_major().expect("supernode columns are contiguous").as_slice();
            let pk = packed.col_mut(j).subrows_mut(j, mt - j);
            pk.try_as_col_major_mut().expect("contiguous").as_slice_mut().copy_from_slice(src);
            let dst = ld.col_mut(j).subrows_mut(j, mt - j);
            let dst = dst.try_as_col_major_mut().expect("contiguous").as_slice_mut();
            let d = src[0];
            dst[0] = d;
            for (a, b) in dst[1..].iter_mut().zip(&src[1..]) {
                *a = b * d;
            }
        }
        let mut s = Mat::<f64>::zeros(mt, mt);
        tri_matmul(
            s.as_mut(),
            BlockStructure::TriangularLower,
            Accum::Replace,
            ld.as_ref(),
            BlockStructure::TriangularLower,
            packed.transpose(),
            BlockStructure::UnitTriangularUpper,
            1.0,
            // m³/3 flops at m ~ 10³: worth the threads.
            faer::get_global_parallelism(),
        );
        drop(ld);
        for j in 0..mt {
            s[(j, j)] -= shift[j];
        }
        mirror_lower(&mut s);
        self.tail_factor = self.plain.then(|| {
            // G = −S/4 has the same L and D/(−4).
            for j in 0..mt {
                packed[(j, j)] *= -0.25;
            }
            std::rc::Rc::new(packed)
        });
        // Take the shift back off the stored values too, so that residual
        // checks see the true matrix.
        for (&t, &sh) in self.tail.iter().zip(&shift) {
            self.sys.add_diag(t, -sh);
        }
        self.schur = s;
        Ok(())
    }

    /// A natural-numbering vector in elimination order.
    fn permuted(&self, nat: &[f64]) -> Mat<f64> {
        let fwd = self.factor.fwd();
        Mat::from_fn(fwd.len(), 1, |k, _| nat[fwd[k]])
    }

    /// Right-hand side of the tail's Schur system for a natural rhs.
    pub(crate) fn reduced_rhs(&self, nat_cols: &[Vec<f64>]) -> Mat<f64> {
        let dim = self.sys.dim();
        let fwd = self.factor.fwd();
        let mut x = Mat::from_fn(dim, nat_cols.len(), |k, j| nat_cols[j][fwd[k]]);
        self.factor.forward_partial(x.as_mut(), self.cut);
        x.subrows(self.cut, dim - self.cut).to_owned()
    }

    /// The partial forward substitution of a natural rhs (elimination
    /// order, every row), as [`Interrupted::reduced_rhs`] computes it.
    pub(crate) fn forward(&self, nat_cols: &[Vec<f64>]) -> Mat<f64> {
        let fwd = self.factor.fwd();
        let mut x = Mat::from_fn(fwd.len(), nat_cols.len(), |k, j| nat_cols[j][fwd[k]]);
        self.factor.forward_partial(x.as_mut(), self.cut);
        x
    }

    /// Natural-numbering solution of the first block with the tail fixed.
    pub(crate) fn solve_with_tail(&self, nat: &[f64], tail_values: &[f64]) -> Vec<f64> {
        let mut x = self.permuted(nat);
        self.factor.forward_partial(x.as_mut(), self.cut);
        self.finish_with_tail(x, tail_values)
    }

    /// [`Interrupted::solve_with_tail`] from the forwarded rhs `x` (one column).
    pub(crate) fn finish_with_tail(&self, mut x: Mat<f64>, tail_values: &[f64]) -> Vec<f64> {
        self.factor.diagonal_partial(x.as_mut(), self.cut);
        for (q, &v) in tail_values.iter().enumerate() {
            x[(self.cut + q, 0)] = v;
        }
        self.factor.backward_partial(x.as_mut(), self.cut);
        let mut out = vec![0.0; x.nrows()];
        for (k, &o) in self.factor.fwd().iter().enumerate() {
            out[o] = x[(k, 0)];
        }
        out
    }
}

/// Copies the lower triangle of a square matrix onto its upper one, by
/// tiles so that both the reads and the writes stay in cache.
pub(crate) fn mirror_lower(s: &mut Mat<f64>) {
    const B: usize = 64;
    let n = s.nrows();
    for jb in (0..n).step_by(B) {
        for ib in (jb..n).step_by(B) {
            for j in jb..(jb + B).min(n) {
                for i in ib.max(j + 1)..(ib + B).min(n) {
                    s[(j, i)] = s[(i, j)];
                }
            }
        }
    }
}

/// Static condensation of a bilateral problem onto chosen primal unknowns
/// (Cast3M's SUPER, the 'ANCIEN' method): `keep` are ordered last and the
/// Schur complement of the trailing block is read from the factor.
///
/// Conditions whose unknowns are all kept, or whose last unknown is kept,
/// have multipliers inside the trailing block too: [`SchurOnto::unknowns`]
/// lists what each row of [`SchurOnto::matrix`] is, in the natural numbering
/// (`j < n` primal, `n + i` the λ1 of condition i, `n + m + i` its λ2, with
/// the §2.2 scaling of [`SchurOnto::sigma`]).
#[derive(Debug)]
pub struct SchurOnto {
    core: Interrupted,
}

impl SchurOnto {
    /// The condensed operator over [`SchurOnto::unknowns`].
    pub fn matrix(&self) -> &Mat<f64> {
        &self.core.schur
    }
    pub fn unknowns(&self) -> &[usize] {
        &self.core.tail
    }
    pub fn sigma(&self) -> &[f64] {
        &self.core.sys.scaling.sigma
    }

    /// The condensed load: F_t − A_tr A_rr⁻¹ b_r over the trailing block.
    pub fn load(&self, load: &Load) -> Vec<f64> {
        let sys = &self.core.sys;
        let mut rhs = vec![0.0; sys.dim()];
        sys.rhs(&load.f, &load.d, &mut rhs);
        let r = self.core.reduced_rhs(&[rhs]);
        (0..r.nrows()).map(|q| r[(q, 0)]).collect()
    }

    /// Expands the trailing values back to the whole solution.
    pub fn expand(&self, load: &Load, tail_values: &[f64]) -> Solution {
        let sys = &self.core.sys;
        let (n, m) = (sys.n, sys.m);
        let mut rhs = vec![0.0; sys.dim()];
        sys.rhs(&load.f, &load.d, &mut rhs);
        let z = self.core.solve_with_tail(&rhs, tail_values);
        Solution {
            u: z[..n].to_vec(),
            lambda: (0..m).map(|i| sys.scaling.sigma[i] * (z[n + i] + z[n + m + i])).collect(),
            active: vec![true; m],
        }
    }
}

/// Builds the condensation of `p` (all conditions as equalities) onto the
/// primal unknowns `keep`.
pub fn schur_onto(p: &Problem, keep: &[usize]) -> Result<SchurOnto, SolveError> {
    schur_onto_signed(p, keep, usize::MAX)
}

/// [`schur_onto`] where the primal unknowns from `negative_from` on are
/// multipliers written as unknowns (their Schur complement is negative).
pub fn schur_onto_signed(p: &Problem, keep: &[usize], negative_from: usize) -> Result<SchurOnto, SolveError> {
    super::lagrange::validate(p)?;
    let n = p.k.n;
    let mut seen = vec![false; n];
    for &j in keep {
        if j >= n || seen[j] {
            return Err(SolveError::Other(format!("bad kept unknown {j}")));
        }
        seen[j] = true;
    }
    let primal = ordering::primal_amd(p, keep, None)?;
    let fwd = ordering::doubled_order_interleaved(p, &primal, &[]);
    // The tail starts at the first kept unknown or at a λ1 opening there.
    let first_kept = n - keep.len();
    let mut cut = fwd.len();
    let mut seen_primal = 0;
    for (k, &o) in fwd.iter().enumerate() {
        if o < n {
            if seen_primal == first_kept {
                cut = k;
                break;
            }
            seen_primal += 1;
        }
    }
    while cut > 0 && fwd[cut - 1] >= n && fwd[cut - 1] < n + p.conditions.len() && {
        let ci = fwd[cut - 1] - n;
        p.conditions[ci].terms.iter().all(|&(j, _)| seen[j])
    } {
        cut -= 1;
    }
    let core = Interrupted::try_new_signed(p, fwd, cut, None, false, negative_from)?
        .ok_or_else(|| SolveError::Other("the condensed block does not form one trailing supernode".into()))?;
    Ok(SchurOnto { core })
}
#[cfg(test)]
#[path = "tests/schur.rs"]
mod tests;
