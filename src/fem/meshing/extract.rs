//! Extraction: ELEM (by type, by number, by support), CONT (boundary),
//! COTE (side n of a DALL/TRAN surface) and FACE (face n of a volume made
//! by VOLU, TRAN or ROTA).

use super::{fail, mesh_of, MeshError};
use crate::fem::mesh::{ElemType, Mesh, Part};
use crate::fem::shape;
use std::collections::{HashMap, HashSet};

/// Local edges of a surface element, each as `(end, end)` or
/// `(end, middle, end)`, turning like the element.
pub(crate) fn edges(ty: ElemType) -> &'static [&'static [usize]] {
    match ty {
        ElemType::Tri3 => &[&[0, 1], &[1, 2], &[2, 0]],
        ElemType::Qua4 => &[&[0, 1], &[1, 2], &[2, 3], &[3, 0]],
        ElemType::Tri6 => &[&[0, 1, 2], &[2, 3, 4], &[4, 5, 0]],
        ElemType::Qua8 => &[&[0, 1, 2], &[2, 3, 4], &[4, 5, 6], &[6, 7, 0]],
        _ => &[],
    }
}

/// `GEO ELEM type`: the elements of one type, in their order (an empty
/// mesh if there are none).
pub fn elem_type(mesh: &Mesh, ty: ElemType) -> Mesh {
    let conn = mesh.parts.iter().filter(|p| p.ty == ty).flat_map(|p| p.conn.iter().copied()).collect();
    mesh_of(vec![(ty, conn)])
}

/// `GEO ELEM (type) n` / `GEO ELEM (type) LENTI`: elements by 1-based
/// number, counted among the elements of `ty` when it is given, else over
/// the whole mesh (parts in order). The result lists them in the order
/// asked, a number asked twice giving one element.
pub fn elem_numbers(mesh: &Mesh, ty: Option<ElemType>, numbers: &[i64]) -> Result<Mesh, MeshError> {
    let pool: Vec<(ElemType, &[usize])> = mesh
        .parts
        .iter()
        .filter(|p| ty.is_none_or(|t| t == p.ty))
        .flat_map(|p| p.elems().map(move |e| (p.ty, e)))
        .collect();
    let mut seen = HashSet::new();
    let mut out: Vec<(ElemType, Vec<usize>)> = Vec::new();
    for &k in numbers {
        if k < 1 || k as usize > pool.len() {
            let what = ty.map_or("elements".to_string(), |t| format!("{} elements", t.name()));
            return fail("ELEM", format!("element number {k} is out of range (the mesh has {} {what})", pool.len()));
        }
        if !seen.insert(k) {
            continue;
        }
        let (t, e) = pool[k as usize - 1];
        match out.iter_mut().find(|(u, _)| *u == t) {
            Some((_, c)) => c.extend_from_slice(e),
            None => out.push((t, e.to_vec())),
        }
    }
    Ok(mesh_of(out))
}

/// `GEO ELEM 'APPU' ('STRI'|'LARG') GEO2`: the elements of `mesh` resting
/// on the nodes of `support` — all their nodes (`strict`, 'STRI') or at
/// least one ('LARG') — in their order.
pub fn elem_appui(mesh: &Mesh, support: &Mesh, strict: bool) -> Mesh {
    let on: HashSet<usize> = support.node_list().into_iter().collect();
    let parts = mesh
        .parts
        .iter()
        .map(|p| {
            let keep = |e: &&[usize]| {
                if strict {
                    e.iter().all(|n| on.contains(n))
                } else {
                    e.iter().any(|n| on.contains(n))
                }
            };
            (p.ty, p.elems().filter(keep).flatten().copied().collect())
        })
        .collect();
    mesh_of(parts)
}

/// `CONT GEO`: the boundary.
///
/// * Of a surface: the edges used by exactly one element (mid-side nodes
///   compared too), as SEG2 (SEG3 for quadratic elements), each oriented as
///   in its element, so the contour of a counter-clockwise surface runs
///   counter-clockwise. Edges are chained: the first loop starts with the
///   first boundary edge in element order and each next edge is the unused
///   one (first in element order) starting where the previous ends; when a
///   loop closes, the next starts at the first unused edge.
/// * Of a line: its end points (nodes ending exactly one element), as POI1
///   in order of appearance; empty for a closed line.
pub fn cont(mesh: &Mesh) -> Result<Mesh, MeshError> {
    cont_with(mesh, ContEdges::Exterior, true)
}

