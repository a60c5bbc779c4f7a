//! The step solver of an elastic structure: one operator, many loads.
//!
//! The operator (stiffness and conditions) is the same at every step of an
//! elastic analysis, so it is factorised once:
//! * without unilateral conditions, one sparse LDLᵀ ([`Factorization`]);
//!   a step is one forward and backward solve;
//! * with unilateral conditions (contact, `BLOQ`/`RELA` 'MINI'/'MAXI'),
//!   the interrupted factorisation of the condensed method
//!   ([`Condenser`]): the condensed operator on the conditions is built
//!   once; a step is a partial forward substitution of its load, the status
//!   iteration of [`operator::run`] warm-started from the previous step's
//!   statuses, and a partial back substitution.
//!
//! Problems the condensed method does not take (a non-symmetric operator,
//! conditions on a large share of the unknowns) go through the solver's
//! general entry point with its cache ([`solve_unilateral`]).

use std::time::Instant;

use super::history::{axpy, LoadHistory};
use crate::solve::direct::{DirectOptions, Factorization};
use crate::solve::unilateral::backend::to_global;
use crate::solve::unilateral::condensed::condenser::{Condenser, Forwarded};
use crate::solve::unilateral::condensed::operator;
use crate::solve::unilateral::status::{Cancel, IterRecord, Rule, StatusOptions};
use crate::solve::unilateral::{solve_unilateral, Condensed, UnilCache, UnilOptions};
use crate::solve::{Load, Problem, Solution, SolveError};

/// Above this many unilateral conditions on a large share of the unknowns
/// the dense condensed operator is not the right tool: the general entry
/// point picks the sparse status iteration (CREUX) there.
const DENSE_MAX: usize = 2000;

enum Core {
    Direct(Box<Factorization>),
    Condensed(Box<Condenser>),
    General(Box<UnilCache>),
}

/// What one step did.
#[derive(Debug, Clone)]
pub struct StepOutcome {
    pub solution: Solution,
    /// Solves of the status iteration (1 without unilateral conditions).
    pub iterations: usize,
    /// Unilateral conditions whose status differs from the previous step.
    pub changed: usize,
    /// Active unilateral conditions at the end of the step.
    pub active: usize,
    /// Seconds per phase of the step.
    pub phases: Vec<(&'static str, f64)>,
}

/// The operator of a run, factorised, and the statuses of the last step.
pub struct Stepper {
    problem: Problem,
    core: Core,
    /// Global numbers of the unilateral conditions.
    uni: Vec<usize>,
    /// Final statuses of the last step (unilateral order): the warm start.
    status: Option<Vec<bool>>,
    /// Seconds spent building the operator.
    pub setup_seconds: f64,
    /// Without unilateral conditions the response is linear in the load:
    /// the solutions of a history's base and terms, by history id.
    basis: Option<(u64, Solution, Vec<Solution>)>,
    /// With unilateral conditions the forward substitution is linear in
    /// the load: a history's base and terms forwarded once, by history id.
    forwarded: Option<(u64, Forwarded, Vec<Forwarded>)>,
    /// The tension each unilateral condition holds before it opens
    /// (unilateral order), if any holds one.
    adhesion: Option<Vec<f64>>,
    /// Stops a status iteration between two solves (Ctrl-C).
    cancel: Option<Cancel>,
}

impl Stepper {
    /// Factorises (or condenses) the operator of `problem` once.
    pub fn new(problem: Problem) -> Result<Self, SolveError> {
        let t = Instant::now();
        let uni: Vec<usize> =
            (0..problem.conditions.len()).filter(|&i| problem.conditions[i].kind.is_unilateral()).collect();
        let (n, m) = (problem.k.n, uni.len());
        let core = if m == 0 {
            let opts = DirectOptions { check_residual: true, stab: false };
            Core::Direct(Box::new(Factorization::new(&problem, &opts)?))
        } else if problem.k.symmetric && !(m > DENSE_MAX && 4 * m > n) && 8.0 * (m * m) as f64 <= 1.0e9 {
            Core::Condensed(Box::new(Condenser::new(&problem)?))
        } else {
            Core::General(Box::default())
        };
        Ok(Stepper {
            problem,
            core,
            uni,
            status: None,
            setup_seconds: t.elapsed().as_secs_f64(),
            basis: None,
            forwarded: None,
            adhesion: None,
            cancel: None,
        })
    }

