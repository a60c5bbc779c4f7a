//! X-FEM: elements enriched by the functions of a crack described by two
//! level sets, PSI (signed distance to the line or plane through the tip or
//! front, positive ahead of it) and PHI (signed distance to the crack).
//!
//! A node is enriched by the *jump* (Heaviside, unknowns AX AY (AZ)) when
//! the crack cuts its support in two, or by the four *tip* functions
//! (unknowns B1X … E1Y) when the tip lies in its support; [`select`] makes
//! that choice (TRIE), dimension-blind: it only reads level sets at nodes.
//! The displacement is the classical (unshifted) one,
//! u = Σ Nᵢ uᵢ + Σ_jump Nᵢ H aᵢ + Σ_tip Σ_k Nᵢ F_k bᵢₖ,
//! so the physical displacement at a node is uᵢ + H aᵢ + Σ F_k bᵢₖ there.

pub mod functions;
pub mod on_crack;
pub mod q4;
pub mod subcell;
#[cfg(test)]
mod tests;

use std::collections::BTreeMap;

/// The enrichment of one node.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum NodeKind {
    /// Heaviside across the crack.
    Jump,
    /// The four crack-tip functions.
    Tip,
}

impl NodeKind {
    /// Its code in TRIE's enrichment field (0 for a classical node).
    pub fn code(k: Option<NodeKind>) -> f64 {
        match k {
            None => 0.0,
            Some(NodeKind::Jump) => 1.0,
            Some(NodeKind::Tip) => 2.0,
        }
    }

    pub fn from_code(c: f64) -> Option<NodeKind> {
        match c.round() as i64 {
            1 => Some(NodeKind::Jump),
            2 => Some(NodeKind::Tip),
            _ => None,
        }
    }
}

/// Extra unknowns of an enriched node, in element order, per dimension.
pub fn kind_dofs(kind: NodeKind, dim: usize) -> &'static [&'static str] {
    match (kind, dim) {
        (NodeKind::Jump, 3) => &["AX", "AY", "AZ"],
        (NodeKind::Jump, _) => &["AX", "AY"],
        (NodeKind::Tip, 3) => &["B1X", "B1Y", "B1Z", "C1X", "C1Y", "C1Z", "D1X", "D1Y", "D1Z", "E1X", "E1Y", "E1Z"],
        (NodeKind::Tip, _) => &["B1X", "B1Y", "C1X", "C1Y", "D1X", "D1Y", "E1X", "E1Y"],
    }
}

/// Every enriched unknown name (RECO drops them from the physical field).
pub const ENRICHED_DOFS: &[&str] =
    &["AX", "AY", "AZ", "B1X", "B1Y", "B1Z", "C1X", "C1Y", "C1Z", "D1X", "D1Y", "D1Z", "E1X", "E1Y", "E1Z"];

/// The state of an X-FEM zone after TRIE: the level sets at its nodes and
/// the enrichment of each enriched node (a node absent is classical).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Enrichment {
    /// node -> (psi, phi)
    pub levels: BTreeMap<usize, (f64, f64)>,
    pub kinds: BTreeMap<usize, NodeKind>,
}

impl Enrichment {
    pub fn kind(&self, node: usize) -> Option<NodeKind> {
        self.kinds.get(&node).copied()
    }

    /// psi and phi at the nodes of an element, or None when one is missing.
    pub fn element_levels(&self, nodes: &[usize]) -> Option<(Vec<f64>, Vec<f64>)> {
        let mut psi = Vec::with_capacity(nodes.len());
        let mut phi = Vec::with_capacity(nodes.len());
        for n in nodes {
            let (s, f) = *self.levels.get(n)?;
            psi.push(s);
            phi.push(f);
        }
        Some((psi, phi))
    }
}

/// One element as [`select`] sees it: its nodes, psi and phi there, and a
/// length of the element (tolerances are relative to it).
pub struct ElemLevels<'a> {
    pub nodes: &'a [usize],
    pub psi: &'a [f64],
    pub phi: &'a [f64],
    pub size: f64,
}

fn range(v: &[f64]) -> (f64, f64) {
    v.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| (a.min(x), b.max(x)))
}

/// TRIE's choice. An element *holds the tip* when both PSI and PHI take
/// (within a tolerance) the value 0 on it; it is *cut* when PHI changes
/// sign on it and it lies wholly behind the tip (PSI < 0). Nodes of
/// elements holding the tip get the tip functions (none with `jump_only`,
/// TRIE 'SAUT': the crack then stops at the edge of such an element);
/// other nodes of cut elements get the jump. A node whose support holds
/// the tip is never given the jump: its support is not cut in two, and the
/// Heaviside would open the crack past the tip.
pub fn select(elems: &[ElemLevels], jump_only: bool) -> BTreeMap<usize, NodeKind> {
    let mut tip_nodes = std::collections::BTreeSet::new();
    let mut cut_nodes = std::collections::BTreeSet::new();
    for e in elems {
        let tol = 1e-9 * e.size;
        let (f0, f1) = range(e.phi);
        let (s0, s1) = range(e.psi);
        if f0 <= tol && f1 >= -tol && s0 <= tol && s1 >= -tol {
            tip_nodes.extend(e.nodes.iter().copied());
        } else if f0 < -tol && f1 > tol && s1 < -tol {
            cut_nodes.extend(e.nodes.iter().copied());
        }
    }
    cut_nodes.extend(on_crack::nodes_on_crack(elems));
    let mut out = BTreeMap::new();
    for n in cut_nodes.difference(&tip_nodes) {
        out.insert(*n, NodeKind::Jump);
    }
    if !jump_only {
        for n in tip_nodes {
            out.insert(n, NodeKind::Tip);
        }
    }
    out
}