/// Which edges of a surface CONT keeps, by the number of elements
/// sharing them (cont.notice): one (`EXTE`), three or more (`INTE`: the
/// junctions of several surfaces), anything but two (`TOUT`).
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum ContEdges {
    Exterior,
    Interior,
    All,
}

impl ContEdges {
    fn keeps(self, uses: usize) -> bool {
        match self {
            ContEdges::Exterior => uses == 1,
            ContEdges::Interior => uses >= 3,
            ContEdges::All => uses != 2,
        }
    }
}

/// CONT with its options: `which` edges of a surface; an empty contour is
/// an error unless `empty_ok` (`'NOID'`).
pub fn cont_with(mesh: &Mesh, which: ContEdges, empty_ok: bool) -> Result<Mesh, MeshError> {
    let out = cont_edges(mesh, which)?;
    // Only a surface without contour is an error: the end points of a
    // closed line are an empty mesh, as before.
    let surface = mesh.parts.iter().any(|p| !p.is_empty() && p.ty.dim() == 2);
    if !empty_ok && surface && out.parts.iter().all(|p| p.is_empty()) {
        return fail("CONT", "the mesh has no contour (add 'NOID' to get an empty mesh)");
    }
    Ok(out)
}

fn cont_edges(mesh: &Mesh, which: ContEdges) -> Result<Mesh, MeshError> {
    let parts: Vec<&Part> = mesh.parts.iter().filter(|p| !p.is_empty()).collect();
    let dim = parts.iter().map(|p| p.ty.dim()).max().unwrap_or(0);
    match dim {
        0 => fail("CONT", "a mesh of points has no contour"),
        3 => fail("CONT", "the contour of a volume is a surface: use ENVE"),
        1 => Ok(line_ends(&parts)),
        _ => {
            let bnd = shared_edges(&parts, which);
            let loops = walk(&bnd);
            let mut out: Vec<(ElemType, Vec<usize>)> = Vec::new();
            for &i in loops.iter().flatten() {
                push_edge(&mut out, &bnd[i]);
            }
            Ok(mesh_of(out))
        }
    }
}

/// `COTE n SURF`: side `n` (1 to 4) of a structured surface. A surface of
/// quadrilaterals is read as a grid from its connectivity (see
/// [`super::grid`]); one of triangles must come from DALL or TRAN:
///
/// The sides are recovered from the structure: the boundary is walked from
/// the first edge of element 1 (the start of side 1 for DALL and TRAN, see
/// their orderings) in the elements' direction, and cut at the four
/// corners, a corner being a boundary node in fewer elements than a side
/// node (1 for quadrilaterals, at most 2 for triangles). Side `n` comes
/// back as SEG2/SEG3 in contour direction, so for DALL it is the n-th side
/// as given.
///
/// A closed line swept by TRAN or ROTA has no corners: its sides 1 and 3
/// are then found from the sweep's layers ([`super::cote_swept`]).
pub fn cote(mesh: &Mesh, n: i64) -> Result<Mesh, MeshError> {
    cote_structured(mesh, n).or_else(|e| super::cote_swept::side(mesh, n).ok_or(e))
}

fn cote_structured(mesh: &Mesh, n: i64) -> Result<Mesh, MeshError> {
    const OP: &str = "COTE";
    if !(1..=4).contains(&n) {
        return fail(OP, format!("the side number must be 1 to 4 (got {n})"));
    }
    let parts: Vec<&Part> = mesh.parts.iter().filter(|p| !p.is_empty()).collect();
    if parts.first().is_some_and(|p| super::grid::is_quad(p.ty)) && parts.iter().all(|q| q.ty == parts[0].ty) {
        let sides = super::grid::grid_sides(&parts)?;
        let mut out = Vec::new();
        for e in &sides[n as usize - 1] {
            push_edge(&mut out, e);
        }
        return Ok(mesh_of(out));
    }
    let p = match parts.as_slice() {
        [p] if p.ty.dim() == 2 => *p,
        _ => return fail(OP, "needs a surface of a single element type, as DALL or TRAN make"),
    };
    let bnd = boundary_edges(&parts);
    let first = p.elem(0);
    let e0 = edges(p.ty)[0];
    let starts_right = bnd.first().is_some_and(|b| b[0] == first[e0[0]] && b[b.len() - 1] == first[e0[e0.len() - 1]]);
    let loops = walk(&bnd);
    if !starts_right || loops.len() != 1 {
        return fail(
            OP,
            "the surface does not have the structure of a DALL or TRAN surface (one boundary starting with element 1)",
        );
    }
    let mut count: HashMap<usize, usize> = HashMap::new();
    for e in p.elems() {
        for &k in edges(p.ty).iter().map(|ed| &ed[0]) {
            *count.entry(e[k]).or_default() += 1;
        }
    }
    let limit = if matches!(p.ty, ElemType::Qua4 | ElemType::Qua8) { 1 } else { 2 };
    let lp = &loops[0];
    let is_corner = |i: usize| count.get(&bnd[lp[i]][0]).is_some_and(|&c| c <= limit);
    let corners: Vec<usize> = (0..lp.len()).filter(|&i| is_corner(i)).collect();
    if corners.len() != 4 || corners[0] != 0 {
        return fail(
            OP,
            format!("found {} corners on the boundary; COTE needs a four-sided DALL or TRAN surface", corners.len()),
        );
    }
    let k = n as usize - 1;
    let end = if k == 3 { lp.len() } else { corners[k + 1] };
    let mut out = Vec::new();
    for &i in &lp[corners[k]..end] {
        push_edge(&mut out, &bnd[i]);
    }
    Ok(mesh_of(out))
}