    /// New numbers on the same structure (a material that changes from
    /// step to step). Without unilateral conditions only the numeric
    /// factorisation reruns, on the ordering and symbolic analysis found
    /// once; with unilateral conditions, or a pattern that changed, the
    /// operator is built anew. The statuses and the stop flag are kept.
    pub fn renew(&mut self, problem: Problem) -> Result<(), SolveError> {
        let t = Instant::now();
        if let Core::Direct(f) = &mut self.core {
            if f.same_pattern(&problem) {
                f.refactor(&problem)?;
                self.problem = problem;
                // The solutions kept per history belong to the old numbers.
                self.basis = None;
                self.forwarded = None;
                self.setup_seconds += t.elapsed().as_secs_f64();
                return Ok(());
            }
        }
        let mut next = Stepper::new(problem)?;
        next.status = self.status.take().filter(|s| s.len() == next.uni.len());
        next.cancel = self.cancel.take();
        *self = next;
        Ok(())
    }

    /// A stop flag for the status iterations of the steps (the host's
    /// interrupt): a step then ends with [`SolveError::Interrupted`].
    pub fn set_cancel(&mut self, cancel: Cancel) {
        self.cancel = Some(cancel);
    }

    pub fn problem(&self) -> &Problem {
        &self.problem
    }

    /// Statuses of the unilateral conditions after the last step (true =
    /// active), in the order of the conditions.
    pub fn statuses(&self) -> Option<&[bool]> {
        self.status.as_deref()
    }

    /// Adhesion (contact that holds a tension before it opens): the force
    /// each condition holds while active, by condition number (0 for none).
    /// The condensed method honours it; the general path (non-symmetric
    /// operators, conditions on most unknowns) refuses it.
    pub fn set_adhesion(&mut self, by_condition: &[f64]) -> Result<(), SolveError> {
        if by_condition.iter().all(|v| *v == 0.0) {
            self.adhesion = None;
            return Ok(());
        }
        if !matches!(self.core, Core::Condensed(_)) {
            return Err(SolveError::Other(
                "adhesion needs the condensed method (a symmetric operator and not too many conditions)".into(),
            ));
        }
        self.adhesion = Some(self.uni.iter().map(|&i| by_condition.get(i).copied().unwrap_or(0.0)).collect());
        Ok(())
    }

    /// Starts the next step from these statuses (a continued run).
    pub fn set_statuses(&mut self, s: Vec<bool>) {
        if s.len() == self.uni.len() {
            self.status = Some(s);
        }
    }

    /// Solves the step of `history` whose term weights are `c` (see
    /// [`LoadHistory::coefficients`]), plus an `extra` load of that step.
    ///
    /// Without unilateral conditions the answer is linear in the load: the
    /// base and each term are solved once per history, and a step is their
    /// combination (no solve; the same numbers for the same time whatever
    /// the steps before, so a continued run repeats a single one exactly).
    /// With unilateral conditions this is [`Stepper::solve`] of the
    /// combined load.
    pub fn solve_history(
        &mut self,
        history: &LoadHistory,
        c: &[f64],
        extra: Option<&Load>,
        on_iter: &mut dyn FnMut(&IterRecord),
    ) -> Result<StepOutcome, SolveError> {
        if let Core::Condensed(cond) = &self.core {
            // The forward half of the step is a combination of forwarded
            // loads; only the status iteration and the back substitution
            // remain.
            let t0 = Instant::now();
            if self.forwarded.as_ref().is_none_or(|f| f.0 != history.id()) {
                let base = cond.forward_load(&history.base)?;
                let terms = history.terms.iter().map(|term| cond.forward_load(&term.load)).collect::<Result<_, _>>()?;
                self.forwarded = Some((history.id(), base, terms));
            }
            let (_, base, terms) = self.forwarded.as_ref().expect("set above");
            let mut fw = base.clone();
            for (tf, &ck) in terms.iter().zip(c) {
                if ck != 0.0 {
                    fw.add(ck, tf);
                }
            }
            let mut d = history.combine_limits(c);
            if let Some(e) = extra {
                fw.add(1.0, &cond.forward_load(e)?);
                axpy(&mut d, 1.0, &e.d);
            }
            let condensed = cond.condensed_from(&fw, &d);
            let mut phases = vec![("combine", t0.elapsed().as_secs_f64())];
            let t1 = Instant::now();
            let (x, active, iterations) = self.status_iteration(&condensed, on_iter)?;
            phases.push(("status", t1.elapsed().as_secs_f64()));
            let t2 = Instant::now();
            let Core::Condensed(cond) = &self.core else { unreachable!("checked above") };
            let solution = cond.recover_from(&fw, &x, &active)?;
            phases.push(("recover", t2.elapsed().as_secs_f64()));
            return Ok(self.finish_step(solution, iterations, active, phases));
        }
        let Core::Direct(f) = &self.core else {
            let mut load = history.combine(c);
            if let Some(e) = extra {
                axpy(&mut load.f, 1.0, &e.f);
                axpy(&mut load.d, 1.0, &e.d);
            }
            return self.solve(&load, on_iter);
        };
        let t = Instant::now();
        if self.basis.as_ref().is_none_or(|b| b.0 != history.id()) {
            let mut loads = vec![history.base.clone()];
            loads.extend(history.terms.iter().map(|term| term.load.clone()));
            let mut sols = f.solve_checked(&loads, true)?;
            let base = sols.remove(0);
            self.basis = Some((history.id(), base, sols));
        }
        let (_, base, terms) = self.basis.as_ref().expect("set above");
        let mut s = base.clone();
        for (ts, &ck) in terms.iter().zip(c) {
            if ck != 0.0 {
                axpy(&mut s.u, ck, &ts.u);
                axpy(&mut s.lambda, ck, &ts.lambda);
            }
        }
        if let Some(e) = extra {
            let x = f.solve_checked(std::slice::from_ref(e), true)?.pop().expect("one load, one solution");
            axpy(&mut s.u, 1.0, &x.u);
            axpy(&mut s.lambda, 1.0, &x.lambda);
        }
        let phases = vec![("combine", t.elapsed().as_secs_f64())];
        Ok(StepOutcome { solution: s, iterations: 1, changed: 0, active: 0, phases })
    }

