//! VOLU of a closed surface: tetrahedra filling the volume it bounds, and
//! TRIA of points in space: their Delaunay tetrahedrisation.
//!
//! The volume is meshed with the surface's own nodes (no point added, so
//! the envelope of the result is the surface given): the Delaunay
//! tetrahedrisation of the nodes (`tet_delaunay`), the surface's edges and
//! triangles recovered by flips (`tet_recover`), then the tetrahedra kept
//! are those inside, found by crossing the surface from the outside (each
//! crossing turns inside and outside over, so cavities stay empty).

use super::tet_delaunay::{face_key, Tets, NONE};
use super::tet_recover::{flat, recover_edge, recover_face, unflat, Surface};
use super::{check_nodes, fail, mesh_of, MeshError};
use crate::fem::mesh::{ElemType, Mesh, Nodes};
use std::collections::{HashMap, HashSet};

/// Cast3M's positive TET4 from a tetrahedron positive in Shewchuk's sign.
fn cast3m(t: [usize; 4]) -> [usize; 4] {
    [t[0], t[1], t[3], t[2]]
}

/// `TRIA` of points in space: the Delaunay tetrahedra (indices into `pts`).
pub fn points_3d(op: &'static str, pts: &[[f64; 3]]) -> Result<Vec<[usize; 4]>, MeshError> {
    let t = Tets::delaunay(op, pts)?;
    let tets = t.inner();
    if tets.is_empty() {
        return fail(op, "the points are all in one plane: there is no tetrahedron to make");
    }
    Ok(tets.into_iter().map(cast3m).collect())
}

/// `VOLU` of a closed surface of TRI3 (oriented either way).
pub fn volu_closed(op: &'static str, nodes: &Nodes, surf: &Mesh) -> Result<Mesh, MeshError> {
    check_nodes(op, nodes, surf)?;
    let mut tris: Vec<[usize; 3]> = vec![];
    for p in surf.parts.iter().filter(|p| !p.is_empty()) {
        match p.ty {
            ElemType::Tri3 => tris.extend(p.elems().map(|e| [e[0], e[1], e[2]])),
            other => return fail(op, format!("a closed surface to fill is made of TRI3, not {}", other.name())),
        }
    }
    if tris.len() < 4 {
        return fail(op, "the surface is empty or too small to enclose a volume");
    }
    let ids = surf.node_list();
    let local: HashMap<usize, usize> = ids.iter().enumerate().map(|(k, &n)| (n, k)).collect();
    let pts: Vec<[f64; 3]> = ids.iter().map(|&n| nodes.get(n)).collect();
    let tris: Vec<[usize; 3]> = tris.iter().map(|f| f.map(|n| local[&n])).collect();
    let mut faces = HashSet::new();
    let mut edge_use: HashMap<[usize; 2], usize> = HashMap::new();
    for f in &tris {
        let mut k = *f;
        k.sort_unstable();
        if k[0] == k[1] || k[1] == k[2] {
            return fail(op, "a surface triangle has two corners at the same node");
        }
        if !faces.insert(k) {
            return fail(
                op,
                format!(
                    "the surface has the triangle of nodes {} {} {} twice",
                    ids[k[0]] + 1,
                    ids[k[1]] + 1,
                    ids[k[2]] + 1
                ),
            );
        }
        for (a, b) in [(k[0], k[1]), (k[1], k[2]), (k[0], k[2])] {
            *edge_use.entry([a, b]).or_default() += 1;
        }
    }
    // The first open edge in node order: the same message at every run.
    if let Some(e) = edge_use.iter().filter(|(_, &n)| n % 2 == 1).map(|(e, _)| *e).min() {
        return fail(
            op,
            format!(
                "the surface is not closed: the edge from node {} to node {} borders an odd number of triangles",
                ids[e[0]] + 1,
                ids[e[1]] + 1
            ),
        );
    }
    let s = Surface { faces, edges: edge_use.keys().copied().collect() };
    let mut last = None;
    for seed in 0..4u64 {
        match fill(op, &pts, &s, seed, &ids) {
            Ok(inside) => {
                let conn: Vec<usize> = inside.into_iter().flat_map(|t| cast3m(t).map(|v| ids[v])).collect();
                return Ok(mesh_of(vec![(ElemType::Tet4, conn)]));
            }
            Err(e) => last = Some(e),
        }
    }
    Err(last.unwrap_or_else(|| MeshError::new(op, "the surface encloses no volume")))
}

