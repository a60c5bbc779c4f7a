//! WEIP: Weibull parameters from four-point bending failure stresses
//! (numerics in `value::signal::weibull`).

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::signal::weibull;
use crate::value::Value;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "WEIP",
    signature: "WEIP LISTREEL D1 D2 A1",
    doc: "Weibull modulus M and normalising stress SIG0 from the failure stresses of four-point bending tests (supports D1 apart, loads D2 apart, cross-section A1). M and the sample's characteristic stress S by maximum likelihood (P = 1 - exp(-(sigma/S)^M)); SIG0 = S·Veff^(1/M) with the bar's effective volume Veff = A1·D1·(M·D2/D1 + 1)/(2(M+1)²), so that P = 1 - exp(-∫(sigma/SIG0)^M dV).",
    example: "m s0 = weip (prog 400. 450. 500. 550. 600.) 40. 20. 12. ;",
    f: weip,
}];

fn weip(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let l = a.req::<Rc<Vec<f64>>>()?;
    let d1 = a.req_num()?;
    let d2 = a.req_num()?;
    let area = a.req_num()?;
    if !(d1 > 0.0 && d1.is_finite() && d2 >= 0.0 && d2 <= d1 && area > 0.0 && area.is_finite()) {
        return Err(a.err(format!(
            "the spans must satisfy 0 < D1, 0 <= D2 <= D1 and the section A1 > 0, found D1 = {}, D2 = {}, A1 = {}",
            d1, d2, area
        )));
    }
    let (m, s) = weibull::fit(&l).map_err(|e| a.err(e))?;
    let sig0 = s * weibull::four_point_volume(m, d1, d2, area).powf(1.0 / m);
    Ok(vec![Value::Float(m), Value::Float(sig0)])
}
