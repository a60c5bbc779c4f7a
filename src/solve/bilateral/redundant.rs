//! Consistent redundant conditions: a condition row that the others
//! already imply (a BLOQ of a middle node whose RELA 'MILI' row ties it to
//! two blocked corners) makes the doubled system singular in its
//! multiplier block. Cast3M accepts such a set when the imposed values
//! agree and drops the duplicates; so does the direct RESO: the row whose
//! multiplier pivot vanishes is left out of the factorisation, and each
//! right-hand side must satisfy it with the solution of the others. Values
//! that disagree (the rows contradict each other) are still refused, with
//! the dependent row and the rows sharing its unknowns.

use crate::solve::error::SolveError;
use crate::solve::problem::{Condition, Load, Problem, Solution};

/// Largest accepted violation of a dropped condition, relative to the size
/// of its terms: well above the rounding of the solve, far below any real
/// contradiction between imposed values.
const CONSISTENCY_TOL: f64 = 1e-7;

/// A condition left out of the factorisation.
#[derive(Debug, Clone)]
struct Dropped {
    /// Its number in the given problem.
    index: usize,
    row: Condition,
    /// It, then the rows sharing its unknowns (given numbers): the error
    /// reported if a right-hand side contradicts it.
    sharing: Vec<usize>,
}

/// Which conditions of a problem were factorised and which were dropped.
#[derive(Debug, Clone, Default)]
pub(crate) struct Redundant {
    /// Given numbers of the factorised conditions, in order.
    kept: Vec<usize>,
    dropped: Vec<Dropped>,
    /// Conditions of the given problem.
    m: usize,
}

impl Redundant {
    /// Nothing dropped yet.
    pub fn none(p: &Problem) -> Self {
        let m = p.conditions.len();
        Redundant { kept: (0..m).collect(), dropped: Vec::new(), m }
    }

    pub fn is_empty(&self) -> bool {
        self.dropped.is_empty()
    }

    /// Conditions of the given problem (what a load's `d` must hold).
    pub fn given(&self) -> usize {
        self.m
    }

    /// Drops condition `local` of the current reduced problem; `sharing`
    /// is in reduced numbers too. False when nothing is left to drop.
    pub fn drop_row(&mut self, p: &Problem, local: usize, sharing: &[usize]) -> bool {
        if local >= self.kept.len() {
            return false;
        }
        let index = self.kept[local];
        let sharing = sharing.iter().filter_map(|&c| self.kept.get(c).copied()).collect();
        self.kept.remove(local);
        self.dropped.push(Dropped { index, row: p.conditions[index].clone(), sharing });
        true
    }

    /// `p` without the dropped conditions.
    pub fn reduced(&self, p: &Problem) -> Problem {
        Problem { k: p.k.clone(), conditions: self.kept.iter().map(|&c| p.conditions[c].clone()).collect() }
    }

    /// A load of the given problem for the reduced one.
    pub fn load(&self, l: &Load) -> Load {
        Load { f: l.f.clone(), d: self.kept.iter().map(|&c| l.d[c]).collect() }
    }

    /// Checks that `s` (reduced solution of load `l`) satisfies every
    /// dropped row, and gives it a zero multiplier there: the kept rows
    /// carry the whole reaction.
    pub fn expand(&self, l: &Load, s: Solution) -> Result<Solution, SolveError> {
        let umax = s.u.iter().fold(0.0f64, |a, x| a.max(x.abs()));
        for d in &self.dropped {
            let lhs: f64 = d.row.terms.iter().map(|&(j, a)| a * s.u[j]).sum();
            let size: f64 = d.row.terms.iter().map(|&(_, a)| a.abs()).sum::<f64>() * umax + l.d[d.index].abs();
            if (lhs - l.d[d.index]).abs() > CONSISTENCY_TOL * size {
                return Err(SolveError::DependentConditions { conditions: d.sharing.clone() });
            }
        }
        let mut lambda = vec![0.0; self.m];
        let mut active = vec![true; self.m];
        for (k, &c) in self.kept.iter().enumerate() {
            lambda[c] = s.lambda[k];
            active[c] = s.active[k];
        }
        Ok(Solution { u: s.u, lambda, active })
    }
}
