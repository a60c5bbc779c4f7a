//! ORIE: give a mesh one orientation.
//!
//! * Lines: every element runs the same way as its neighbours, each
//!   connected piece following its first element, and the elements of a
//!   part are put in order along their chain, head to tail (POIN 'FINAL'
//!   and the line operators read a line in element order).
//! * Surfaces in the plane (OPTI DIME 2): every element counter-clockwise
//!   (normal along +z), the convention of the plane elements.
//! * Surfaces in space: neighbours across an edge run that edge in
//!   opposite directions (one normal side), each connected piece following
//!   its first element.
//! * Volumes: every element with a positive volume.
//!
//! Surface and volume elements keep their place and their first node; a
//! line element is run backwards. The mesh keeps its nodes: no node is
//! created.

use super::symmetry::turn_over;
use super::vec3::{cross, dot, sub, V3};
use super::{check_nodes, MeshError};
use crate::fem::mesh::{ElemType, Mesh, Nodes, Part};
use std::collections::{HashMap, VecDeque};

/// The corner nodes of an element, in order around it (for a line, its
/// two ends).
pub(super) fn corners(ty: ElemType) -> &'static [usize] {
    match ty {
        ElemType::Poi1 => &[0],
        ElemType::Seg2 => &[0, 1],
        ElemType::Seg3 => &[0, 2],
        ElemType::Tri3 => &[0, 1, 2],
        ElemType::Tri6 => &[0, 2, 4],
        ElemType::Qua4 => &[0, 1, 2, 3],
        ElemType::Qua8 => &[0, 2, 4, 6],
        ElemType::Cub8 => &[0, 1, 3, 4],
        ElemType::Tet4 => &[0, 1, 2, 3],
        ElemType::Pri6 => &[0, 1, 2, 3],
        ElemType::Pyr5 => &[0, 1, 3, 4],
        // Quadratic volumes: the first corner, its two neighbours in the
        // base and the corner above it (enough for the volume's sign).
        ElemType::Cu20 => &[0, 2, 6, 12],
        ElemType::Pr15 => &[0, 2, 4, 9],
        ElemType::Rac2 => &[0, 1],
        ElemType::Rac3 => &[0, 2],
        ElemType::Lia3 => &[0, 1, 2],
        ElemType::Lia4 => &[0, 1, 2, 3],
        ElemType::Mult3 | ElemType::Mult4 | ElemType::Mult5 => &[0],
    }
}

/// Node order that turns an element the other way.
pub(super) fn flip_perm(ty: ElemType) -> &'static [usize] {
    match ty {
        ElemType::Seg2 => &[1, 0],
        ElemType::Seg3 => &[2, 1, 0],
        t => turn_over(t),
    }
}

/// Where two elements meet and how each runs through it: a line's ends
/// (the end node +1, the start node -1) or a surface's edges (+1 when
/// run from the lower node number to the higher). Two neighbours agree
/// when they run through the meeting place with opposite signs.
/// A meeting place: a node (as `(n, n)`) or an edge `(low, high)`.
type Key = (usize, usize);

pub(super) fn connectors(ty: ElemType, e: &[usize]) -> Vec<(Key, i8)> {
    let c: Vec<usize> = corners(ty).iter().map(|&k| e[k]).collect();
    match ty.dim() {
        1 => vec![((c[1], c[1]), 1), ((c[0], c[0]), -1)],
        2 => (0..c.len())
            .map(|i| {
                let (a, b) = (c[i], c[(i + 1) % c.len()]);
                ((a.min(b), a.max(b)), if a < b { 1 } else { -1 })
            })
            .collect(),
        _ => vec![],
    }
}

/// Which elements of `parts` (a flat list over the parts of dimension
/// `dim`) must be turned so that neighbours agree.
fn propagate(parts: &[&Part]) -> Vec<Vec<bool>> {
    let mut at: HashMap<Key, Vec<(usize, usize, i8)>> = HashMap::new();
    for (pi, p) in parts.iter().enumerate() {
        for (ei, e) in p.elems().enumerate() {
            for (key, s) in connectors(p.ty, e) {
                at.entry(key).or_default().push((pi, ei, s));
            }
        }
    }
    let mut flip: Vec<Vec<bool>> = parts.iter().map(|p| vec![false; p.len()]).collect();
    let mut seen: Vec<Vec<bool>> = flip.clone();
    for (pi, p) in parts.iter().enumerate() {
        for ei in 0..p.len() {
            if seen[pi][ei] {
                continue;
            }
            seen[pi][ei] = true;
            let mut queue = VecDeque::from([(pi, ei)]);
            while let Some((qp, qe)) = queue.pop_front() {
                let sign = if flip[qp][qe] { -1 } else { 1 };
                for (key, s) in connectors(parts[qp].ty, parts[qp].elem(qe)) {
                    for &(op, oe, os) in &at[&key] {
                        if !seen[op][oe] {
                            seen[op][oe] = true;
                            flip[op][oe] = os == s * sign;
                            queue.push_back((op, oe));
                        }
                    }
                }
            }
        }
    }
    flip
}

/// Twice the signed area in the plane (z ignored) of the corner polygon.
fn signed_area(x: &[V3]) -> f64 {
    (0..x.len()).map(|i| x[i][0] * x[(i + 1) % x.len()][1] - x[(i + 1) % x.len()][0] * x[i][1]).sum()
}

/// The sign of the volume: the triple product of the edges from the
/// first corner (for CUB8, along the first three edges of a corner).
fn signed_volume(x: &[V3]) -> f64 {
    dot(sub(x[1], x[0]), cross(sub(x[2], x[0]), sub(x[3], x[0])))
}