/// `FACE n VOL`: face `n` of a volume swept by VOLU, TRAN or ROTA:
/// 1 the base, 2 the opposite face, 3 the lateral surface (face.notice).
///
/// As for COTE, the faces are recovered from the structure the sweeps give
/// (see [`super::sweep`]): elements come layer after layer, each listing its
/// bottom face then the face above it, so the layer size is the element
/// whose bottom is element 1's top. Face 1 is the bottom of the first
/// layer and face 2 the top of the last, both in the elements' order with
/// the node order of the bottom faces, so face 2 corresponds to face 1
/// node for node (for TRAN it is face 1 translated). Face 3 is every other
/// boundary face of the volume, in element order, its normal outward.
pub fn face(mesh: &Mesh, n: i64) -> Result<Mesh, MeshError> {
    const OP: &str = "FACE";
    if !(1..=3).contains(&n) {
        return fail(OP, format!("the face number must be 1, 2 or 3 (got {n})"));
    }
    let parts: Vec<&Part> = mesh.parts.iter().filter(|p| !p.is_empty()).collect();
    if parts.is_empty()
        || parts.iter().any(|p| !matches!(p.ty, ElemType::Cub8 | ElemType::Pri6 | ElemType::Cu20 | ElemType::Pr15))
    {
        return fail(OP, "needs a volume of CUB8, PRI6, CU20 or PR15 elements, as VOLU, TRAN or ROTA make");
    }
    let sorted = |mut k: Vec<usize>| {
        k.sort_unstable();
        k
    };
    let key = |e: &[usize], idx: &[usize]| sorted(idx.iter().map(|&i| e[i]).collect());
    let mut ends: [Vec<(ElemType, Vec<usize>)>; 2] = [Vec::new(), Vec::new()];
    for p in &parts {
        let (bottom, top, face_ty): (&[usize], &[usize], _) = match p.ty {
            ElemType::Cub8 => (&[0, 1, 2, 3], &[4, 5, 6, 7], ElemType::Qua4),
            ElemType::Cu20 => (&[0, 1, 2, 3, 4, 5, 6, 7], &[12, 13, 14, 15, 16, 17, 18, 19], ElemType::Qua8),
            ElemType::Pr15 => (&[0, 1, 2, 3, 4, 5], &[9, 10, 11, 12, 13, 14], ElemType::Tri6),
            _ => (&[0, 1, 2], &[3, 4, 5], ElemType::Tri3),
        };
        let count = p.len();
        let top0 = key(p.elem(0), top);
        let layer = (1..count).find(|&j| key(p.elem(j), bottom) == top0).unwrap_or(count);
        let stacked =
            count % layer == 0 && (0..count - layer).all(|i| key(p.elem(i + layer), bottom) == key(p.elem(i), top));
        if !stacked {
            return fail(OP, "the volume does not have the layered structure of a VOLU, TRAN or ROTA volume");
        }
        let base: Vec<usize> = (0..layer).flat_map(|e| bottom.iter().map(move |&i| p.elem(e)[i])).collect();
        let opposite: Vec<usize> =
            (count - layer..count).flat_map(|e| top.iter().map(move |&i| p.elem(e)[i])).collect();
        ends[0].push((face_ty, base));
        ends[1].push((face_ty, opposite));
    }
    if n <= 2 {
        return Ok(mesh_of(std::mem::take(&mut ends[n as usize - 1])));
    }
    let ends_keys: HashSet<Vec<usize>> =
        ends.iter().flatten().flat_map(|(ty, conn)| conn.chunks(ty.nodes()).map(|f| sorted(f.to_vec()))).collect();
    let all: Vec<(ElemType, Vec<usize>)> = parts
        .iter()
        .flat_map(|p| {
            p.elems().flat_map(move |e| {
                shape::faces(p.ty).into_iter().map(move |(t, l)| (t, l.iter().map(|&i| e[i]).collect()))
            })
        })
        .collect();
    let mut uses: HashMap<Vec<usize>, usize> = HashMap::new();
    for (_, f) in &all {
        *uses.entry(sorted(f.clone())).or_default() += 1;
    }
    let mut lateral: Vec<(ElemType, Vec<usize>)> = Vec::new();
    for (ty, f) in all {
        let k = sorted(f.clone());
        if uses[&k] == 1 && !ends_keys.contains(&k) {
            match lateral.iter_mut().find(|(t, _)| *t == ty) {
                Some((_, c)) => c.extend(f),
                None => lateral.push((ty, f)),
            }
        }
    }
    Ok(mesh_of(lateral))
}

