//! Linear programming by the two-phase simplex method on a dense tableau
//! (SIMPLEX): maximise c0 + c·x subject to x ≥ 0, A x ≤ b and E x = e.
//!
//! A hand-written dense solver rather than a crate: the problems SIMPLEX
//! receives are small (tens of unknowns, built in Gibiane tables), no LP
//! crate is in the project's dependency tree, and the maintained ones pull
//! sparse-matrix stacks far larger than this file. Bland's rule (smallest
//! index enters, ties in the ratio test leave by smallest index) rules
//! out cycling on the degenerate vertices such problems often have.

/// A linear program in the form SIMPLEX reads it.
#[derive(Debug, Clone, Default)]
pub struct Program {
    /// Constant term of the objective.
    pub c0: f64,
    /// Objective coefficients, one per unknown.
    pub c: Vec<f64>,
    /// Inequalities `row · x ≤ rhs`.
    pub le: Vec<(Vec<f64>, f64)>,
    /// Equalities `row · x = rhs`.
    pub eq: Vec<(Vec<f64>, f64)>,
}

/// How the program ended.
#[derive(Debug, Clone, PartialEq)]
pub enum Outcome {
    /// A finite optimum: the objective, the unknowns and the slack of
    /// each inequality (`rhs − row · x`).
    Optimum { value: f64, x: Vec<f64>, slack: Vec<f64> },
    /// The objective grows without bound on the feasible set.
    Unbounded,
    /// No point satisfies the constraints.
    Infeasible,
}

struct Tableau {
    rows: Vec<Vec<f64>>,
    basis: Vec<usize>,
    tol: f64,
}

enum Step {
    Optimal,
    Unbounded,
}

impl Tableau {
    fn pivot(&mut self, r: usize, col: usize) {
        let p = self.rows[r][col];
        for v in self.rows[r].iter_mut() {
            *v /= p;
        }
        let pr = self.rows[r].clone();
        for (i, row) in self.rows.iter_mut().enumerate() {
            if i != r {
                let f = row[col];
                if f != 0.0 {
                    for (v, q) in row.iter_mut().zip(&pr) {
                        *v -= f * q;
                    }
                }
            }
        }
        self.basis[r] = col;
    }

    /// Maximise `cost · x` over the columns `0..ncols`, from the current
    /// feasible basis, by Bland's rule.
    fn run(&mut self, cost: &[f64], ncols: usize) -> Step {
        let rhs = cost.len();
        loop {
            let entering = (0..ncols).find(|&j| {
                let d = cost[j] - self.rows.iter().zip(&self.basis).map(|(row, &b)| cost[b] * row[j]).sum::<f64>();
                d > self.tol
            });
            let Some(col) = entering else { return Step::Optimal };
            let mut best: Option<(usize, f64)> = None;
            for (i, row) in self.rows.iter().enumerate() {
                if row[col] > self.tol {
                    let ratio = row[rhs] / row[col];
                    best = match best {
                        None => Some((i, ratio)),
                        Some((bi, br)) => {
                            if ratio < br - self.tol || (ratio <= br + self.tol && self.basis[i] < self.basis[bi]) {
                                Some((i, ratio))
                            } else {
                                Some((bi, br))
                            }
                        }
                    }
                }
            }
            let Some((r, _)) = best else { return Step::Unbounded };
            self.pivot(r, col);
        }
    }
}

