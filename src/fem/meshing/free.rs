//! Free triangulation of a plane region bounded by closed polygons, for
//! SURF. The robust geometry (constrained Delaunay triangulation, point
//! location, legal flips) is spade's; this file decides where interior
//! points go so that elements follow the size asked for, as Cast3M's
//! mesher does.
//!
//! # The rule
//!
//! * The contour is kept as given: no node is added on it, no segment is
//!   split (spade's constraint edges are never subdivided because we only
//!   insert points strictly inside faces of the domain).
//! * The target size `h(x)` interpolates the sizes given at the contour
//!   nodes by inverse squared distance, so a contour graded from fine to
//!   coarse gives an interior graded the same way.
//! * Delaunay refinement by size: a triangle whose circumradius `R` exceeds
//!   `1.3 h / √3` (the circumradius of an equilateral triangle of side
//!   `1.3 h`) gets a new point at its circumcentre, or at its centroid when
//!   the circumcentre falls outside the domain or closer than `0.55 h` to a
//!   node. Insertions keep every new node at least `0.55 h` from the others,
//!   so the process ends.
//! * A few passes of Laplacian smoothing (each interior node to the mean of
//!   its neighbours, when its triangles stay positive), each followed by a
//!   new Delaunay triangulation, even out the shapes.
//!
//! Which side of the polygons is meshed follows the even-odd rule: a face
//! is inside when reaching it from outside crosses the contour an odd
//! number of times, so inner loops are holes.

use super::{fail, MeshError};
use spade::handles::FixedFaceHandle;
use spade::{ConstrainedDelaunayTriangulation, FloatTriangulation, Point2, PositionInTriangulation, Triangulation};

pub(crate) type Cdt = ConstrainedDelaunayTriangulation<Point2<f64>>;

/// A triangulated region: `points` starts with the input points, in their
/// order; `sizes` is the target size at each point; `triangles` are
/// counter-clockwise.
#[derive(Debug, Clone)]
pub struct Planar {
    pub points: Vec<[f64; 2]>,
    pub sizes: Vec<f64>,
    pub triangles: Vec<[usize; 3]>,
}

/// Refinement threshold: edge of the equilateral triangle with the same
/// circumradius, relative to the target size.
const TOO_BIG: f64 = 1.45;
/// No new node closer than this fraction of the target size to another.
const SPACING: f64 = 0.55;
const SMOOTHING_PASSES: usize = 4;
/// A safety net on the node count: a density far too small for the region.
pub const MAX_POINTS: usize = 2_000_000;

/// Triangulate the region bounded by `loops` (closed polygons given as
/// indices into `pts`), with target sizes `sizes[i]` at the contour points.
pub fn triangulate(
    op: &'static str,
    pts: &[[f64; 2]],
    sizes: &[f64],
    loops: &[Vec<usize>],
) -> Result<Planar, MeshError> {
    if pts.iter().flatten().any(|c| !c.is_finite()) || sizes.iter().any(|s| !(s.is_finite() && *s > 0.0)) {
        return fail(op, "the contour has a coordinate or a size that is not a positive finite number");
    }
    let edges: Vec<[usize; 2]> =
        loops.iter().flat_map(|l| (0..l.len()).map(move |i| [l[i], l[(i + 1) % l.len()]])).collect();
    let size = SizeField::new(pts, sizes);
    let mut points: Vec<[f64; 2]> = pts.to_vec();
    let mut cdt = load(op, &points, &edges)?;
    refine(op, &mut cdt, &size)?;
    for _ in 0..SMOOTHING_PASSES {
        points = cdt.vertices().map(|v| [v.position().x, v.position().y]).collect();
        if !smooth(&cdt, pts.len(), &mut points) {
            break;
        }
        cdt = load(op, &points, &edges)?;
    }
    let points: Vec<[f64; 2]> = cdt.vertices().map(|v| [v.position().x, v.position().y]).collect();
    let triangles = inside_triangles(&cdt);
    let sizes = points.iter().map(|p| size.at(Point2::new(p[0], p[1]))).collect();
    Ok(Planar { points, sizes, triangles })
}

pub(crate) fn load(op: &'static str, points: &[[f64; 2]], edges: &[[usize; 2]]) -> Result<Cdt, MeshError> {
    // Coordinates below spade's smallest (about 1e-43, left by rounding in
    // a change of frame) are zeros.
    let verts: Vec<Point2<f64>> = points.iter().map(|p| spade::mitigate_underflow(Point2::new(p[0], p[1]))).collect();
    let mut crossing = false;
    let cdt = Cdt::try_bulk_load_cdt(verts, edges.to_vec(), |_| crossing = true)
        .map_err(|e| super::MeshError::new(op, format!("the contour cannot be triangulated ({e:?})")))?;
    if cdt.num_vertices() != points.len() {
        return fail(op, "two points of the contour are at the same place (merge them with ELIM)");
    }
    if crossing {
        return fail(op, "the contour crosses itself");
    }
    Ok(cdt)
}

/// The triangles inside the region, as vertex indices of the triangulation.
pub(crate) fn inside_triangles(cdt: &Cdt) -> Vec<[usize; 3]> {
    let inside = inside_faces(cdt);
    cdt.inner_faces()
        .filter(|f| inside[f.fix().index()])
        .map(|f| {
            let v = f.vertices();
            [v[0].fix().index(), v[1].fix().index(), v[2].fix().index()]
        })
        .collect()
}

