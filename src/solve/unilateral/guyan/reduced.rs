//! The paper's *old* method (unilateral.md §5), for comparison: the status
//! iteration on the stiffness condensed onto the primal unknowns P of the
//! unilateral rows, with the doubled multipliers of the active conditions
//! assembled and the whole small system refactored at every status.
//!
//! It shares the decision logic of [`crate::solve::unilateral::status`] (same rule, same
//! tolerances, same group pre-pass), so both methods take the same
//! decisions up to round-off. Its linear algebra differs: a status that
//! frees a rigid mode of K_c shows up as a non-positive pivot in the
//! displacement block, and the freed mode is computed by imposing a unit
//! motion on the released row.

use crate::solve::error::SolveError;
use crate::solve::unilateral::dense_ldlt::DenseLdlt;
use crate::solve::unilateral::status::{iterate, Backend, IterRecord, RigidMode, StatusOptions, EPS_PIV, EPS_SING};
use faer::Mat;

/// The answer of the old method.
#[derive(Debug, Clone, PartialEq)]
pub struct ReducedResult {
    /// Displacements of the condensed unknowns P.
    pub u: Vec<f64>,
    /// Physical multiplier of every condition (0 when inactive).
    pub lambda: Vec<f64>,
    pub active: Vec<bool>,
    pub records: Vec<IterRecord>,
    /// Physical multipliers of the `eq_rows`.
    pub eq_lambda: Vec<f64>,
}

/// The data of the old method, condensed onto the unknowns P.
#[derive(Debug, Clone, Copy)]
pub struct ReducedProblem<'a> {
    /// K_c (n_P × n_P, symmetric).
    pub kc: &'a Mat<f64>,
    /// F_c (n_P).
    pub fc: &'a [f64],
    /// The unilateral rows over `0..n_P`.
    pub rows: &'a [Vec<(usize, f64)>],
    /// s_i: +1 MINI, −1 MAXI.
    pub sense: &'a [f64],
    /// The limits d_i.
    pub d: &'a [f64],
    /// k_i of the §2.2 scaling, taken from the stiffness before
    /// condensation, as Cast3M does: one per unilateral row, then one per
    /// `eq_rows` row. `None` takes it from K_c, which is wrong when K_c is
    /// (nearly) zero, e.g. a body held only by its unilateral supports
    /// condensed onto the supported dofs.
    pub k_ref: Option<&'a [f64]>,
    /// Bilateral rows over `0..n_P` (`c·u = d`), always assembled: those
    /// that share unknowns with the unilateral rows cannot stay inside K_c.
    pub eq_rows: &'a [Vec<(usize, f64)>],
    /// Their limits.
    pub eq_d: &'a [f64],
}

/// Runs the old method.
pub fn run(
    p: &ReducedProblem,
    opts: &StatusOptions,
    on_iter: &mut dyn FnMut(&IterRecord),
) -> Result<ReducedResult, SolveError> {
    let mut old = Old::new(p)?;
    let (_, active, records) = iterate(&mut old, p.sense, p.rows, p.d, opts, on_iter)?;
    let (n, rows, mu) = (p.fc.len(), p.rows, p.rows.len());
    let (u, mut lambda) = if rows.is_empty() {
        // No condition: plain solve (K_c must then be regular).
        old.active = Vec::new();
        old.set_status(&[]).map_err(|_| SolveError::Singular { dofs: (0..n).collect() })?;
        old.solve()?;
        (old.u.clone(), old.lambda.clone())
    } else {
        (old.u.clone(), old.lambda.clone())
    };
    let eq_lambda = lambda.split_off(mu.min(lambda.len()));
    Ok(ReducedResult { u, lambda, active, records, eq_lambda })
}

struct Old<'a> {
    kc: Mat<f64>,
    fc: &'a [f64],
    /// The unilateral rows (`0..mu`), then the bilateral ones.
    rows: Vec<Vec<(usize, f64)>>,
    mu: usize,
    sense: &'a [f64],
    d: Vec<f64>,
    sigma: Vec<f64>,
    alpha: Vec<f64>,
    chat: Vec<f64>,
    kmax: f64,
    /// Current status, its assembled matrix, factor and active list.
    active: Vec<bool>,
    list: Vec<usize>,
    mat: Mat<f64>,
    factor: Option<DenseLdlt>,
    /// Last solution: displacements and physical multipliers.
    u: Vec<f64>,
    lambda: Vec<f64>,
}

