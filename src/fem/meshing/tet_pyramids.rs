//! VOLU of a closed surface with quadrangles: a pyramid (PYR5) on each
//! quadrangle, its apex a new node inside, and tetrahedra filling the rest
//! (`tet_fill` on the triangles and the pyramids' sides). The envelope of
//! the volume is then the surface given, quadrangles included.
//!
//! The apex stands over the quadrangle's centre, along its normal toward
//! the inside, at a height kept well below the distance to the rest of
//! the surface in that direction (a thin wall must not be pierced) and
//! below the distance from the centre to the nearest side (neighbouring
//! pyramids must not meet). Should the tetrahedra still not fit the pyramids' sides,
//! the heights are halved and the whole made again.

use super::tet_fill::volu_closed;
use super::vec3::{add, cross, dot, norm, scale, sub, V3};
use super::{fail, mesh_of, MeshError};
use crate::fem::mesh::{ElemType, Mesh, Nodes};
use std::collections::HashSet;

/// `VOLU` of a closed surface of TRI3 and QUA4, oriented either way.
pub fn volu_with_pyramids(op: &'static str, nodes: &mut Nodes, surf: &Mesh) -> Result<Mesh, MeshError> {
    let mut tris: Vec<[usize; 3]> = vec![];
    let mut quads: Vec<[usize; 4]> = vec![];
    for p in surf.parts.iter().filter(|p| !p.is_empty()) {
        match p.ty {
            ElemType::Tri3 => tris.extend(p.elems().map(|e| [e[0], e[1], e[2]])),
            ElemType::Qua4 => quads.extend(p.elems().map(|e| [e[0], e[1], e[2], e[3]])),
            other => {
                return fail(op, format!("a closed surface to fill is made of TRI3 and QUA4, not {}", other.name()))
            }
        }
    }
    let x = |n: usize| nodes.get(n);
    // Six times the signed volume enclosed: positive when the faces turn
    // with their normals outward.
    let mut vol6 = 0.0;
    for t in &tris {
        vol6 += dot(x(t[0]), cross(x(t[1]), x(t[2])));
    }
    for q in &quads {
        vol6 += dot(x(q[0]), cross(x(q[1]), x(q[2]))) + dot(x(q[0]), cross(x(q[2]), x(q[3])));
    }
    if !(vol6.is_finite() && vol6 != 0.0) {
        return fail(op, "the surface encloses no volume");
    }
    let inward = -vol6.signum();
    // Every face as triangles, to measure the room in front of each
    // quadrangle.
    let mut flat: Vec<[usize; 3]> = tris.clone();
    flat.extend(quads.iter().flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]]));
    let mut tops: Vec<(V3, V3, f64)> = Vec::with_capacity(quads.len());
    for q in &quads {
        let c = q.map(x);
        let g = scale(add(add(c[0], c[1]), add(c[2], c[3])), 0.25);
        let nq = cross(sub(c[2], c[0]), sub(c[3], c[1]));
        let len = norm(nq);
        if len == 0.0 {
            return fail(
                op,
                format!("the quadrangle of nodes {} {} {} {} is flat", q[0] + 1, q[1] + 1, q[2] + 1, q[3] + 1),
            );
        }
        let d = scale(nq, inward / len);
        // The distance from the centre to the nearest side's line: sides
        // sloping at most 45 degrees leave room to a neighbour at a right
        // angle.
        let side = (0..4)
            .map(|i| {
                let e = sub(c[(i + 1) % 4], c[i]);
                norm(cross(e, sub(g, c[i]))) / norm(e).max(1e-300)
            })
            .fold(f64::INFINITY, f64::min);
        let own: HashSet<usize> = q.iter().copied().collect();
        let room = flat
            .iter()
            .filter(|f| !f.iter().all(|v| own.contains(v)))
            .filter_map(|f| ray_hit(g, d, f.map(x)))
            .fold(f64::INFINITY, f64::min);
        tops.push((g, d, (0.8 * side).min(0.4 * room)));
    }
    let start = nodes.len();
    let mut last = None;
    // Varied heights first (see below), then equal ones, each lower and
    // lower.
    for attempt in 0..6 {
        let f = 0.5f64.powi(attempt / 2);
        let vary = if attempt % 2 == 0 { 0.15 } else { 0.0 };
        let mut apex = Vec::with_capacity(quads.len());
        for (k, q) in quads.iter().enumerate() {
            let (g, dir, h) = tops[k];
            // Heights differing a little from one quadrangle to the next:
            // apexes over a plane face are then not coplanar, where the
            // tetrahedra between them could be flat.
            let f = f * (1.0 - vary + vary * ((k as f64 * 0.618_033_988_749_895) % 1.0));
            let d = q.iter().map(|&n| nodes.density[n]).sum::<f64>() / 4.0;
            apex.push(nodes.push(add(g, scale(dir, f * h)), d));
        }
        let mut conn: Vec<usize> = tris.iter().flatten().copied().collect();
        for (q, &a) in quads.iter().zip(&apex) {
            for i in 0..4 {
                conn.extend([q[i], q[(i + 1) % 4], a]);
            }
        }
        match volu_closed(op, nodes, &mesh_of(vec![(ElemType::Tri3, conn)])) {
            Ok(tets) => {
                let faces = tet_faces(&tets);
                let fits = quads.iter().zip(&apex).all(|(q, &a)| {
                    (0..4).all(|i| {
                        let mut k = [q[i], q[(i + 1) % 4], a];
                        k.sort_unstable();
                        faces.contains(&k)
                    })
                });
                if fits {
                    // Positive pyramids: the base turns about the apex's side.
                    let pyr: Vec<usize> =
                        quads
                            .iter()
                            .zip(&apex)
                            .flat_map(|(q, &a)| {
                                if inward > 0.0 {
                                    [q[0], q[1], q[2], q[3], a]
                                } else {
                                    [q[0], q[3], q[2], q[1], a]
                                }
                            })
                            .collect();
                    let mut parts: Vec<(ElemType, Vec<usize>)> =
                        tets.parts.iter().map(|p| (p.ty, p.conn.clone())).collect();
                    parts.push((ElemType::Pyr5, pyr));
                    return Ok(mesh_of(parts));
                }
                last = Some(MeshError::new(op, "the pyramids on the quadrangles do not fit the tetrahedra"));
            }
            Err(e) => last = Some(e),
        }
        nodes.coords.truncate(start);
        nodes.density.truncate(start);
    }
    Err(last.unwrap_or_else(|| MeshError::new(op, "the surface encloses no volume")))
}

