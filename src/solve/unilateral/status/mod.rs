//! The status (active-set) iteration: the one loop every unilateral
//! method runs (unilateral.md §7.2, §7.5).
//!
//! [`iterate`] solves T x = h (T = G − A·P_I on the condensed operator, or
//! what a backend computes in its place) for the current status, tests
//! the single sign rule s_i x_i ≤ τ (§3.4), and changes statuses by the
//! damped Cast3M-like rule (releases first, then the 70 % most violated
//! activations), falling back to Murty's least-index single change when a
//! status repeats, then to relaxed tolerances, then to `NoConvergence`.
//! Releases that would free a rigid mode are resolved by the determinant
//! lemma and a ratio test (`RIGID_MODE_STEP`), or reported as `Infeasible`.
//!
//! The decision logic is written once, over the [`Backend`] trait, so that
//! every backend (the condensed operator, the old method's reduced system,
//! the sparse system of CREUX) makes exactly the same decisions from its
//! own linear algebra.

pub mod groups;

use crate::solve::error::SolveError;
use groups::Groups;
use std::collections::HashSet;

/// How statuses change in the normal (fast) mode.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Rule {
    /// §7.2 FAST mode, Cast3M-like: release every wrong-sign active
    /// condition first; otherwise activate the violated ones within 70 % of
    /// the worst.
    #[default]
    Damped,
    /// Flip every violated status at once (primal-dual active set). For
    /// tests: it can cycle (case f), which the history detects.
    Pdas,
    /// Release every wrong-sign active condition and, in the same step,
    /// activate the violated ones within 70 % of the worst. When a contact
    /// zone is too large only its outermost ring has wrong-sign multipliers,
    /// so a set that must shrink loses one ring per step (PDAS from all
    /// inactive overshoots first: 88 steps on the 512² obstacle); damping the
    /// activation makes the zone grow from below in large steps (17).
    Mixed,
    /// Murty's least-index single change from the first iteration.
    SingleChange,
    /// The method's default: [`Rule::Mixed`] for the sparse iteration on
    /// obstacle problems (CREUX), [`Rule::Damped`] otherwise.
    Auto,
}

/// Options of the status iteration.
#[derive(Debug, Clone, Default)]
pub struct StatusOptions {
    /// Cap on the number of solves; default max(100, 20·m).
    pub max_iter: Option<usize>,
    /// Initial statuses (true = active); default: every condition active,
    /// as Cast3M's cold start (one per proportional group).
    pub start: Option<Vec<bool>>,
    pub rule: Rule,
    /// On no convergence, return the last iterate instead of
    /// `NoConvergence` (RESO 'SOUC', Cast3M's UNILATER behaviour): its
    /// record then has the mode [`UNCONVERGED`], with the conditions that
    /// still wanted to change as activated / released.
    pub keep_last: bool,
    /// Set from outside (Ctrl-C) to stop between two solves with
    /// [`SolveError::Interrupted`]: a long status loop is not waited out.
    pub cancel: Option<Cancel>,
    /// Adhesion: the tension each condition holds while active before it
    /// is released, in the units of its physical multiplier (a force);
    /// none by default. Honoured by the condensed operator's `run`.
    pub adhesion: Option<Vec<f64>>,
}

impl StatusOptions {
    fn cancelled(&self) -> bool {
        self.cancel.as_ref().is_some_and(Cancel::is_set)
    }
}

/// A stop flag shared with whoever may stop the solver (the interpreter's
/// interrupt handle). Options compare equal when they share the flag.
#[derive(Debug, Clone, Default)]
pub struct Cancel(pub std::sync::Arc<std::sync::atomic::AtomicBool>);

impl Cancel {
    pub fn is_set(&self) -> bool {
        self.0.load(std::sync::atomic::Ordering::Relaxed)
    }
}

impl PartialEq for Cancel {
    fn eq(&self, other: &Self) -> bool {
        std::sync::Arc::ptr_eq(&self.0, &other.0)
    }
}