    /// Solves one step. `on_iter` sees each status solve.
    pub fn solve(&mut self, load: &Load, on_iter: &mut dyn FnMut(&IterRecord)) -> Result<StepOutcome, SolveError> {
        let mut phases = Vec::new();
        let (solution, iterations, active) = match &mut self.core {
            Core::Direct(f) => {
                let t = Instant::now();
                let s = f.solve_checked(std::slice::from_ref(load), true)?.pop().expect("one load, one solution");
                phases.push(("solve", t.elapsed().as_secs_f64()));
                (s, 1, Vec::new())
            }
            Core::Condensed(c) => {
                let t0 = Instant::now();
                let condensed = c.condensed(load)?;
                phases.push(("condense", t0.elapsed().as_secs_f64()));
                let t1 = Instant::now();
                let (x, active, iterations) = self.status_iteration(&condensed, on_iter)?;
                phases.push(("status", t1.elapsed().as_secs_f64()));
                let t2 = Instant::now();
                let Core::Condensed(c) = &self.core else { unreachable!("matched above") };
                let s = c.recover(load, &x, &active)?;
                phases.push(("recover", t2.elapsed().as_secs_f64()));
                (s, iterations, active)
            }
            Core::General(cache) => {
                let opts =
                    UnilOptions { initial: self.status.clone(), cancel: self.cancel.clone(), ..Default::default() };
                let (s, rep) = solve_unilateral(&self.problem, load, &opts, cache, on_iter)?;
                phases.extend(rep.phase_seconds.iter().copied());
                let active: Vec<bool> = self.uni.iter().map(|&i| s.active[i]).collect();
                (s, rep.iterations, active)
            }
        };
        Ok(self.finish_step(solution, iterations, active, phases))
    }

    /// The status iteration on a condensed step, warm-started from the last
    /// step's statuses: x, the statuses and the number of solves.
    fn status_iteration(
        &self,
        condensed: &Condensed,
        on_iter: &mut dyn FnMut(&IterRecord),
    ) -> Result<(Vec<f64>, Vec<bool>, usize), SolveError> {
        let opts = StatusOptions {
            max_iter: None,
            start: self.status.clone(),
            rule: Rule::Damped,
            keep_last: false,
            cancel: self.cancel.clone(),
            adhesion: self.adhesion.clone(),
        };
        let uni = &self.uni;
        let mut global = |r: &IterRecord| {
            let g = |v: &[usize]| v.iter().map(|&q| uni[q]).collect();
            on_iter(&IterRecord { activated: g(&r.activated), released: g(&r.released), ..r.clone() })
        };
        let res = operator::run(condensed, &opts, &mut global).map_err(|e| to_global(e, uni))?;
        Ok((res.x, res.active, res.records.len()))
    }

