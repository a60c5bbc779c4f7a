//! Sizes read from a deck are checked before anything is allocated: a slip
//! like `PROG 100000000000 * 1.` must be a clean error, never an
//! allocation abort that ends the process (and a REPL session with it).
//!
//! A local helper until `Args` has a size check of its own: the wording is
//! kept here, in one place, for every operator that grows a list or a text.

use super::Args;
use crate::error::Error;

/// Most items one list, or characters one MOT, may hold (800 MB of
/// FLOTTANT): far above any deck, far below the machine.
pub(crate) const MAX_ITEMS: usize = 100_000_000;

/// Check that `have + more` items stay within [`MAX_ITEMS`]; `more` is a
/// count as read from the deck (a FLOTTANT past 9 digits), not yet cast.
pub(crate) fn room(a: &Args, have: usize, more: f64) -> Result<usize, Error> {
    if more.is_nan() || more < 0.0 || more.fract() != 0.0 {
        return Err(a.err(format!("a count must be a non-negative ENTIER, found {}", more)));
    }
    let total = have as f64 + more;
    if total > MAX_ITEMS as f64 {
        return Err(too_many(a, total));
    }
    Ok(more as usize)
}

/// The error for a result of `total` items.
pub(crate) fn too_many(a: &Args, total: f64) -> Error {
    a.err(format!("too many values: {} asked, at most {}", total, MAX_ITEMS))
}

/// A result of `len` items, checked after the fact (joins of lists that
/// already exist: `l = l ET l` in a loop doubles each time).
pub(crate) fn check_len(a: &Args, len: usize) -> Result<(), Error> {
    if len > MAX_ITEMS {
        return Err(too_many(a, len as f64));
    }
    Ok(())
}