/// Mode of the last record of an iteration that stopped unconverged
/// ([`StatusOptions::keep_last`]).
pub const UNCONVERGED: &str = "unconverged";

/// What happened at one solve. Indices are positions 0..m in the
/// [`crate::solve::unilateral::Condensed`] data.
#[derive(Debug, Clone, PartialEq)]
pub struct IterRecord {
    /// 1-based number of the solve.
    pub iteration: usize,
    /// Conditions activated after this solve.
    pub activated: Vec<usize>,
    /// Conditions released after this solve.
    pub released: Vec<usize>,
    /// Largest s_i x_i over inactive conditions (a scaled penetration), ≥ 0.
    pub worst_violation: f64,
    /// Largest s_i x_i over active conditions (a scaled wrong-sign
    /// reaction), ≥ 0.
    pub worst_wrong_sign: f64,
    /// Number of active conditions during this solve.
    pub active_count: usize,
    /// "fast", "pdas", "safe" or "slow": the mode that took the decision.
    pub mode: &'static str,
}

/// The converged status: x = λ2 (physical λ_i = 2σ_i x_i when active).
#[derive(Debug, Clone, PartialEq)]
pub struct StatusResult {
    pub x: Vec<f64>,
    pub active: Vec<bool>,
    pub records: Vec<IterRecord>,
}

/// ε of §7.1 (Cast3M's 1e−10), times 1e4 in the slow mode.
const EPS_TOL: f64 = 1e-10;
const SLOW_FACTOR: f64 = 1e4;
/// Relative size under which a pivot counts as zero.
pub(crate) const EPS_PIV: f64 = 1e-10;
/// |1 − α_i z_i| under which releasing i is singular (§3.5). Looser than
/// EPS_PIV on purpose: z carries the round-off of a solve with T.
pub(crate) const EPS_SING: f64 = 1e-9;
/// Load work along a rigid mode below this fraction of Σ|terms| is zero.
/// The work is a sum with cancellation, computed through the condensed
/// operator: on a stiff body resting on soft supports (stiffness ratios of
/// 10⁹, a steel beam on soil springs) its round-off reaches 10⁻⁵ of the
/// terms, while a load that truly drives a free body away does work of the
/// order of the terms themselves.
const EPS_WORK: f64 = 1e-4;
/// Motion of a condition along a rigid mode below this fraction of the
/// largest motion is zero.
const EPS_MOTION: f64 = 1e-9;
/// Cast3M's activation threshold (fraction of the largest violation).
const ACTIVATION_FRACTION: f64 = 0.7;

/// A rigid mode freed by releasing one condition, seen from the conditions.
pub(crate) struct RigidMode {
    /// s_j c_j u_r for every j, in the units of x_j (so that the gap of an
    /// inactive j in the same units is −s_j x_j). Oriented so that the
    /// released condition moves away from its support (motion > 0).
    pub motion: Vec<f64>,
    /// F·u_r, and Σ|F_k u_r,k| to judge it.
    pub work: f64,
    pub work_scale: f64,
}

