//! The condensed operator T = G − A·P_I as a status-iteration backend
//! (unilateral.md §3.2–§3.5, §8 option 2).
//!
//! One dense LDLᵀ of T is kept up to date across status changes by
//! rank-one diagonal updates. Safeguards: every updated factor is checked
//! for the expected inertia (pivot k positive iff k is active) and refactored
//! from scratch if the check fails, after `MAX_UPDATES` updates, or when the
//! residual ‖Tx − h‖ of a solve grows.

use super::Condensed;
use crate::solve::error::SolveError;
use crate::solve::unilateral::dense_ldlt::DenseLdlt;
use crate::solve::unilateral::status::{
    iterate, Backend, IterRecord, RigidMode, StatusOptions, StatusResult, EPS_PIV, EPS_SING,
};
use faer::Mat;
use std::borrow::Cow;

/// Updates allowed before refactoring from scratch.
const MAX_UPDATES: usize = 20;
/// A status change of more than m/UPDATE_FRACTION conditions refactors:
/// one rank-r update costs ≈ 2m²r flops against m³/3.
const UPDATE_FRACTION: usize = 16;
/// Relative residual that a solve must reach (after refinement).
const RESIDUAL_OK: f64 = 1e-12;
/// Relative residual beyond which the answer is reported inaccurate.
const RESIDUAL_FAIL: f64 = 1e-8;

pub(crate) struct TOperator<'a> {
    c: &'a Condensed,
    /// G itself when it is exactly symmetric (the interrupted factorisation
    /// mirrors it), else its symmetric part: a condensation by iterative
    /// solves leaves round-off asymmetry, and the factor reads one triangle.
    g: Cow<'a, Mat<f64>>,
    /// Pivot scales max(|G_kk|, α_k) of the inertia check.
    scale: Vec<f64>,
    /// ĉ_i = max(1, max_j |c_ij|).
    chat: Vec<f64>,
    active: Vec<bool>,
    factor: Option<DenseLdlt>,
    /// Relative residual of the last solve with a fresh factor.
    fresh_residual: f64,
}

impl<'a> TOperator<'a> {
    pub fn new(c: &'a Condensed) -> Result<Self, SolveError> {
        let m = c.h.len();
        let bad = |what: &str| Err(SolveError::Other(format!("condensed data: {what}")));
        if c.g.nrows() != m || c.g.ncols() != m {
            return bad("G is not m×m");
        }
        if [c.alpha.len(), c.sigma.len(), c.sense.len(), c.xtf.len(), c.rows.len(), c.d.len()].iter().any(|&l| l != m) {
            return bad("vector lengths differ");
        }
        let finite = |v: &[f64]| v.iter().all(|x| x.is_finite());
        if !finite(&c.h) || !finite(&c.xtf) || !finite(&c.d) {
            return bad("non-finite h, XᵀF or d");
        }
        if c.alpha.iter().chain(&c.sigma).any(|&a| !(a > 0.0 && a.is_finite())) {
            return bad("α and σ must be positive");
        }
        if c.sense.iter().any(|&s| s != 1.0 && s != -1.0) {
            return bad("sense must be ±1");
        }
        if (0..m).any(|j| !finite(c.g.col_as_slice(j))) {
            return bad("non-finite G");
        }
        let g = if exactly_symmetric(&c.g) {
            Cow::Borrowed(&*c.g)
        } else {
            // (G + Gᵀ)/2 by faer's blocked transpose: element-wise (j, i)
            // reads stride through memory (≈ 0.1 s at m = 2000).
            let mut g = &*c.g + c.g.transpose();
            g *= faer::Scale(0.5);
            Cow::Owned(g)
        };
        let scale = (0..m).map(|k| g[(k, k)].abs().max(c.alpha[k])).collect();
        let chat = c.rows.iter().map(|r| r.iter().fold(1.0_f64, |a, &(_, v)| a.max(v.abs()))).collect();
        Ok(TOperator { c, g, scale, chat, active: vec![true; m], factor: None, fresh_residual: 0.0 })
    }

    fn t_matrix(&self, active: &[bool]) -> Mat<f64> {
        self.t_matrix_in(active, None)
    }

