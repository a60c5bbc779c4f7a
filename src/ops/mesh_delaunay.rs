//! TRIA (TRIANGULATION): Delaunay triangulation of a set of points, or of
//! the inside of closed lines. The geometry is `fem::meshing::delaunay`
//! (spade); this file reads the Gibiane arguments.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::{ElemType, Mesh, Part};
use crate::fem::meshing as mg;
use crate::value::Value;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "TRIA",
    signature: "TRIA POINTS ('CONV') (size) | TRIA LINES (n_max | size) | TRIA SURFACE|VOLUME (size)",
    doc: "Delaunay triangulation: of a POI1 point set (SEG2 chain in 1D, TRI3 over the convex hull in 2D, TET4 over it in 3D), of the inside of a closed TRI3 surface in 3D (TET4), or of the inside of closed SEG2 lines in the plane with no node added (with a size: free triangles of that size, as SURF). With a size, points get nodes added (hull cut, inside refined) and a closed surface inside nodes at that spacing; a surface (2D) or volume (3D) is meshed again from its boundary. Points on one line give no element.",
    example: "t = tria ((0. 0.) et (1. 0.) et (0. 1.) et (1. 1.)) ;",
    f: tria,
}];

fn tria(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let geo = super::mesh::req_geo(a)?;
    // 'CONV' asks for a convex result: a Delaunay triangulation of points
    // always covers their convex hull.
    a.keyword(&["CONV"]);
    let max_nodes = a.opt::<i64>();
    let size = match max_nodes {
        Some(_) => None,
        None => a.opt::<f64>(),
    };
    a.keyword(&["CONV"]);
    if let Some(h) = size {
        if !(h.is_finite() && h > 0.0) {
            return Err(a.err(format!("the element size must be positive (got {h})")));
        }
    }
    let dim = it.opts.dime.max(1);
    let kinds: Vec<ElemType> = geo.parts.iter().filter(|p| !p.is_empty()).map(|p| p.ty).collect();
    if kinds.is_empty() {
        return Err(a.err("the mesh is empty"));
    }
    if kinds.iter().all(|&t| t == ElemType::Poi1) {
        let ids = geo.node_list();
        let coords: Vec<[f64; 3]> = ids.iter().map(|&n| it.nodes.get(n)).collect();
        if let Some(h) = size {
            if dim >= 2 {
                return Ok(vec![Value::Mesh(Rc::new(points_sized(it, &ids, &coords, dim, h)?))]);
            }
        }
        let conn: Vec<usize> = match dim {
            1 => {
                let xs: Vec<f64> = coords.iter().map(|c| c[0]).collect();
                mg::delaunay::chain_1d("TRIA", &xs)?.iter().flat_map(|e| [ids[e[0]], ids[e[1]]]).collect()
            }
            // Points on one line have no triangle: the result is empty.
            2 if mg::tria_sized::collinear(&coords) => vec![],
            2 => {
                let pts: Vec<[f64; 2]> = coords.iter().map(|c| [c[0], c[1]]).collect();
                mg::delaunay::points_2d("TRIA", &pts)?.iter().flat_map(|t| t.map(|k| ids[k])).collect()
            }
            _ if mg::tria_sized::collinear(&coords) => vec![],
            // Points of one plane in 3D are triangulated in that plane.
            _ => match in_plane(&coords) {
                Some((pts, _)) => {
                    mg::delaunay::points_2d("TRIA", &pts)?.iter().flat_map(|t| t.map(|k| ids[k])).collect()
                }
                None => {
                    let tets = mg::tet_fill::points_3d("TRIA", &coords)?;
                    let conn = tets.iter().flat_map(|t| t.map(|k| ids[k])).collect();
                    return Ok(vec![Value::Mesh(Rc::new(Mesh::single(Part::with(ElemType::Tet4, conn))))]);
                }
            },
        };
        let ty = if dim == 1 { ElemType::Seg2 } else { ElemType::Tri3 };
        return Ok(vec![Value::Mesh(Rc::new(Mesh::single(Part::with(ty, conn))))]);
    }
    // A volume (3D) or a surface (2D) is meshed again from its boundary.
    let mut geo = geo;
    let solid = |t: ElemType| if dim == 3 { t.dim() == 3 } else { dim == 2 && t.dim() == 2 };
    if kinds.iter().all(|&t| solid(t)) {
        let faces = mg::edges::boundary_faces(geo.parts.iter());
        let mut by_type: Vec<(ElemType, Vec<usize>)> = vec![];
        for (ty, f) in faces {
            match by_type.iter_mut().find(|(t, _)| *t == ty) {
                Some((_, c)) => c.extend(f),
                None => by_type.push((ty, f)),
            }
        }
        geo = Mesh { parts: by_type.into_iter().map(|(ty, c)| Part::with(ty, c)).collect() };
    }
    let kinds: Vec<ElemType> = geo.parts.iter().filter(|p| !p.is_empty()).map(|p| p.ty).collect();
    // In 3D a closed surface of TRI3 is filled with tetrahedra (points are
    // added only where the surface cannot be recovered otherwise, or inside
    // at the size given).
    if dim == 3 && !kinds.is_empty() && kinds.iter().all(|&t| t == ElemType::Tri3) {
        return Ok(vec![Value::Mesh(Rc::new(mg::tet_fill::volu_closed_sized("TRIA", &mut it.nodes, &geo, size)?))]);
    }
    if dim != 2 {
        return Err(a.err("the triangulation of the inside of lines is available in 2D (OPTI DIME 2)"));
    }
    if let Some(k) = kinds.iter().find(|&&t| t != ElemType::Seg2) {
        return Err(a.err(format!("TRIA fills lines of SEG2 elements, not {}", k.name())));
    }
    if let Some(h) = size {
        // With a size, the inside is meshed freely, as SURF does, but with
        // elements of that size everywhere.
        let o = mg::surf::SurfOptions {
            space_dim: 2,
            crit: 1e-2,
            sizes: geo.node_list().into_iter().map(|n| (n, h)).collect(),
            sphere: None,
        };
        return Ok(vec![Value::Mesh(Rc::new(mg::surf::surf(&mut it.nodes, &geo, ElemType::Tri3, &o)?))]);
    }
    let ids = geo.node_list();
    let local: std::collections::HashMap<usize, usize> = ids.iter().enumerate().map(|(k, &n)| (n, k)).collect();
    let pts: Vec<[f64; 2]> = ids.iter().map(|&n| it.nodes.get(n)).map(|c| [c[0], c[1]]).collect();
    let edges: Vec<[usize; 2]> =
        geo.parts.iter().flat_map(|p| p.elems().map(|e| [local[&e[0]], local[&e[1]]]).collect::<Vec<_>>()).collect();
    let tris = mg::delaunay::region_2d("TRIA", &pts, &edges)?;
    if let Some(n) = max_nodes {
        if n < ids.len() as i64 {
            return Err(a.err(format!("the maximum number of nodes ({n}) is less than the lines' {} nodes", ids.len())));
        }
    }
    let conn: Vec<usize> = tris.iter().flat_map(|t| t.map(|k| ids[k])).collect();
    Ok(vec![Value::Mesh(Rc::new(Mesh::single(Part::with(ElemType::Tri3, conn))))])
}