/// The linear algebra behind a status iteration.
pub(crate) trait Backend {
    /// Makes `active` the current status if it is regular; otherwise keeps
    /// the previous one and returns the first bad pivot.
    fn set_status(&mut self, active: &[bool]) -> Result<(), usize>;
    /// x for the current status (x_i = λ2_i of §3.3).
    fn solve(&mut self) -> Result<Vec<f64>, SolveError>;
    /// Whether releasing the active condition i is singular (determinant
    /// lemma), with the mode it would free.
    fn release(&mut self, i: usize) -> Result<(bool, RigidMode), SolveError>;
    /// The conditions involved in a singular `active` status.
    fn dependent(&mut self, active: &[bool]) -> Vec<usize>;
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Mode {
    Fast,
    Safe,
    Slow,
}

enum Decision {
    Changed {
        activated: Vec<usize>,
        released: Vec<usize>,
    },
    /// Releasing this condition frees an unloaded rigid mode: keep it
    /// active and ignore its (round-off) wrong sign.
    Frozen(usize),
}

type Outcome = (Vec<f64>, Vec<bool>, Vec<IterRecord>);

/// The §7.2 loop over any backend.
pub(crate) fn iterate(
    b: &mut dyn Backend,
    sense: &[f64],
    rows: &[Vec<(usize, f64)>],
    d: &[f64],
    opts: &StatusOptions,
    on_iter: &mut dyn FnMut(&IterRecord),
) -> Result<Outcome, SolveError> {
    let m = sense.len();
    let mut groups = groups::analyse(rows, sense, d)?;
    if m == 0 {
        return Ok((Vec::new(), Vec::new(), Vec::new()));
    }
    // Floor of the length reference of §7.1: max |d_i| / ĉ_i.
    let lref0 = rows
        .iter()
        .zip(d)
        .map(|(r, di)| di.abs() / r.iter().fold(1.0_f64, |a, &(_, v)| a.max(v.abs())))
        .fold(0.0_f64, f64::max);

    let mut cold = start_status(&groups, &vec![true; m]);
    let mut status = match &opts.start {
        Some(s) if s.len() != m => {
            return Err(SolveError::Other(format!("start status has {} entries for {m} conditions", s.len())))
        }
        Some(s) => start_status(&groups, s),
        None => cold.clone(),
    };
    // Conditions left out of the iteration because their rows depend on
    // others, with the rows they depend on.
    let mut dropped: Vec<(usize, Vec<usize>)> = Vec::new();
    if b.set_status(&status).is_err() {
        // A warm start that frees a rigid mode falls back to the cold start,
        // which holds every mode that any support holds.
        if status == cold || b.set_status(&cold).is_err() {
            // The cold start itself is singular. A row that depends on the
            // bilateral conditions alone (a RELA 'MINI' over two blocked
            // nodes, as a node-by-node relation along clamped edges gives)
            // has its value fixed by them: it never needs to act, and it
            // must hold at the end. Cast3M drops such rows too (MAFREIN).
            // Rows that depend on other unilateral rows are reported
            // (§7.5: do not guess which of them should act).
            // A row that depends on other unilateral rows starts inactive
            // (deferred, not dropped): its value follows from theirs while
            // they act, and it is checked like any inactive row. The
            // symmetric node-to-segment contact of two meshes makes such
            // rows (impo.notice's default), and Cast3M solves them.
            let mut deferred = 0;
            loop {
                let dep = b.dependent(&cold);
                let k = match dep[..] {
                    [k] if cold[k] => {
                        groups.fixed_inactive[k] = true;
                        dropped.push((k, dep));
                        k
                    }
                    [.., k] if cold[k] => {
                        deferred += 1;
                        k
                    }
                    _ => return Err(SolveError::DependentConditions { conditions: dep }),
                };
                cold[k] = false;
                if b.set_status(&cold).is_ok() {
                    break;
                }
                if dropped.len() + deferred >= m {
                    return Err(SolveError::DependentConditions { conditions: (0..m).collect() });
                }
            }
        }
        status = cold;
    }

    let mut mode = if opts.rule == Rule::SingleChange { Mode::Safe } else { Mode::Fast };
    let maxit = opts.max_iter.unwrap_or((20 * m).max(100));
    let mut history: HashSet<Vec<bool>> = HashSet::new();
    let mut frozen = vec![false; m];
    let mut records = Vec::new();
    let mut last_set = Vec::new();
    for it in 1..=maxit {
        if opts.cancelled() {
            return Err(SolveError::Interrupted);
        }
        let x = b.solve()?;
        // s_i x_i: a penetration for an inactive condition, a tension for
        // an active one, beyond its adhesion if it has some.
        let held = |i: usize| match &opts.adhesion {
            Some(a) if status[i] => a[i],
            _ => 0.0,
        };
        let v: Vec<f64> = (0..m).map(|i| sense[i] * x[i] - held(i)).collect();
        let worst = |act: bool| {
            (0..m).filter(|&i| status[i] == act && !groups.fixed_inactive[i]).fold(0.0_f64, |a, i| a.max(v[i]))
        };
        let mut rec = IterRecord {
            iteration: it,
            activated: Vec::new(),
            released: Vec::new(),
            worst_violation: worst(false),
            worst_wrong_sign: worst(true),
            active_count: status.iter().filter(|&&a| a).count(),
            mode: mode_name(mode, opts.rule),
        };
        let lref = x.iter().fold(lref0, |a, xi| a.max(xi.abs()));
        let tau_of = |mode: Mode| EPS_TOL * lref * if mode == Mode::Slow { SLOW_FACTOR } else { 1.0 };
        let violated = |mode: Mode, frozen: &[bool]| -> Vec<usize> {
            let tau = tau_of(mode);
            (0..m).filter(|&i| v[i] > tau && !groups.fixed_inactive[i] && !frozen[i]).collect()
        };
        let mut set = violated(mode, &frozen);
        if !set.is_empty() && !history.insert(status.clone()) {
            // A repeated status: the current rule cycles.
            mode = match mode {
                Mode::Fast => Mode::Safe,
                Mode::Safe => Mode::Slow,
                Mode::Slow => {
                    if opts.keep_last {
                        unconverged(&mut rec, &set, &status);
                        on_iter(&rec);
                        records.push(rec);
                        return Ok((x, status, records));
                    }
                    on_iter(&rec);
                    records.push(rec);
                    return Err(SolveError::NoConvergence { iterations: it, conditions: set });
                }
            };
            history.clear();
            history.insert(status.clone());
            rec.mode = mode_name(mode, opts.rule);
            set = violated(mode, &frozen);
        }
        if it == maxit && opts.keep_last && !set.is_empty() {
            // The cap: this solve is the last iterate.
            unconverged(&mut rec, &set, &status);
            on_iter(&rec);
            records.push(rec);
            return Ok((x, status, records));
        }
        loop {
            if set.is_empty() {
                on_iter(&rec);
                records.push(rec);
                // A dropped row violated at the end cannot be met together
                // with the bilateral conditions that fix it.
                if let Some((k, dep)) = dropped.iter().find(|(k, _)| v[*k] > tau_of(mode)) {
                    let mut conditions = dep.clone();
                    if !conditions.contains(k) {
                        conditions.push(*k);
                    }
                    return Err(SolveError::Conflicting { conditions });
                }
                return Ok((x, status, records));
            }
            let ctx = Ctx { groups: &groups, v: &v, rule: opts.rule };
            match decide(b, &ctx, mode, &set, &mut status) {
                Ok(Decision::Changed { activated, released }) => {
                    rec.activated = activated;
                    rec.released = released;
                    frozen.fill(false);
                    break;
                }
                Ok(Decision::Frozen(i)) => {
                    frozen[i] = true;
                    set.retain(|&k| k != i);
                }
                Err(e) => {
                    on_iter(&rec);
                    records.push(rec);
                    return Err(e);
                }
            }
        }
        on_iter(&rec);
        records.push(rec);
        last_set = set;
    }
    Err(SolveError::NoConvergence { iterations: maxit, conditions: last_set })
}

/// Marks `rec` as the last, unconverged iterate: the conditions of `set`
/// that still wanted to change, split by their status.
fn unconverged(rec: &mut IterRecord, set: &[usize], status: &[bool]) {
    rec.mode = UNCONVERGED;
    rec.activated = set.iter().copied().filter(|&i| !status[i]).collect();
    rec.released = set.iter().copied().filter(|&i| status[i]).collect();
}

fn mode_name(mode: Mode, rule: Rule) -> &'static str {
    match (mode, rule) {
        (Mode::Fast, Rule::Pdas) => "pdas",
        (Mode::Fast, Rule::Mixed) => "mixed",
        (Mode::Fast, _) => "fast",
        (Mode::Safe, _) => "safe",
        (Mode::Slow, _) => "slow",
    }
}