impl<'a> Old<'a> {
    fn new(p: &ReducedProblem<'a>) -> Result<Self, SolveError> {
        let (kc, fc, sense) = (p.kc, p.fc, p.sense);
        let (n, mu) = (fc.len(), p.rows.len());
        let bad = |what: &str| Err(SolveError::Other(format!("old method data: {what}")));
        if kc.nrows() != n || kc.ncols() != n || sense.len() != mu || p.d.len() != mu || p.eq_d.len() != p.eq_rows.len()
        {
            return bad("dimensions differ");
        }
        let rows: Vec<Vec<(usize, f64)>> = p.rows.iter().chain(p.eq_rows).cloned().collect();
        let d: Vec<f64> = p.d.iter().chain(p.eq_d).copied().collect();
        let m = rows.len();
        if rows.iter().flatten().any(|&(j, v)| j >= n || !v.is_finite()) {
            return bad("row entry out of range or not finite");
        }
        let kc = Mat::<f64>::from_fn(n, n, |i, j| 0.5 * (kc[(i, j)] + kc[(j, i)]));
        if (0..n).any(|j| kc.col_as_slice(j).iter().any(|v| !v.is_finite()))
            || fc.iter().chain(&d).any(|v| !v.is_finite())
        {
            return bad("non-finite stiffness, load or limit");
        }
        if sense.iter().any(|&s| s != 1.0 && s != -1.0) {
            return bad("sense must be ±1");
        }
        if p.k_ref.is_some_and(|k| k.len() != m || k.iter().any(|&v| !(v.is_finite() && v > 0.0))) {
            return bad("k_ref must hold one positive value per condition");
        }
        let kmax = (0..n).flat_map(|j| kc.col_as_slice(j).to_vec()).fold(0.0_f64, |a, v| a.max(v.abs()));
        // The stiffness reference of the singularity tests.
        let kmax = p.k_ref.unwrap_or(&[]).iter().fold(kmax, |a, &v| a.max(v));
        // §2.2 scaling, as Cast3M: k_i from the stiffness rows of the dofs
        // of condition i, κ = 1.5 k, σ = κ/ĉ, α = 2κ.
        let (mut sigma, mut alpha, mut chat) = (vec![0.0; m], vec![0.0; m], vec![0.0; m]);
        for (i, r) in rows.iter().enumerate() {
            let mut k = r.iter().flat_map(|&(j, _)| kc.col_as_slice(j).to_vec()).fold(0.0_f64, |a, v| a.max(v.abs()));
            if k.is_nan() || k <= 1e-12 * kmax {
                k = if kmax > 0.0 { kmax } else { 1.0 };
            }
            if let Some(kr) = p.k_ref {
                k = kr[i];
            }
            chat[i] = r.iter().fold(1.0_f64, |a, &(_, v)| a.max(v.abs()));
            sigma[i] = 1.5 * k / chat[i];
            alpha[i] = 3.0 * k;
        }
        // Duplicate dofs in a row are summed once here.
        let rows = rows
            .iter()
            .map(|r| {
                let mut out: Vec<(usize, f64)> = Vec::new();
                for &(j, v) in r {
                    match out.iter_mut().find(|e| e.0 == j) {
                        Some(e) => e.1 += v,
                        None => out.push((j, v)),
                    }
                }
                out
            })
            .collect();
        Ok(Old {
            kc,
            fc,
            rows,
            mu,
            sense,
            d,
            sigma,
            alpha,
            chat,
            kmax,
            active: Vec::new(),
            list: Vec::new(),
            mat: Mat::zeros(0, 0),
            factor: None,
            u: vec![0.0; n],
            lambda: vec![0.0; m],
        })
    }

    fn n(&self) -> usize {
        self.fc.len()
    }

    fn row_dot(&self, i: usize, u: &[f64]) -> f64 {
        self.rows[i].iter().map(|&(j, v)| v * u[j]).sum()
    }