/// `ORIE GEO` in a space of dimension `space_dim` (see the module doc).
pub fn orie(nodes: &Nodes, mesh: &Mesh, space_dim: usize) -> Result<Mesh, MeshError> {
    check_nodes("ORIE", nodes, mesh)?;
    let coords = |ty: ElemType, e: &[usize]| -> Vec<V3> { corners(ty).iter().map(|&k| nodes.get(e[k])).collect() };
    let mut flips: Vec<Vec<bool>> = mesh.parts.iter().map(|p| vec![false; p.len()]).collect();
    for dim in [1, 2] {
        if dim == 2 && space_dim < 3 {
            continue;
        }
        let idx: Vec<usize> = (0..mesh.parts.len()).filter(|&i| mesh.parts[i].ty.dim() == dim).collect();
        let parts: Vec<&Part> = idx.iter().map(|&i| &mesh.parts[i]).collect();
        for (k, f) in idx.iter().zip(propagate(&parts)) {
            flips[*k] = f;
        }
    }
    for (p, f) in mesh.parts.iter().zip(flips.iter_mut()) {
        match p.ty.dim() {
            2 if space_dim < 3 => {
                for (e, fe) in p.elems().zip(f.iter_mut()) {
                    *fe = signed_area(&coords(p.ty, e)) < 0.0;
                }
            }
            3 => {
                for (e, fe) in p.elems().zip(f.iter_mut()) {
                    *fe = signed_volume(&coords(p.ty, e)) < 0.0;
                }
            }
            _ => {}
        }
    }
    let parts = mesh
        .parts
        .iter()
        .zip(&flips)
        .map(|(p, f)| {
            let perm = flip_perm(p.ty);
            let conn = p
                .elems()
                .zip(f)
                .flat_map(|(e, &fl)| {
                    let v: Vec<usize> = if fl { perm.iter().map(|&k| e[k]).collect() } else { e.to_vec() };
                    v
                })
                .collect();
            let part = Part { ty: p.ty, conn, colour: p.colour };
            if p.ty.dim() == 1 {
                chain_order(&part)
            } else {
                part
            }
        })
        .collect();
    Ok(Mesh { parts })
}

/// The elements of an oriented line part in order along their chains:
/// each chain from its head (an element that no other one leads to; for a
/// closed loop, its first element), pieces in order of their first
/// element. At a branch the first element in mesh order is followed and
/// the others start chains of their own.
fn chain_order(p: &Part) -> Part {
    let n = p.len();
    let last = p.ty.nodes() - 1;
    let (start, end) = (|e: &[usize]| e[0], move |e: &[usize]| e[last]);
    let mut from: HashMap<usize, Vec<usize>> = HashMap::new();
    let mut ends: HashMap<usize, usize> = HashMap::new();
    for (i, e) in p.elems().enumerate() {
        from.entry(start(e)).or_default().push(i);
        *ends.entry(end(e)).or_default() += 1;
    }
    let mut used = vec![false; n];
    let mut order = Vec::with_capacity(n);
    let heads = (0..n).filter(|&i| !ends.contains_key(&start(p.elem(i))));
    // Chains from their heads first, then what is left (closed loops).
    for h in heads.chain(0..n).collect::<Vec<_>>() {
        let mut cur = h;
        while !used[cur] {
            used[cur] = true;
            order.push(cur);
            match from.get(&end(p.elem(cur))).and_then(|v| v.iter().find(|&&j| !used[j])) {
                Some(&j) => cur = j,
                None => break,
            }
        }
    }
    let conn = order.iter().flat_map(|&i| p.elem(i).iter().copied()).collect();
    Part { ty: p.ty, conn, colour: p.colour }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn nodes(xs: &[V3]) -> Nodes {
        let mut n = Nodes::default();
        for x in xs {
            n.push(*x, 1.0);
        }
        n
    }

    #[test]
    fn a_line_runs_head_to_tail() {
        let n = nodes(&[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0], [3.0, 0.0, 0.0]]);
        let m = Mesh::single(Part::with(ElemType::Seg2, vec![0, 1, 2, 1, 2, 3]));
        assert_eq!(orie(&n, &m, 2).unwrap().parts[0].conn, vec![0, 1, 1, 2, 2, 3]);
        // Pieces that run towards each other: the second is turned and put
        // in order after the first.
        let m = Mesh::single(Part::with(ElemType::Seg2, vec![0, 1, 3, 2, 2, 1]));
        assert_eq!(orie(&n, &m, 2).unwrap().parts[0].conn, vec![0, 1, 1, 2, 2, 3]);
    }

    #[test]
    fn surfaces_in_space_agree_across_edges() {
        let n = nodes(&[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0], [2.0, 0.0, 0.0]]);
        // Second triangle 1-4-2 turned the other way as 1-2-4.
        let m = Mesh::single(Part::with(ElemType::Tri3, vec![0, 1, 2, 0, 2, 3, 1, 2, 4]));
        let o = orie(&n, &m, 3).unwrap();
        assert_eq!(o.parts[0].conn, vec![0, 1, 2, 0, 2, 3, 1, 4, 2]);
    }

    #[test]
    fn plane_surfaces_turn_counter_clockwise_and_volumes_positive() {
        let n = nodes(&[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);
        let t = Mesh::single(Part::with(ElemType::Tri3, vec![0, 2, 1]));
        assert_eq!(orie(&n, &t, 2).unwrap().parts[0].conn, vec![0, 1, 2]);
        let v = Mesh::single(Part::with(ElemType::Tet4, vec![0, 2, 1, 3]));
        assert_eq!(orie(&n, &v, 3).unwrap().parts[0].conn, vec![0, 1, 2, 3]);
    }
}