/// The requested start made admissible: dominated conditions inactive, at
/// most one active per proportional pair (the lower index).
fn start_status(groups: &Groups, wanted: &[bool]) -> Vec<bool> {
    let mut s: Vec<bool> = wanted.iter().zip(&groups.fixed_inactive).map(|(&w, &f)| w && !f).collect();
    for i in 0..s.len() {
        if let Some(p) = groups.partner[i] {
            if p < i && s[p] {
                s[i] = false;
            }
        }
    }
    s
}

struct Ctx<'a> {
    groups: &'a Groups,
    v: &'a [f64],
    rule: Rule,
}

/// Activates i in `trial`, releasing its active partner (a swap keeps at
/// most one active per proportional pair).
fn activate(ctx: &Ctx, trial: &mut [bool], i: usize, released: &mut Vec<usize>) {
    trial[i] = true;
    if let Some(p) = ctx.groups.partner[i] {
        if trial[p] {
            trial[p] = false;
            released.push(p);
        }
    }
}

/// Activates `list` (most violated first; a partner of an already chosen
/// condition is skipped) and applies the status; a singular result means
/// dependent rows.
fn activate_all(
    b: &mut dyn Backend,
    ctx: &Ctx,
    list: &[usize],
    status: &mut Vec<bool>,
) -> Result<Decision, SolveError> {
    let mut order = list.to_vec();
    order.sort_by(|&a, &b| ctx.v[b].total_cmp(&ctx.v[a]).then(a.cmp(&b)));
    let mut trial = status.clone();
    let (mut activated, mut released) = (Vec::new(), Vec::new());
    for i in order {
        if ctx.groups.partner[i].is_some_and(|p| activated.contains(&p)) {
            continue;
        }
        activate(ctx, &mut trial, i, &mut released);
        activated.push(i);
    }
    // An activation that makes the active rows dependent is skipped: that
    // row's value follows from the others once they act, and it is tested
    // again at the next solve. Only when every activation is of that kind
    // are the rows reported (§7.5: a violated row that depends on active
    // ones cannot be met without releasing one of them).
    while let Err(k) = b.set_status(&trial) {
        match activated.iter().position(|&i| i == k) {
            Some(pos) if activated.len() > 1 => {
                activated.remove(pos);
                trial[k] = false;
            }
            _ => return Err(SolveError::DependentConditions { conditions: b.dependent(&trial) }),
        }
    }
    *status = trial;
    activated.sort_unstable();
    released.sort_unstable();
    Ok(Decision::Changed { activated, released })
}

