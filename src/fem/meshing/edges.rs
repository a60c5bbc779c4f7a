//! ARETE: the sharp edges of a mesh in space, as SEG2; and every edge of
//! a mesh (`CHAN 'LIGNE'`).

use super::vec3::{add, cross, dot, norm, V3};
use super::{check_nodes, fail, mesh_of, MeshError};
use crate::fem::mesh::{ElemType, Mesh, Nodes, Part};
use crate::fem::shape::faces;
use std::collections::HashMap;

/// `ARET GEO (angle)`: the facets are the surface elements of `mesh`, or
/// the faces of its volume elements that belong to one element only (its
/// skin). An edge is kept when it borders one facet only, more than two,
/// or two whose normals differ by more than `angle_deg` (20° by default
/// in Cast3M). Edges come as SEG2, in the order the facets first use them,
/// run as in their first facet.
pub fn aret(nodes: &Nodes, mesh: &Mesh, angle_deg: f64) -> Result<Mesh, MeshError> {
    check_nodes("ARET", nodes, mesh)?;
    if !angle_deg.is_finite() {
        return fail("ARET", "the angle is not a finite number");
    }
    // Facets as corner lists (quadratic faces by their corners).
    let mut facets: Vec<Vec<usize>> = Vec::new();
    for p in mesh.parts.iter().filter(|p| p.ty.dim() == 2) {
        facets.extend(p.elems().map(|e| corners(p.ty, e)));
    }
    let volumes = mesh.parts.iter().filter(|p| p.ty.dim() == 3);
    facets.extend(boundary_faces(volumes).into_iter().map(|(fty, f)| corners(fty, &f)));
    if facets.is_empty() {
        return fail("ARET", "the mesh has no surface or volume elements");
    }
    let normal = |c: &[usize]| -> V3 {
        let x: Vec<V3> = c.iter().map(|&n| nodes.get(n)).collect();
        let mut s = [0.0; 3];
        for i in 0..x.len() {
            s = add(s, cross(x[i], x[(i + 1) % x.len()]));
        }
        s
    };
    let mut order: Vec<(usize, usize)> = Vec::new();
    let mut by_edge: HashMap<(usize, usize), Vec<usize>> = HashMap::new();
    for (f, c) in facets.iter().enumerate() {
        for i in 0..c.len() {
            let (a, b) = (c[i], c[(i + 1) % c.len()]);
            let key = (a.min(b), a.max(b));
            let list = by_edge.entry(key).or_default();
            if list.is_empty() {
                order.push((a, b));
            }
            list.push(f);
        }
    }
    let cos_lim = angle_deg.to_radians().cos();
    let mut conn = Vec::new();
    for (a, b) in order {
        let fs = &by_edge[&(a.min(b), a.max(b))];
        let sharp = match fs.as_slice() {
            [f1, f2] => {
                let (n1, n2) = (normal(&facets[*f1]), normal(&facets[*f2]));
                let l = norm(n1) * norm(n2);
                // Facets that share an edge run it in opposite directions
                // when they turn the same way; if not, turn one over.
                let consistent =
                    facets[*f1].iter().zip(facets[*f1].iter().cycle().skip(1)).any(|(&x, &y)| x == a && y == b)
                        != facets[*f2].iter().zip(facets[*f2].iter().cycle().skip(1)).any(|(&x, &y)| x == a && y == b);
                let c = if l > 0.0 { dot(n1, n2) / l } else { 1.0 };
                let c = if consistent { c } else { -c };
                c < cos_lim
            }
            _ => true,
        };
        if sharp {
            conn.extend([a, b]);
        }
    }
    Ok(mesh_of(vec![(ElemType::Seg2, conn)]))
}

fn corners(ty: ElemType, e: &[usize]) -> Vec<usize> {
    match ty {
        ElemType::Tri6 => vec![e[0], e[2], e[4]],
        ElemType::Qua8 => vec![e[0], e[2], e[4], e[6]],
        ElemType::Cu20 => [0, 2, 4, 6, 12, 14, 16, 18].iter().map(|&k| e[k]).collect(),
        ElemType::Pr15 => [0, 2, 4, 9, 11, 13].iter().map(|&k| e[k]).collect(),
        _ => e.to_vec(),
    }
}

/// `CHAN 'LIGNE' GEO`: every edge of the elements of `mesh` once, as SEG2
/// (SEG3 for quadratic edges), run as in the first element that has it;
/// lines are kept, points dropped.
pub fn all_edges(mesh: &Mesh) -> Mesh {
    let mut seen = std::collections::HashSet::new();
    let mut parts: Vec<(ElemType, Vec<usize>)> = Vec::new();
    for p in &mesh.parts {
        let edges: Vec<(ElemType, Vec<usize>)> = match p.ty.dim() {
            0 => continue,
            1 => vec![(p.ty, (0..p.ty.nodes()).collect())],
            2 => faces(p.ty),
            _ => {
                // The edges of the faces.
                let mut v = Vec::new();
                for (fty, floc) in faces(p.ty) {
                    for (ety, eloc) in faces(fty) {
                        v.push((ety, eloc.iter().map(|&k| floc[k]).collect()));
                    }
                }
                v
            }
        };
        for e in p.elems() {
            for (ety, loc) in &edges {
                let nodes: Vec<usize> = loc.iter().map(|&k| e[k]).collect();
                let (a, b) = (nodes[0], nodes[nodes.len() - 1]);
                if seen.insert((a.min(b), a.max(b))) {
                    match parts.iter_mut().find(|(t, _)| t == ety) {
                        Some((_, c)) => c.extend(nodes),
                        None => parts.push((*ety, nodes)),
                    }
                }
            }
        }
    }
    mesh_of(parts)
}

/// The faces of `parts`' elements that no other element shares (the same
/// node set), in element order, each as its element orients it
/// (`shape::faces`): the skin of volumes, the boundary edges of surfaces.
/// ENVE, ARET and PRES on a field all start from it.
pub fn boundary_faces<'a>(parts: impl IntoIterator<Item = &'a Part>) -> Vec<(ElemType, Vec<usize>)> {
    let mut count: HashMap<Vec<usize>, usize> = HashMap::new();
    let mut all: Vec<(ElemType, Vec<usize>)> = Vec::new();
    for part in parts {
        for e in part.elems() {
            for (fty, loc) in faces(part.ty) {
                let f: Vec<usize> = loc.iter().map(|&k| e[k]).collect();
                let mut key = f.clone();
                key.sort_unstable();
                *count.entry(key).or_default() += 1;
                all.push((fty, f));
            }
        }
    }
    all.retain(|(_, f)| {
        let mut key = f.clone();
        key.sort_unstable();
        count[&key] == 1
    });
    all
}
