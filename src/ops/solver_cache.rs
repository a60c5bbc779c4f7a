//! What RESO remembers between calls.
//!
//! * Per RIGIDITE object ([`SolverCache`]): its numbering and the unilateral
//!   cache (symbolic analysis, condensed operator, final statuses for the
//!   warm start of the next RESO on the same object).
//! * Per interpreter ([`FactorPool`]): the last direct factorisations, keyed
//!   by the structure of the system. A new RHS on the same object is one
//!   solve; a *new object with the same pattern* — a deck that re-assembles
//!   `RIGI` with new material values in a loop — reuses the symbolic
//!   analysis and only refactorises numerically.

use super::assemble::Assembled;
use crate::solve::direct::Factorization;
use crate::solve::unilateral::UnilCache;
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
    /// The diagnostics TABLE of the last unilateral solve of this object
    /// (what UNIL returns), for `EXTR RIG 'CONT'`.
    pub last_unil: Option<crate::value::Value>,
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

/// One factorisation and the object whose values it holds.
#[derive(Debug)]
pub struct PoolEntry {
    pub key: u64,
    pub owner: u64,
    pub fact: Factorization,
}

/// The interpreter's last direct factorisations (most recent last).
#[derive(Debug, Default)]
pub struct FactorPool {
    entries: Vec<PoolEntry>,
}

/// Factorisations kept: enough for a deck alternating two structures,
/// small enough not to hold many factors in memory.
const CAPACITY: usize = 2;

impl FactorPool {
    /// The entry for a structure key, moved to the most-recent position.
    pub fn get(&mut self, key: u64) -> Option<&mut PoolEntry> {
        let i = self.entries.iter().position(|e| e.key == key)?;
        let e = self.entries.remove(i);
        self.entries.push(e);
        self.entries.last_mut()
    }

    pub fn insert(&mut self, entry: PoolEntry) -> &mut PoolEntry {
        self.entries.retain(|e| e.key != entry.key);
        if self.entries.len() >= CAPACITY {
            self.entries.remove(0);
        }
        self.entries.push(entry);
        self.entries.last_mut().expect("just pushed")
    }
}
