//! CREUX: the status iteration on the full sparse system (unilateral.md
//! §2.4, §8 "sparse PDAS"), for conditions on a large fraction of the
//! unknowns (obstacle problems), where the dense m×m operator of CONDENSE
//! would dominate.
//!
//! The symbolic analysis is done once (and cached with the RIGIDITE); each
//! status costs one numeric factorisation on the fixed pattern and one
//! solve. The decisions are those of [`super::status`] (same rule, cycle
//! detection and least-index fallback), through the [`Backend`] trait.
//!
//! * A unilateral row with several unknowns keeps its doubled multipliers;
//!   a status change is the λ2 diagonal −α (active) ↔ +3α (inactive).
//! * A unilateral row on one unknown j (BLOQ MINI/MAXI, the obstacle case)
//!   is not doubled: its doubled block, once λ1 is eliminated, pairs u_j
//!   with λ2 in a 2×2 pivot [[H_jj, 2σc], [2σc, 0]] (active) whose inverse
//!   has a zero (u_j, u_j) entry, so it changes nothing but fixing u_j, and
//!   the inactive pivot 4α only removes the penalty again. Both are exactly
//!   "u_j = d/c imposed" or "u_j free", done here by zeroing row and column
//!   j on the fixed pattern. This keeps the factor the size of K's instead
//!   of three times larger.
//!
//! Bilateral rows on one unknown (BLOQ) are imposed the same way, always.
//!
//! x_i (the λ2 of §3, the quantity the sign test reads) is recovered from
//! the solution: the λ2 itself for doubled rows; λ_i/(2σ_i) from the
//! reaction at j for an active single-unknown row; σ_i(d_i − c_i u)/(2α_i)
//! (the scaled gap of §2.4) for an inactive one.

use faer::Mat;

use super::backend::{values_hash, Job, Outcome, StatusError, Trace};
use super::status::{iterate, Backend, RigidMode, EPS_PIV, EPS_SING};
use crate::solve::bilateral::direct::check_structure;
use crate::solve::bilateral::lagrange::{self, Doubled};
use crate::solve::bilateral::linear::SymFactor;
use crate::solve::bilateral::ordering;
use crate::solve::error::SolveError;
use crate::solve::problem::{Load, Problem, Solution};

#[derive(Debug, Clone, Copy)]
enum Row {
    /// One unknown: `c u_dof ⋈ d`.
    Single { dof: usize, c: f64 },
    /// Doubled, condition `s` of the sparse system.
    Multi { s: usize },
}

/// The sparse operator of CREUX with its symbolic analysis.
#[derive(Debug)]
pub(super) struct Creux {
    structure: u64,
    values: u64,
    /// Global numbers of the conditions kept doubled.
    sub: Vec<usize>,
    sys: Doubled,
    factor: SymFactor,
    rows: Vec<Row>,
    /// Single-unknown bilateral rows (condition, unknown, coefficient),
    /// always imposed.
    imposed: Vec<(usize, usize, f64)>,
    /// Per single-row unknown: (slot, other index) of every stored entry
    /// of its row and column (the diagonal has other == dof).
    slots: Vec<Vec<(usize, usize)>>,
    /// slot list of each unknown (usize::MAX when it carries no single row).
    slot_of: Vec<usize>,
    /// Numeric data of the current values.
    base: Vec<f64>,
    scale: Vec<f64>,
    kmax: f64,
    sigma: Vec<f64>,
    alpha: Vec<f64>,
}