    /// T for `active`, written into `buf` when given (a factor's storage
    /// that is no longer needed: no fresh m² allocation to page in).
    fn t_matrix_in(&self, active: &[bool], buf: Option<Mat<f64>>) -> Mat<f64> {
        let mut t = match buf {
            Some(mut b) if b.nrows() == self.g.nrows() && b.ncols() == self.g.ncols() => {
                b.copy_from(self.g.as_ref());
                b
            }
            _ => self.g.as_ref().clone(),
        };
        for (k, &a) in active.iter().enumerate() {
            if !a {
                t[(k, k)] -= self.c.alpha[k];
            }
        }
        t
    }

    fn check(&self, f: &DenseLdlt, active: &[bool]) -> Option<usize> {
        f.first_bad_pivot(active, &self.scale, EPS_PIV)
    }

    /// Relative residual max|h − Tx| / max(Σ|T_ij x_j| + |h_i|), and h − Tx.
    fn residual(&self, x: &[f64]) -> (f64, Vec<f64>) {
        let m = x.len();
        // r = h − Tx by one (threaded) matrix-vector product; the exact
        // denominator Σ|T_ij x_j| costs a second pass over T, needed only
        // when a lower bound of it (|h_i|, |T_ii x_i|) does not already
        // show the residual small.
        let mut r = Mat::<f64>::from_fn(m, 1, |i, _| self.c.h[i]);
        let xm = faer::MatRef::from_column_major_slice(x, m, 1);
        let par = if m >= 256 { faer::get_global_parallelism() } else { faer::Par::Seq };
        faer::linalg::matmul::matmul(r.as_mut(), faer::Accum::Add, self.g.as_ref(), xm, -1.0, par);
        let mut r: Vec<f64> = (0..m).map(|i| r[(i, 0)]).collect();
        let mut lower = 0.0_f64;
        for j in 0..m {
            if !self.active[j] {
                r[j] += self.c.alpha[j] * x[j];
            }
            let t = if self.active[j] { self.g[(j, j)] } else { self.g[(j, j)] - self.c.alpha[j] };
            lower = lower.max(self.c.h[j].abs()).max((t * x[j]).abs());
        }
        let num = r.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
        if num.is_finite() && lower > 0.0 && num <= RESIDUAL_OK * lower {
            return (num / lower, r);
        }
        self.exact_residual(x)
    }

    /// [`TOperator::residual`] with the exact denominator.
    fn exact_residual(&self, x: &[f64]) -> (f64, Vec<f64>) {
        let m = x.len();
        let mut r = self.c.h.clone();
        let mut s: Vec<f64> = self.c.h.iter().map(|v| v.abs()).collect();
        for (j, &xj) in x.iter().enumerate() {
            let col = self.g.col_as_slice(j);
            for i in 0..m {
                r[i] -= col[i] * xj;
                s[i] += (col[i] * xj).abs();
            }
            if !self.active[j] {
                r[j] += self.c.alpha[j] * xj;
                s[j] += (self.c.alpha[j] * xj).abs();
            }
        }
        let num = r.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
        let den = s.iter().fold(0.0_f64, |a, v| a.max(*v));
        (if den > 0.0 { num / den } else { num }, r)
    }

    fn solve_with(&self, f: &DenseLdlt) -> (Vec<f64>, f64) {
        let mut x = self.c.h.clone();
        f.solve_in_place(&mut x);
        let (mut res, mut r) = self.residual(&x);
        // Iterative refinement: cheap (O(m²)) and repairs a slightly
        // inaccurate (updated) factor.
        for _ in 0..2 {
            if res <= RESIDUAL_OK || res.is_nan() {
                break;
            }
            f.solve_in_place(&mut r);
            let trial: Vec<f64> = x.iter().zip(&r).map(|(a, b)| a + b).collect();
            let (res2, r2) = self.residual(&trial);
            if res2.is_nan() || res2 >= res {
                break;
            }
            (x, res, r) = (trial, res2, r2);
        }
        (x, res)
    }
}