    /// The outcome of a step, the statuses kept for the next.
    fn finish_step(
        &mut self,
        solution: Solution,
        iterations: usize,
        active: Vec<bool>,
        phases: Vec<(&'static str, f64)>,
    ) -> StepOutcome {
        let changed = match &self.status {
            Some(prev) => prev.iter().zip(&active).filter(|(a, b)| a != b).count(),
            None => active.iter().filter(|a| **a).count(),
        };
        let n_active = active.iter().filter(|a| **a).count();
        if !self.uni.is_empty() {
            self.status = Some(active);
        }
        StepOutcome { solution, iterations, changed, active: n_active, phases }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solve::{Condition, Kind, Matrix};

    /// A spring of stiffness 10 on one unknown, pushed against a stop at
    /// −0.1 (MINI) by a force that grows, then reverses: the stop acts only
    /// once the free displacement passes it, and the warm start carries the
    /// status from step to step.
    #[test]
    fn spring_against_a_stop_opens_and_closes() {
        let p = Problem {
            k: Matrix { n: 1, entries: vec![(0, 0, 10.0)], symmetric: true },
            conditions: vec![Condition { terms: vec![(0, 1.0)], kind: Kind::Mini, dual: None }],
        };
        let mut s = Stepper::new(p).unwrap();
        let mut last = 0;
        for (f, u, active) in [(-0.5, -0.05, 0), (-2.0, -0.1, 1), (-3.0, -0.1, 1), (1.0, 0.1, 0)] {
            let out = s.solve(&Load { f: vec![f], d: vec![-0.1] }, &mut |_| {}).unwrap();
            assert!((out.solution.u[0] - u).abs() < 1e-14, "f = {f}: u = {}", out.solution.u[0]);
            assert_eq!(out.active, active);
            assert_eq!(out.changed, (active != last) as usize);
            if active == 1 {
                // K u + Cᵀλ = f: λ = f + 1, and the reaction −λ pushes up.
                assert!((out.solution.lambda[0] - (f + 1.0)).abs() < 1e-12, "{}", out.solution.lambda[0]);
            }
            last = active;
        }
    }

    /// Two springs in series, fixed at one end by an equality: a stiffer
    /// first spring (a material that changed) is refactorised on the same
    /// structure and the end moves by f/k1 + f/k2 with the new k1; the
    /// stop of a unilateral problem survives a renewal built anew.
    #[test]
    fn renew_refactorises_the_new_numbers() {
        let springs = |k1: f64, k2: f64| Problem {
            k: Matrix {
                n: 3,
                entries: vec![
                    (0, 0, k1),
                    (0, 1, -k1),
                    (1, 0, -k1),
                    (1, 1, k1 + k2),
                    (1, 2, -k2),
                    (2, 1, -k2),
                    (2, 2, k2),
                ],
                symmetric: true,
            },
            conditions: vec![Condition { terms: vec![(0, 1.0)], kind: Kind::Equal, dual: None }],
        };
        let load = Load { f: vec![0.0, 0.0, 6.0], d: vec![0.0] };
        let mut s = Stepper::new(springs(2.0, 3.0)).unwrap();
        let u = s.solve(&load, &mut |_| {}).unwrap().solution.u[2];
        assert!((u - (3.0 + 2.0)).abs() < 1e-13, "{u}");
        s.renew(springs(6.0, 3.0)).unwrap();
        assert!(matches!(s.core, Core::Direct(_)));
        let u = s.solve(&load, &mut |_| {}).unwrap().solution.u[2];
        assert!((u - (1.0 + 2.0)).abs() < 1e-13, "{u}");
        let stop = |k: f64| Problem {
            k: Matrix { n: 1, entries: vec![(0, 0, k)], symmetric: true },
            conditions: vec![Condition { terms: vec![(0, 1.0)], kind: Kind::Mini, dual: None }],
        };
        let mut s = Stepper::new(stop(10.0)).unwrap();
        let out = s.solve(&Load { f: vec![-2.0], d: vec![-0.1] }, &mut |_| {}).unwrap();
        assert_eq!(out.active, 1);
        s.renew(stop(40.0)).unwrap();
        assert_eq!(s.statuses(), Some(&[true][..]));
        let out = s.solve(&Load { f: vec![-2.0], d: vec![-0.1] }, &mut |_| {}).unwrap();
        assert!((out.solution.u[0] + 0.05).abs() < 1e-14, "{}", out.solution.u[0]);
        assert_eq!(out.active, 0);
    }

    /// A stop (u ≥ 0) that holds a tension of 2 (adhesion) before it lets
    /// go: a spring pressed on it, then pulled away by f, stays at 0 while
    /// f ≤ 2; once free it is a plain stop again.
    #[test]
    fn adhesion_holds_a_tension_then_lets_go() {
        let p = Problem {
            k: Matrix { n: 1, entries: vec![(0, 0, 10.0)], symmetric: true },
            conditions: vec![Condition { terms: vec![(0, 1.0)], kind: Kind::Mini, dual: None }],
        };
        let mut s = Stepper::new(p).unwrap();
        s.set_adhesion(&[2.0]).unwrap();
        let steps = [(-1.0, 0.0, 1), (1.0, 0.0, 1), (1.9, 0.0, 1), (2.5, 0.25, 0), (0.5, 0.05, 0), (-1.0, 0.0, 1)];
        for (f, u, active) in steps {
            let out = s.solve(&Load { f: vec![f], d: vec![0.0] }, &mut |_| {}).unwrap();
            assert!((out.solution.u[0] - u).abs() < 1e-14, "f = {f}: u = {}", out.solution.u[0]);
            assert_eq!(out.active, active, "f = {f}");
        }
    }

    /// A step from a history gives what a step from its combined load gives,
    /// with and without unilateral conditions (the combined forward
    /// substitution, the combined responses).
    #[test]
    fn steps_of_a_history_match_steps_of_its_loads() {
        use crate::analysis::history::{Term, TimeFunction};
        let k = Matrix {
            n: 3,
            entries: vec![
                (0, 0, 4.0),
                (0, 1, -2.0),
                (1, 0, -2.0),
                (1, 1, 4.0),
                (1, 2, -2.0),
                (2, 1, -2.0),
                (2, 2, 3.0),
            ],
            symmetric: true,
        };
        for unilateral in [false, true] {
            let mut conditions = vec![Condition { terms: vec![(0, 1.0)], kind: Kind::Equal, dual: None }];
            if unilateral {
                conditions.push(Condition { terms: vec![(2, 1.0)], kind: Kind::Mini, dual: None });
            }
            let m = conditions.len();
            let p = Problem { k: k.clone(), conditions };
            let mut h = LoadHistory::new(3, m);
            if unilateral {
                h.base.d[1] = -0.3;
            }
            let ramp = TimeFunction::new(vec![0.0, 1.0, 2.0], vec![0.0, 1.0, -1.0]).unwrap();
            h.terms.push(Term { load: Load { f: vec![0.0, 0.5, -1.0], d: vec![0.0; m] }, time: ramp });
            let (mut a, mut b) = (Stepper::new(p.clone()).unwrap(), Stepper::new(p).unwrap());
            for t in [0.25, 0.5, 1.0, 1.5, 2.0] {
                let c = h.coefficients(t).unwrap();
                let x = a.solve_history(&h, &c, None, &mut |_| {}).unwrap();
                let y = b.solve(&h.at(t).unwrap(), &mut |_| {}).unwrap();
                for (p, q) in x.solution.u.iter().zip(&y.solution.u) {
                    assert!((p - q).abs() < 1e-13, "t = {t}: {:?} vs {:?}", x.solution.u, y.solution.u);
                }
                assert_eq!(x.solution.active, y.solution.active);
            }
        }
    }

    /// Without unilateral conditions a step is one solve of the factor.
    #[test]
    fn bilateral_steps_reuse_the_factor() {
        let p = Problem {
            k: Matrix { n: 2, entries: vec![(0, 0, 2.0), (0, 1, -1.0), (1, 0, -1.0), (1, 1, 1.0)], symmetric: true },
            conditions: vec![Condition { terms: vec![(0, 1.0)], kind: Kind::Equal, dual: None }],
        };
        let mut s = Stepper::new(p).unwrap();
        for t in [1.0, 2.0] {
            let out = s.solve(&Load { f: vec![0.0, t], d: vec![0.0] }, &mut |_| {}).unwrap();
            // u0 = 0 imposed; u1 = t / k = t.
            assert!((out.solution.u[1] - t).abs() < 1e-13);
            assert_eq!(out.iterations, 1);
        }
    }
}
