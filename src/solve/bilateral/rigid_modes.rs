//! 'ENSE': a singular system solved with each free rigid mode held, as
//! Cast3M's RESO does for UNILATER. Each time the factorisation meets a
//! free mode, the largest unknown it moves is blocked by one more equality
//! condition, and the factorisation starts again.

use super::direct::{DirectOptions, Factorization};
use crate::solve::error::SolveError;
use crate::solve::problem::{Condition, Kind, Load, Problem, Solution};

/// Modes held at the most: a system with more free modes is not a
/// structure with a few missing supports.
const MAX_HELD: usize = 64;

/// The factorisation of a system with its free rigid modes held.
#[derive(Debug)]
pub struct HeldModes {
    fact: Factorization,
    /// The unknowns blocked, one per mode, in the order they were found.
    pub held: Vec<usize>,
    /// Conditions of the extended system (the given ones, then one per
    /// held mode).
    conditions: usize,
}

/// Factorises `p`, holding each free rigid mode at its largest unknown.
pub fn hold_rigid_modes(p: &Problem, opts: &DirectOptions) -> Result<HeldModes, SolveError> {
    let mut p = p.clone();
    let mut held: Vec<usize> = Vec::new();
    loop {
        match Factorization::new(&p, opts) {
            Ok(fact) => return Ok(HeldModes { fact, held, conditions: p.conditions.len() }),
            Err(SolveError::Singular { dofs })
                if !dofs.is_empty() && !held.contains(&dofs[0]) && held.len() < MAX_HELD =>
            {
                held.push(dofs[0]);
                p.conditions.push(Condition { terms: vec![(dofs[0], 1.0)], kind: Kind::Equal, dual: None });
            }
            Err(e) => return Err(e),
        }
    }
}

impl HeldModes {
    /// Solves for loads of the original system (the held unknowns stay 0).
    /// Each solution holds one multiplier per condition of the extended
    /// system: the original ones first.
    pub fn solve(&self, loads: &[Load]) -> Result<Vec<Solution>, SolveError> {
        let extended: Vec<Load> = loads
            .iter()
            .map(|l| {
                let mut d = l.d.clone();
                d.resize(self.conditions, 0.0);
                Load { f: l.f.clone(), d }
            })
            .collect();
        self.fact.solve(&extended)
    }
}

#[cfg(test)]
#[path = "tests/rigid_modes.rs"]
mod tests;
