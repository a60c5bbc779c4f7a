//! The last direct factorisations, kept by the interpreter and reused by
//! RESO.
//!
//! Entries are keyed by the structure of the system. A new right-hand side
//! on the same object is one solve; a *new object with the same pattern*
//! (a deck that re-assembles `RIGI` with new material values in a loop)
//! reuses the symbolic analysis and only refactorises numerically.

use super::direct::{DirectOptions, Factorization};
use super::lagrange::structure_hash;
use crate::solve::error::SolveError;
use crate::solve::problem::Problem;

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

/// How the factorisation of a solve was obtained.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Phase {
    /// The object's own factorisation, kept from a previous solve.
    Reused,
    /// Another object's, with the same pattern: numeric factorisation only.
    Refactored,
    /// A new one, symbolic analysis included.
    Factorised,
}

impl Phase {
    /// As RESO's echo line and timers name it.
    pub fn name(self) -> &'static str {
        match self {
            Phase::Reused => "reused",
            Phase::Refactored => "numeric refactorisation",
            Phase::Factorised => "factorisation",
        }
    }
}

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

    /// The factorisation of `p`, the system of object `owner` (its
    /// [`crate::solve::SolverCache`] id and structure key, computed here
    /// once per object): its own if kept, another object's refactorised if
    /// the pattern is the same, else a new one. A failed refactorisation
    /// leaves nothing behind for the next solve to reuse.
    pub fn factor(
        &mut self,
        owner: u64,
        structure: &mut Option<u64>,
        p: &Problem,
        opts: &DirectOptions,
    ) -> Result<(&Factorization, Phase), SolveError> {
        let id = owner;
        let structure = *structure.get_or_insert_with(|| structure_hash(p));
        // STAB changes the values factorised: keep it in the key.
        let key = structure ^ (opts.stab as u64).wrapping_mul(0x9e37_79b9_7f4a_7c15);
        let phase = match self.get(key) {
            Some(e) if e.owner == id => Phase::Reused,
            Some(e) if e.fact.same_pattern(p) => {
                if let Err(err) = e.fact.refactor(p) {
                    self.entries.retain(|e| e.key != key);
                    return Err(err);
                }
                e.owner = id;
                Phase::Refactored
            }
            _ => {
                let fact = Factorization::new(p, opts)?;
                self.insert(PoolEntry { key, owner: id, fact });
                Phase::Factorised
            }
        };
        let entry = self.get(key).expect("present");
        Ok((&entry.fact, phase))
    }
}

#[cfg(test)]
#[path = "tests/pool.rs"]
mod tests;
