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
use super::tet_steiner::Refined;
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

/// `VOLU` of a closed surface of TRI3 (oriented either way). The
/// tetrahedra use the surface's nodes, plus points added on the surface
/// (new nodes) where flips alone cannot make it appear (`tet_steiner`).
pub fn volu_closed(op: &'static str, nodes: &mut Nodes, surf: &Mesh) -> Result<Mesh, MeshError> {
    volu_closed_sized(op, nodes, surf, None)
}

/// `volu_closed` with, given a target size `h`, interior nodes at about
/// that spacing (`tria_sized::interior_points`); the surface is kept.
pub fn volu_closed_sized(op: &'static str, nodes: &mut Nodes, surf: &Mesh, h: Option<f64>) -> Result<Mesh, MeshError> {
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
    let s = surface_of(op, &tris, &ids)?;
    let (mut ids, mut pts) = (ids, pts);
    if let Some(h) = h {
        // Interior points are new nodes from the start: the points added on
        // the surface come after them, as the numbering below expects.
        for p in super::tria_sized::interior_points(op, &pts, &tris, h)? {
            ids.push(nodes.push(p, h));
            pts.push(p);
        }
    }
    let mut r = Refined { pts, tris, added: vec![] };
    let mut s = s;
    let mut last = None;
    for round in 0..ROUNDS {
        // The first round tries several perturbations before adding any
        // point (a surface that flips can recover keeps its nodes); later
        // rounds one each.
        let seeds = if round == 0 { 0..4u64 } else { round as u64 + 3..round as u64 + 4 };
        let mut missing: Option<Missing> = None;
        for seed in seeds {
            match fill(op, &r.pts, &s, seed) {
                Ok(inside) => {
                    let first = nodes.len();
                    for (k, e) in r.added.iter().enumerate() {
                        // A point may split an edge ending at a point
                        // added before it (pushed already, in order).
                        let dens = |v: usize| nodes.density[if v < ids.len() { ids[v] } else { first + v - ids.len() }];
                        let d = 0.5 * (dens(e[0]) + dens(e[1]));
                        let at = nodes.push(r.pts[ids.len() + k], d);
                        debug_assert_eq!(at, first + k);
                    }
                    let id = |v: usize| if v < ids.len() { ids[v] } else { first + v - ids.len() };
                    let conn: Vec<usize> = inside.into_iter().flat_map(|t| cast3m(t).map(id)).collect();
                    return Ok(mesh_of(vec![(ElemType::Tet4, conn)]));
                }
                Err(Failure::Fatal(e)) => last = Some(e),
                Err(Failure::Missing(m)) => {
                    if missing.as_ref().is_none_or(|x| m.count() < x.count()) {
                        missing = Some(m);
                    }
                }
            }
        }
        let Some(m) = missing else { break };
        last = Some(m.error(op, &ids));
        let cut = match &m {
            Missing::Edges(es) => es.iter().fold(false, |c, &[a, b]| r.split_edge(a, b) | c),
            Missing::Faces(fs) => fs.iter().fold(false, |c, &f| r.split_face(f) | c),
        };
        if !cut {
            break;
        }
        s = surface_of(op, &r.tris, &ids)?;
    }
    Err(last.unwrap_or_else(|| MeshError::new(op, "the surface encloses no volume")))
}

/// Rounds of refinement before giving up.
const ROUNDS: usize = 12;

/// What stopped one try at filling.
enum Failure {
    Fatal(MeshError),
    Missing(Missing),
}

/// The surface edges (or, all edges being there, triangles) that the flips
/// could not make appear.
enum Missing {
    Edges(Vec<[usize; 2]>),
    Faces(Vec<[usize; 3]>),
}

impl Missing {
    fn count(&self) -> usize {
        match self {
            Missing::Edges(e) => e.len(),
            Missing::Faces(f) => f.len(),
        }
    }

    /// The error when no refinement helps: the first one missing.
    fn error(&self, op: &'static str, ids: &[usize]) -> MeshError {
        let name = |v: usize| match ids.get(v) {
            Some(n) => format!("node {}", n + 1),
            None => "a point added on the surface".to_string(),
        };
        match self {
            Missing::Edges(e) => MeshError::new(
                op,
                format!(
                    "the surface edge from {} to {} cannot be made an edge of tetrahedra, even with points added",
                    name(e[0][0]),
                    name(e[0][1])
                ),
            ),
            Missing::Faces(f) => MeshError::new(
                op,
                format!(
                    "the surface triangle of {}, {} and {} cannot be made a face of tetrahedra, even with points added",
                    name(f[0][0]),
                    name(f[0][1]),
                    name(f[0][2])
                ),
            ),
        }
    }
}

/// The faces and edges of a surface of triangles (local numbers), checked
/// to be closed and without repeated triangles.
fn surface_of(op: &'static str, tris: &[[usize; 3]], ids: &[usize]) -> Result<Surface, MeshError> {
    let mut faces = HashSet::new();
    let mut edge_use: HashMap<[usize; 2], usize> = HashMap::new();
    for f in tris {
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
    Ok(Surface { faces, edges: edge_use.keys().copied().collect() })
}

/// One try at filling, with the points moved by a tiny pseudo-random
/// amount (from `seed`): surfaces of regular grids are full of cospherical
/// and coplanar points, where a Delaunay choice is arbitrary and the flips
/// that recover the surface get stuck; in general position they do not.
/// The tetrahedra are the same node numbers with the true coordinates.
fn fill(op: &'static str, pts: &[[f64; 3]], s: &Surface, seed: u64) -> Result<Vec<[usize; 4]>, Failure> {
    let (lo, hi) = super::tet_delaunay::bounding_box(pts);
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
    let mut t = Tets::delaunay(op, &moved).map_err(Failure::Fatal)?;
    let mut edges: Vec<[usize; 2]> = s.edges.iter().copied().collect();
    edges.sort_unstable();
    let lost: Vec<[usize; 2]> = edges.into_iter().filter(|&[a, b]| !recover_edge(&mut t, s, a, b)).collect();
    if !lost.is_empty() {
        return Err(Failure::Missing(Missing::Edges(lost)));
    }
    let mut fs: Vec<[usize; 3]> = s.faces.iter().copied().collect();
    fs.sort_unstable();
    let lost: Vec<[usize; 3]> = fs.into_iter().filter(|&f| !recover_face(&mut t, s, f)).collect();
    if !lost.is_empty() {
        return Err(Failure::Missing(Missing::Faces(lost)));
    }
    let inside = classify(op, &t, s).map_err(Failure::Fatal)?;
    if inside.is_empty() {
        return Err(Failure::Fatal(MeshError::new(op, "the surface encloses no volume")));
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
        inside = classify(op, &t, s).map_err(Failure::Fatal)?;
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