/// Every face of the tetrahedra, as sorted node triples.
fn tet_faces(m: &Mesh) -> HashSet<[usize; 3]> {
    let mut out = HashSet::new();
    for p in &m.parts {
        for e in p.elems() {
            for skip in 0..4 {
                let mut k = [0; 3];
                let mut j = 0;
                for (i, &v) in e.iter().enumerate().take(4) {
                    if i != skip {
                        k[j] = v;
                        j += 1;
                    }
                }
                k.sort_unstable();
                out.insert(k);
            }
        }
    }
    out
}

/// The distance along the ray from `o` in unit direction `d` to triangle
/// `t`, if it meets it ahead (Möller-Trumbore).
fn ray_hit(o: V3, d: V3, t: [V3; 3]) -> Option<f64> {
    let e1 = sub(t[1], t[0]);
    let e2 = sub(t[2], t[0]);
    let p = cross(d, e2);
    let det = dot(e1, p);
    if det.abs() < 1e-300 {
        return None;
    }
    let s = sub(o, t[0]);
    let u = dot(s, p) / det;
    let q = cross(s, e1);
    let v = dot(d, q) / det;
    let w = dot(e2, q) / det;
    let tol = 1e-9;
    (u >= -tol && v >= -tol && u + v <= 1.0 + tol && w > 0.0).then_some(w)
}
