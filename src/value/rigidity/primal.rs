//! The primal unknowns of a RIGIDITE, as (node, component) pairs.

use super::Rigidite;
use std::collections::HashSet;

impl Rigidite {
    /// Every primal unknown, in the order the blocks meet them, then those
    /// only the conditions name; the multipliers (LX) are not included.
    pub fn primal_unknowns(&self) -> Vec<(usize, String)> {
        let mut seen = HashSet::new();
        let mut out = Vec::new();
        let mut push = |n: usize, c: &str| {
            if seen.insert((n, c.to_string())) {
                out.push((n, c.to_string()));
            }
        };
        for b in &self.blocks {
            for e in 0..b.n_elem() {
                for (l, c) in &b.dofs {
                    push(b.conn[e * b.nodes_per_elem + l], c);
                }
            }
        }
        for c in &self.conds {
            for (n, comp, _) in &c.terms {
                push(*n, comp);
            }
        }
        out
    }
}
