//! The bilateral RESO: every condition treated as an equality, solved on the
//! doubled system by one LDLᵀ without pivoting (or sparse LU when K is not
//! symmetric).
//!
//! A [`Factorization`] keeps the assembled pattern, the symbolic analysis
//! and the numeric factor, so that new right-hand sides cost one solve and
//! new values on the same structure cost one numeric factorisation.

use faer::Mat;

use super::lagrange::Doubled;
use super::linear::{LuFactor, SymFactor, ZeroPivot};
use super::ordering;
use super::redundant::Redundant;
use crate::solve::error::SolveError;
use crate::solve::problem::{Kind, Load, Problem, Solution};

/// Options of a direct RESO.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DirectOptions {
    /// Check the residual after the solve (`false` = 'NOID').
    pub check_residual: bool,
    /// 'STAB': add a tiny multiple of each primal row's largest entry to its
    /// diagonal, so that unloaded rigid modes do not stop the solve.
    pub stab: bool,
}

impl Default for DirectOptions {
    fn default() -> Self {
        DirectOptions { check_residual: true, stab: false }
    }
}

/// Relative diagonal shift of 'STAB'.
const STAB: f64 = 1e-9;
/// Largest accepted normwise backward error of the (undoubled) system.
pub const RESIDUAL_TOL: f64 = 1e-8;
/// Systems up to this size (doubled unknowns) always get one step of
/// iterative refinement. The elimination of doubled multipliers leaves a
/// few ulps on the unknowns a relation ties (a relation's result two ulps
/// off where Cast3M's decks compare it to one); a refinement step removes
/// them. Below this size the step costs well under a millisecond; above
/// it a second solve would double the cost of a new right-hand side, so
/// large systems are refined only when the residual check fails.
const ALWAYS_REFINE_UP_TO: usize = 20_000;
/// How many unknowns a `Singular` error names at most.
const MAX_NAMED: usize = 50;

#[derive(Debug)]
enum Engine {
    Ldlt(SymFactor),
    Lu(LuFactor),
}

/// A factorised bilateral problem.
#[derive(Debug)]
pub struct Factorization {
    sys: Doubled,
    engine: Engine,
    opts: DirectOptions,
    /// Conditions left out as consistent duplicates of others.
    redundant: Redundant,
}

impl Factorization {
    /// Checks, assembles, orders and factorises `p`. A condition that the
    /// others imply is dropped (see [`super::redundant`]): each solve then
    /// checks that its imposed value agrees.
    pub fn new(p: &Problem, opts: &DirectOptions) -> Result<Self, SolveError> {
        let mut redundant = Redundant::none(p);
        loop {
            let reduced;
            let q = if redundant.is_empty() {
                p
            } else {
                reduced = redundant.reduced(p);
                &reduced
            };
            match Self::build(q, opts) {
                Ok((sys, engine)) => return Ok(Factorization { sys, engine, opts: *opts, redundant }),
                Err(Built::Dependent(rows)) => {
                    if !redundant.drop_row(p, rows[0], &rows) {
                        return Err(SolveError::DependentConditions { conditions: rows });
                    }
                }
                Err(Built::Failed(e)) => return Err(e),
            }
        }
    }

    /// One attempt of [`Factorization::new`].
    fn build(p: &Problem, opts: &DirectOptions) -> Result<(Doubled, Engine), Built> {
        let mut sys = Doubled::new(p, &[])?;
        check_structure(p)?;
        let stab = if opts.stab { STAB } else { 0.0 };
        if stab > 0.0 {
            sys.fill(p, stab)?;
        }
        let engine = if p.k.symmetric {
            let primal = ordering::primal_best(p, &[], Some((&sys.col_ptr, &sys.row_idx)))?;
            let fwd = ordering::doubled_order(p, &primal, &[]);
            let mut f = SymFactor::analyse(&sys.col_ptr, &sys.row_idx, fwd)?;
            if let Err(z) = f.factor(&sys.col_ptr, &sys.row_idx, &sys.values, &sys.row_scale, usize::MAX, None) {
                return Err(match diagnose(&sys, &mut f, z) {
                    SolveError::DependentConditions { conditions } => Built::Dependent(conditions),
                    e => Built::Failed(e),
                });
            }
            Engine::Ldlt(f)
        } else {
            Engine::Lu(LuFactor::new(&sys.col_ptr, &sys.row_idx, &sys.values)?)
        };
        Ok((sys, engine))
    }

