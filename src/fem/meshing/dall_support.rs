//! DALL's support surfaces (`'SPHE'`, `'CYLI'`, `'CONI'`): the Coons patch
//! of the four sides is flat between them; its inner nodes are then moved
//! onto the surface the sides lie on.

use super::vec3::{add, dot, norm, scale, sub, V3};
use super::{fail, MeshError};
use crate::fem::mesh::Nodes;

/// The surface a DALL rests on.
#[derive(Clone, Copy, Debug)]
pub enum Support {
    /// Sphere of this centre.
    Sphere(V3),
    /// Cylinder of axis through the two points.
    Cylinder(V3, V3),
    /// Cone of apex the first point, axis towards the second.
    Cone(V3, V3),
}

/// Moves nodes `first..` (those DALL created) onto `support`; its size
/// (radius, half-angle) is the mean over `contour`, the side nodes, which
/// Cast3M expects to lie on it.
pub fn project(nodes: &mut Nodes, first: usize, contour: &[usize], support: Support) -> Result<(), MeshError> {
    const OP: &str = "DALL";
    if contour.is_empty() {
        return fail(OP, "the contour has no nodes");
    }
    let mean = |f: &dyn Fn(V3) -> f64| contour.iter().map(|&n| f(nodes.get(n))).sum::<f64>() / contour.len() as f64;
    match support {
        Support::Sphere(c) => {
            let r = mean(&|x| norm(sub(x, c)));
            for n in first..nodes.len() {
                let d = sub(nodes.get(n), c);
                let l = norm(d);
                if l < 1e-300 {
                    return fail(OP, "a node of the surface is at the centre of the sphere");
                }
                nodes.coords[n] = add(c, scale(d, r / l));
            }
        }
        Support::Cylinder(p1, p2) | Support::Cone(p1, p2) => {
            let axis = sub(p2, p1);
            let la = norm(axis);
            if la < 1e-300 {
                return fail(OP, "the two points of the axis are the same");
            }
            let u = scale(axis, 1.0 / la);
            // Axial coordinate and radial vector of a point.
            let split = |x: V3| {
                let d = sub(x, p1);
                let h = dot(d, u);
                (h, sub(d, scale(u, h)))
            };
            let cone = matches!(support, Support::Cone(..));
            // Radius of the cylinder, or slope (radius per axial length) of the cone.
            let size = mean(&|x| {
                let (h, r) = split(x);
                if cone {
                    norm(r) / h.abs().max(1e-300)
                } else {
                    norm(r)
                }
            });
            for n in first..nodes.len() {
                let (h, r) = split(nodes.get(n));
                let l = norm(r);
                if l < 1e-300 {
                    return fail(OP, "a node of the surface is on the axis");
                }
                let want = if cone { size * h.abs() } else { size };
                nodes.coords[n] = add(add(p1, scale(u, h)), scale(r, want / l));
            }
        }
    }
    Ok(())
}
