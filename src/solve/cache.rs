//! What RESO remembers between calls, per RIGIDITE object: its numbering,
//! the structure key of its direct system, the unilateral cache (symbolic
//! analysis, condensed operator, final statuses for the warm start of the
//! next RESO on the same object) and the report of its last unilateral
//! solve (`EXTR RIG 'CONT'`). The direct factorisations themselves are kept
//! per interpreter ([`crate::solve::bilateral::pool`]), so that a new object
//! with the same pattern reuses them.

use super::numbering::Assembled;
use super::unilateral::{UnilCache, UnilReport};
use std::rc::Rc;
use std::sync::atomic::{AtomicU64, Ordering};

/// Unique ids, so a pool entry never mistakes a new object for the one
/// whose values it holds (addresses can be reused after a drop).
static NEXT_ID: AtomicU64 = AtomicU64::new(1);

#[derive(Debug)]
pub struct SolverCache {
    pub id: u64,
    pub assembled: Option<Rc<Assembled>>,
    /// Structure key of the direct system, computed once per object.
    pub key: Option<u64>,
    pub unil: UnilCache,
    /// The last unilateral solve of this object: its report and the final
    /// status of every unilateral condition, in condition order.
    pub last_unil: Option<(UnilReport, Vec<bool>)>,
}

impl Default for SolverCache {
    fn default() -> Self {
        SolverCache {
            id: NEXT_ID.fetch_add(1, Ordering::Relaxed),
            assembled: None,
            key: None,
            unil: Default::default(),
            last_unil: None,
        }
    }
}
