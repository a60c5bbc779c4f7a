//! The data exchanged with the solver: plain numbers and indices.

/// A sparse matrix given as a list of entries over the primal unknowns
/// `0..n`. Duplicates are summed. For a symmetric matrix both triangles may
/// be present (as elementary blocks give them); the solver reads what it
/// needs. `symmetric == false` sends the system through sparse LU.
#[derive(Debug, Clone, Default)]
pub struct Matrix {
    pub n: usize,
    pub entries: Vec<(usize, usize, f64)>,
    pub symmetric: bool,
}

/// The kind of a condition row `c·u ⋈ d`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Kind {
    /// `c·u = d` (BLOQ, RELA without keyword).
    Equal,
    /// `c·u >= d` (`'MINI'`).
    Mini,
    /// `c·u <= d` (`'MAXI'`).
    Maxi,
}

impl Kind {
    pub fn is_unilateral(self) -> bool {
        self != Kind::Equal
    }
    /// s_i of unilateral.md §1: +1 for MINI, −1 for MAXI (0 for equalities).
    pub fn sense(self) -> f64 {
        match self {
            Kind::Equal => 0.0,
            Kind::Mini => 1.0,
            Kind::Maxi => -1.0,
        }
    }
}

/// One condition: a sparse row over primal unknowns and its kind. Its
/// limit `d` comes with the load ([`Load::d`]), because DEPI values change
/// from one RESO to the next while the matrix does not.
///
/// `dual` makes the condition *non-associated* (RELA … 'DUAL'): the
/// reaction acts along `dual` instead of `terms`, i.e. the equilibrium reads
/// `K u + Σ dualᵢᵀ λᵢ = F` while the condition stays `terms·u ⋈ d`. The
/// system is then not symmetric: a problem holding such a condition must
/// have `k.symmetric == false` (every K entry given), and goes through
/// sparse LU.
#[derive(Debug, Clone, PartialEq)]
pub struct Condition {
    pub terms: Vec<(usize, f64)>,
    pub kind: Kind,
    pub dual: Option<Vec<(usize, f64)>>,
}

impl Condition {
    /// The direction of the reaction: `dual` when given, else the row.
    pub fn reaction_terms(&self) -> &[(usize, f64)] {
        self.dual.as_deref().unwrap_or(&self.terms)
    }
}

/// The whole operator: stiffness plus condition rows.
#[derive(Debug, Clone, Default)]
pub struct Problem {
    pub k: Matrix,
    pub conditions: Vec<Condition>,
}

/// One right-hand side: forces on the primal unknowns (`f.len() == n`) and
/// the limit of every condition (`d.len() == m`, 0 where no DEPI was given).
#[derive(Debug, Clone, PartialEq)]
pub struct Load {
    pub f: Vec<f64>,
    pub d: Vec<f64>,
}

/// The answer for one load: primal unknowns, the physical multiplier of
/// every condition (`λ = σ(λ1 + λ2)`, the value RESO stores as `LX`; 0 for
/// an inactive unilateral condition) and whether each condition is active
/// (always true for equalities).
#[derive(Debug, Clone, PartialEq)]
pub struct Solution {
    pub u: Vec<f64>,
    pub lambda: Vec<f64>,
    pub active: Vec<bool>,
}

impl Solution {
    /// An unknown fixed alone by an equality (a BLOQ) takes its imposed
    /// value exactly rather than to rounding: a blocked displacement then
    /// reads as 0., not 1e-19, as in Cast3M.
    pub fn snap_blocked(&mut self, p: &Problem, load: &Load) {
        for (c, d) in p.conditions.iter().zip(&load.d) {
            if let (Kind::Equal, [(j, a)]) = (c.kind, c.terms.as_slice()) {
                if *a != 0.0 && c.dual.is_none() && *j < self.u.len() {
                    self.u[*j] = d / a;
                }
            }
        }
    }
}