/// Whether `g == gᵀ` bit for bit, read by tiles so that the transposed
/// reads stay in cache (a copy of G costs 32 MB and ≈ 25 ms at m = 2000).
fn exactly_symmetric(g: &Mat<f64>) -> bool {
    const B: usize = 64;
    let m = g.nrows();
    for jb in (0..m).step_by(B) {
        for ib in (jb..m).step_by(B) {
            for j in jb..(jb + B).min(m) {
                for i in ib.max(j + 1)..(ib + B).min(m) {
                    if g[(i, j)] != g[(j, i)] {
                        return false;
                    }
                }
            }
        }
    }
    true
}

impl Backend for TOperator<'_> {
    fn set_status(&mut self, active: &[bool]) -> Result<(), usize> {
        let m = active.len();
        let mut lost = false;
        let mut spare = None;
        if let Some(mut f) = self.factor.take() {
            let changed: Vec<usize> = (0..m).filter(|&k| active[k] != self.active[k]).collect();
            if changed.is_empty() {
                self.factor = Some(f);
                return Ok(());
            }
            if f.updates() < MAX_UPDATES && changed.len() <= (m / UPDATE_FRACTION).max(4) {
                let deltas: Vec<f64> =
                    changed.iter().map(|&k| if active[k] { self.c.alpha[k] } else { -self.c.alpha[k] }).collect();
                f.update_diags(&changed, &deltas);
                if self.check(&f, active).is_none() {
                    self.factor = Some(f);
                    self.active = active.to_vec();
                    return Ok(());
                }
                // A bad updated pivot may be update round-off: decide on a
                // fresh factorisation.
            }
            // Refactored from scratch below in its storage: the previous
            // status's factor is gone (refactored if the new one fails).
            spare = Some(f.into_storage());
            lost = true;
        }
        // The condensation's own factor of G serves the all-active status.
        let given = match &self.c.g_factor {
            Some(gf) if self.factor.is_none() && active.iter().all(|&a| a) && gf.nrows() == m => {
                Some(DenseLdlt::from_packed(gf.as_ref().clone())).filter(|f| self.check(f, active).is_none())
            }
            _ => None,
        };
        let f = match given {
            Some(f) => f,
            None => DenseLdlt::factor_owned(self.t_matrix_in(active, spare)),
        };
        if let Some(k) = self.check(&f, active) {
            if lost {
                // The contract keeps the previous status usable.
                let prev = self.t_matrix_in(&self.active, Some(f.into_storage()));
                self.factor = Some(DenseLdlt::factor_owned(prev));
            }
            return Err(k);
        }
        self.factor = Some(f);
        self.active = active.to_vec();
        Ok(())
    }

    fn solve(&mut self) -> Result<Vec<f64>, SolveError> {
        let Some(f) = &self.factor else {
            return Err(SolveError::Other("status solve before factorisation".into()));
        };
        let (mut x, mut res) = self.solve_with(f);
        let grew = res > RESIDUAL_OK && res > 10.0 * self.fresh_residual;
        if f.updates() > 0 && (grew || !x.iter().all(|v| v.is_finite())) {
            let fresh = DenseLdlt::factor_owned(self.t_matrix(&self.active));
            (x, res) = self.solve_with(&fresh);
            self.factor = Some(fresh);
            self.fresh_residual = res;
        } else if f.updates() == 0 {
            self.fresh_residual = res;
        }
        if res.is_nan() || res > RESIDUAL_FAIL || !x.iter().all(|v| v.is_finite()) {
            return Err(SolveError::Inaccurate { residual: res, weakest: vec![] });
        }
        Ok(x)
    }

    fn release(&mut self, i: usize) -> Result<(bool, RigidMode), SolveError> {
        let c = self.c;
        let m = c.h.len();
        let Some(f) = &self.factor else {
            return Err(SolveError::Other("status solve before factorisation".into()));
        };
        let mut z = vec![0.0; m];
        z[i] = 1.0;
        f.solve_in_place(&mut z);
        // det(T − α_i e_ie_iᵀ) = det(T)(1 − α_i z_i); z is then the null vector.
        let singular = (1.0 - c.alpha[i] * z[i]).abs() <= EPS_SING;
        // Orient y = −s_i z so that s_i c_i u_r > 0. With u_r = −2Xy:
        // C u_r = −2Σ⁻¹G y, i.e. s_j c_j u_r = (2α_j/σ_j)·(−s_j (Gy)_j/α_j),
        // and the bracket is in the units of x_j.
        let y: Vec<f64> = z.iter().map(|zj| -c.sense[i] * zj).collect();
        let mut gy = vec![0.0; m];
        for (j, &yj) in y.iter().enumerate() {
            for (k, g) in self.g.col_as_slice(j).iter().enumerate() {
                gy[k] += g * yj;
            }
        }
        let motion = (0..m).map(|j| -c.sense[j] * gy[j] / c.alpha[j]).collect();
        // F·u_r = −2 (XᵀF)·y, reported for the mode normalised so that
        // s_i c_i u_r = ĉ_i (here s_i c_i u_r = 2/σ_i): a unit motion of
        // the normalised row, as the old method reports it.
        let unit = c.sigma[i] * self.chat[i] / 2.0;
        let work = -2.0 * unit * c.xtf.iter().zip(&y).map(|(a, b)| a * b).sum::<f64>();
        let work_scale = 2.0 * unit * c.xtf.iter().zip(&y).map(|(a, b)| (a * b).abs()).sum::<f64>();
        Ok((singular, RigidMode { motion, work, work_scale }))
    }

    fn dependent(&mut self, active: &[bool]) -> Vec<usize> {
        let t = self.t_matrix(active);
        let Some(k) = self.check(&DenseLdlt::factor(t.as_ref()), active) else {
            return Vec::new();
        };
        // The leading block before k is regular (its pivots passed): the
        // null vector of the leading (k+1) block is (T_<k⁻¹ T_<k,k, −1).
        let lead = DenseLdlt::factor(t.as_ref().submatrix(0, 0, k, k));
        let mut a: Vec<f64> = (0..k).map(|j| t[(j, k)]).collect();
        lead.solve_in_place(&mut a);
        let amax = a.iter().fold(1.0_f64, |s, v| s.max(v.abs()));
        let mut out: Vec<usize> = (0..k).filter(|&j| a[j].abs() > 1e-8 * amax).collect();
        out.push(k);
        out
    }
}

