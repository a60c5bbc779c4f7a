//! What a RIGIDITE object remembers between RESO calls: its numbering, the
//! direct factorisation (reused for every new right-hand side), and the
//! unilateral cache (symbolic analysis, condensed operator, final statuses
//! for the warm start of the next RESO on the same object).

use super::assemble::Assembled;
use crate::solve::direct::Factorization;
use crate::solve::unilateral::UnilCache;
use std::rc::Rc;

#[derive(Debug, Default)]
pub struct SolverCache {
    pub assembled: Option<Rc<Assembled>>,
    pub direct: Option<Factorization>,
    /// Options the direct factorisation was made with ('STAB').
    pub direct_stab: bool,
    pub unil: UnilCache,
}
