//! CONDENSE, the default method (unilateral.md §3): one interrupted LDLᵀ
//! gives the condensed operator on the second multipliers of the
//! unilateral conditions ([`condenser`], normally through the border of
//! `border`); the status loop runs on that dense m×m problem through
//! [`operator`]; one partial substitution recovers u and the multipliers.

mod border;
pub mod condenser;
pub mod operator;

use super::backend::values_hash;
use super::backend::{Job, Outcome, StatusError, Trace};
use condenser::Condenser;
use std::time::Instant;

/// The problem condensed onto the second multipliers of the `m` unilateral
/// conditions (unilateral.md §3.2, negated quarter-scaled form):
/// `T x = h` with `T = G − A·P_I`, where `P_I` is the 0/1 diagonal of the
/// inactive conditions. Produced by the condenser (or by ITER), consumed by [`operator::run`].
/// Indices `0..m` here are positions among the unilateral conditions only.
#[derive(Debug, Clone)]
pub struct Condensed {
    /// `G = ΣC H⁻¹ CᵀΣ` (m×m, symmetric; positive definite when the rows
    /// are independent).
    pub g: std::rc::Rc<faer::Mat<f64>>,
    /// The packed LDLᵀ of `g` (D on the diagonal, unit L strictly below)
    /// when the condensation produced it (an unshifted interrupted
    /// factorisation): the status loop's factor while every condition is
    /// active, with no dense factorisation.
    pub g_factor: Option<std::rc::Rc<faer::Mat<f64>>>,
    /// `h = ½ (ΣC H⁻¹ (F + CᵀW d) − Σd)`.
    pub h: Vec<f64>,
    /// Multiplier-block scaling α_i (the diagonal change on release is α_i).
    pub alpha: Vec<f64>,
    /// Coupling scaling σ_i (physical λ_i = 2 σ_i x_i when active).
    pub sigma: Vec<f64>,
    /// s_i: +1 for MINI, −1 for MAXI.
    pub sense: Vec<f64>,
    /// `XᵀF = ΣC H⁻¹ F`, for the work of the load along a rigid mode (§7.5).
    pub xtf: Vec<f64>,
    /// The rows c_i (primal unknown, coefficient), to group proportional rows.
    pub rows: Vec<Vec<(usize, f64)>>,
    /// The limits d_i.
    pub d: Vec<f64>,
}

/// The condenser kept between solves, with the fingerprint of the values
/// it was factorised with.
#[derive(Debug, Default)]
pub struct KeptCondenser {
    condenser: Option<Condenser>,
    values: u64,
}

/// CONDENSE: interrupted factorisation, dense status loop, recovery.
pub(super) fn solve(job: &Job, kept: &mut KeptCondenser, trace: &mut Trace) -> Outcome {
    let Job { p, load, sopts, .. } = *job;
    let Trace { on_iter, phases } = trace;
    let g = StatusError::Global;
    let t0 = Instant::now();
    let values = values_hash(p);
    let reuse = kept.condenser.as_ref().is_some_and(|c| c.same_pattern(p));
    if !reuse {
        kept.condenser = None;
        kept.condenser = Some(Condenser::new(p).map_err(g)?);
    } else if kept.values != values {
        let c = kept.condenser.as_mut().expect("checked above");
        if let Err(e) = c.refactor(p) {
            kept.condenser = None;
            return Err(g(e));
        }
    }
    kept.values = values;
    let cond = kept.condenser.as_ref().expect("built above");
    let condensed = cond.condensed(load).map_err(g)?;
    phases.push(("condense", t0.elapsed().as_secs_f64()));

    let t1 = Instant::now();
    let res = operator::run(&condensed, sopts, on_iter).map_err(StatusError::Local)?;
    phases.push(("status", t1.elapsed().as_secs_f64()));

    let t2 = Instant::now();
    let sol = cond.recover(load, &res.x, &res.active).map_err(g)?;
    phases.push(("recover", t2.elapsed().as_secs_f64()));
    Ok((sol, res.active))
}