    /// The doubled system ordered (λ1 of the active rows, u, λ2): λ1 before
    /// and λ2 after every dof (§2.3), so no pivoting is needed. Returns the
    /// matrix, the expected pivot signs and the pivot scales.
    fn assemble(&self, list: &[usize]) -> (Mat<f64>, Vec<bool>, Vec<f64>) {
        let (n, a) = (self.n(), list.len());
        let mut mat = Mat::<f64>::zeros(n + 2 * a, n + 2 * a);
        let mut scale = vec![0.0; n + 2 * a];
        for j in 0..n {
            for i in 0..n {
                mat[(a + i, a + j)] = self.kc[(i, j)];
            }
            // A u pivot must also stand out of the round-off of the whole
            // stiffness: K_c of a body held only by unilateral supports is
            // round-off, and so would be its pivots.
            scale[a + j] = self.kc[(j, j)].abs().max(self.kmax);
        }
        for (p, &i) in list.iter().enumerate() {
            let (l1, l2, al, s) = (p, n + a + p, self.alpha[i], self.sigma[i]);
            mat[(l1, l1)] = -al;
            mat[(l2, l2)] = -al;
            mat[(l1, l2)] = al;
            mat[(l2, l1)] = al;
            scale[l1] = al;
            scale[l2] = al;
            for &(j, c) in &self.rows[i] {
                for l in [l1, l2] {
                    mat[(l, a + j)] = s * c;
                    mat[(a + j, l)] = s * c;
                }
                // The u pivot after eliminating λ1 includes the penalty wσ²c².
                scale[a + j] += s * s * c * c / al;
            }
        }
        let positive = (0..n + 2 * a).map(|k| k >= a && k < a + n).collect();
        (mat, positive, scale)
    }

    /// Solves the current system for `rhs`, with one refinement step.
    fn solve_rhs(&self, rhs: &[f64]) -> Result<Vec<f64>, SolveError> {
        let Some(f) = &self.factor else {
            return Err(SolveError::Other("old method: solve before factorisation".into()));
        };
        let mut y = rhs.to_vec();
        f.solve_in_place(&mut y);
        let resid = |y: &[f64]| -> (Vec<f64>, f64, f64) {
            let mut r = rhs.to_vec();
            let mut s: Vec<f64> = rhs.iter().map(|v| v.abs()).collect();
            for (j, &yj) in y.iter().enumerate() {
                for (i, mij) in self.mat.col_as_slice(j).iter().enumerate() {
                    r[i] -= mij * yj;
                    s[i] += (mij * yj).abs();
                }
            }
            let num = r.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
            let den = s.iter().fold(0.0_f64, |a, v| a.max(*v));
            (r, num, den)
        };
        let (mut r, _, _) = resid(&y);
        f.solve_in_place(&mut r);
        y.iter_mut().zip(&r).for_each(|(a, b)| *a += b);
        let (_, num, den) = resid(&y);
        let rel = if den > 0.0 { num / den } else { num };
        if rel.is_nan() || rel > 1e-8 || y.iter().any(|v| !v.is_finite()) {
            return Err(SolveError::Inaccurate { residual: rel, weakest: vec![] });
        }
        Ok(y)
    }
}

