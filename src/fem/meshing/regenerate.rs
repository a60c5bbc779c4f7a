//! REGENERER: elements whose nodes were merged (ELIM after a ROTA that
//! touches its axis, a DALL with a side of length zero…) become the
//! element of lower order they now are: SEG2 → POI1, TRI3 → SEG2,
//! QUA4 → TRI3, QUA8 → TRI6, CUB8 → PRI6. Other elements, and degenerate
//! shapes that have no such counterpart, are kept as they are.

use super::vec3::{cross, dot, sub};
use super::{check_nodes, mesh_of, MeshError};
use crate::fem::mesh::{ElemType, Mesh, Nodes};

/// `REGE GEO`: element order and part order are kept; each regenerated
/// element joins the part of its new type.
pub fn rege(nodes: &Nodes, mesh: &Mesh) -> Result<Mesh, MeshError> {
    check_nodes("REGE", nodes, mesh)?;
    let mut out: Vec<(ElemType, Vec<usize>)> = Vec::new();
    let mut push = |ty: ElemType, e: &[usize]| match out.iter_mut().rev().find(|(t, _)| *t == ty) {
        Some((_, c)) => c.extend_from_slice(e),
        None => out.push((ty, e.to_vec())),
    };
    for p in &mesh.parts {
        for e in p.elems() {
            let (ty, new) = regenerate(nodes, p.ty, e);
            push(ty, &new);
        }
    }
    Ok(mesh_of(out))
}

/// The element `e` of type `ty` with its repeated nodes removed.
fn regenerate(nodes: &Nodes, ty: ElemType, e: &[usize]) -> (ElemType, Vec<usize>) {
    let same = (ty, e.to_vec());
    match ty {
        ElemType::Seg2 if e[0] == e[1] => (ElemType::Poi1, vec![e[0]]),
        ElemType::Tri3 | ElemType::Qua4 => {
            // Corners in cyclic order, a corner equal to the next dropped.
            let n = e.len();
            let kept: Vec<usize> = (0..n).filter(|&i| e[i] != e[(i + 1) % n]).map(|i| e[i]).collect();
            match (ty, kept.len()) {
                (ElemType::Qua4, 3) => (ElemType::Tri3, kept),
                (_, 2) => (ElemType::Seg2, kept),
                _ => same,
            }
        }
        ElemType::Qua8 => {
            // One side collapsed (corner k = corner k + 1): the triangle of
            // the other three sides, with their middle nodes.
            let c = |k: usize| e[(2 * k) % 8];
            let collapsed: Vec<usize> = (0..4).filter(|&k| c(k) == c(k + 1)).collect();
            if collapsed.len() != 1 {
                return same;
            }
            let k = collapsed[0] + 1;
            let t: Vec<usize> = (0..6).map(|i| e[(2 * k + i) % 8]).collect();
            (ElemType::Tri6, t)
        }
        ElemType::Cub8 => cub8_to_pri6(nodes, e).map_or(same, |t| (ElemType::Pri6, t)),
        _ => same,
    }
}

/// A CUB8 with one face crushed to an edge (two parallel edges of length
/// zero) is a prism: its two triangular faces are the opposite faces that
/// lost one node each, matched node to node along the hexahedron's edges.
fn cub8_to_pri6(nodes: &Nodes, e: &[usize]) -> Option<Vec<usize>> {
    // Opposite faces, node k of the first facing node k of the second.
    const PAIRS: [([usize; 4], [usize; 4]); 3] =
        [([0, 1, 2, 3], [4, 5, 6, 7]), ([0, 1, 5, 4], [3, 2, 6, 7]), ([0, 3, 7, 4], [1, 2, 6, 5])];
    let mut distinct = e.to_vec();
    distinct.sort_unstable();
    distinct.dedup();
    if distinct.len() != 6 {
        return None;
    }
    for (f1, f2) in PAIRS {
        let tri = |f: [usize; 4]| -> Vec<usize> { (0..4).filter(|&i| e[f[i]] != e[f[(i + 1) % 4]]).collect() };
        let (t1, t2) = (tri(f1), tri(f2));
        if t1.len() == 3 && t1 == t2 {
            let mut a: Vec<usize> = t1.iter().map(|&i| e[f1[i]]).collect();
            let mut b: Vec<usize> = t1.iter().map(|&i| e[f2[i]]).collect();
            // Positive volume: the first triangle's normal points away
            // from the second.
            let x = |n: usize| nodes.get(n);
            let nrm = cross(sub(x(a[1]), x(a[0])), sub(x(a[2]), x(a[0])));
            if dot(nrm, sub(x(b[0]), x(a[0]))) < 0.0 {
                a.swap(1, 2);
                b.swap(1, 2);
            }
            a.extend(b);
            return Some(a);
        }
    }
    None
}