impl Creux {
    fn new(p: &Problem, uni: &[usize], structure: u64) -> Result<Self, SolveError> {
        lagrange::validate(p)?;
        check_structure(p)?;
        if !p.k.symmetric {
            return Err(SolveError::Other("method CREUX needs a symmetric stiffness".into()));
        }
        let n = p.k.n;
        let mut is_single = vec![false; p.conditions.len()];
        let mut rows = Vec::with_capacity(uni.len());
        for &i in uni {
            let t = &p.conditions[i].terms;
            let dof = t[0].0;
            let c: f64 = t.iter().map(|e| e.1).sum();
            if t.iter().all(|e| e.0 == dof) && c != 0.0 {
                is_single[i] = true;
                rows.push(Row::Single { dof, c });
            } else {
                rows.push(Row::Multi { s: usize::MAX });
            }
        }
        // Bilateral rows on one unknown (BLOQ) are imposed the same way, for
        // good: the factor keeps K's size.
        let mut imposed = Vec::new();
        for (i, cnd) in p.conditions.iter().enumerate() {
            let t = &cnd.terms;
            let dof = t[0].0;
            let c: f64 = t.iter().map(|e| e.1).sum();
            if !cnd.kind.is_unilateral() && t.iter().all(|e| e.0 == dof) && c != 0.0 {
                is_single[i] = true;
                imposed.push((i, dof, c));
            }
        }
        let sub: Vec<usize> = (0..p.conditions.len()).filter(|&i| !is_single[i]).collect();
        let mut at = vec![usize::MAX; p.conditions.len()];
        for (s, &i) in sub.iter().enumerate() {
            at[i] = s;
        }
        for (q, &i) in uni.iter().enumerate() {
            if let Row::Multi { s } = &mut rows[q] {
                *s = at[i];
            }
        }
        let ps = sub_problem(p, &sub, &rows, &imposed);
        let sys = Doubled::new(&ps, &[])?;
        let primal = ordering::primal_best(&ps, &[], Some((&sys.col_ptr, &sys.row_idx)))?;
        let fwd = ordering::doubled_order(&ps, &primal, &[]);
        let factor = SymFactor::analyse(&sys.col_ptr, &sys.row_idx, fwd)?;
        let mut slot_of = vec![usize::MAX; n];
        let mut slots: Vec<Vec<(usize, usize)>> = Vec::new();
        let single_dofs = rows
            .iter()
            .filter_map(|r| if let Row::Single { dof, .. } = *r { Some(dof) } else { None })
            .chain(imposed.iter().map(|e| e.1));
        for dof in single_dofs {
            if slot_of[dof] == usize::MAX {
                slot_of[dof] = slots.len();
                slots.push(Vec::new());
            }
        }
        for col in 0..sys.dim() {
            for k in sys.col_ptr[col]..sys.col_ptr[col + 1] {
                let r = sys.row_idx[k];
                if r < n && slot_of[r] != usize::MAX {
                    slots[slot_of[r]].push((k, col));
                }
                if col < n && col != r && slot_of[col] != usize::MAX {
                    slots[slot_of[col]].push((k, r));
                }
            }
        }
        let mut c = Creux {
            structure,
            values: 0,
            sub,
            sys,
            factor,
            rows,
            imposed,
            slots,
            slot_of,
            base: Vec::new(),
            scale: Vec::new(),
            kmax: 0.0,
            sigma: Vec::new(),
            alpha: Vec::new(),
        };
        drop(ps);
        c.numbers(p, uni, false)?;
        Ok(c)
    }

    /// Takes the values of `p` (same structure).
    fn numbers(&mut self, p: &Problem, uni: &[usize], refill: bool) -> Result<(), SolveError> {
        if refill {
            let ps = sub_problem(p, &self.sub, &self.rows, &self.imposed);
            self.sys.fill(&ps, 0.0)?;
        }
        let n = p.k.n;
        let sys = &self.sys;
        let mut row_max = vec![0.0_f64; n];
        for col in 0..n {
            for k in sys.col_ptr[col]..sys.col_ptr[col + 1] {
                let r = sys.row_idx[k];
                if r < n {
                    let a = sys.values[k].abs();
                    row_max[r] = row_max[r].max(a);
                    row_max[col] = row_max[col].max(a);
                }
            }
        }
        self.kmax = row_max.iter().fold(0.0, |a, &b| a.max(b));
        let global = if self.kmax > 0.0 { self.kmax } else { 1.0 };
        self.sigma.clear();
        self.alpha.clear();
        for (q, &i) in uni.iter().enumerate() {
            match self.rows[q] {
                Row::Multi { s } => {
                    self.sigma.push(sys.scaling.sigma[s]);
                    self.alpha.push(sys.scaling.alpha[s]);
                }
                // The §2.2 scaling, as the doubled rows get it.
                Row::Single { dof, .. } => {
                    let k = if row_max[dof] > 0.0 { row_max[dof] } else { global };
                    let chat = p.conditions[i].terms.iter().fold(1.0_f64, |a, &(_, v)| a.max(v.abs()));
                    self.sigma.push(1.5 * k / chat);
                    self.alpha.push(3.0 * k);
                }
            }
        }
        self.base = sys.values.clone();
        self.scale = sys.row_scale.iter().map(|&s| if s > 0.0 { s } else { global }).collect();
        Ok(())
    }

