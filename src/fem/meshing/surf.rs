//! SURF: free meshing of the inside of closed contours lying in a plane
//! (2D, or a plane contour in 3D).
//!
//! The contour's loops ([`contour::loops`]) are brought into their plane's
//! frame, triangulated there ([`free::triangulate`]) and the new nodes
//! brought back. Elements turn like the contour (counter-clockwise seen
//! from the normal the loops turn about: in 2D, counter-clockwise when the
//! outer loop is), holes are the inner loops. Under QUA4/QUA8 the triangles
//! are paired into quadrangles ([`pairing`]) and the leftovers stay TRI3
//! (TRI6). Quadratic elements reuse the middle nodes of a SEG3 contour.
//!
//! Node order: the new interior nodes are appended in the order the mesher
//! made them, then the mid-side nodes of quadratic elements. Their density
//! is the target size there.

use super::contour::{corner_sizes, loops, Frame};
use super::surf_sphere::Stereographic;
use super::{free, mesh_of, pairing, MeshError};
use crate::fem::mesh::{ElemType, Mesh, Nodes, Part};
use std::collections::HashMap;

const OP: &str = "SURF";

/// The surface element SURF makes under `OPTI ELEM name`: quadrangles for
/// QUA4/QUA8 (and the volumes whose faces are quadrangles), triangles
/// otherwise, quadratic for the quadratic types.
pub fn surface_type(elem: &str) -> ElemType {
    match elem {
        "QUA4" | "CUB8" => ElemType::Qua4,
        "QUA8" | "CU20" => ElemType::Qua8,
        "TRI6" | "SEG3" | "TE10" | "PR15" => ElemType::Tri6,
        _ => ElemType::Tri3,
    }
}

/// What SURF needs besides the contour.
#[derive(Debug, Clone, Default)]
pub struct SurfOptions {
    /// 2 or 3.
    pub space_dim: usize,
    /// The planarity criterion (see [`Frame::of`]).
    pub crit: f64,
    /// Sizes given by a field at some contour nodes; they win over the
    /// node densities.
    pub sizes: HashMap<usize, f64>,
    /// 'SPHE': the centre of the sphere the contour lies on.
    pub sphere: Option<[f64; 3]>,
}

/// `SURF contour` with elements of type `ty` (TRI3, TRI6, QUA4, QUA8).
pub fn surf(nodes: &mut Nodes, contour: &Mesh, ty: ElemType, o: &SurfOptions) -> Result<Mesh, MeshError> {
    let lps = loops(OP, nodes, contour)?;
    // On a sphere the contour is filled on its stereographic projection.
    let sphere = match o.sphere {
        Some(c) => {
            let corners: Vec<[f64; 3]> = lps.iter().flat_map(|l| l.corners.iter().map(|&n| nodes.get(n))).collect();
            Some(Stereographic::new(OP, c, &corners)?)
        }
        None => None,
    };
    let flat;
    let geo: &Nodes = match &sphere {
        None => nodes,
        Some(g) => {
            let mut f = nodes.clone();
            for &n in lps.iter().flat_map(|l| &l.corners) {
                f.coords[n] = g.to_plane(nodes.get(n));
            }
            flat = f;
            &flat
        }
    };
    let frame = Frame::of(OP, geo, &lps, o.space_dim, o.crit)?;
    let mut local: HashMap<usize, usize> = HashMap::new();
    let (mut pts, mut sizes, mut ids, mut polys) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for l in &lps {
        let hs = corner_sizes(geo, l);
        let mut poly = Vec::with_capacity(l.corners.len());
        for (&n, h) in l.corners.iter().zip(hs) {
            let k = *local.entry(n).or_insert_with(|| {
                pts.push(frame.local(geo.get(n)));
                sizes.push(o.sizes.get(&n).copied().unwrap_or(h));
                ids.push(n);
                ids.len() - 1
            });
            poly.push(k);
        }
        polys.push(poly);
    }
    let planar = free::triangulate(OP, &pts, &sizes, &polys)?;
    for (p, h) in planar.points.iter().zip(&planar.sizes).skip(ids.len()) {
        let x = frame.global(*p);
        ids.push(nodes.push(sphere.map_or(x, |g| g.to_sphere(x)), *h));
    }
    let g = |t: &[usize]| t.iter().map(|&k| ids[k]).collect::<Vec<_>>();
    let mut parts: Vec<(ElemType, Vec<usize>)> = Vec::new();
    if matches!(ty, ElemType::Qua4 | ElemType::Qua8) {
        let (quads, tris) = pairing::pair(&planar.points, &planar.triangles);
        parts.push((ElemType::Qua4, quads.iter().flat_map(|q| g(q)).collect()));
        parts.push((ElemType::Tri3, tris.iter().flat_map(|t| g(t)).collect()));
    } else {
        parts.push((ElemType::Tri3, planar.triangles.iter().flat_map(|t| g(t)).collect()));
    }
    let linear = mesh_of(parts);
    if !matches!(ty, ElemType::Tri6 | ElemType::Qua8) {
        return Ok(linear);
    }
    // Quadratic: CHAN's rule, with the contour's SEG3 parts alongside so
    // that their middle nodes are the ones on the boundary.
    let seg3: Vec<Part> = contour.parts.iter().filter(|p| p.ty == ElemType::Seg3).cloned().collect();
    let mut both = linear.clone();
    both.parts.extend(seg3);
    let quad = super::change_to_quadratic(nodes, &both).map_err(|e| MeshError::new(OP, e.message))?;
    Ok(Mesh { parts: quad.parts.into_iter().filter(|p| p.ty != ElemType::Seg3).collect() })
}