/// Points' coordinates in their plane, and the plane's origin and axes.
type InPlane = (Vec<[f64; 2]>, [[f64; 3]; 3]);

/// TRIA of points with a target size `h` (2D, or 3D): the input nodes
/// and nodes added (density `h`), Delaunay elements over them.
fn points_sized(it: &mut Interp, ids: &[usize], coords: &[[f64; 3]], dim: usize, h: f64) -> Result<Mesh> {
    let plane: Option<InPlane> = if mg::tria_sized::collinear(coords) {
        // Points on one line: no element, as without a size.
        return Ok(Mesh::single(Part::with(ElemType::Tri3, vec![])));
    } else if dim == 2 {
        Some((coords.iter().map(|c| [c[0], c[1]]).collect(), [[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]))
    } else {
        in_plane(coords)
    };
    let node_of = |it: &mut Interp, k: usize, p: [f64; 3]| if k < ids.len() { ids[k] } else { it.nodes.push(p, h) };
    if let Some((pts, [o, u, v])) = plane {
        let (all, tris) = mg::tria_sized::points_2d("TRIA", &pts, h)?;
        let mut num = Vec::with_capacity(all.len());
        for (k, q) in all.iter().enumerate() {
            let p = [0, 1, 2].map(|i| o[i] + q[0] * u[i] + q[1] * v[i]);
            num.push(node_of(it, k, p));
        }
        let conn = tris.iter().flat_map(|t| t.map(|k| num[k])).collect();
        return Ok(Mesh::single(Part::with(ElemType::Tri3, conn)));
    }
    let (all, tets) = mg::tria_sized::points_3d("TRIA", coords, h)?;
    let mut num = Vec::with_capacity(all.len());
    for (k, p) in all.iter().enumerate() {
        num.push(node_of(it, k, *p));
    }
    let conn = tets.iter().flat_map(|t| t.map(|k| num[k])).collect();
    Ok(Mesh::single(Part::with(ElemType::Tet4, conn)))
}

/// The points' coordinates in their common plane (axes: the direction to
/// the farthest point, then the normal, oriented to its largest component
/// being positive, crossed with it), or None if they span a volume or lie
/// on one line.
fn in_plane(x: &[[f64; 3]]) -> Option<InPlane> {
    let sub = |a: [f64; 3], b: [f64; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let cross =
        |a: [f64; 3], b: [f64; 3]| [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    let p0 = *x.first()?;
    let far =
        x.iter().copied().max_by(|a, b| dot(sub(*a, p0), sub(*a, p0)).total_cmp(&dot(sub(*b, p0), sub(*b, p0))))?;
    let d = sub(far, p0);
    let size = dot(d, d).sqrt();
    if size == 0.0 {
        return None;
    }
    let u = d.map(|c| c / size);
    let n = x.iter().map(|p| cross(u, sub(*p, p0))).max_by(|a, b| dot(*a, *a).total_cmp(&dot(*b, *b)))?;
    let len = dot(n, n).sqrt();
    if len <= 1e-9 * size {
        return None;
    }
    let mut n = n.map(|c| c / len);
    let big = (0..3).max_by(|&i, &j| n[i].abs().total_cmp(&n[j].abs())).unwrap_or(2);
    if n[big] < 0.0 {
        n = n.map(|c| -c);
    }
    if x.iter().any(|p| dot(n, sub(*p, p0)).abs() > 1e-9 * size) {
        return None;
    }
    let v = cross(n, u);
    Some((x.iter().map(|p| [dot(sub(*p, p0), u), dot(sub(*p, p0), v)]).collect(), [p0, u, v]))
}