    /// The sparse solution for forces `f` and limits `d` (global), the
    /// single rows of `active` imposed.
    fn solve_load(&self, f: &[f64], d: &[f64], active: &[bool], uni: &[usize]) -> Result<Vec<f64>, SolveError> {
        let (n, ms) = (self.sys.n, self.sys.m);
        let dim = self.sys.dim();
        let mut rhs = Mat::<f64>::zeros(dim, 1);
        for j in 0..n {
            rhs[(j, 0)] = f[j];
        }
        for (s, &i) in self.sub.iter().enumerate() {
            let v = self.sys.scaling.sigma[s] * d[i];
            rhs[(n + s, 0)] = v;
            rhs[(n + ms + s, 0)] = v;
        }
        let mut fixed = Vec::new();
        let singles = self.rows.iter().enumerate().filter_map(|(q, r)| match (*r, active[q]) {
            (Row::Single { dof, c }, true) => Some((uni[q], dof, c)),
            _ => None,
        });
        for (i, dof, c) in singles.chain(self.imposed.iter().copied()) {
            let g = d[i] / c;
            for &(k, o) in &self.slots[self.slot_of[dof]] {
                if o != dof {
                    rhs[(o, 0)] -= self.base[k] * g;
                }
            }
            fixed.push((dof, g));
        }
        for (dof, g) in fixed {
            rhs[(dof, 0)] = self.scale[dof] * g;
        }
        self.factor.solve_in_place(rhs.as_mut())?;
        let z: Vec<f64> = (0..dim).map(|k| rhs[(k, 0)]).collect();
        if z.iter().any(|v| !v.is_finite()) {
            return Err(SolveError::Inaccurate { residual: f64::INFINITY, weakest: vec![] });
        }
        Ok(z)
    }

    /// (K u)_dof + (Cᵀλ)_dof of the unconstrained row, from the base values.
    fn row_product(&self, dof: usize, z: &[f64]) -> f64 {
        self.slots[self.slot_of[dof]].iter().map(|&(k, o)| self.base[k] * z[o]).sum()
    }

    /// uᵀK u from the stored (upper) K entries.
    fn energy(&self, u: &[f64]) -> f64 {
        let n = self.sys.n;
        let mut e = 0.0;
        for col in 0..n {
            for k in self.sys.col_ptr[col]..self.sys.col_ptr[col + 1] {
                let r = self.sys.row_idx[k];
                if r < n {
                    let t = self.base[k] * u[r] * u[col];
                    e += if r == col { t } else { 2.0 * t };
                }
            }
        }
        e
    }
}

/// The status backend over a [`Creux`] operator and one load.
struct Op<'a> {
    c: &'a mut Creux,
    p: &'a Problem,
    load: &'a Load,
    uni: &'a [usize],
    active: Vec<bool>,
    factored: bool,
    bad: Option<usize>,
    /// Last status solution (natural numbering).
    z: Vec<f64>,
}

impl Op<'_> {
    fn x_of(&self, z: &[f64]) -> Vec<f64> {
        let (n, ms) = (self.c.sys.n, self.c.sys.m);
        (0..self.uni.len())
            .map(|q| {
                let i = self.uni[q];
                match self.c.rows[q] {
                    Row::Multi { s } => z[n + ms + s],
                    Row::Single { dof, c } if self.active[q] => {
                        let lambda = (self.load.f[dof] - self.c.row_product(dof, z)) / c;
                        lambda / (2.0 * self.c.sigma[q])
                    }
                    Row::Single { dof, c } => self.c.sigma[q] * (self.load.d[i] - c * z[dof]) / (2.0 * self.c.alpha[q]),
                }
            })
            .collect()
    }

    fn row_dot(&self, q: usize, u: &[f64]) -> f64 {
        self.p.conditions[self.uni[q]].terms.iter().map(|&(j, v)| v * u[j]).sum()
    }
}