/// One try at filling, with the points moved by a tiny pseudo-random
/// amount (from `seed`): surfaces of regular grids are full of cospherical
/// and coplanar points, where a Delaunay choice is arbitrary and the flips
/// that recover the surface get stuck; in general position they do not.
/// The tetrahedra are the same node numbers with the true coordinates.
fn fill(
    op: &'static str,
    pts: &[[f64; 3]],
    s: &Surface,
    seed: u64,
    ids: &[usize],
) -> Result<Vec<[usize; 4]>, MeshError> {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for p in pts {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let size = (0..3).map(|k| hi[k] - lo[k]).fold(0.0, f64::max);
    let mut r: u64 = 0x2545_f491_4f6c_dd1d ^ (seed.wrapping_mul(0x9e37_79b9_7f4a_7c15));
    let mut next = move || {
        r ^= r << 13;
        r ^= r >> 7;
        r ^= r << 17;
        (r >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    let eps = 1e-9 * size;
    let moved: Vec<[f64; 3]> = pts.iter().map(|p| p.map(|x| x + eps * next())).collect();
    let mut t = Tets::delaunay(op, &moved)?;
    let mut edges: Vec<[usize; 2]> = s.edges.iter().copied().collect();
    edges.sort_unstable();
    for [a, b] in edges {
        if !recover_edge(&mut t, s, a, b) {
            return fail(
                op,
                format!("the surface edge from node {} to node {} cannot be made an edge of tetrahedra without adding points", ids[a] + 1, ids[b] + 1),
            );
        }
    }
    let mut fs: Vec<[usize; 3]> = s.faces.iter().copied().collect();
    fs.sort_unstable();
    for f in fs {
        if !recover_face(&mut t, s, f) {
            return fail(
                op,
                format!(
                    "the surface triangle of nodes {} {} {} cannot be made a face of tetrahedra without adding points",
                    ids[f[0]] + 1,
                    ids[f[1]] + 1,
                    ids[f[2]] + 1
                ),
            );
        }
    }
    let inside = classify(op, &t, s)?;
    if inside.is_empty() {
        return fail(op, "the surface encloses no volume");
    }
    t.pts[..pts.len()].copy_from_slice(pts);
    let mut inside = inside;
    for _ in 0..16 {
        let flats: Vec<usize> = inside.iter().copied().filter(|&k| flat(&t, k)).collect();
        if flats.is_empty() {
            return Ok(inside.into_iter().map(|k| t.tets[k]).collect());
        }
        for k in flats {
            if t.alive[k] {
                unflat(&mut t, s, k);
            }
        }
        inside = classify(op, &t, s)?;
    }
    // Flat slivers left on plane parts of the surface are kept (known
    // limitation): their faces are still conforming.
    Ok(inside.into_iter().map(|k| t.tets[k]).collect())
}

/// The living tetrahedra inside the surface, in order.
fn classify(op: &'static str, t: &Tets, s: &Surface) -> Result<Vec<usize>, MeshError> {
    let n = t.tets.len();
    let mut side = vec![u8::MAX; n];
    let mut stack = vec![];
    for (k, sk) in side.iter_mut().enumerate() {
        if t.alive[k] && t.touches_corner(k) {
            *sk = 0;
            stack.push(k);
        }
    }
    while let Some(k) = stack.pop() {
        for i in 0..4 {
            let m = t.nb[k][i];
            if m == NONE {
                continue;
            }
            let cross = u8::from(s.faces.contains(&face_key(&t.tets[k], i)));
            let want = side[k] ^ cross;
            if side[m] == u8::MAX {
                side[m] = want;
                stack.push(m);
            } else if side[m] != want {
                return fail(op, "the surface does not bound a volume consistently (it crosses itself)");
            }
        }
    }
    Ok((0..n).filter(|&k| t.alive[k] && side[k] == 1).collect())
}