/// Which faces (by index) are inside the region: faces reached from the
/// convex hull without crossing a constraint are outside, and each
/// constraint crossed flips the side.
pub(crate) fn inside_faces(cdt: &Cdt) -> Vec<bool> {
    let n = cdt.num_all_faces();
    let mut side: Vec<Option<bool>> = vec![None; n];
    type Item = (FixedFaceHandle<spade::handles::PossiblyOuterTag>, bool);
    let (mut todo, mut next): (Vec<Item>, Vec<Item>) = (Vec::new(), Vec::new());
    // Layer by layer: the faces reached from outside without crossing the
    // contour first, then those behind one crossing, and so on.
    for e in cdt.convex_hull() {
        let f = e.rev().face().fix();
        if e.is_constraint_edge() {
            next.push((f, true));
        } else {
            todo.push((f, false));
        }
    }
    if todo.is_empty() {
        std::mem::swap(&mut todo, &mut next);
    }
    while !todo.is_empty() {
        while let Some((f, s)) = todo.pop() {
            let Some(inner) = cdt.face(f).as_inner() else { continue };
            let k = inner.fix().index();
            if side[k].is_some() {
                continue;
            }
            side[k] = Some(s);
            for e in inner.adjacent_edges() {
                let other = e.rev().face().fix();
                if e.is_constraint_edge() {
                    next.push((other, !s));
                } else {
                    todo.push((other, s));
                }
            }
        }
        std::mem::swap(&mut todo, &mut next);
    }
    side.into_iter().map(|s| s == Some(true)).collect()
}

fn refine(op: &'static str, cdt: &mut Cdt, size: &SizeField) -> Result<(), MeshError> {
    loop {
        let mut inside = inside_faces(cdt);
        let mut cands: Vec<(f64, Point2<f64>, Point2<f64>)> = Vec::new();
        for f in cdt.inner_faces().filter(|f| inside[f.fix().index()]) {
            let (cc, r2) = f.circumcircle();
            let c = f.center();
            let ratio = (3.0 * r2).sqrt() / size.at(c);
            if ratio > TOO_BIG {
                cands.push((ratio, cc, c));
            }
        }
        if cands.is_empty() {
            return Ok(());
        }
        cands.sort_by(|a, b| b.0.total_cmp(&a.0));
        let mut inserted = 0;
        for (_, cc, c) in cands {
            for p in [cc, c] {
                if !p.x.is_finite() || !p.y.is_finite() {
                    continue;
                }
                let inside_face = match cdt.locate(p) {
                    PositionInTriangulation::OnFace(f) => inside.get(f.index()).copied().unwrap_or(true),
                    _ => false,
                };
                let h = size.at(p);
                if !inside_face || cdt.get_vertices_in_circle(p, (SPACING * h).powi(2)).next().is_some() {
                    continue;
                }
                cdt.insert(spade::mitigate_underflow(p))
                    .map_err(|e| super::MeshError::new(op, format!("cannot insert a point ({e:?})")))?;
                // Faces made by an insertion inside the region are inside.
                inside.resize(cdt.num_all_faces(), true);
                inserted += 1;
                break;
            }
        }
        if cdt.num_vertices() > MAX_POINTS {
            return fail(op, format!("more than {MAX_POINTS} nodes: the density is far too small for the region"));
        }
        if inserted == 0 {
            return Ok(());
        }
    }
}

/// One pass of Laplacian smoothing of the points after the first `fixed`
/// ones (the contour); a point moves only if its triangles stay
/// counter-clockwise. Returns whether anything moved.
fn smooth(cdt: &Cdt, fixed: usize, points: &mut [[f64; 2]]) -> bool {
    let mut moved = false;
    for v in cdt.vertices().skip(fixed) {
        let ring: Vec<[f64; 2]> = v.out_edges().map(|e| points[e.to().fix().index()]).collect();
        if ring.len() < 3 {
            continue;
        }
        let k = ring.len() as f64;
        let p = [ring.iter().map(|q| q[0]).sum::<f64>() / k, ring.iter().map(|q| q[1]).sum::<f64>() / k];
        // out_edges turn counter-clockwise around v, so (p, r_i, r_i+1)
        // must stay counter-clockwise.
        let ok = (0..ring.len()).all(|i| {
            let (a, b) = (ring[i], ring[(i + 1) % ring.len()]);
            (a[0] - p[0]) * (b[1] - p[1]) - (a[1] - p[1]) * (b[0] - p[0]) > 0.0
        });
        let i = v.fix().index();
        if ok && p != points[i] {
            points[i] = p;
            moved = true;
        }
    }
    moved
}

/// Target size inside: inverse-squared-distance mean of the contour sizes.
struct SizeField {
    at: Vec<([f64; 2], f64)>,
}

impl SizeField {
    fn new(pts: &[[f64; 2]], sizes: &[f64]) -> Self {
        SizeField { at: pts.iter().copied().zip(sizes.iter().copied()).collect() }
    }

    fn at(&self, p: Point2<f64>) -> f64 {
        let (mut num, mut den) = (0.0, 0.0);
        for (q, h) in &self.at {
            let d2 = (q[0] - p.x).powi(2) + (q[1] - p.y).powi(2);
            if d2 == 0.0 {
                return *h;
            }
            num += h / d2;
            den += 1.0 / d2;
        }
        num / den
    }
}