impl Op<'_> {
    fn change_status(&mut self, active: &[bool]) -> Result<(), usize> {
        if self.factored && active == self.active.as_slice() {
            return Ok(());
        }
        let had = self.factored;
        let res = self.factorise(active);
        if res.is_err() && had {
            // The contract keeps the previous status usable (a release test
            // follows a refused trial): factor it again.
            let prev = std::mem::take(&mut self.active);
            let bad = self.bad;
            if self.factorise(&prev).is_err() {
                self.factored = false;
            }
            self.bad = bad;
        }
        res
    }

    /// Numeric factorisation of the status `active` and its inertia check.
    fn factorise(&mut self, active: &[bool]) -> Result<(), usize> {
        let c = &mut *self.c;
        let (n, ms) = (c.sys.n, c.sys.m);
        let mut vals = c.base.clone();
        let mut fixed = vec![false; c.slots.len()];
        for &(_, dof, _) in &c.imposed {
            let l = c.slot_of[dof];
            fixed[l] = true;
            for &(k, _) in &c.slots[l] {
                vals[k] = 0.0;
            }
            if let Some(k) = c.sys.find(dof, dof) {
                vals[k] = c.scale[dof];
            }
        }
        for (q, r) in c.rows.iter().enumerate() {
            match (*r, active[q]) {
                (Row::Single { dof, .. }, true) => {
                    let l = c.slot_of[dof];
                    if fixed[l] {
                        // Two active rows on one unknown: dependent.
                        self.bad = Some(dof);
                        return Err(q);
                    }
                    fixed[l] = true;
                    for &(k, _) in &c.slots[l] {
                        vals[k] = 0.0;
                    }
                    if let Some(k) = c.sys.find(dof, dof) {
                        vals[k] = c.scale[dof];
                    }
                }
                (Row::Multi { s }, false) => {
                    if let Some(k) = c.sys.find(n + ms + s, n + ms + s) {
                        vals[k] += 4.0 * c.sys.scaling.alpha[s];
                    }
                }
                _ => {}
            }
        }
        self.factored = false;
        let sys = &c.sys;
        if let Err(z) = c.factor.factor(&sys.col_ptr, &sys.row_idx, &vals, &c.scale, usize::MAX, None) {
            self.bad = Some(z.index);
            return Err(0);
        }
        // Inertia: + for u, − for λ1, − for the λ2 of bilateral and active
        // rows, + for the λ2 of inactive ones (§3.5 on every leading block).
        let mut inactive_sub = vec![false; ms];
        for (q, r) in c.rows.iter().enumerate() {
            if let (Row::Multi { s }, false) = (*r, active[q]) {
                inactive_sub[s] = true;
            }
        }
        let fwd = c.factor.fwd();
        for (k, &d) in c.factor.pivots().iter().enumerate() {
            let t = fwd[k];
            let positive = t < n || (t >= n + ms && inactive_sub[t - n - ms]);
            let right = if positive { d > 0.0 } else { d < 0.0 };
            if !d.is_finite() || !right || d.abs() <= EPS_PIV * c.scale[t] {
                self.bad = Some(t);
                return Err(0);
            }
        }
        self.factored = true;
        self.active = active.to_vec();
        Ok(())
    }
}

/// The sparse system CREUX factorises: K and the conditions `sub` that
/// keep doubled multipliers. Every unknown a single row imposes gets a
/// stored diagonal, where its imposition is written: a BLOQ may hold an
/// unknown that no stiffness touches (UX of a spring node).
fn sub_problem(p: &Problem, sub: &[usize], rows: &[Row], imposed: &[(usize, usize, f64)]) -> Problem {
    let mut k = p.k.clone();
    for r in rows {
        if let Row::Single { dof, .. } = *r {
            k.entries.push((dof, dof, 0.0));
        }
    }
    k.entries.extend(imposed.iter().map(|&(_, dof, _)| (dof, dof, 0.0)));
    Problem { k, conditions: sub.iter().map(|&i| p.conditions[i].clone()).collect() }
}

