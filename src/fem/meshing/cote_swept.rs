//! COTE of a surface swept from a line whose boundary has no four
//! corners (a closed line, or several lines, moved by TRAN or ROTA).
//!
//! The sweeps list their elements layer after layer, each layer in the
//! order of the line's elements, and a QUA4 `(a, b, b', a')` has its edge
//! 0-1 on the lower layer and 2-3 on the upper one (see `sweep`); under
//! `OPTI ELEM TRI3` each QUA4 is the pair `(a, b, b')`, `(a, b', a')`.
//! The layer size is the number of leading elements whose edge 0-1 is on
//! the boundary; element `k` of a layer must sit on element `k` of the
//! layer below. Side 1 is the lower edges of the first layer in order,
//! side 3 the upper edges of the last layer in reverse order (contour
//! direction), side 2 the edges 1-2 of each layer's last element going up
//! and side 4 the edges 3-0 of each layer's first element going down; a
//! side whose edges are not all on the boundary does not exist.

use super::mesh_of;
use crate::fem::mesh::{ElemType, Mesh};
use std::collections::HashMap;

/// Side `n` (1 to 4), or `None` when the surface is not such a sweep.
pub(crate) fn side(mesh: &Mesh, n: i64) -> Option<Mesh> {
    let parts: Vec<_> = mesh.parts.iter().filter(|p| !p.is_empty()).collect();
    let quads: Vec<[usize; 4]> = match parts.as_slice() {
        [p] if p.ty == ElemType::Qua4 => p.elems().map(|e| [e[0], e[1], e[2], e[3]]).collect(),
        [p] if p.ty == ElemType::Tri3 && p.len().is_multiple_of(2) => {
            let t: Vec<&[usize]> = p.elems().collect();
            let mut q = Vec::with_capacity(t.len() / 2);
            for pair in t.chunks(2) {
                let (x, y) = (pair[0], pair[1]);
                if x[0] != y[0] || x[2] != y[1] {
                    return None;
                }
                q.push([x[0], x[1], x[2], y[2]]);
            }
            q
        }
        _ => return None,
    };
    let key = |a: usize, b: usize| (a.min(b), a.max(b));
    let mut uses: HashMap<(usize, usize), usize> = HashMap::new();
    for q in &quads {
        for k in 0..4 {
            *uses.entry(key(q[k], q[(k + 1) % 4])).or_default() += 1;
        }
    }
    let on_boundary = |a: usize, b: usize| uses.get(&key(a, b)) == Some(&1);
    let width = quads.iter().take_while(|q| on_boundary(q[0], q[1])).count();
    if width == 0 || !quads.len().is_multiple_of(width) {
        return None;
    }
    if (width..quads.len()).any(|k| quads[k][0] != quads[k - width][3] || quads[k][1] != quads[k - width][2]) {
        return None;
    }
    let layers = quads.len() / width;
    let edges: Vec<[usize; 2]> = match n {
        1 => quads[..width].iter().map(|q| [q[0], q[1]]).collect(),
        2 => (0..layers).map(|l| quads[l * width + width - 1]).map(|q| [q[1], q[2]]).collect(),
        3 => quads[quads.len() - width..].iter().rev().map(|q| [q[2], q[3]]).collect(),
        4 => (0..layers).rev().map(|l| quads[l * width]).map(|q| [q[3], q[0]]).collect(),
        _ => return None,
    };
    if edges.iter().any(|&[a, b]| !on_boundary(a, b)) {
        return None;
    }
    Some(mesh_of(vec![(ElemType::Seg2, edges.concat())]))
}
