//! Hooks through which the generic operators (ABS, MAXI, MINI, EXTR, DIME)
//! reach the finite-element objects.

use super::Args;
use crate::error::Result;
use crate::eval::Interp;
use crate::value::Value;

pub(crate) fn abs(_it: &mut Interp, _v: &Value) -> Option<Value> {
    None
}

pub(crate) fn extremum(_it: &mut Interp, _a: &mut Args, _max: bool, _abs: bool) -> Result<Option<Value>> {
    Ok(None)
}

/// EXTR on FE objects; None when the arguments are not FE objects.
pub(crate) fn extr(_it: &mut Interp, _a: &mut Args) -> Result<Option<Vec<Value>>> {
    Ok(None)
}

pub(crate) fn dime(_v: &Value) -> Option<i64> {
    None
}
