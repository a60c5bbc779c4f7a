//! PVEC (pvec.notice): the product of n-1 vectors of an n-dimensional
//! space, the vector orthogonal to them all. In 2D it is one vector turned
//! a quarter turn anticlockwise, (x, y) -> (-y, x); in 3D the usual cross
//! product. Either of points, or of node fields over listed components.

use super::{Args, PointId};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::{Chpoint, Value};
use std::rc::Rc;

/// r_i = det(v_1, …, v_{n-1}, e_i) for n = 2 or 3.
fn product(dime: usize, v: &[[f64; 3]]) -> [f64; 3] {
    match dime {
        2 => [-v[0][1], v[0][0], 0.0],
        _ => {
            let (x, y) = (v[0], v[1]);
            [x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]]
        }
    }
}

pub(super) fn pvec(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let dime = it.opts.dime;
    if dime < 2 {
        return Err(a.err("the vector product needs OPTI DIME 2 or 3"));
    }
    if a.has_any::<Rc<Chpoint>>() {
        return fields(it, a, dime);
    }
    let mut v = Vec::new();
    for _ in 1..dime {
        let p = a.req::<PointId>()?;
        let x = it.nodes.get(p.0);
        v.push([x[0], x[1], if dime == 3 { x[2] } else { 0.0 }]);
    }
    let w = product(dime, &v);
    let d = it.opts.dens;
    Ok(vec![Value::Point(it.nodes.push(w, d))])
}

/// `PVEC CH1 L1 (CH2 L2 in 3D) L3`: node by node over the nodes of the
/// fields, a component missing at a node reading as 0 (as in the fields'
/// arithmetic); the result's components are named by L3.
fn fields(_: &mut Interp, a: &mut Args, dime: usize) -> Result<Vec<Value>> {
    let mut operands = Vec::new();
    for _ in 1..dime {
        let c = a.req::<Rc<Chpoint>>()?;
        let l = comps(a, dime, "of the field")?;
        if let Some(k) = l.iter().find(|k| !c.components().contains(k)) {
            return Err(a.err(format!("the field has no component {} (it has {})", k, c.components().join(" "))));
        }
        operands.push((c, l));
    }
    let out_names = comps(a, dime, "of the result")?;
    let mut nodes: Vec<usize> = Vec::new();
    let mut seen = std::collections::HashSet::new();
    for (c, _) in &operands {
        nodes.extend(c.nodes.iter().copied().filter(|n| seen.insert(*n)));
    }
    let mut out = Chpoint::new(operands[0].0.nature);
    for n in nodes {
        let v: Vec<[f64; 3]> = operands
            .iter()
            .map(|(c, l)| {
                let mut x = [0.0; 3];
                for (i, k) in l.iter().enumerate() {
                    x[i] = c.get(n, k).unwrap_or(0.0);
                }
                x
            })
            .collect();
        let w = product(dime, &v);
        for (i, k) in out_names.iter().enumerate() {
            out.add(n, k, w[i], false);
        }
    }
    Ok(vec![Value::Chpo(Rc::new(out))])
}

/// A LISTMOTS of exactly `dime` components.
fn comps(a: &mut Args, dime: usize, what: &str) -> Result<Vec<String>> {
    let l = a.req::<Rc<Vec<String>>>()?;
    if l.len() != dime {
        return Err(a.err(format!(
            "the components {} are {} words: {} are needed in dimension {}",
            what,
            l.len(),
            dime,
            dime
        )));
    }
    Ok(l.iter().map(|s| s.trim().to_uppercase()).collect())
}