    /// Whether `p` has the structure this factorisation was built for
    /// (never, once a condition was dropped: the caller factorises anew).
    pub fn same_pattern(&self, p: &Problem) -> bool {
        self.redundant.is_empty() && self.sys.same_pattern(p)
    }

    /// New values, same structure: numeric factorisation only. With
    /// dropped conditions, the new values may make other rows dependent:
    /// everything is redone.
    pub fn refactor(&mut self, p: &Problem) -> Result<(), SolveError> {
        if !self.redundant.is_empty() {
            *self = Factorization::new(p, &self.opts)?;
            return Ok(());
        }
        let stab = if self.opts.stab { STAB } else { 0.0 };
        self.sys.fill(p, stab)?;
        let sys = &self.sys;
        match &mut self.engine {
            Engine::Ldlt(f) => {
                if let Err(z) = f.factor(&sys.col_ptr, &sys.row_idx, &sys.values, &sys.row_scale, usize::MAX, None) {
                    return Err(diagnose(sys, f, z));
                }
            }
            Engine::Lu(f) => f.refactor(&sys.col_ptr, &sys.row_idx, &sys.values)?,
        }
        Ok(())
    }

    /// The `k` primal unknowns whose pivots are smallest relative to their
    /// row (LDLᵀ only), weakest first.
    fn weakest_pivots(&self, k: usize) -> Vec<usize> {
        let Engine::Ldlt(f) = &self.engine else { return Vec::new() };
        let n = self.sys.n;
        let mut r: Vec<(f64, usize)> = f
            .pivots()
            .iter()
            .zip(f.fwd())
            .filter(|(_, &o)| o < n && self.sys.row_scale[o] > 0.0)
            .map(|(d, &o)| (d.abs() / self.sys.row_scale[o], o))
            .collect();
        r.sort_by(|a, b| a.0.total_cmp(&b.0));
        r.into_iter().take(k).map(|x| x.1).collect()
    }

    /// Solves for several loads at once.
    pub fn solve(&self, loads: &[Load]) -> Result<Vec<Solution>, SolveError> {
        self.solve_checked(loads, self.opts.check_residual)
    }

    /// [`Factorization::solve`] with the residual check chosen per call
    /// ('NOID' on a reused factorisation, 'SOUC' after an inaccurate solve).
    pub fn solve_checked(&self, loads: &[Load], check_residual: bool) -> Result<Vec<Solution>, SolveError> {
        if self.redundant.is_empty() {
            return self.solve_factorised(loads, check_residual);
        }
        let m = self.redundant.given();
        if let Some(l) = loads.iter().find(|l| l.f.len() != self.sys.n || l.d.len() != m) {
            return Err(SolveError::Other(format!(
                "load sizes ({}, {}) do not match ({}, {m})",
                l.f.len(),
                l.d.len(),
                self.sys.n
            )));
        }
        let reduced: Vec<Load> = loads.iter().map(|l| self.redundant.load(l)).collect();
        let sols = self.solve_factorised(&reduced, check_residual)?;
        loads.iter().zip(sols).map(|(l, s)| self.redundant.expand(l, s)).collect()
    }

