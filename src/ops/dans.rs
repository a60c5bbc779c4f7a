//! DANS: membership tests (dans.notice): a LISTENTI as one aligned block
//! of another, a real in a LISTREEL, a point among the nodes of a mesh, a
//! LISTREEL as a run of another ('SEQU') or as a subset ('QUEL').

use super::{Args, OpDef, PointId};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::value::Value;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "DANS",
    signature: "DANS LISTENTI1 LISTENTI2 | DANS LISTREEL FLOTTANT | DANS POINT MAILLAGE | DANS ('SEQU'|'QUEL') LISTREEL1 LISTREEL2",
    doc: "VRAI when LISTENTI1 (p values) equals values n·p+1 … (n+1)·p of LISTENTI2 for some n; when the real is in the list (within 1e-8 of the smallest gap between consecutive values); when the point is a node of the mesh; 'SEQU': when LISTREEL1 appears as consecutive values of LISTREEL2; 'QUEL': when every value of LISTREEL1 is in LISTREEL2.",
    example: "b = dans (prog 0. 0.5 1.) 0.5 ; c = dans (lect 3 4) (lect 1 2 3 4) ;",
    f: dans,
}];

fn dans(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let found = if let Some(w) = a.keyword(&["SEQU", "QUEL"]) {
        let l1 = a.req::<Rc<Vec<f64>>>()?;
        let l2 = a.req::<Rc<Vec<f64>>>()?;
        let tol = tolerance(&l2);
        let near = |x: f64, y: f64| (x - y).abs() <= tol;
        if w == "QUEL" {
            l1.iter().all(|x| l2.iter().any(|y| near(*x, *y)))
        } else {
            l1.is_empty() || l2.windows(l1.len()).any(|win| win.iter().zip(l1.iter()).all(|(y, x)| near(*x, *y)))
        }
    } else if let Some(l1) = a.opt::<Rc<Vec<i64>>>() {
        let l2 = a.req::<Rc<Vec<i64>>>()?;
        !l1.is_empty() && l2.len() % l1.len() == 0 && l2.chunks(l1.len()).any(|c| c == l1.as_slice())
    } else if let Some(l) = a.opt::<Rc<Vec<f64>>>() {
        let x = a.req::<f64>()?;
        let tol = tolerance(&l);
        l.iter().any(|y| (x - y).abs() <= tol)
    } else {
        let p = a.req::<PointId>()?;
        let m = a.req::<Rc<Mesh>>()?;
        m.node_list().contains(&p.0)
    };
    Ok(vec![Value::Bool(found)])
}

/// 1e-8 times the smallest gap between consecutive values (1e-8 times the
/// largest magnitude when there is no nonzero gap).
fn tolerance(l: &[f64]) -> f64 {
    let gap = l.windows(2).map(|w| (w[1] - w[0]).abs()).filter(|g| *g > 0.0).fold(f64::INFINITY, f64::min);
    if gap.is_finite() {
        1e-8 * gap
    } else {
        1e-8 * l.iter().fold(0.0f64, |m, v| m.max(v.abs()))
    }
}
