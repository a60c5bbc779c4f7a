//! The words of the solver, on the language side: a right-hand side field
//! read into a numbered system, and solver errors in node and component
//! names. The numbering itself is `solve::Assembled`, built from a
//! RIGIDITE in `value::rigidity::numbering`.

use crate::error::{Error, Result};
use crate::eval::Interp;
use crate::solve::{Kind, Load, LoadError, SolveError};
use crate::value::{fmt_float, Chpoint, Rigidite};

pub use crate::solve::Assembled;
pub use crate::value::rigidity::numbering::solution_field;

/// The load of right-hand side fields on a numbered system without
/// merged twin conditions ([`Rigidite::number`]).
pub fn load(it: &Interp, asm: &Assembled, rhs: &[&Chpoint]) -> Result<Load> {
    load_of(it, &Rigidite::new(crate::value::rigidity::Subtype::Rigidite), asm, rhs)
}

/// The load of right-hand side fields on the system of `r`.
pub fn load_of(it: &Interp, r: &Rigidite, asm: &Assembled, rhs: &[&Chpoint]) -> Result<Load> {
    asm.load(rhs.iter().flat_map(|c| c.entries())).map_err(|e| match e {
        LoadError::NoCondition { node } => Error::runtime(format!(
            "the right-hand side imposes a value (FLX) at {} which carries no condition of this RIGIDITE",
            node_name(it, node)
        )),
        LoadError::NoUnknown { node, comp } => Error::runtime(format!(
            "the right-hand side has {} at {}, which is no unknown of this RIGIDITE",
            comp,
            node_name(it, node)
        )),
        LoadError::Conflicting { kept, twin } => {
            let value = |k: usize| {
                let node = r.conds.get(k).map(|c| c.mult_node);
                rhs.iter().flat_map(|c| c.entries()).filter(|e| Some(e.0) == node && e.1 == "FLX").map(|e| e.2).sum()
            };
            Error::runtime(format!(
                "conflicting conditions: the same condition is imposed twice with different values: {}; {}",
                describe_condition(it, r, kept, value(kept)),
                describe_condition(it, r, twin, value(twin))
            ))
        }
    })
}

/// A solver error in words a user can act on.
pub fn explain(it: &Interp, r: &Rigidite, asm: &Assembled, e: SolveError, loads: &[Load]) -> Error {
    let dof = |i: usize| match asm.dofs.get(i) {
        Some((n, c)) => format!("{} of {}", c, node_name(it, *n)),
        None => format!("unknown {}", i),
    };
    let cond = |k: usize| {
        describe_condition(it, r, asm.origin(k), loads.first().map_or(0.0, |l| l.d.get(k).copied().unwrap_or(0.0)))
    };
    let list = |v: &[usize], f: &dyn Fn(usize) -> String| {
        let mut s: Vec<String> = v.iter().take(8).map(|&i| f(i)).collect();
        if v.len() > 8 {
            s.push(format!("… ({} in all)", v.len()));
        }
        s.join("; ")
    };
    let msg = match &e {
        SolveError::Singular { dofs } => format!(
            "singular system: a rigid mode is free (nothing holds it); it moves {}",
            list(dofs, &dof)
        ),
        SolveError::Untouched { dofs } => {
            format!("unknowns touched by no stiffness and no condition: {}", list(dofs, &dof))
        }
        SolveError::DoublyConstrained { dof: d, conditions } => format!(
            "{} is imposed by more than one equality condition: {}",
            dof(*d),
            list(conditions, &cond)
        ),
        SolveError::DependentConditions { conditions } if conditions.is_empty() => {
            "the conditions make the system singular (linearly dependent rows that could not be singled out)"
                .to_string()
        }
        SolveError::DependentConditions { conditions } => {
            format!("linearly dependent conditions: {}", list(conditions, &cond))
        }
        SolveError::Conflicting { conditions } => {
            format!(
                "conflicting conditions (no position satisfies them all together with the other conditions): {}",
                list(conditions, &cond)
            )
        }
        SolveError::Infeasible { conditions, work } => format!(
            "no equilibrium: the load pushes the structure away from its unilateral supports along a rigid-body motion (load work {}); released: {}",
            fmt_float(*work),
            list(conditions, &cond)
        ),
        SolveError::NoConvergence { iterations, conditions } => format!(
            "the status iteration did not converge after {} solves; still changing: {}",
            iterations,
            list(conditions, &cond)
        ),
        SolveError::Inaccurate { residual, weakest } if !weakest.is_empty() => format!(
            "inaccurate solution: relative residual {}; the weakest pivots are at {}: a rigid mode held by almost nothing there? (check the supports, or stiffnesses many orders of magnitude apart)",
            fmt_float(*residual),
            list(weakest, &dof)
        ),
        other => other.to_string(),
    };
    Error::runtime(format!("RESO: {}", msg))
}

/// `node 3 (1.00000E+00, 0.00000E+00)`: users number nodes from 1.
pub fn node_name(it: &Interp, n: usize) -> String {
    let x = it.nodes.get(n);
    let d = it.opts.dime.clamp(1, 3);
    format!("node {} ({})", n + 1, x[..d].iter().map(|c| fmt_float(*c)).collect::<Vec<_>>().join(", "))
}

/// `MINI UX >= 0 at node 1 (…)` or `MINI 1*UX(node 2) - 1*UX(node 1) >= -1`.
pub fn describe_condition(it: &Interp, r: &Rigidite, k: usize, limit: f64) -> String {
    let Some(c) = r.conds.get(k) else { return format!("condition {}", k + 1) };
    let (kw, op) = match c.kind {
        Kind::Equal => ("", "="),
        Kind::Mini => ("MINI ", ">="),
        Kind::Maxi => ("MAXI ", "<="),
    };
    match c.terms.as_slice() {
        [(n, comp, coef)] if *coef == 1.0 => {
            format!("{}{} {} {} at {}", kw, comp, op, fmt_float(limit), node_name(it, *n))
        }
        terms => {
            let t: Vec<String> =
                terms.iter().map(|(n, comp, coef)| format!("{}*{}(node {})", fmt_float(*coef), comp, n + 1)).collect();
            format!("{}{} {} {}", kw, t.join(" + "), op, fmt_float(limit))
        }
    }
}