    /// The solve of the factorised (reduced) system.
    fn solve_factorised(&self, loads: &[Load], check_residual: bool) -> Result<Vec<Solution>, SolveError> {
        let (n, m) = (self.sys.n, self.sys.m);
        let dim = self.sys.dim();
        for l in loads {
            if l.f.len() != n || l.d.len() != m {
                return Err(SolveError::Other(format!(
                    "load sizes ({}, {}) do not match ({n}, {m})",
                    l.f.len(),
                    l.d.len()
                )));
            }
        }
        let mut b = Mat::<f64>::zeros(dim, loads.len());
        for (j, l) in loads.iter().enumerate() {
            let col = b.col_mut(j).try_as_col_major_mut().expect("contiguous");
            self.sys.rhs(&l.f, &l.d, col.as_slice_mut());
        }
        let mut z = b.clone();
        self.solve_mat(&mut z)?;
        // Whatever 'NOID' says: a solution that overflowed is no solution.
        if (0..z.ncols()).any(|j| z.col(j).iter().any(|x| !x.is_finite())) {
            return Err(SolveError::Overflow);
        }
        let small = dim <= ALWAYS_REFINE_UP_TO && self.sys.m > 0;
        let mut eta = if check_residual || small { self.backward_error(&b, &z) } else { 0.0 };
        if eta > RESIDUAL_TOL || (small && eta > 0.0) {
            // One step of iterative refinement, kept only if it helps. An
            // accurate solution of a small system is polished with the
            // double-double residual (see `refine`); a solution failing the
            // check is far from the last ulps, and a nearly singular
            // factor amplifies whatever residual it is given, so it gets
            // the plain one, which has proved the better rescue there.
            let polish = small && eta <= RESIDUAL_TOL;
            let mut r = if polish { self.residual_accurate(&b, &z) } else { self.residual(&b, &z) };
            self.solve_mat(&mut r)?;
            let refined = &z + &r;
            let eta_refined = self.backward_error(&b, &refined);
            if eta_refined.is_finite() && (eta.is_nan() || eta_refined <= eta) {
                z = refined;
                eta = eta_refined;
            }
        }
        // NaN counts as a failure too.
        if check_residual && (eta.is_nan() || eta > RESIDUAL_TOL) {
            return Err(SolveError::Inaccurate { residual: eta, weakest: self.weakest_pivots(3) });
        }
        Ok((0..loads.len())
            .map(|j| {
                let zc = z.col(j);
                Solution {
                    u: (0..n).map(|i| zc[i]).collect(),
                    lambda: (0..m).map(|i| self.sys.scaling.sigma[i] * (zc[n + i] + zc[n + m + i])).collect(),
                    active: vec![true; m],
                }
            })
            .collect())
    }

    fn solve_mat(&self, z: &mut Mat<f64>) -> Result<(), SolveError> {
        match &self.engine {
            Engine::Ldlt(f) => f.solve_in_place(z.as_mut()),
            Engine::Lu(f) => {
                f.solve_in_place(z.as_mut());
                Ok(())
            }
        }
    }

    /// b − M z with every row summed in double-double.
    fn residual_accurate(&self, b: &Mat<f64>, z: &Mat<f64>) -> Mat<f64> {
        let dim = self.sys.dim();
        let mut r = Mat::<f64>::zeros(dim, b.ncols());
        for j in 0..b.ncols() {
            let x: Vec<f64> = (0..dim).map(|i| z[(i, j)]).collect();
            let bj: Vec<f64> = (0..dim).map(|i| b[(i, j)]).collect();
            for (i, v) in super::refine::residual(&self.sys, &bj, &x).into_iter().enumerate() {
                r[(i, j)] = v;
            }
        }
        r
    }

    /// b − M z, column by column.
    fn residual(&self, b: &Mat<f64>, z: &Mat<f64>) -> Mat<f64> {
        let dim = self.sys.dim();
        let mut r = Mat::<f64>::zeros(dim, b.ncols());
        let (mut y, mut t) = (vec![0.0; dim], vec![0.0; dim]);
        for j in 0..b.ncols() {
            let x: Vec<f64> = (0..dim).map(|i| z[(i, j)]).collect();
            self.sys.apply(&x, &mut y, &mut t);
            for i in 0..dim {
                r[(i, j)] = b[(i, j)] - y[i];
            }
        }
        r
    }

