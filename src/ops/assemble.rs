//! From a RIGIDITE (elementary blocks over named unknowns, condition rows)
//! to the numbered `solve::Problem`, and back from a `Solution` to a field.
//! Also the translation of solver errors into node and component names.

use super::dofs;
use crate::error::{Error, Result};
use crate::eval::Interp;
use crate::solve::{Condition, Kind, Load, Matrix, Problem, Solution, SolveError};
use crate::value::rigidity::Symmetry;
use crate::value::{fmt_float, Chpoint, Nature, Rigidite};
use rustc_hash::FxHashMap as HashMap;

/// Numbering of the primal unknowns of one RIGIDITE.
///
/// Component names are interned (a structure has a handful of them), so the
/// per-unknown map is keyed by (node, component id) and numbering a
/// million unknowns allocates no strings.
#[derive(Debug, Clone, Default)]
pub struct Assembled {
    /// (node, component) of each primal unknown, in numbering order.
    pub dofs: Vec<(usize, String)>,
    /// Interned component names, and the dual name of each.
    comps: Vec<String>,
    duals: Vec<String>,
    index: HashMap<(usize, u16), usize>,
    /// Multiplier node of each condition -> condition number.
    mult: HashMap<usize, usize>,
    pub problem: Problem,
}

impl Assembled {
    pub fn new(r: &Rigidite) -> Assembled {
        let mut a = Assembled::default();
        let mut entries = Vec::new();
        let mut symmetric = true;
        for b in &r.blocks {
            symmetric &= b.symmetry == Symmetry::Symmetric;
            let nd = b.ndof();
            let mut idx = vec![0usize; nd];
            let ids: Vec<u16> = b.dofs.iter().zip(&b.duals).map(|((_, c), d)| a.intern(c, d)).collect();
            entries.reserve(b.n_elem() * nd * nd);
            for e in 0..b.n_elem() {
                let conn = &b.conn[e * b.nodes_per_elem..(e + 1) * b.nodes_per_elem];
                for (i, (l, _)) in b.dofs.iter().enumerate() {
                    idx[i] = a.unknown_id(conn[*l], ids[i]);
                }
                let m = b.mat(e);
                for i in 0..nd {
                    for j in 0..nd {
                        entries.push((idx[i], idx[j], m[i * nd + j]));
                    }
                }
            }
        }
        let mut conditions = Vec::with_capacity(r.conds.len());
        for (k, c) in r.conds.iter().enumerate() {
            let mut number = |t: &[(usize, String, f64)]| -> Vec<(usize, f64)> {
                t.iter().map(|(n, comp, coef)| (a.unknown(*n, comp), *coef)).collect()
            };
            let terms = number(&c.terms);
            let dual = c.dual.as_deref().map(&mut number);
            // A non-associated condition makes the system non-symmetric
            // (the blocks give every entry of K, so LU can read them all).
            symmetric &= dual.is_none();
            conditions.push(Condition { terms, kind: c.kind, dual });
            a.mult.insert(c.mult_node, k);
        }
        a.problem = Problem { k: Matrix { n: a.dofs.len(), entries, symmetric }, conditions };
        a
    }

    /// The id of a component name, registering it (with its dual) if new.
    fn intern(&mut self, comp: &str, dual: &str) -> u16 {
        match self.comps.iter().position(|c| c == comp) {
            Some(i) => i as u16,
            None => {
                self.comps.push(comp.to_string());
                self.duals.push(dual.to_string());
                (self.comps.len() - 1) as u16
            }
        }
    }

    fn unknown_id(&mut self, node: usize, id: u16) -> usize {
        let next = self.dofs.len();
        let i = *self.index.entry((node, id)).or_insert(next);
        if i == next {
            self.dofs.push((node, self.comps[id as usize].clone()));
        }
        i
    }

    fn unknown(&mut self, node: usize, comp: &str) -> usize {
        let id = self.intern(comp, &dofs::dual_of(comp));
        self.unknown_id(node, id)
    }

    /// The unknown a load component names: a dual name (FX) or the primal
    /// name itself.
    fn find(&self, node: usize, comp: &str) -> Option<usize> {
        let by = |names: &[String]| names.iter().position(|c| c == comp);
        by(&self.duals).or_else(|| by(&self.comps)).and_then(|id| self.index.get(&(node, id as u16)).copied())
    }

    /// The load of one right-hand side field: forces by dual (or primal)
    /// name on the unknowns, FLX on the multiplier nodes as limits.
    pub fn load(&self, it: &Interp, rhs: &[&Chpoint]) -> Result<Load> {
        let mut f = vec![0.0; self.dofs.len()];
        let mut d = vec![0.0; self.problem.conditions.len()];
        for ch in rhs {
            for (n, c, v) in ch.entries() {
                if c == "FLX" {
                    match self.mult.get(&n) {
                        Some(&k) => d[k] += v,
                        None => {
                            return Err(Error::runtime(format!(
                                "the right-hand side imposes a value (FLX) at {} which carries no condition of this RIGIDITE",
                                node_name(it, n)
                            )))
                        }
                    }
                    continue;
                }
                match self.find(n, c) {
                    Some(i) => f[i] += v,
                    None => {
                        return Err(Error::runtime(format!(
                            "the right-hand side has {} at {}, which is no unknown of this RIGIDITE",
                            c,
                            node_name(it, n)
                        )))
                    }
                }
            }
        }
        Ok(Load { f, d })
    }

    /// The RESO result: every primal unknown and the LX of active conditions.
    pub fn field(&self, r: &Rigidite, s: &Solution) -> Chpoint {
        let mut out = Chpoint::new(Nature::Diffus);
        for ((n, c), v) in self.dofs.iter().zip(&s.u) {
            out.add(*n, c, *v, false);
        }
        for (k, c) in r.conds.iter().enumerate() {
            if s.active[k] {
                out.add(c.mult_node, "LX", s.lambda[k], false);
            }
        }
        out
    }

    /// A solver error in words a user can act on.
    pub fn explain(&self, it: &Interp, r: &Rigidite, e: SolveError, loads: &[Load]) -> Error {
        let dof = |i: usize| match self.dofs.get(i) {
            Some((n, c)) => format!("{} of {}", c, node_name(it, *n)),
            None => format!("unknown {}", i),
        };
        let cond =
            |k: usize| describe_condition(it, r, k, loads.first().map_or(0.0, |l| l.d.get(k).copied().unwrap_or(0.0)));
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