fn push_edge(out: &mut Vec<(ElemType, Vec<usize>)>, e: &[usize]) {
    let ty = if e.len() == 3 { ElemType::Seg3 } else { ElemType::Seg2 };
    match out.iter_mut().find(|(t, _)| *t == ty) {
        Some((_, c)) => c.extend_from_slice(e),
        None => out.push((ty, e.to_vec())),
    }
}

/// Boundary edges of the surface parts, in element order.
pub(crate) fn boundary_edges(parts: &[&Part]) -> Vec<Vec<usize>> {
    shared_edges(parts, ContEdges::Exterior)
}

/// The edges of the surface elements whose number of users `which`
/// keeps, each once (at its first occurrence, oriented as there).
fn shared_edges(parts: &[&Part], which: ContEdges) -> Vec<Vec<usize>> {
    let key = |e: &[usize]| {
        let mut k = e.to_vec();
        k.sort_unstable();
        k
    };
    let all: Vec<Vec<usize>> = parts
        .iter()
        .filter(|p| p.ty.dim() == 2)
        .flat_map(|p| p.elems().flat_map(move |e| edges(p.ty).iter().map(move |ed| ed.iter().map(|&k| e[k]).collect())))
        .collect();
    let mut uses: HashMap<Vec<usize>, usize> = HashMap::new();
    for e in &all {
        *uses.entry(key(e)).or_default() += 1;
    }
    let mut seen = HashSet::new();
    all.into_iter().filter(|e| which.keeps(uses[&key(e)]) && seen.insert(key(e))).collect()
}

/// Chain edges into loops (lists of edge indices), as described in [`cont`].
fn walk(edges: &[Vec<usize>]) -> Vec<Vec<usize>> {
    let mut by_start: HashMap<usize, Vec<usize>> = HashMap::new();
    for (i, e) in edges.iter().enumerate() {
        by_start.entry(e[0]).or_default().push(i);
    }
    let mut used = vec![false; edges.len()];
    let mut loops = Vec::new();
    for seed in 0..edges.len() {
        if used[seed] {
            continue;
        }
        let mut lp = vec![seed];
        used[seed] = true;
        let mut at = edges[seed][edges[seed].len() - 1];
        while let Some(&next) = by_start.get(&at).and_then(|c| c.iter().find(|&&i| !used[i])) {
            used[next] = true;
            lp.push(next);
            at = edges[next][edges[next].len() - 1];
        }
        loops.push(lp);
    }
    loops
}

fn line_ends(parts: &[&Part]) -> Mesh {
    let mut count: HashMap<usize, usize> = HashMap::new();
    let mut order = Vec::new();
    for p in parts.iter().filter(|p| p.ty.dim() == 1) {
        for e in p.elems() {
            for n in [e[0], e[e.len() - 1]] {
                let c = count.entry(n).or_default();
                if *c == 0 {
                    order.push(n);
                }
                *c += 1;
            }
        }
    }
    let ends: Vec<usize> = order.into_iter().filter(|n| count[n] == 1).collect();
    mesh_of(vec![(ElemType::Poi1, ends)])
}
