//! Static condensation onto Lagrange multipliers (SUPER with the
//! multiplier nodes of some conditions as masters): those conditions'
//! multipliers become ordinary unknowns of an augmented symmetric system
//!
//! ```text
//!   [ K   Cₘᵀ ] [u ]   [F ]
//!   [ Cₘ  0   ] [λₘ] = [dₘ]
//! ```
//!
//! (the other conditions stay doubled multipliers), and the λₘ are kept in
//! the trailing block of [`super::schur::schur_onto`]: their zero diagonal
//! is never a pivot, and the Schur complement −Cₘ K⁻¹ Cₘᵀ (K with the
//! other conditions) is what Cast3M's condensed rigidity holds.
//!
//! Each λₘ is scaled to the stiffness of its unknowns (λ = s λ′, the
//! coupling written s·c): the condensation reads S off a trailing block
//! shifted by its row size, and an unscaled −C K⁻¹ Cᵀ (1e-15 for a steel
//! plate) would vanish in the rounding of a unit shift.

use crate::solve::problem::{Load, Matrix, Problem, Solution};

/// The augmented problem and the way back to the given one.
#[derive(Debug, Clone)]
pub struct MultiplierMasters {
    /// Primal unknowns of the given problem.
    n: usize,
    /// Conditions of the given problem.
    m: usize,
    /// Given numbers of the conditions whose multipliers are unknowns
    /// `n..n + masters.len()` of the augmented problem.
    masters: Vec<usize>,
    /// Given numbers of the conditions the augmented problem keeps.
    others: Vec<usize>,
    /// s of each master multiplier.
    scale: Vec<f64>,
    pub problem: Problem,
}

impl MultiplierMasters {
    /// `masters`: condition numbers of `p` (distinct, in range).
    pub fn new(p: &Problem, masters: &[usize]) -> Self {
        let (n, m) = (p.k.n, p.conditions.len());
        let others: Vec<usize> = (0..m).filter(|c| !masters.contains(c)).collect();
        let mut row_max = vec![0.0f64; n];
        for &(i, _, v) in &p.k.entries {
            row_max[i] = row_max[i].max(v.abs());
        }
        let global = row_max.iter().fold(0.0f64, |a, &b| a.max(b));
        let mut entries = p.k.entries.clone();
        let mut scale = Vec::with_capacity(masters.len());
        for (t, &c) in masters.iter().enumerate() {
            let terms = &p.conditions[c].terms;
            // The softest unknown of the row (as the doubled scaling does):
            // a coupling far above its own stiffness would pass its pivot
            // for a zero one.
            let k = terms.iter().map(|&(j, _)| row_max[j]).filter(|&r| r > 0.0).fold(f64::INFINITY, f64::min);
            let k = if k.is_finite() {
                k
            } else if global > 0.0 {
                global
            } else {
                1.0
            };
            let chat = terms.iter().fold(0.0f64, |a, &(_, v)| a.max(v.abs()));
            let s = if chat > 0.0 { k / chat } else { 1.0 };
            scale.push(s);
            for &(j, a) in terms {
                entries.push((n + t, j, s * a));
                entries.push((j, n + t, s * a));
            }
            // The zero diagonal, so the unknown is in the pattern on its own.
            entries.push((n + t, n + t, 0.0));
        }
        let problem = Problem {
            k: Matrix { n: n + masters.len(), entries, symmetric: p.k.symmetric },
            conditions: others.iter().map(|&c| p.conditions[c].clone()).collect(),
        };
        MultiplierMasters { n, m, masters: masters.to_vec(), others, scale, problem }
    }

    /// The augmented unknown of master condition `t`.
    pub fn unknown(&self, t: usize) -> usize {
        self.n + t
    }

    /// λ / (augmented unknown `j`): s for a master multiplier, 1 for a
    /// primal unknown.
    pub fn scale_of(&self, j: usize) -> f64 {
        if j >= self.n {
            self.scale[j - self.n]
        } else {
            1.0
        }
    }

    /// A load of the given problem for the augmented one: the imposed
    /// values of the master conditions become forces on their multipliers.
    pub fn load(&self, l: &Load) -> Load {
        let mut f = l.f.clone();
        f.extend(self.masters.iter().zip(&self.scale).map(|(&c, s)| s * l.d[c]));
        Load { f, d: self.others.iter().map(|&c| l.d[c]).collect() }
    }

    /// A solution of the augmented problem as one of the given problem.
    pub fn solution(&self, s: &Solution) -> Solution {
        let mut lambda = vec![0.0; self.m];
        for (t, &c) in self.masters.iter().enumerate() {
            lambda[c] = self.scale[t] * s.u[self.n + t];
        }
        for (k, &c) in self.others.iter().enumerate() {
            lambda[c] = s.lambda[k];
        }
        Solution { u: s.u[..self.n].to_vec(), lambda, active: vec![true; self.m] }
    }
}
