//! The data exchanged with the solver: plain numbers and indices.

/// A sparse matrix given as a list of entries over the primal unknowns
/// `0..n`. Duplicates are summed. For a symmetric matrix both triangles may
/// be present (as elementary blocks give them); the solver reads what it
/// needs. `symmetric == false` sends the system through sparse LU.
#[derive(Debug, Clone, Default)]
pub struct Matrix {
    pub n: usize,
    pub entries: Vec<(usize, usize, f64)>,
    pub symmetric: bool,
}

/// The kind of a condition row `c·u ⋈ d`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Kind {
    /// `c·u = d` (BLOQ, RELA without keyword).
    Equal,
    /// `c·u >= d` (`'MINI'`).
    Mini,
    /// `c·u <= d` (`'MAXI'`).
    Maxi,
}

impl Kind {
    pub fn is_unilateral(self) -> bool {
        self != Kind::Equal
    }
    /// s_i of unilateral.md §1: +1 for MINI, −1 for MAXI (0 for equalities).
    pub fn sense(self) -> f64 {
        match self {
            Kind::Equal => 0.0,
            Kind::Mini => 1.0,
            Kind::Maxi => -1.0,
        }
    }
}

/// One condition: a sparse row over primal unknowns and its kind. Its
/// limit `d` comes with the load ([`Load::d`]), because DEPI values change
/// from one RESO to the next while the matrix does not.
///
/// `dual` makes the condition *non-associated* (RELA … 'DUAL'): the
/// reaction acts along `dual` instead of `terms`, i.e. the equilibrium reads
/// `K u + Σ dualᵢᵀ λᵢ = F` while the condition stays `terms·u ⋈ d`. The
/// system is then not symmetric: a problem holding such a condition must
/// have `k.symmetric == false` (every K entry given), and goes through
/// sparse LU.
#[derive(Debug, Clone, PartialEq)]
pub struct Condition {
    pub terms: Vec<(usize, f64)>,
    pub kind: Kind,
    pub dual: Option<Vec<(usize, f64)>>,
}

impl Condition {
    /// The direction of the reaction: `dual` when given, else the row.
    pub fn reaction_terms(&self) -> &[(usize, f64)] {
        self.dual.as_deref().unwrap_or(&self.terms)
    }
}

/// The whole operator: stiffness plus condition rows.
#[derive(Debug, Clone, Default)]
pub struct Problem {
    pub k: Matrix,
    pub conditions: Vec<Condition>,
}

/// One right-hand side: forces on the primal unknowns (`f.len() == n`) and
/// the limit of every condition (`d.len() == m`, 0 where no DEPI was given).
#[derive(Debug, Clone, PartialEq)]
pub struct Load {
    pub f: Vec<f64>,
    pub d: Vec<f64>,
}

/// The answer for one load: primal unknowns, the physical multiplier of
/// every condition (`λ = σ(λ1 + λ2)`, the value RESO stores as `LX`; 0 for
/// an inactive unilateral condition) and whether each condition is active
/// (always true for equalities).
#[derive(Debug, Clone, PartialEq)]
pub struct Solution {
    pub u: Vec<f64>,
    pub lambda: Vec<f64>,
    pub active: Vec<bool>,
}

/// The problem condensed onto the second multipliers of the `m` unilateral
/// conditions (unilateral.md §3.2, negated quarter-scaled form):
/// `T x = h` with `T = G − A·P_I`, where `P_I` is the 0/1 diagonal of the
/// inactive conditions. Produced by `condense`, consumed by `status`.
/// Indices `0..m` here are positions among the unilateral conditions only.
#[derive(Debug, Clone)]
pub struct Condensed {
    /// `G = ΣC H⁻¹ CᵀΣ` (m×m, symmetric; positive definite when the rows
    /// are independent).
    pub g: std::rc::Rc<faer::Mat<f64>>,
    /// The packed LDLᵀ of `g` (D on the diagonal, unit L strictly below)
    /// when the condensation produced it (an unshifted interrupted
    /// factorisation): the status loop's factor while every condition is
    /// active, with no dense factorisation.
    pub g_factor: Option<std::rc::Rc<faer::Mat<f64>>>,
    /// `h = ½ (ΣC H⁻¹ (F + CᵀW d) − Σd)`.
    pub h: Vec<f64>,
    /// Multiplier-block scaling α_i (the diagonal change on release is α_i).
    pub alpha: Vec<f64>,
    /// Coupling scaling σ_i (physical λ_i = 2 σ_i x_i when active).
    pub sigma: Vec<f64>,
    /// s_i: +1 for MINI, −1 for MAXI.
    pub sense: Vec<f64>,
    /// `XᵀF = ΣC H⁻¹ F`, for the work of the load along a rigid mode (§7.5).
    pub xtf: Vec<f64>,
    /// The rows c_i (primal unknown, coefficient), to group proportional rows.
    pub rows: Vec<Vec<(usize, f64)>>,
    /// The limits d_i.
    pub d: Vec<f64>,
}
