//! TRIA: Delaunay triangulations of point sets and of plane regions.
//!
//! The geometry (incremental Delaunay insertion, constrained edges) is
//! spade's; this file turns point numbers into triangles and back.
//!
//! * A set of points on a line (1D) is joined in increasing abscissa.
//! * A set of points in the plane gives the Delaunay triangulation of the
//!   points: it covers their convex hull, and no point lies strictly inside
//!   the circumcircle of a triangle. Triangles are counter-clockwise.
//! * A region bounded by closed polygons (with, inside, imposed edges)
//!   gives the constrained Delaunay triangulation of its inside (even-odd
//!   rule, inner loops are holes), with no node added: TRIA's "minimal
//!   number of nodes".

use super::free::{inside_triangles, load};
use super::{fail, MeshError};
use spade::{DelaunayTriangulation, Point2, Triangulation};

/// The chain of 1D points in increasing abscissa: pairs of indices into
/// `xs`. Points at the same abscissa are an error (merge them with ELIM).
pub fn chain_1d(op: &'static str, xs: &[f64]) -> Result<Vec<[usize; 2]>, MeshError> {
    if xs.iter().any(|x| !x.is_finite()) {
        return fail(op, "a point has a coordinate that is not a finite number");
    }
    let mut order: Vec<usize> = (0..xs.len()).collect();
    order.sort_by(|&a, &b| xs[a].total_cmp(&xs[b]));
    if let Some(w) = order.windows(2).find(|w| xs[w[0]] == xs[w[1]]) {
        return fail(op, format!("points {} and {} are at the same place (merge them with ELIM)", w[0] + 1, w[1] + 1));
    }
    Ok(order.windows(2).map(|w| [w[0], w[1]]).collect())
}

/// The Delaunay triangulation of plane points: counter-clockwise triangles
/// of indices into `pts`. Two points at the same place, or fewer than
/// three points not all on a line, are errors.
pub fn points_2d(op: &'static str, pts: &[[f64; 2]]) -> Result<Vec<[usize; 3]>, MeshError> {
    if pts.iter().flatten().any(|c| !c.is_finite()) {
        return fail(op, "a point has a coordinate that is not a finite number");
    }
    let mut dt: DelaunayTriangulation<Point2<f64>> = DelaunayTriangulation::new();
    // The vertex each input point became: spade merges equal positions.
    let mut vertex_of = Vec::with_capacity(pts.len());
    let mut input_of: Vec<usize> = Vec::with_capacity(pts.len());
    for (i, p) in pts.iter().enumerate() {
        let v = dt
            .insert(Point2::new(p[0], p[1]))
            .map_err(|e| MeshError::new(op, format!("point {} cannot be inserted ({e:?})", i + 1)))?;
        if v.index() < input_of.len() {
            return fail(
                op,
                format!(
                    "points {} and {} are at the same place (merge them with ELIM)",
                    input_of[v.index()] + 1,
                    i + 1
                ),
            );
        }
        input_of.push(i);
        vertex_of.push(v.index());
    }
    if dt.num_inner_faces() == 0 {
        return fail(op, "the points are all on a line: there is no triangle to make");
    }
    Ok(dt
        .inner_faces()
        .map(|f| {
            let v = f.vertices();
            [input_of[v[0].fix().index()], input_of[v[1].fix().index()], input_of[v[2].fix().index()]]
        })
        .collect())
}

/// The constrained Delaunay triangulation of the region bounded by the
/// segments `edges` (indices into `pts`), no point added: counter-clockwise
/// triangles of indices into `pts`.
pub fn region_2d(op: &'static str, pts: &[[f64; 2]], edges: &[[usize; 2]]) -> Result<Vec<[usize; 3]>, MeshError> {
    if pts.iter().flatten().any(|c| !c.is_finite()) {
        return fail(op, "a point has a coordinate that is not a finite number");
    }
    let cdt = load(op, pts, edges)?;
    let tris = inside_triangles(&cdt);
    if tris.is_empty() {
        return fail(op, "the lines enclose no region (TRIA fills closed contours)");
    }
    Ok(tris)
}
