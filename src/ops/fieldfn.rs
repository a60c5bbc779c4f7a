//! Hooks through which the generic operators (MAXI, MINI, EXTR, DIME)
//! reach the finite-element objects.

use super::Args;
use crate::error::Result;
use crate::eval::Interp;
use crate::value::Value;

pub(crate) fn extremum(_it: &mut Interp, a: &mut Args, max: bool, abs: bool) -> Result<Option<Value>> {
    super::fields::extremum(a, max, abs)
}

/// EXTR on FE objects; None when the arguments are not FE objects.
pub(crate) fn extr(it: &mut Interp, a: &mut Args) -> Result<Option<Vec<Value>>> {
    if let Some(v) = super::evol::extr(a)? {
        return Ok(Some(v));
    }
    super::fields::extr(it, a)
}

pub(crate) fn dime(v: &Value) -> Option<i64> {
    super::fields::dime(v)
}
