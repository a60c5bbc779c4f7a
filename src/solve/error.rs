//! Solver failures, in terms of unknown numbers (`dofs`) and condition
//! numbers. The language side turns them into node/component names.

use thiserror::Error;

#[derive(Debug, Clone, Error, PartialEq)]
pub enum SolveError {
    /// The operator has a free rigid mode: `dofs` are the unknowns that move
    /// in it (largest components first).
    #[error("singular system: a rigid mode is free")]
    Singular { dofs: Vec<usize> },
    /// Unknowns that no matrix term and no condition touch.
    #[error("unknowns touched by no matrix")]
    Untouched { dofs: Vec<usize> },
    /// The same unknown is imposed by several equality conditions
    /// (the rows are dependent).
    #[error("unknown constrained twice")]
    DoublyConstrained { dof: usize, conditions: Vec<usize> },
    /// Linearly dependent condition rows (other than proportional pairs).
    #[error("linearly dependent conditions")]
    DependentConditions { conditions: Vec<usize> },
    /// Parallel unilateral conditions with crossed limits: empty feasible set.
    #[error("conflicting unilateral conditions")]
    Conflicting { conditions: Vec<usize> },
    /// The load drives a rigid mode away from every unilateral support.
    /// `work` is F·r along the escaping mode r.
    #[error("no equilibrium: the load pushes the structure away from its unilateral supports")]
    Infeasible { conditions: Vec<usize>, work: f64 },
    /// The status iteration did not settle within its cap; `conditions` are
    /// the ones still changing.
    #[error("the status iteration did not converge")]
    NoConvergence { iterations: usize, conditions: Vec<usize> },
    /// The a-posteriori residual check failed. `weakest` lists the primal
    /// unknowns with the smallest pivots relative to their row, when the
    /// factor gives them: a rigid mode held by almost nothing (too small
    /// to count as singular) shows there.
    #[error("inaccurate solution: relative residual {residual:e}")]
    Inaccurate { residual: f64, weakest: Vec<usize> },
    /// The solution overflows (an infinity or a NaN) although the data are
    /// finite: loads or imposed values too large for the matrix.
    #[error("the solution overflows: the loads or imposed values are too large for this matrix")]
    Overflow,
    /// Stopped from outside (Ctrl-C) between two solves.
    #[error("interrupted")]
    Interrupted,
    /// Anything else the numerical library reported.
    #[error("{0}")]
    Other(String),
}
