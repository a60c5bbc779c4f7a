//! What the generic operators do with a RIGIDITE: `FLOT * RIGIDITE`,
//! `RIGIDITE * CHPOINT` (K u), `ET` (assembly by concatenation), REAC, and
//! the parts EXTR and DIME read.

use super::{Rigidite, Subtype};
use crate::fem::element::dual_name;
use crate::value::{Chpoint, Nature};
use std::collections::{HashMap, HashSet};

/// The dual a condition's reaction lands on: the one the blocks pair
/// with that unknown (CHAN 'INCO' may have renamed it), else the default.
fn dual_for(blocks: &HashMap<&str, &str>, comp: &str) -> String {
    blocks.get(comp).map_or_else(|| dual_name(comp), |d| d.to_string())
}

impl Rigidite {
    /// Primal → dual names as the elementary blocks pair them.
    fn duals_of_blocks(&self) -> HashMap<&str, &str> {
        let mut m = HashMap::new();
        for b in &self.blocks {
            for ((_, c), d) in b.dofs.iter().zip(&b.duals) {
                m.entry(c.as_str()).or_insert(d.as_str());
            }
        }
        m
    }

    /// Every elementary matrix times `s` (the conditions unchanged). A new
    /// object: it starts with a fresh solver cache.
    pub fn scaled(&self, s: f64) -> Rigidite {
        let mut out = Rigidite::new(self.subtype);
        out.blocks = self.blocks.clone();
        for b in out.blocks.iter_mut() {
            for v in b.mats.iter_mut() {
                *v *= s;
            }
        }
        out.conds = self.conds.clone();
        out
    }

    /// `ET` of two rigidities: the lists are concatenated (lazy assembly).
    /// The result is a new object, so it starts with a fresh solver cache
    /// (no warm start after re-assembly, as in Cast3M).
    pub fn union(&self, s: &Rigidite) -> Rigidite {
        let subtype = if self.subtype == Subtype::Blocage { s.subtype } else { self.subtype };
        let mut out = Rigidite::new(subtype);
        out.blocks = self.blocks.iter().chain(s.blocks.iter()).cloned().collect();
        out.conds = self.conds.iter().chain(s.conds.iter()).cloned().collect();
        out
    }

    /// `RIGIDITE * CHPOINT`: K u on the primal rows (dual names), and for
    /// the conditions c·u on FLX and cᵀλ on the primal rows (λ = LX of the
    /// field).
    pub fn matvec(&self, u: &Chpoint) -> Chpoint {
        let dual = self.duals_of_blocks();
        let mut out = Chpoint::new(Nature::Discret);
        for b in &self.blocks {
            let nd = b.ndof();
            for e in 0..b.n_elem() {
                let conn = &b.conn[e * b.nodes_per_elem..(e + 1) * b.nodes_per_elem];
                let m = b.mat(e);
                let ue: Vec<f64> = b.dofs.iter().map(|(l, c)| u.get(conn[*l], c).unwrap_or(0.0)).collect();
                for i in 0..nd {
                    let s: f64 = (0..nd).map(|j| m[i * nd + j] * ue[j]).sum();
                    out.add(conn[b.dofs[i].0], &b.duals[i], s, true);
                }
            }
        }
        for c in &self.conds {
            let cu: f64 = c.terms.iter().map(|(n, comp, k)| k * u.get(*n, comp).unwrap_or(0.0)).sum();
            out.add(c.mult_node, "FLX", cu, true);
            if let Some(l) = u.get(c.mult_node, "LX") {
                for (n, comp, k) in c.reaction_terms() {
                    out.add(*n, &dual_for(&dual, comp), k * l, true);
                }
            }
        }
        out
    }

    /// REAC: the reactions −Cᵀλ of the conditions, from the LX of a RESO
    /// result (a DISCRET field).
    pub fn reactions(&self, u: &Chpoint) -> Chpoint {
        let dual = self.duals_of_blocks();
        let mut out = Chpoint::new(Nature::Discret);
        for c in &self.conds {
            // An inactive unilateral condition has no LX: its reaction is 0
            // (reac.notice), written explicitly so EXTR finds it.
            let l = u.get(c.mult_node, "LX").unwrap_or(0.0);
            for (n, comp, coef) in c.reaction_terms() {
                out.add(*n, &dual_for(&dual, comp), -coef * l, true);
            }
        }
        out
    }

    /// The physical nodes (of the blocks, then of the condition rows),
    /// each once.
    pub fn physical_nodes(&self) -> Vec<usize> {
        let mut phys = Vec::new();
        for b in &self.blocks {
            phys.extend_from_slice(&b.conn);
        }
        for c in &self.conds {
            phys.extend(c.terms.iter().map(|t| t.0));
        }
        let mut seen = HashSet::new();
        phys.retain(|n| seen.insert(*n));
        phys
    }

    /// The multiplier nodes, of every condition or of the unilateral ones.
    pub fn multiplier_nodes(&self, unilateral_only: bool) -> Vec<usize> {
        self.conds.iter().filter(|c| !unilateral_only || c.kind.is_unilateral()).map(|c| c.mult_node).collect()
    }

    /// The primal component names of the blocks, then LX if there are
    /// conditions.
    pub fn component_names(&self) -> Vec<String> {
        let mut comps: Vec<String> = Vec::new();
        for b in &self.blocks {
            for (_, c) in &b.dofs {
                if !comps.contains(c) {
                    comps.push(c.clone());
                }
            }
        }
        if !self.conds.is_empty() {
            comps.push("LX".into());
        }
        comps
    }

    /// The diagonal of the assembled blocks, as a DIFFUS field.
    pub fn diagonal(&self) -> Chpoint {
        let mut diag: HashMap<(usize, String), f64> = HashMap::new();
        let mut order = Vec::new();
        for b in &self.blocks {
            let nd = b.ndof();
            for e in 0..b.n_elem() {
                let conn = &b.conn[e * b.nodes_per_elem..(e + 1) * b.nodes_per_elem];
                for (i, (l, c)) in b.dofs.iter().enumerate() {
                    let key = (conn[*l], c.clone());
                    if !diag.contains_key(&key) {
                        order.push(key.clone());
                    }
                    *diag.entry(key).or_insert(0.0) += b.mat(e)[i * nd + i];
                }
            }
        }
        Chpoint::from_entries(Nature::Diffus, order.iter().map(|k| (k.0, k.1.as_str(), diag[k])))
    }

    /// DIME: the number of unknowns, primal (of the blocks and the rows)
    /// and one LX per condition.
    pub fn n_unknowns(&self) -> usize {
        let mut set = HashSet::new();
        for b in &self.blocks {
            for e in 0..b.n_elem() {
                for (l, c) in &b.dofs {
                    set.insert((b.conn[e * b.nodes_per_elem + l], c.clone()));
                }
            }
        }
        for c in &self.conds {
            for (n, comp, _) in &c.terms {
                set.insert((*n, comp.clone()));
            }
        }
        set.len() + self.conds.len()
    }
}
