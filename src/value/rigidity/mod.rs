//! RIGIDITE: a list of elementary matrices over named unknowns, plus
//! condition rows (BLOQ, RELA), exactly as Cast3M keeps it: assembly is lazy
//! and happens in RESO. The solver cache (a `solve` type) lives in the
//! object so a later RESO on the same object reuses the numbering and the
//! symbolic analysis, and warm-starts the status of unilateral conditions.
//!
//! [`algebra`]: what the generic operators do with one (scaling, K u,
//! union, extraction); [`numbering`]: the numbered `solve` problem and the
//! field of a solution.

pub mod algebra;
mod cmct;
mod dense;
pub mod numbering;
mod primal;

use crate::solve::{Kind, SolverCache};
use std::cell::RefCell;
use std::rc::Rc;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Subtype {
    Rigidite,
    Masse,
    Blocage,
    /// Heat conduction and capacity matrices (COND, CAPA).
    Conductivite,
    Capacite,
    /// Damping (MANU 'RIGI' 'TYPE' 'AMORTISSEMENT').
    Amortissement,
}

impl Subtype {
    pub fn name(self) -> &'static str {
        match self {
            Subtype::Rigidite => "RIGIDITE",
            Subtype::Masse => "MASSE",
            Subtype::Blocage => "BLOCAGE",
            Subtype::Conductivite => "CONDUCTIVITE",
            Subtype::Capacite => "CAPACITE",
            Subtype::Amortissement => "AMORTISSEMENT",
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Symmetry {
    Symmetric,
    Antisymmetric,
    General,
}

/// The same kind of elementary matrix on every element of a connectivity.
#[derive(Debug, Clone)]
pub struct Block {
    pub nodes_per_elem: usize,
    pub conn: Vec<usize>,
    /// (local node, primal component) of each row/column.
    pub dofs: Vec<(usize, String)>,
    /// Dual component of each row (FX for UX ...).
    pub duals: Vec<String>,
    /// `n_elem × ndof × ndof`, row-major per element.
    pub mats: Vec<f64>,
    pub symmetry: Symmetry,
}

impl Block {
    pub fn n_elem(&self) -> usize {
        self.conn.len() / self.nodes_per_elem.max(1)
    }
    pub fn ndof(&self) -> usize {
        self.dofs.len()
    }
    pub fn mat(&self, e: usize) -> &[f64] {
        let n = self.ndof() * self.ndof();
        &self.mats[e * n..(e + 1) * n]
    }
}

/// One condition `Σ c·u ⋈ d`, carried by its own multiplier node (`LX`).
#[derive(Debug, Clone)]
pub struct CondRow {
    pub mult_node: usize,
    pub terms: Vec<(usize, String, f64)>,
    pub kind: Kind,
    /// Non-associated reaction direction (`RELA … 'DUAL' CHPO`): the
    /// reaction acts along these terms instead of `terms`.
    pub dual: Option<Vec<(usize, String, f64)>>,
}

impl CondRow {
    /// An associated condition (the reaction along its own row).
    pub fn new(mult_node: usize, terms: Vec<(usize, String, f64)>, kind: Kind) -> CondRow {
        CondRow { mult_node, terms, kind, dual: None }
    }
    /// The direction of the reaction.
    pub fn reaction_terms(&self) -> &[(usize, String, f64)] {
        self.dual.as_deref().unwrap_or(&self.terms)
    }
}

#[derive(Debug, Clone)]
pub struct Rigidite {
    pub subtype: Subtype,
    pub blocks: Vec<Block>,
    pub conds: Vec<CondRow>,
    /// Shared by copies with the same pattern (`FLOT * RIGIDITE`), so new
    /// values reuse the symbolic analysis.
    pub cache: Rc<RefCell<SolverCache>>,
}

impl Rigidite {
    pub fn new(subtype: Subtype) -> Self {
        Rigidite { subtype, blocks: vec![], conds: vec![], cache: Default::default() }
    }
    pub fn n_unilateral(&self) -> usize {
        self.conds.iter().filter(|c| c.kind.is_unilateral()).count()
    }
}