impl Backend for Op<'_> {
    fn set_status(&mut self, active: &[bool]) -> Result<(), usize> {
        self.change_status(active)
    }

    fn solve(&mut self) -> Result<Vec<f64>, SolveError> {
        if !self.factored {
            return Err(SolveError::Other("status solve before factorisation".into()));
        }
        let z = self.c.solve_load(&self.load.f, &self.load.d, &self.active, self.uni)?;
        let x = self.x_of(&z);
        self.z = z;
        Ok(x)
    }

    fn release(&mut self, i: usize) -> Result<(bool, RigidMode), SolveError> {
        let n = self.c.sys.n;
        // Impose c_i r = 1 with the other active rows held and no load
        // (as the old method): rᵀK r is the stiffness condition i sees.
        let mut d = vec![0.0; self.p.conditions.len()];
        d[self.uni[i]] = 1.0;
        let z = self.c.solve_load(&vec![0.0; n], &d, &self.active, self.uni)?;
        let r = &z[..n];
        let kr = self.c.energy(r);
        let rr: f64 = r.iter().map(|v| v * v).sum();
        let singular = kr.abs() <= EPS_SING * self.c.kmax.max(f64::MIN_POSITIVE) * rr;
        let sense = |q: usize| self.p.conditions[self.uni[q]].kind.sense();
        let chat = self.p.conditions[self.uni[i]].terms.iter().fold(1.0_f64, |a, &(_, v)| a.max(v.abs()));
        let ur: Vec<f64> = r.iter().map(|v| sense(i) * chat * v).collect();
        let motion = (0..self.uni.len())
            .map(|q| self.c.sigma[q] / (2.0 * self.c.alpha[q]) * sense(q) * self.row_dot(q, &ur))
            .collect();
        let f = &self.load.f;
        let work = f.iter().zip(&ur).map(|(a, b)| a * b).sum();
        let work_scale = f.iter().zip(&ur).map(|(a, b)| (a * b).abs()).sum();
        Ok((singular, RigidMode { motion, work, work_scale }))
    }

    fn dependent(&mut self, active: &[bool]) -> Vec<usize> {
        let (n, ms) = (self.c.sys.n, self.c.sys.m);
        let Some(t) = self.bad else { return Vec::new() };
        let mut out: Vec<usize> = if t < n {
            (0..self.uni.len())
                .filter(|&q| active[q] && self.p.conditions[self.uni[q]].terms.iter().any(|e| e.0 == t))
                .collect()
        } else {
            let s = (t - n) % ms.max(1);
            let i = self.c.sub.get(s).copied();
            let dofs: Vec<usize> =
                i.map(|i| self.p.conditions[i].terms.iter().map(|e| e.0).collect()).unwrap_or_default();
            (0..self.uni.len())
                .filter(|&q| active[q] && self.p.conditions[self.uni[q]].terms.iter().any(|e| dofs.contains(&e.0)))
                .collect()
        };
        out.sort_unstable();
        out
    }
}

/// CREUX for `p` (unilateral conditions `uni`).
pub(super) fn solve(job: &Job, kept: &mut Option<Creux>, trace: &mut Trace) -> Outcome {
    let Job { p, load, uni, sopts } = *job;
    let Trace { on_iter, phases } = trace;
    let g = StatusError::Global;
    let t0 = std::time::Instant::now();
    let structure = lagrange::structure_hash(p);
    let values = values_hash(p);
    match kept.as_mut() {
        Some(c) if c.structure == structure => {
            if c.values != values {
                c.numbers(p, uni, true).map_err(g)?;
            }
        }
        _ => {
            *kept = None;
            *kept = Some(Creux::new(p, uni, structure).map_err(g)?);
        }
    }
    let c = kept.as_mut().expect("built above");
    c.values = values;
    phases.push(("analyse", t0.elapsed().as_secs_f64()));

    let t1 = std::time::Instant::now();
    let sense: Vec<f64> = uni.iter().map(|&i| p.conditions[i].kind.sense()).collect();
    let rows: Vec<Vec<(usize, f64)>> = uni.iter().map(|&i| p.conditions[i].terms.clone()).collect();
    let d: Vec<f64> = uni.iter().map(|&i| load.d[i]).collect();
    let mut op = Op { c, p, load, uni, active: Vec::new(), factored: false, bad: None, z: Vec::new() };
    let (x, active, _) = iterate(&mut op, &sense, &rows, &d, sopts, on_iter).map_err(StatusError::Local)?;
    phases.push(("status", t1.elapsed().as_secs_f64()));

    let (n, ms) = (op.c.sys.n, op.c.sys.m);
    let z = &op.z;
    let mut lambda = vec![0.0; p.conditions.len()];
    let mut act = vec![true; p.conditions.len()];
    for &(i, dof, c) in &op.c.imposed {
        lambda[i] = (load.f[dof] - op.c.row_product(dof, z)) / c;
    }
    for (s, &i) in op.c.sub.iter().enumerate() {
        lambda[i] = op.c.sys.scaling.sigma[s] * (z[n + s] + z[n + ms + s]);
    }
    for (q, &i) in uni.iter().enumerate() {
        act[i] = active[q];
        lambda[i] = if active[q] { 2.0 * op.c.sigma[q] * x[q] } else { 0.0 };
    }
    Ok((Solution { u: z[..n].to_vec(), lambda, active: act }, active))
}
