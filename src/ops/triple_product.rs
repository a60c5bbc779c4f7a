//! PMIXTE (pmix.notice): the scalar triple product of 3 vectors in 3D,
//! det(v1, v2, v3) = (v1 x v2) . v3; in 2D the determinant of 2 vectors.

use super::{Args, OpDef, PointId};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::Value;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "PMIX",
    signature: "PMIX POINT POINT (POINT in 3D)",
    doc:
        "Scalar triple product of vectors (POINTs read as vectors): det(v1, v2) in 2D, (v1 x v2) . v3 in 3D (FLOTTANT).",
    example: "x = pmix (1. 0. 0.) (0. 1. 0.) (0. 0. 2.) ;",
    f: pmix,
}];

fn pmix(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let dime = it.opts.dime;
    if dime != 2 && dime != 3 {
        return Err(a.err("the triple product needs OPTI DIME 2 or 3"));
    }
    let mut v = Vec::new();
    for _ in 0..dime {
        v.push(it.nodes.get(a.req::<PointId>()?.0));
    }
    let det = match dime {
        2 => v[0][0] * v[1][1] - v[0][1] * v[1][0],
        _ => {
            let (x, y, z) = (v[0], v[1], v[2]);
            (x[1] * y[2] - x[2] * y[1]) * z[0] + (x[2] * y[0] - x[0] * y[2]) * z[1] + (x[0] * y[1] - x[1] * y[0]) * z[2]
        }
    };
    Ok(vec![Value::Float(det)])
}