    /// Normwise backward error of the undoubled system: equilibrium rows
    /// `Ku + Cᵀλ − F` and condition rows `Cu − d` (the sum of the two
    /// doubled rows), each relative to the size of its terms.
    fn backward_error(&self, b: &Mat<f64>, z: &Mat<f64>) -> f64 {
        backward_error(&self.sys, b, z)
    }
}

/// Why one factorisation attempt stopped.
enum Built {
    /// A multiplier pivot vanished: this row (first) depends on the others.
    Dependent(Vec<usize>),
    Failed(SolveError),
}

impl From<SolveError> for Built {
    fn from(e: SolveError) -> Self {
        Built::Failed(e)
    }
}

/// See [`Factorization::solve`]'s residual check; shared with condensation.
pub(crate) fn backward_error(sys: &Doubled, b: &Mat<f64>, z: &Mat<f64>) -> f64 {
    let (n, m, dim) = (sys.n, sys.m, sys.dim());
    let (mut y, mut t) = (vec![0.0; dim], vec![0.0; dim]);
    let mut worst = 0.0f64;
    for j in 0..b.ncols() {
        let x: Vec<f64> = (0..dim).map(|i| z[(i, j)]).collect();
        sys.apply(&x, &mut y, &mut t);
        let (mut ru, mut tu, mut rc, mut tc) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
        // f64::max drops a NaN operand: an overflowing solution (inf − inf)
        // must not pass as a zero residual.
        let mut finite = true;
        for i in 0..n {
            let r = (b[(i, j)] - y[i]).abs();
            finite &= r.is_finite();
            ru = ru.max(r);
            tu = tu.max(t[i] + b[(i, j)].abs());
        }
        for i in 0..m {
            let s = 2.0 * sys.scaling.sigma[i];
            let (a, c) = (n + i, n + m + i);
            let r = (b[(a, j)] - y[a]) + (b[(c, j)] - y[c]);
            finite &= r.is_finite();
            rc = rc.max((r / s).abs());
            tc = tc.max((t[a] + t[c] + b[(a, j)].abs() + b[(c, j)].abs()) / s);
        }
        if !(finite && ru.is_finite() && rc.is_finite()) {
            return f64::INFINITY;
        }
        if tu > 0.0 {
            worst = worst.max(ru / tu);
        }
        if tc > 0.0 {
            worst = worst.max(rc / tc);
        }
    }
    worst
}

/// Convenience: factorise and solve in one call.
pub fn solve(p: &Problem, loads: &[Load], opts: &DirectOptions) -> Result<Vec<Solution>, SolveError> {
    Factorization::new(p, opts)?.solve(loads)
}

/// Structural diagnostics that need no factorisation: unknowns nothing
/// touches, and unknowns fixed by two single-term equalities (Cast3M's
/// VERLAG). Both would otherwise show up as an anonymous zero pivot.
pub fn check_structure(p: &Problem) -> Result<(), SolveError> {
    let n = p.k.n;
    let mut touched = vec![false; n];
    for &(i, j, _) in &p.k.entries {
        touched[i] = true;
        touched[j] = true;
    }
    let mut single: Vec<Vec<usize>> = vec![Vec::new(); n];
    for (ci, c) in p.conditions.iter().enumerate() {
        for &(j, _) in c.terms.iter().chain(c.dual.iter().flatten()) {
            touched[j] = true;
        }
        let mut dofs: Vec<usize> = c.terms.iter().map(|t| t.0).collect();
        dofs.sort_unstable();
        dofs.dedup();
        if dofs.len() == 1 && c.kind == Kind::Equal {
            single[dofs[0]].push(ci);
        }
    }
    let untouched: Vec<usize> = (0..n).filter(|&j| !touched[j]).collect();
    if !untouched.is_empty() {
        return Err(SolveError::Untouched { dofs: untouched });
    }
    if let Some((dof, cs)) = single.iter().enumerate().find(|(_, c)| c.len() > 1) {
        return Err(SolveError::DoublyConstrained { dof, conditions: cs.clone() });
    }
    Ok(())
}

