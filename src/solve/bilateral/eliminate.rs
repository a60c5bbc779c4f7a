//! Bilateral conditions eliminated by substitution, as Cast3M's RESO does
//! before UNILATER (unilateral.md §4.1): each equality row gets a *slave*
//! unknown, expressed over the remaining *master* unknowns, so that
//! `u = T ū + g`. The ITER method needs this: its conjugate gradients want
//! a positive definite operator, which doubled multipliers would not give.
//!
//! Rows are taken in order and reduced over the masters left by the rows
//! before them (a sparse Gauss–Jordan step); the slave is the term with the
//! largest coefficient. A row that reduces to nothing is dependent on the
//! previous ones. The multipliers are recovered afterwards from the
//! residual forces at the slaves.

use super::linear::LuFactor;
use crate::solve::error::SolveError;
use crate::solve::problem::{Kind, Problem};

/// A reduced coefficient below this fraction of its row's largest is
/// round-off of the substitutions.
const DROP: f64 = 1e-12;

/// `u_s = Σ coef·u_master + constant`.
#[derive(Debug, Clone, Default)]
struct Expr {
    terms: Vec<(usize, f64)>,
    constant: f64,
}

#[derive(Debug)]
pub(crate) struct Elimination {
    expr: Vec<Option<Expr>>,
    /// (condition, its slave unknown), in elimination order.
    slaves: Vec<(usize, usize)>,
    /// The master unknowns, and each unknown's position among them
    /// (`usize::MAX` for a slave).
    pub masters: Vec<usize>,
    pub local: Vec<usize>,
}

/// Sorted by unknown, duplicates summed, negligible terms dropped.
fn compress(mut v: Vec<(usize, f64)>) -> Vec<(usize, f64)> {
    v.sort_unstable_by_key(|t| t.0);
    let mut out: Vec<(usize, f64)> = Vec::with_capacity(v.len());
    for (j, c) in v {
        match out.last_mut() {
            Some(last) if last.0 == j => last.1 += c,
            _ => out.push((j, c)),
        }
    }
    let big = out.iter().fold(0.0_f64, |a, t| a.max(t.1.abs()));
    out.retain(|t| t.1.abs() > DROP * big);
    out
}

impl Elimination {
    /// Eliminates every equality condition of `p` with limits `d`.
    /// Errors: `DependentConditions` for a row that the previous ones
    /// already determine; `Other` for a non-associated relation.
    pub fn new(p: &Problem, d: &[f64]) -> Result<Self, SolveError> {
        let n = p.k.n;
        let mut expr: Vec<Option<Expr>> = vec![None; n];
        // The slaves whose expression uses each master.
        let mut users: Vec<Vec<usize>> = vec![Vec::new(); n];
        let mut slaves = Vec::new();
        for (ci, c) in p.conditions.iter().enumerate() {
            if c.kind != Kind::Equal {
                continue;
            }
            if c.dual.is_some() {
                return Err(SolveError::Other(format!(
                    "condition {ci} is non-associated: eliminating it would need a non-symmetric operator"
                )));
            }
            let mut acc = Vec::with_capacity(c.terms.len());
            let mut k0 = 0.0;
            for &(j, v) in &c.terms {
                match &expr[j] {
                    Some(e) => {
                        acc.extend(e.terms.iter().map(|&(k, w)| (k, v * w)));
                        k0 += v * e.constant;
                    }
                    None => acc.push((j, v)),
                }
            }
            let acc = compress(acc);
            let Some(&(s, a_s)) = acc.iter().max_by(|x, y| x.1.abs().total_cmp(&y.1.abs())) else {
                let mut rows: Vec<usize> =
                    slaves.iter().filter(|&&(_, sl)| c.terms.iter().any(|t| t.0 == sl)).map(|&(q, _)| q).collect();
                rows.push(ci);
                return Err(SolveError::DependentConditions { conditions: rows });
            };
            let e = Expr {
                terms: acc.iter().filter(|t| t.0 != s).map(|&(j, v)| (j, -v / a_s)).collect(),
                constant: (d[ci] - k0) / a_s,
            };
            // Earlier slaves that use s now use its expression.
            for q in std::mem::take(&mut users[s]) {
                let Some(eq) = expr[q].as_mut() else { continue };
                let Some(pos) = eq.terms.iter().position(|t| t.0 == s) else { continue };
                let w = eq.terms.swap_remove(pos).1;
                eq.constant += w * e.constant;
                let mut t = std::mem::take(&mut eq.terms);
                t.extend(e.terms.iter().map(|&(j, v)| (j, w * v)));
                eq.terms = compress(t);
                for &(j, _) in &e.terms {
                    users[j].push(q);
                }
            }
            for &(j, _) in &e.terms {
                users[j].push(s);
            }
            expr[s] = Some(e);
            slaves.push((ci, s));
        }
        let masters: Vec<usize> = (0..n).filter(|&j| expr[j].is_none()).collect();
        let mut local = vec![usize::MAX; n];
        for (q, &j) in masters.iter().enumerate() {
            local[j] = q;
        }
        Ok(Elimination { expr, slaves, masters, local })
    }