/// Runs the status iteration on the condensed problem.
///
/// Calls `on_iter` once per solve of T x = h (also for the solve that
/// precedes an error). Errors:
/// * `Conflicting`: proportional rows with crossed limits (pre-pass, before
///   any solve);
/// * `Infeasible`: the load drives a rigid mode away from every support;
///   `conditions` holds the condition whose release frees the mode, then
///   the other conditions the mode lifts off; `work` is F·u_r for the mode
///   normalised to a unit motion of that condition's row (c_i/ĉ_i)·u_r = ±1;
/// * `DependentConditions`: an activation makes the active rows dependent
///   (other than proportional pairs), with the rows involved;
/// * `NoConvergence`: the cap (default max(100, 20·m)) or a cycle that the
///   least-index and relaxed-tolerance modes could not break;
/// * `Inaccurate`: the residual of T x = h stays large after refinement;
/// * `Other`: inconsistent input (sizes, non-finite values, α ≤ 0, s ≠ ±1).
pub fn run(
    c: &Condensed,
    opts: &StatusOptions,
    on_iter: &mut dyn FnMut(&IterRecord),
) -> Result<StatusResult, SolveError> {
    let mut op = TOperator::new(c)?;
    // The adhesion in the units of x (physical λ = 2σx).
    let scaled;
    let opts = match &opts.adhesion {
        Some(a) if a.len() != c.sigma.len() => {
            return Err(SolveError::Other(format!("{} adhesion values for {} conditions", a.len(), c.sigma.len())))
        }
        Some(a) if a.iter().any(|v| !(v.is_finite() && *v >= 0.0)) => {
            return Err(SolveError::Other("adhesion must be finite and non-negative".into()))
        }
        Some(a) => {
            scaled = StatusOptions {
                adhesion: Some(a.iter().zip(&c.sigma).map(|(v, s)| v / (2.0 * s)).collect()),
                ..opts.clone()
            };
            &scaled
        }
        None => opts,
    };
    let (x, active, records) = iterate(&mut op, &c.sense, &c.rows, &c.d, opts, on_iter)?;
    Ok(StatusResult { x, active, records })
}

#[cfg(test)]
#[path = "../tests/operator.rs"]
mod tests;
