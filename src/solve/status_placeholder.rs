//! PLACEHOLDER for `status.rs` (written by another helper): the same public
//! signature, with a plain Cast3M-like status loop, so that the UNIL driver
//! can be built and tested before the real one lands. It has none of the
//! real loop's safeguards (groups of proportional rows, rigid-mode swaps,
//! anti-cycling). Delete this file and switch the `use` line in
//! `unilateral.rs` once `status::run` exists.

use faer::linalg::solvers::Solve;
use faer::Mat;

use super::error::SolveError;
use super::problem::Condensed;

pub struct StatusOptions {
    pub max_iter: Option<usize>,
    pub start: Option<Vec<bool>>,
    pub rule: Rule,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Rule {
    /// Cast3M-like: release every wrong sign, else activate the violations
    /// within 70 % of the largest.
    Damped,
    /// Flip every violated status.
    Pdas,
    /// Flip the most violated one.
    SingleChange,
}

#[derive(Debug, Clone)]
pub struct IterRecord {
    pub iteration: usize,
    pub activated: Vec<usize>,
    pub released: Vec<usize>,
    pub worst_violation: f64,
    pub worst_wrong_sign: f64,
    pub active_count: usize,
    pub mode: &'static str,
}

pub struct StatusResult {
    pub x: Vec<f64>,
    pub active: Vec<bool>,
    pub records: Vec<IterRecord>,
}

pub fn run(
    c: &Condensed,
    opts: &StatusOptions,
    on_iter: &mut dyn FnMut(&IterRecord),
) -> Result<StatusResult, SolveError> {
    let m = c.h.len();
    let mut active = opts.start.clone().unwrap_or_else(|| vec![true; m]);
    let max_iter = opts.max_iter.unwrap_or((20 * m).max(100));
    let dref = (0..m).fold(0.0f64, |a, i| {
        let chat = c.rows[i].iter().fold(1.0f64, |b, t| b.max(t.1.abs()));
        a.max(c.d[i].abs() / chat)
    });
    let mut records = Vec::new();
    for it in 1..=max_iter {
        let mut t = c.g.clone();
        for i in 0..m {
            if !active[i] {
                t[(i, i)] -= c.alpha[i];
            }
        }
        let h = Mat::from_fn(m, 1, |i, _| c.h[i]);
        // T is quasi-definite for a regular status: LDLᵀ without pivoting.
        let xm = match t.ldlt(faer::Side::Lower) {
            Ok(f) => f.solve(&h),
            Err(_) => return Err(SolveError::Singular { dofs: vec![] }),
        };
        let x: Vec<f64> = (0..m).map(|i| xm[(i, 0)]).collect();
        if x.iter().any(|v| !v.is_finite()) {
            return Err(SolveError::Singular { dofs: vec![] });
        }
        let lref = x.iter().fold(dref, |a, v| a.max(v.abs()));
        let tau = 1e-10 * lref;
        let v: Vec<f64> = (0..m).map(|i| c.sense[i] * x[i]).collect();
        let viol: Vec<usize> = (0..m).filter(|&i| v[i] > tau).collect();
        let wrong: Vec<usize> = viol.iter().copied().filter(|&i| active[i]).collect();
        let pen: Vec<usize> = viol.iter().copied().filter(|&i| !active[i]).collect();
        let worst = |s: &[usize]| s.iter().fold(0.0f64, |a, &i| a.max(v[i]));
        let (mut activated, mut released) = (Vec::new(), Vec::new());
        match opts.rule {
            Rule::Pdas => {
                released = wrong.clone();
                activated = pen.clone();
            }
            Rule::SingleChange => {
                if let Some(&i) = viol.iter().max_by(|&&a, &&b| v[a].total_cmp(&v[b])) {
                    if active[i] {
                        released.push(i);
                    } else {
                        activated.push(i);
                    }
                }
            }
            Rule::Damped => {
                if !wrong.is_empty() {
                    released = wrong.clone();
                } else {
                    let vmax = worst(&pen);
                    activated = pen
                        .iter()
                        .copied()
                        .filter(|&i| v[i] >= 0.7 * vmax)
                        .collect();
                }
            }
        }
        for &i in &released {
            active[i] = false;
        }
        for &i in &activated {
            active[i] = true;
        }
        let rec = IterRecord {
            iteration: it,
            activated,
            released,
            worst_violation: worst(&pen),
            worst_wrong_sign: worst(&wrong),
            active_count: active.iter().filter(|a| **a).count(),
            mode: "placeholder",
        };
        on_iter(&rec);
        records.push(rec);
        if viol.is_empty() {
            return Ok(StatusResult { x, active, records });
        }
    }
    Err(SolveError::NoConvergence {
        iterations: max_iter,
        conditions: vec![],
    })
}