impl Backend for Old<'_> {
    fn set_status(&mut self, active: &[bool]) -> Result<(), usize> {
        if self.factor.is_some() && active == self.active.as_slice() {
            return Ok(());
        }
        // The bilateral rows are always there.
        let list: Vec<usize> = (0..active.len()).filter(|&i| active[i]).chain(self.mu..self.rows.len()).collect();
        let (mat, positive, scale) = self.assemble(&list);
        // The old method refactors the whole small system at every status.
        let f = DenseLdlt::factor(mat.as_ref());
        if let Some(k) = f.first_bad_pivot(&positive, &scale, EPS_PIV) {
            return Err(k);
        }
        (self.active, self.list, self.mat, self.factor) = (active.to_vec(), list, mat, Some(f));
        Ok(())
    }

    fn solve(&mut self) -> Result<Vec<f64>, SolveError> {
        let (n, a, m) = (self.n(), self.list.len(), self.rows.len());
        let mut rhs = vec![0.0; n + 2 * a];
        rhs[a..a + n].copy_from_slice(self.fc);
        for (p, &i) in self.list.iter().enumerate() {
            rhs[p] = self.sigma[i] * self.d[i];
            rhs[n + a + p] = self.sigma[i] * self.d[i];
        }
        let y = self.solve_rhs(&rhs)?;
        self.u = y[a..a + n].to_vec();
        self.lambda = vec![0.0; m];
        // x in the units of the condensed method: λ/(2σ) when active,
        // σ(d − c·u)/(2α) (the scaled gap of §2.4) when inactive.
        let mut x: Vec<f64> = (0..self.mu)
            .map(|i| self.sigma[i] * (self.d[i] - self.row_dot(i, &self.u)) / (2.0 * self.alpha[i]))
            .collect();
        for (p, &i) in self.list.iter().enumerate() {
            if i < self.mu {
                x[i] = 0.5 * (y[p] + y[n + a + p]);
            }
            self.lambda[i] = self.sigma[i] * (y[p] + y[n + a + p]);
        }
        Ok(x)
    }

    fn release(&mut self, i: usize) -> Result<(bool, RigidMode), SolveError> {
        let (n, a, m) = (self.n(), self.list.len(), self.mu);
        let Some(p) = self.list.iter().position(|&k| k == i) else {
            return Err(SolveError::Other("old method: release of an inactive condition".into()));
        };
        // Impose c_i r = 1 with the other active rows held and no load:
        // K r = −Cᵀμ, and rᵀK r = −μ_i is the stiffness that condition i
        // sees. It vanishes iff r is a rigid mode freed by the release.
        let mut rhs = vec![0.0; n + 2 * a];
        rhs[p] = self.sigma[i];
        rhs[n + a + p] = self.sigma[i];
        let y = self.solve_rhs(&rhs)?;
        let r = &y[a..a + n];
        let kr: f64 = (0..n).map(|j| r[j] * (0..n).map(|l| self.kc[(j, l)] * r[l]).sum::<f64>()).sum();
        let rr: f64 = r.iter().map(|v| v * v).sum();
        let singular = kr.abs() <= EPS_SING * self.kmax * rr;
        // Orient and normalise so that s_i c_i u_r = ĉ_i (unit motion of the
        // normalised row, away from the support).
        let ur: Vec<f64> = r.iter().map(|v| self.sense[i] * self.chat[i] * v).collect();
        let motion =
            (0..m).map(|j| self.sigma[j] / (2.0 * self.alpha[j]) * self.sense[j] * self.row_dot(j, &ur)).collect();
        let work = self.fc.iter().zip(&ur).map(|(f, u)| f * u).sum();
        let work_scale = self.fc.iter().zip(&ur).map(|(f, u)| (f * u).abs()).sum();
        Ok((singular, RigidMode { motion, work, work_scale }))
    }

    fn dependent(&mut self, active: &[bool]) -> Vec<usize> {
        // Gram matrix of the bilateral rows (always there, independent)
        // then the active ones: the first negligible pivot and the leading
        // unilateral rows it depends on. A unilateral row that only
        // repeats bilateral ones comes out alone.
        let list: Vec<usize> = (self.mu..self.rows.len()).chain((0..active.len()).filter(|&i| active[i])).collect();
        let k = list.len();
        let gram = Mat::<f64>::from_fn(k, k, |p, q| {
            let (ri, rj) = (&self.rows[list[p]], &self.rows[list[q]]);
            ri.iter().map(|&(j, v)| v * rj.iter().filter(|e| e.0 == j).map(|e| e.1).sum::<f64>()).sum()
        });
        let scale: Vec<f64> = (0..k).map(|p| gram[(p, p)]).collect();
        let f = DenseLdlt::factor(gram.as_ref());
        let unilateral = |v: Vec<usize>| v.into_iter().filter(|&i| i < self.mu).collect::<Vec<_>>();
        let Some(b) = f.first_bad_pivot(&vec![true; k], &scale, EPS_PIV) else {
            return unilateral(list);
        };
        let lead = DenseLdlt::factor(gram.as_ref().submatrix(0, 0, b, b));
        let mut c: Vec<f64> = (0..b).map(|p| gram[(p, b)]).collect();
        lead.solve_in_place(&mut c);
        let cmax = c.iter().fold(1.0_f64, |s, v| s.max(v.abs()));
        let mut out: Vec<usize> = (0..b).filter(|&p| c[p].abs() > 1e-8 * cmax).map(|p| list[p]).collect();
        out.push(list[b]);
        unilateral(out)
    }
}

#[cfg(test)]
#[path = "../tests/guyan.rs"]
mod tests;
