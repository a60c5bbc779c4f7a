//! The numbering of a system written over named unknowns: unknown `i` is
//! a (node, component) pair, condition `k` is carried by a multiplier
//! node. The language builds it from a RIGIDITE (`value::rigidity`); the
//! solver caches it with the object ([`crate::solve::SolverCache`]), so a
//! second RESO on the same object numbers nothing again.
//!
//! Component names are interned (a structure has a handful of them), so the
//! per-unknown map is keyed by (node, component id) and numbering a
//! million unknowns allocates no strings.

use super::problem::{Condition, Load, Matrix, Problem};
use super::twins::{agree, Twin};
use rustc_hash::FxHashMap as HashMap;

/// The numbered problem of one system over named unknowns.
#[derive(Debug, Clone, Default)]
pub struct Assembled {
    /// (node, component) of each primal unknown, in numbering order.
    pub dofs: Vec<(usize, String)>,
    /// Interned component names, and the dual name of each.
    comps: Vec<String>,
    duals: Vec<String>,
    index: HashMap<(usize, u16), usize>,
    /// Multiplier node of each condition -> condition number.
    pub(super) mult: HashMap<usize, usize>,
    /// Multiplier nodes of the rows merged into an earlier twin
    /// ([`Assembled::merge_twins`]).
    pub(super) twins: HashMap<usize, Twin>,
    /// Unmerged number of each condition (empty: nothing was merged).
    pub(super) origin: Vec<usize>,
    /// The multiplier node of each condition, in condition order.
    pub mult_nodes: Vec<usize>,
    pub problem: Problem,
}

/// A right-hand side names what the system does not hold.
#[derive(Debug, Clone, PartialEq)]
pub enum LoadError {
    /// A value (FLX) imposed at a node that carries no condition.
    NoCondition { node: usize },
    /// A force component at a node where the system has no such unknown.
    NoUnknown { node: usize, comp: String },
    /// Twin conditions (one row a multiple of the other) given values that
    /// disagree; both numbered as in the unmerged system.
    Conflicting { kept: usize, twin: usize },
}

impl Assembled {
    /// The id of a component name, registering it (with its dual) if new.
    pub fn intern(&mut self, comp: &str, dual: &str) -> u16 {
        match self.comps.iter().position(|c| c == comp) {
            Some(i) => i as u16,
            None => {
                self.comps.push(comp.to_string());
                self.duals.push(dual.to_string());
                (self.comps.len() - 1) as u16
            }
        }
    }

    /// The number of the unknown (node, interned component), numbering it
    /// if new.
    pub fn unknown_id(&mut self, node: usize, id: u16) -> usize {
        let next = self.dofs.len();
        let i = *self.index.entry((node, id)).or_insert(next);
        if i == next {
            self.dofs.push((node, self.comps[id as usize].clone()));
        }
        i
    }

    /// Adds condition `k`, carried by `mult_node` (numbered in the order
    /// they come).
    pub fn push_condition(&mut self, mult_node: usize, c: Condition) {
        self.mult.insert(mult_node, self.problem.conditions.len());
        self.mult_nodes.push(mult_node);
        self.problem.conditions.push(c);
    }

    /// Sets the stiffness once every unknown is numbered.
    pub fn set_matrix(&mut self, entries: Vec<(usize, usize, f64)>, symmetric: bool) {
        self.problem.k = Matrix { n: self.dofs.len(), entries, symmetric };
    }

    /// The number of the unknown (node, primal component), if the system
    /// has it.
    pub fn position(&self, node: usize, comp: &str) -> Option<usize> {
        let id = self.comps.iter().position(|c| c == comp)?;
        self.index.get(&(node, id as u16)).copied()
    }

    /// The unknown a load component names: a dual name (FX) or the primal
    /// name itself.
    fn find(&self, node: usize, comp: &str) -> Option<usize> {
        let by = |names: &[String]| names.iter().position(|c| c == comp);
        by(&self.duals).or_else(|| by(&self.comps)).and_then(|id| self.index.get(&(node, id as u16)).copied())
    }

    /// The load of one right-hand side given as (node, component, value):
    /// forces by dual (or primal) name on the unknowns, FLX on the
    /// multiplier nodes as limits.
    pub fn load<'a>(&self, entries: impl IntoIterator<Item = (usize, &'a str, f64)>) -> Result<Load, LoadError> {
        let mut f = vec![0.0; self.dofs.len()];
        let mut d = vec![0.0; self.problem.conditions.len()];
        let mut twins: HashMap<usize, f64> = HashMap::default();
        for (n, c, v) in entries {
            if c == "FLX" {
                match (self.mult.get(&n), self.twins.get(&n)) {
                    (Some(&k), _) => d[k] += v,
                    (None, Some(_)) => *twins.entry(n).or_default() += v,
                    // A condensed rigidity over multipliers (SUPER onto LX,
                    // CMCT) holds LX as an ordinary unknown, loaded by FLX.
                    (None, None) => match self.find(n, c) {
                        Some(i) => f[i] += v,
                        // A zero value on a row the system does not have
                        // changes nothing (the FLX of K u for a K with
                        // conditions, solved against M alone).
                        None if v == 0.0 => {}
                        None => return Err(LoadError::NoCondition { node: n }),
                    },
                }
                continue;
            }
            match self.find(n, c) {
                Some(i) => f[i] += v,
                None if v == 0.0 => {}
                None => return Err(LoadError::NoUnknown { node: n, comp: c.to_string() }),
            }
        }
        // A twin given no value imposes 0, as any condition: it must agree too.
        let conflict = self
            .twins
            .iter()
            .filter(|(node, t)| !agree(d[t.kept], twins.get(node).copied().unwrap_or(0.0), t.ratio))
            .min_by_key(|(_, t)| t.origin);
        if let Some((_, t)) = conflict {
            return Err(LoadError::Conflicting { kept: self.origin(t.kept), twin: t.origin });
        }
        Ok(Load { f, d })
    }
}