fn decide(
    b: &mut dyn Backend,
    ctx: &Ctx,
    mode: Mode,
    set: &[usize],
    status: &mut Vec<bool>,
) -> Result<Decision, SolveError> {
    let rel: Vec<usize> = set.iter().copied().filter(|&i| status[i]).collect();
    let act: Vec<usize> = set.iter().copied().filter(|&i| !status[i]).collect();
    let most_violated = |l: &[usize]| l.iter().copied().fold(l[0], |a, i| if ctx.v[i] > ctx.v[a] { i } else { a });
    if mode != Mode::Fast {
        // Murty's least-index rule: one change, the smallest violated index.
        let i = set[0];
        return if status[i] { single_release(b, ctx, i, status) } else { activate_all(b, ctx, &[i], status) };
    }
    if matches!(ctx.rule, Rule::Pdas | Rule::Mixed) {
        let mut trial = status.clone();
        for &i in &rel {
            trial[i] = false;
        }
        let mut released = rel.clone();
        let mut activated = Vec::new();
        let fraction = if ctx.rule == Rule::Mixed { ACTIVATION_FRACTION } else { 0.0 };
        let vmax = act.iter().fold(0.0_f64, |a, &i| a.max(ctx.v[i]));
        for &i in act.iter().filter(|&&i| ctx.v[i] >= fraction * vmax) {
            if !ctx.groups.partner[i].is_some_and(|p| activated.contains(&p)) {
                activate(ctx, &mut trial, i, &mut released);
                activated.push(i);
            }
        }
        if b.set_status(&trial).is_ok() {
            *status = trial;
            released.sort_unstable();
            return Ok(Decision::Changed { activated, released });
        }
        if rel.is_empty() {
            return Err(SolveError::DependentConditions { conditions: b.dependent(&trial) });
        }
        return single_release(b, ctx, most_violated(&rel), status);
    }
    if rel.is_empty() {
        let vmax = act.iter().fold(0.0_f64, |a, &i| a.max(ctx.v[i]));
        let chosen: Vec<usize> = act.iter().copied().filter(|&i| ctx.v[i] >= ACTIVATION_FRACTION * vmax).collect();
        return activate_all(b, ctx, &chosen, status);
    }
    let mut trial = status.clone();
    for &i in &rel {
        trial[i] = false;
    }
    if b.set_status(&trial).is_ok() {
        *status = trial;
        return Ok(Decision::Changed { activated: Vec::new(), released: rel });
    }
    single_release(b, ctx, most_violated(&rel), status)
}

