//! PROB: the probability that a random variable known by its mean,
//! standard deviation, skewness and kurtosis lies below a bound (the law
//! in `value::signal::pearson`).

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::signal::pearson;
use crate::value::Value;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "PROB",
    signature: "PROB MEAN STDDEV SKEWNESS KURTOSIS BOUND -> FLOTTANT",
    doc: "P(X ≤ BOUND) for the Pearson law of the given mean, standard deviation, skewness and kurtosis (skewness 0 and kurtosis 3: the normal law).",
    example: "p = prob 0. 1. 0. 3. 1.645 ;",
    f: prob,
}];

fn prob(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mut v = [0.0; 5];
    for x in v.iter_mut() {
        *x = a.req_num()?;
        if !x.is_finite() {
            return Err(a.err("PROB needs finite numbers"));
        }
    }
    let p = pearson::cdf(v[0], v[1], v[2], v[3], v[4]).map_err(|e| a.err(e))?;
    Ok(vec![Value::Float(p)])
}