/// Turns a zero pivot into an error that names what is wrong.
pub(crate) fn diagnose(sys: &Doubled, f: &mut SymFactor, z: ZeroPivot) -> SolveError {
    let (n, m) = (sys.n, sys.m);
    if z.index == usize::MAX {
        return SolveError::Other("out of memory in the factorisation".into());
    }
    if z.index >= n {
        // A vanishing multiplier pivot: row i is a combination of the rows
        // eliminated before it. Name it and the rows sharing its unknowns.
        let ci = (z.index - n) % m;
        return SolveError::DependentConditions { conditions: sharing_rows(sys, ci) };
    }
    let dofs = null_dofs(sys, f).unwrap_or_else(|| vec![z.index]);
    // The regularised factor used for the diagnosis must not be solved with.
    f.invalidate();
    SolveError::Singular { dofs }
}

/// Condition `ci` first, then every other condition with a common unknown.
fn sharing_rows(sys: &Doubled, ci: usize) -> Vec<usize> {
    let (n, m) = (sys.n, sys.m);
    let l1 = n + ci;
    let mut dofs = Vec::new();
    for col in 0..sys.dim() {
        for k in sys.col_ptr[col]..sys.col_ptr[col + 1] {
            let r = sys.row_idx[k];
            if (r == l1 && col < n) || (col == l1 && r < n) {
                dofs.push(if col < n { col } else { r });
            }
        }
    }
    let mut out = vec![ci];
    for cj in 0..m {
        if cj == ci {
            continue;
        }
        let lj = n + cj;
        let shares = dofs.iter().any(|&d| sys.find(d, lj).is_some_and(|k| sys.values[k] != 0.0));
        if shares {
            out.push(cj);
        }
    }
    out
}

/// Unknowns moving in the free rigid mode, largest first: factor with a
/// small static regularisation (the singular pivot becomes δ), then a few
/// steps of inverse iteration amplify the null vector by 1/δ each.
fn null_dofs(sys: &Doubled, f: &mut SymFactor) -> Option<Vec<usize>> {
    let (n, dim) = (sys.n, sys.dim());
    let scale = sys.row_scale.iter().fold(0.0f64, |a, &b| a.max(b));
    let signs: Vec<i8> = (0..dim).map(|i| if i < n { 1 } else { -1 }).collect();
    let reg = Some((&signs[..], 1e-8 * scale, 1e-10 * scale));
    f.factor(&sys.col_ptr, &sys.row_idx, &sys.values, &sys.row_scale, usize::MAX, reg).ok()?;
    let mut y = Mat::<f64>::zeros(dim, 1);
    for i in 0..n {
        // Not all ones: a symmetric start could be orthogonal to the mode.
        y[(i, 0)] = 1.0 + 0.1 * ((i * 7919) % 13) as f64;
    }
    for _ in 0..3 {
        f.solve_in_place(y.as_mut()).ok()?;
        let mx = (0..n).fold(0.0f64, |a, i| a.max(y[(i, 0)].abs()));
        if !(mx > 0.0 && mx.is_finite()) {
            return None;
        }
        y /= faer::Scale(mx);
    }
    let mut dofs: Vec<usize> = (0..n).filter(|&i| y[(i, 0)].abs() >= 1e-3).collect();
    dofs.sort_by(|&a, &b| y[(b, 0)].abs().total_cmp(&y[(a, 0)].abs()));
    dofs.truncate(MAX_NAMED);
    Some(dofs)
}

#[cfg(test)]
#[path = "tests/direct.rs"]
mod tests;
