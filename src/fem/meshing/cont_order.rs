//! The order of the loops of a contour: a loop that encloses others comes
//! before them, so that the outer boundary of a surface with holes is the
//! first loop of its CONT (and the first component CCON finds), whichever
//! element the mesher numbered first. Loops that do not enclose one
//! another keep their order.

use crate::fem::mesh::{Mesh, Nodes, Part};

/// `cont` (SEG2 or SEG3 loops, each a chain of elements in order) with
/// enclosing loops first. A mesh of several element types is returned as
/// it is.
pub fn outer_first(cont: &Mesh, nodes: &Nodes) -> Mesh {
    let parts: Vec<&Part> = cont.parts.iter().filter(|p| !p.is_empty()).collect();
    let [part] = parts.as_slice() else {
        return cont.clone();
    };
    let elems: Vec<&[usize]> = part.elems().collect();
    // A loop starts where an element does not begin at the previous end.
    let mut chains: Vec<Vec<usize>> = Vec::new();
    for (i, e) in elems.iter().enumerate() {
        match chains.last_mut() {
            Some(c) if elems[c[c.len() - 1]].last() == e.first() => c.push(i),
            _ => chains.push(vec![i]),
        }
    }
    if chains.len() < 2 {
        return cont.clone();
    }
    let boxes: Vec<[[f64; 3]; 2]> = chains
        .iter()
        .map(|c| {
            let mut b = [[f64::INFINITY; 3], [f64::NEG_INFINITY; 3]];
            for &i in c {
                for &n in elems[i] {
                    let x = nodes.get(n);
                    for (k, &xk) in x.iter().enumerate() {
                        b[0][k] = b[0][k].min(xk);
                        b[1][k] = b[1][k].max(xk);
                    }
                }
            }
            b
        })
        .collect();
    let diag = |b: &[[f64; 3]; 2]| (0..3).map(|k| (b[1][k] - b[0][k]).powi(2)).sum::<f64>().sqrt();
    let tol = 1e-9 * boxes.iter().map(diag).fold(0.0, f64::max);
    // `j` encloses `i`: its box holds i's and is larger (so that two
    // loops never enclose each other).
    let encloses = |j: usize, i: usize| {
        (0..3).all(|k| boxes[j][0][k] <= boxes[i][0][k] + tol && boxes[j][1][k] >= boxes[i][1][k] - tol)
            && diag(&boxes[j]) > diag(&boxes[i]) + tol
    };
    let mut order = Vec::with_capacity(chains.len());
    let mut done = vec![false; chains.len()];
    for i in 0..chains.len() {
        // The loops around i, outermost first, then i itself.
        let mut around: Vec<usize> = (0..chains.len()).filter(|&j| !done[j] && encloses(j, i)).collect();
        around.sort_by(|&a, &b| diag(&boxes[b]).total_cmp(&diag(&boxes[a])));
        for j in around.into_iter().chain(std::iter::once(i)) {
            if !done[j] {
                done[j] = true;
                order.push(j);
            }
        }
    }
    if order.iter().enumerate().all(|(k, &j)| k == j) {
        return cont.clone();
    }
    let conn: Vec<usize> =
        order.iter().flat_map(|&c| chains[c].iter().flat_map(|&i| elems[i].iter().copied())).collect();
    let mut out = cont.clone();
    if let Some(slot) = out.parts.iter_mut().find(|p| !p.is_empty()) {
        slot.conn = conn;
    }
    out
}
