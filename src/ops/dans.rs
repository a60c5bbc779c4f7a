//! DANS (dans.notice): is an object in another? A POINT among the nodes of
//! a mesh, a number in a LISTREEL (within 1e-8 of the list's smallest gap
//! between consecutive values), a LISTENTI as one of the aligned blocks of
//! another, a LISTREEL as a run of another ('SEQU') or all its values in
//! another ('QUEL').

use super::{Args, OpDef, PointId};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::value::Value;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "DANS",
    signature: "DANS POINT MAILLAGE | DANS FLOTTANT LISTREEL | DANS LISTENTI LISTENTI | DANS ('SEQU'|'QUEL') LISTREEL LISTREEL",
    doc: "VRAI when the first object is in the second: a point among the nodes of a mesh; a number in a LISTREEL (within 1e-8 of its smallest gap between consecutive values); a LISTENTI of length p equal to values n*p+1 … (n+1)*p of the other for some n; with 'SEQU' a LISTREEL as consecutive values of the other, with 'QUEL' every value of it in the other.",
    example: "l = dans (lect 3 4) (lect 1 2 3 4) ;",
    f: dans,
}];

/// The tolerance for values of `l`: 1e-8 of its smallest nonzero gap.
fn tolerance(l: &[f64]) -> f64 {
    let gap = l.windows(2).map(|w| (w[1] - w[0]).abs()).filter(|g| *g > 0.0).fold(f64::INFINITY, f64::min);
    if gap.is_finite() {
        1e-8 * gap
    } else {
        1e-8 * l.iter().fold(0.0f64, |m, x| m.max(x.abs()))
    }
}

fn has(l: &[f64], x: f64, tol: f64) -> bool {
    l.iter().any(|y| (y - x).abs() <= tol)
}

fn dans(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if let Some(k) = a.keyword(&["SEQU", "QUEL"]) {
        let l1 = a.req::<Rc<Vec<f64>>>()?;
        let l2 = a.req::<Rc<Vec<f64>>>()?;
        let tol = tolerance(&l2);
        let yes = if k == "QUEL" {
            l1.iter().all(|&x| has(&l2, x, tol))
        } else {
            l1.is_empty() || l2.windows(l1.len()).any(|w| w.iter().zip(l1.iter()).all(|(y, x)| (y - x).abs() <= tol))
        };
        return Ok(vec![Value::Bool(yes)]);
    }
    if let Some(p) = a.opt::<PointId>() {
        let m = a.req::<Rc<Mesh>>()?;
        return Ok(vec![Value::Bool(m.parts.iter().any(|part| part.elems().any(|e| e.contains(&p.0))))]);
    }
    if let Some(l1) = a.opt::<Rc<Vec<i64>>>() {
        let l2 = a.req::<Rc<Vec<i64>>>()?;
        let p = l1.len();
        let yes = p > 0 && l2.chunks_exact(p).any(|c| c == l1.as_slice());
        return Ok(vec![Value::Bool(yes)]);
    }
    if let Some(x) = a.opt_num() {
        let l = a.req::<Rc<Vec<f64>>>()?;
        return Ok(vec![Value::Bool(has(&l, x, tolerance(&l)))]);
    }
    Err(a.missing("POINT, FLOTTANT, LISTENTI, 'SEQU' or 'QUEL'"))
}