/// Solves `p` with pivots and feasibility judged at tolerance `tol`.
pub fn solve(p: &Program, tol: f64) -> Outcome {
    let n = p.c.len();
    let ni = p.le.len();
    let m = ni + p.eq.len();
    // Columns: the unknowns, one slack per inequality, then one artificial
    // per row whose slack cannot start the basis (negative right-hand side
    // or equality).
    let needs_art: Vec<bool> = p.le.iter().map(|(_, b)| *b < 0.0).chain(p.eq.iter().map(|_| true)).collect();
    let nart = needs_art.iter().filter(|&&a| a).count();
    let ncols = n + ni + nart;
    let mut rows = Vec::with_capacity(m);
    let mut basis = Vec::with_capacity(m);
    let mut next_art = n + ni;
    for (k, (a, b)) in p.le.iter().map(|(a, b)| (a, *b)).chain(p.eq.iter().map(|(a, b)| (a, *b))).enumerate() {
        let mut row = vec![0.0; ncols + 1];
        row[..n].copy_from_slice(&a[..n]);
        if k < ni {
            row[n + k] = 1.0;
        }
        row[ncols] = b;
        if b < 0.0 {
            for v in row.iter_mut() {
                *v = -*v;
            }
        }
        if needs_art[k] {
            row[next_art] = 1.0;
            basis.push(next_art);
            next_art += 1;
        } else {
            basis.push(n + k);
        }
        rows.push(row);
    }
    let mut t = Tableau { rows, basis, tol };
    if nart > 0 {
        let mut cost = vec![0.0; ncols];
        for c in cost.iter_mut().skip(n + ni) {
            *c = -1.0;
        }
        // Phase one cannot be unbounded: its objective is at most zero.
        t.run(&cost, ncols);
        let infeas: f64 = t.rows.iter().zip(&t.basis).filter(|(_, &b)| b >= n + ni).map(|(r, _)| r[ncols]).sum();
        if infeas > tol * (1.0 + rhs_scale(p)) {
            return Outcome::Infeasible;
        }
        // Drive the artificials left in the basis (at zero) out; a row with
        // no other nonzero is a redundant equality and keeps its artificial.
        for r in 0..m {
            if t.basis[r] >= n + ni {
                if let Some(col) = (0..n + ni).find(|&j| t.rows[r][j].abs() > tol) {
                    t.pivot(r, col);
                }
            }
        }
    }
    let mut cost = vec![0.0; ncols];
    cost[..n].copy_from_slice(&p.c);
    if let Step::Unbounded = t.run(&cost, n + ni) {
        return Outcome::Unbounded;
    }
    let mut x = vec![0.0; n];
    for (row, &b) in t.rows.iter().zip(&t.basis) {
        if b < n {
            x[b] = row[ncols];
        }
    }
    let value = p.c0 + p.c.iter().zip(&x).map(|(c, x)| c * x).sum::<f64>();
    let slack = p.le.iter().map(|(a, b)| b - a.iter().zip(&x).map(|(a, x)| a * x).sum::<f64>()).collect();
    Outcome::Optimum { value, x, slack }
}

fn rhs_scale(p: &Program) -> f64 {
    p.le.iter().chain(&p.eq).map(|(_, b)| b.abs()).fold(0.0, f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn textbook_maximum() {
        // max 3x + 2y, x + y ≤ 4, x + 3y ≤ 6, x ≤ 3: optimum at (3, 1) = 11.
        let p = Program {
            c0: 0.0,
            c: vec![3.0, 2.0],
            le: vec![(vec![1.0, 1.0], 4.0), (vec![1.0, 3.0], 6.0), (vec![1.0, 0.0], 3.0)],
            eq: vec![],
        };
        let Outcome::Optimum { value, x, slack } = solve(&p, 1e-10) else { panic!() };
        assert!((value - 11.0).abs() < 1e-12);
        assert!((x[0] - 3.0).abs() < 1e-12 && (x[1] - 1.0).abs() < 1e-12);
        assert!(slack[0].abs() < 1e-12 && (slack[1] - 0.0).abs() < 1e-12 && slack[2].abs() < 1e-12);
    }

    #[test]
    fn unbounded_and_infeasible() {
        let p = Program { c0: 0.0, c: vec![1.0], le: vec![], eq: vec![] };
        assert_eq!(solve(&p, 1e-10), Outcome::Unbounded);
        let p = Program { c0: 0.0, c: vec![1.0], le: vec![(vec![1.0], -1.0)], eq: vec![] };
        assert_eq!(solve(&p, 1e-10), Outcome::Infeasible);
    }
}
