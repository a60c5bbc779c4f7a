//! What the unilateral solver keeps between RESO calls on one operator.
//!
//! The cache lives with the RIGIDITE object (through `solve::SolverCache`):
//! it keeps the condenser or the sparse operator of CREUX (symbolic
//! analysis always reusable for the same structure, numeric factor reused
//! when the values are identical too) and the last converged statuses, the
//! warm start of the next RESO (reset when the structure changes).

use super::condensed::KeptCondenser;
use super::sparse::Creux;

/// State kept between RESO calls on the same operator.
#[derive(Debug, Default)]
pub struct UnilCache {
    /// CONDENSE: the condenser and the values it holds.
    pub(super) condensed: KeptCondenser,
    /// Structure the warm start belongs to.
    pub(super) structure: Option<u64>,
    /// CREUX: the sparse operator with its symbolic analysis.
    pub(super) sparse: Option<Creux>,
    /// Final statuses of the last converged solve (unilateral order).
    pub status: Option<Vec<bool>>,
}