    /// Unknown `j` as masters and a constant: calls `f(master, coefficient)`
    /// for each term (`f(j, 1)` for a master) and returns the constant.
    pub fn expand(&self, j: usize, mut f: impl FnMut(usize, f64)) -> f64 {
        match &self.expr[j] {
            Some(e) => {
                for &(k, w) in &e.terms {
                    f(k, w);
                }
                e.constant
            }
            None => {
                f(j, 1.0);
                0.0
            }
        }
    }

    /// A row over all unknowns as a row over the masters plus a constant.
    pub fn reduce(&self, terms: &[(usize, f64)]) -> (Vec<(usize, f64)>, f64) {
        let mut acc = Vec::with_capacity(terms.len());
        let mut k0 = 0.0;
        for &(j, v) in terms {
            match &self.expr[j] {
                Some(e) => {
                    acc.extend(e.terms.iter().map(|&(k, w)| (k, v * w)));
                    k0 += v * e.constant;
                }
                None => acc.push((j, v)),
            }
        }
        (compress(acc), k0)
    }

    /// All unknowns from the masters' values (`ubar[local[j]]`).
    pub fn unknowns(&self, ubar: &[f64]) -> Vec<f64> {
        (0..self.expr.len())
            .map(|j| match &self.expr[j] {
                Some(e) => e.constant + e.terms.iter().map(|&(k, w)| w * ubar[self.local[k]]).sum::<f64>(),
                None => ubar[self.local[j]],
            })
            .collect()
    }

    /// The multipliers of the eliminated rows from the forces they must
    /// supply, `res = F − K u − (other reactions)`: `C_bᵀλ_b = res` read at
    /// the slaves (a square system, regular since every row had a pivot).
    /// Returns (condition, λ).
    pub fn multipliers(&self, p: &Problem, res: &[f64]) -> Result<Vec<(usize, f64)>, SolveError> {
        let mb = self.slaves.len();
        if mb == 0 {
            return Ok(Vec::new());
        }
        let mut slave_pos = vec![usize::MAX; self.expr.len()];
        for (q, &(_, s)) in self.slaves.iter().enumerate() {
            slave_pos[s] = q;
        }
        // Column r: the coefficients of row r on the slaves.
        let mut col_ptr = vec![0usize];
        let (mut row_idx, mut values) = (Vec::new(), Vec::new());
        for &(ci, _) in &self.slaves {
            let col = compress(
                p.conditions[ci]
                    .terms
                    .iter()
                    .filter(|t| slave_pos[t.0] != usize::MAX)
                    .map(|&(j, v)| (slave_pos[j], v))
                    .collect(),
            );
            for (q, v) in col {
                row_idx.push(q);
                values.push(v);
            }
            col_ptr.push(row_idx.len());
        }
        let lu = LuFactor::new(&col_ptr, &row_idx, &values)?;
        let mut x = faer::Mat::<f64>::from_fn(mb, 1, |q, _| res[self.slaves[q].1]);
        lu.solve_in_place(x.as_mut());
        Ok(self.slaves.iter().enumerate().map(|(q, &(ci, _))| (ci, x[(q, 0)])).collect())
    }
}