/// Releases the active condition i, or resolves the rigid mode it would
/// free (RIGID_MODE_STEP of §7.5).
fn single_release(b: &mut dyn Backend, ctx: &Ctx, i: usize, status: &mut Vec<bool>) -> Result<Decision, SolveError> {
    let (singular, mode) = b.release(i)?;
    if !singular {
        let mut trial = status.clone();
        trial[i] = false;
        if b.set_status(&trial).is_ok() {
            *status = trial;
            return Ok(Decision::Changed { activated: Vec::new(), released: vec![i] });
        }
        // The factorisation disagrees with the lemma (round-off near a
        // singular release): treat it as the singular case.
    }
    if !mode.work.is_finite() || mode.motion.iter().any(|x| !x.is_finite()) {
        return Err(SolveError::Inaccurate { residual: f64::INFINITY, weakest: vec![] });
    }
    if mode.work <= EPS_WORK * mode.work_scale {
        // The load does no work along the mode: the wrong sign on i is
        // round-off, i stays active (§7.5 step 3).
        return Ok(Decision::Frozen(i));
    }
    let thr = EPS_MOTION * mode.motion.iter().fold(0.0_f64, |a, x| a.max(x.abs()));
    let m = status.len();
    // Inactive conditions the mode moves towards, with the ratio test:
    // the first support reached along the mode.
    let mut best: Option<(usize, f64)> = None;
    for (j, &on) in status.iter().enumerate() {
        if on || ctx.groups.fixed_inactive[j] || mode.motion[j] >= -thr {
            continue;
        }
        let gap = (-ctx.v[j]).max(0.0);
        let ratio = gap / -mode.motion[j];
        if best.is_none_or(|(_, r)| ratio < r) {
            best = Some((j, ratio));
        }
    }
    let Some((j, _)) = best else {
        let mut conditions = vec![i];
        conditions.extend((0..m).filter(|&k| k != i && mode.motion[k] > thr));
        return Err(SolveError::Infeasible { conditions, work: mode.work });
    };
    let mut trial = status.clone();
    trial[i] = false;
    let mut released = vec![i];
    activate(ctx, &mut trial, j, &mut released);
    if b.set_status(&trial).is_err() {
        return Err(SolveError::DependentConditions { conditions: vec![i.min(j), i.max(j)] });
    }
    *status = trial;
    released.sort_unstable();
    Ok(Decision::Changed { activated: vec![j], released })
}
