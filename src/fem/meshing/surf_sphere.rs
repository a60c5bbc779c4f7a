//! SURF 'SPHE': a contour drawn on a sphere is filled on the sphere.
//!
//! The contour is brought onto the plane tangent to the sphere at the mean
//! direction of its nodes (the pole) by stereographic projection from the
//! opposite point, filled there like a plane contour, and the new nodes are
//! sent back to the sphere by the inverse projection. The projection is
//! conformal (shapes are kept, sizes grow by 2 / (1 + cos a) at the angle
//! a from the pole), so well-shaped plane triangles stay well shaped on
//! the sphere, from a small cap to well past a hemisphere. The region filled
//! is the one around the pole: the cap on the side of the sphere where the
//! contour's nodes mostly are.
//!
//! The sphere's radius is the mean distance of the contour's nodes to the
//! centre (they should all be at that distance).

use super::vec3::{add, dot, norm, scale, sub, V3};
use super::{fail, MeshError};

/// Nodes closer than this to the point opposite the pole (in cosine of the
/// angle from the pole, beyond about 160 degrees) would go too far out on
/// the plane.
const MIN_COS: f64 = -0.94;

#[derive(Debug, Clone, Copy)]
pub struct Stereographic {
    centre: V3,
    radius: f64,
    /// Unit vector from the centre towards the contour.
    axis: V3,
}

impl Stereographic {
    /// The projection for the contour nodes at `points` on the sphere
    /// centred at `centre`.
    pub fn new(op: &'static str, centre: V3, points: &[V3]) -> Result<Stereographic, MeshError> {
        if points.is_empty() {
            return fail(op, "the contour has no node");
        }
        let rays: Vec<V3> = points.iter().map(|&x| sub(x, centre)).collect();
        let radius = rays.iter().map(|&r| norm(r)).sum::<f64>() / rays.len() as f64;
        if !(radius > 0.0 && radius.is_finite()) {
            return fail(op, "the contour's nodes are at the centre of the sphere");
        }
        let mut mean = [0.0; 3];
        for &r in &rays {
            let l = norm(r);
            if l > 0.0 {
                mean = add(mean, scale(r, 1.0 / l));
            }
        }
        let l = norm(mean);
        // Written so that a NaN length also fails.
        if l.is_nan() || l <= 1e-9 * rays.len() as f64 {
            return fail(op, "the contour goes all round the sphere: it encloses no cap");
        }
        let axis = scale(mean, 1.0 / l);
        for (i, &r) in rays.iter().enumerate() {
            let (c, m) = (dot(r, axis), MIN_COS * norm(r));
            if c.is_nan() || c <= m {
                return fail(
                    op,
                    format!(
                        "node {} of the contour is too far round the sphere from the others \
                         (the region filled is the cap around their mean direction)",
                        i + 1
                    ),
                );
            }
        }
        Ok(Stereographic { centre, radius, axis })
    }

    /// The point of the tangent plane at the pole seen from the opposite
    /// point through `x`.
    pub fn to_plane(&self, x: V3) -> V3 {
        let south = sub(self.centre, scale(self.axis, self.radius));
        let t = 2.0 * self.radius / (dot(sub(x, self.centre), self.axis) + self.radius);
        add(south, scale(sub(x, south), t))
    }

    /// The point of the sphere seen from the point opposite the pole
    /// through `p` (a point of the tangent plane).
    pub fn to_sphere(&self, p: V3) -> V3 {
        let south = sub(self.centre, scale(self.axis, self.radius));
        let w = sub(p, south);
        add(south, scale(w, 4.0 * self.radius * self.radius / dot(w, w)))
    }
}
