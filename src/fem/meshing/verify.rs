//! Mesh checks of VERM: an element repeated in one part, linear elements
//! joined to quadratic ones, and volumes whose common face is a triangle
//! on one side and a quadrangle on the other. Each finding is given by
//! (part, element) numbers from 0; nothing is changed.

use crate::fem::mesh::{ElemType, Mesh};
use crate::fem::shape::faces;
use std::collections::{HashMap, HashSet};

/// What VERM found, element numbers within their part.
#[derive(Debug, Default, Clone, PartialEq)]
pub struct Findings {
    /// (part, element, element it repeats).
    pub repeated: Vec<(usize, usize, usize)>,
    /// (part, element) of linear elements sharing an edge with a quadratic one.
    pub mixed_degree: Vec<(usize, usize)>,
    /// (part, element) of volumes with a triangular face lying on a
    /// quadrangular face of another volume.
    pub face_mismatch: Vec<(usize, usize)>,
}

fn quadratic(ty: ElemType) -> bool {
    matches!(ty, ElemType::Seg3 | ElemType::Tri6 | ElemType::Qua8 | ElemType::Cu20 | ElemType::Pr15)
}

/// Sorted distinct nodes of an element.
fn key(nodes: &[usize]) -> Vec<usize> {
    let mut k = nodes.to_vec();
    k.sort_unstable();
    k.dedup();
    k
}

pub fn verify(mesh: &Mesh) -> Findings {
    let mut out = Findings::default();
    for (ip, p) in mesh.parts.iter().enumerate() {
        let mut seen: HashMap<Vec<usize>, usize> = HashMap::new();
        for (e, nodes) in p.elems().enumerate() {
            if let Some(first) = seen.insert(key(nodes), e) {
                out.repeated.push((ip, e, first));
                seen.insert(key(nodes), first);
            }
        }
    }
    // Nodes of quadratic surface and volume elements, to find the linear
    // elements that touch them along an edge (two nodes or more).
    let mut quad_elems: HashMap<usize, Vec<(usize, usize)>> = HashMap::new();
    for (ip, p) in mesh.parts.iter().enumerate().filter(|(_, p)| quadratic(p.ty) && p.ty.dim() >= 2) {
        for (e, nodes) in p.elems().enumerate() {
            for n in key(nodes) {
                quad_elems.entry(n).or_default().push((ip, e));
            }
        }
    }
    for (ip, p) in mesh.parts.iter().enumerate().filter(|(_, p)| !quadratic(p.ty) && p.ty.dim() >= 2) {
        for (e, nodes) in p.elems().enumerate() {
            let mut count: HashMap<(usize, usize), usize> = HashMap::new();
            for n in key(nodes) {
                for q in quad_elems.get(&n).into_iter().flatten() {
                    *count.entry(*q).or_default() += 1;
                }
            }
            if count.values().any(|c| *c >= 2) {
                out.mixed_degree.push((ip, e));
            }
        }
    }
    // Corner sets of the volumes' faces: three distinct corners make a
    // triangle (a degenerate quadrangle too), four a quadrangle.
    let corners = |ty: ElemType, nodes: &[usize], local: &[usize]| -> Vec<usize> {
        let step = if quadratic(ty) { 2 } else { 1 };
        key(&local.iter().step_by(step).map(|&l| nodes[l]).collect::<Vec<_>>())
    };
    let mut quad_triples: HashSet<Vec<usize>> = HashSet::new();
    let volumes = || mesh.parts.iter().enumerate().filter(|(_, p)| p.ty.dim() == 3);
    for (_, p) in volumes() {
        for nodes in p.elems() {
            for (_, local) in faces(p.ty) {
                let c = corners(p.ty, nodes, &local);
                if c.len() == 4 {
                    for skip in 0..4 {
                        quad_triples
                            .insert(c.iter().enumerate().filter(|(i, _)| *i != skip).map(|(_, n)| *n).collect());
                    }
                }
            }
        }
    }
    for (ip, p) in volumes() {
        for (e, nodes) in p.elems().enumerate() {
            if faces(p.ty).iter().any(|(_, local)| {
                let c = corners(p.ty, nodes, local);
                c.len() == 3 && quad_triples.contains(&c)
            }) {
                out.face_mismatch.push((ip, e));
            }
        }
    }
    out
}
