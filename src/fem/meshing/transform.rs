//! Point maps applied to copies of meshes: HOMO (homothety), AFFI
//! (affinity), PROJ (projection on a plane, a line, a sphere, a circle or a
//! cylinder: on a round target, the nearer of the two points where the
//! line of projection meets it), and BARY (the
//! barycentre of the nodes).
//!
//! As for PLUS and SYME, every node of the mesh gets a new node at its
//! image, appended in node order ([`Mesh::node_list`]), and the copy has
//! the same elements in the same order. A map that reverses orientation
//! (a homothety of negative ratio in 3D, an affinity of negative ratio)
//! turns surface and volume elements over, as SYME does, so that the image
//! of a counter-clockwise surface or a positive volume stays so.

use super::symmetry::turn_over;
use super::vec3::{add, cross, dot, norm, scale, sub, V3};
use super::{check_nodes, fail, MeshError, NodeMap};
use crate::fem::mesh::{Mesh, Nodes, Part};

/// A point map.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PointMap {
    /// `HOMO k C`: `C + k (x - C)`.
    Homothety { ratio: f64, centre: V3 },
    /// `AFFI k P1 P2 (P3)`: the component of `x - P1` normal to the base
    /// (the line P1 P2 in 2D, the plane P1 P2 P3 in 3D) times k.
    Affinity { ratio: f64, origin: V3, normal: V3 },
    /// `PROJ 'CYLI' V …`: along the direction V onto the target.
    Cylindrical { dir: V3, target: Target },
    /// `PROJ 'CONI' S …`: along the ray from the apex S onto the target.
    Conical { apex: V3, target: Target },
}

/// What PROJ projects on: a plane (3D) or a line (2D), given by a point
/// and a unit normal; a sphere (3D) or a circle (2D); a cylinder.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Target {
    Plane {
        origin: V3,
        normal: V3,
    },
    /// A sphere (a circle in the plane z = 0); with an axis (a unit vector
    /// through the centre), the cylinder about it.
    Round {
        centre: V3,
        axis: Option<V3>,
        radius: f64,
    },
}

impl Target {
    /// `'PLAN' P1 P2 P3`.
    pub fn plane(op: &'static str, a: V3, b: V3, c: V3) -> Result<Target, MeshError> {
        unit(op, cross(sub(b, a), sub(c, a)), "the three points of the plane are aligned")
            .map(|normal| Target::Plane { origin: a, normal })
    }

    /// `'DROI' P1 P2` in the plane z = 0.
    pub fn line2d(op: &'static str, a: V3, b: V3) -> Result<Target, MeshError> {
        let d = sub(b, a);
        unit(op, [-d[1], d[0], 0.0], "the two points of the line coincide")
            .map(|normal| Target::Plane { origin: a, normal })
    }

    /// `'SPHE' C P` (`'CERC' C P` in 2D): centre C, through P.
    pub fn sphere(op: &'static str, centre: V3, p: V3) -> Result<Target, MeshError> {
        let radius = norm(sub(p, centre));
        if !(radius > 0.0 && radius.is_finite()) {
            return fail(op, "the point the sphere passes through is its centre");
        }
        Ok(Target::Round { centre, axis: None, radius })
    }

    /// `'CYLI' C1 C2 P`: the axis through C1 and C2, through P.
    pub fn cylinder(op: &'static str, c1: V3, c2: V3, p: V3) -> Result<Target, MeshError> {
        let k = unit(op, sub(c2, c1), "the two points of the cylinder's axis coincide")?;
        let w = sub(p, c1);
        let radius = norm(sub(w, scale(k, dot(w, k))));
        if !(radius > 0.0 && radius.is_finite()) {
            return fail(op, "the point the cylinder passes through is on its axis");
        }
        Ok(Target::Round { centre: c1, axis: Some(k), radius })
    }

    /// The unit normal of a plane target (AFFI's base).
    fn normal(&self) -> V3 {
        match *self {
            Target::Plane { normal, .. } => normal,
            Target::Round { .. } => [0.0; 3],
        }
    }

    /// Where the line `x + t d` meets the target, nearest to `x` (the
    /// smallest |t|), or None when it misses it.
    fn hit(&self, x: V3, d: V3) -> Option<V3> {
        let t = match *self {
            Target::Plane { origin, normal } => {
                let along = dot(d, normal);
                if along.abs() <= 1e-12 * norm(d) {
                    return None;
                }
                dot(sub(origin, x), normal) / along
            }
            Target::Round { centre, axis, radius } => {
                // Across the axis for a cylinder: |w + t e|² = R².
                let flat = |v: V3| axis.map_or(v, |k| sub(v, scale(k, dot(v, k))));
                let (w, e) = (flat(sub(x, centre)), flat(d));
                let (a, b, c) = (dot(e, e), dot(e, w), dot(w, w) - radius * radius);
                let disc = b * b - a * c;
                if a <= 1e-24 * dot(d, d) || disc < 0.0 {
                    return None;
                }
                let (t1, t2) = ((-b - disc.sqrt()) / a, (-b + disc.sqrt()) / a);
                // A tie (the point on the axis) goes along the direction.
                if t2.abs() <= t1.abs() {
                    t2
                } else {
                    t1
                }
            }
        };
        t.is_finite().then(|| add(x, scale(d, t)))
    }
}

fn unit(op: &'static str, v: V3, why: &str) -> Result<V3, MeshError> {
    let l = norm(v);
    if l == 0.0 || !l.is_finite() {
        return fail(op, why);
    }
    Ok(scale(v, 1.0 / l))
}

impl PointMap {
    /// `AFFI` in 2D: base line P1 P2.
    pub fn affinity_2d(ratio: f64, a: V3, b: V3) -> Result<PointMap, MeshError> {
        let t = Target::line2d("AFFI", a, b)?;
        Ok(PointMap::Affinity { ratio, origin: a, normal: t.normal() })
    }

    /// `AFFI ratio P1 P2` in 3D (affi.notice): distances along the
    /// direction P1 → P2, from the plane through P1 across it, scaled.
    pub fn affinity_along(ratio: f64, a: V3, b: V3) -> Result<PointMap, MeshError> {
        let d = sub(b, a);
        if norm(d) == 0.0 {
            return fail("AFFI", "the two points giving the direction coincide");
        }
        Ok(PointMap::Affinity { ratio, origin: a, normal: scale(d, 1.0 / norm(d)) })
    }

    /// `AFFI` in 3D: base plane P1 P2 P3.
    pub fn affinity_3d(ratio: f64, a: V3, b: V3, c: V3) -> Result<PointMap, MeshError> {
        let t = Target::plane("AFFI", a, b, c)?;
        Ok(PointMap::Affinity { ratio, origin: a, normal: t.normal() })
    }

    fn op(&self) -> &'static str {
        match self {
            PointMap::Homothety { .. } => "HOMO",
            PointMap::Affinity { .. } => "AFFI",
            _ => "PROJ",
        }
    }

    /// The image of `x`; a projection fails for a point whose ray misses
    /// the target (parallel to it, or through the apex).
    pub fn image(&self, x: V3) -> Result<V3, MeshError> {
        match *self {
            PointMap::Homothety { ratio, centre } => Ok(add(centre, scale(sub(x, centre), ratio))),
            PointMap::Affinity { ratio, origin, normal } => {
                let h = dot(sub(x, origin), normal);
                Ok(add(x, scale(normal, (ratio - 1.0) * h)))
            }
            PointMap::Cylindrical { dir, target } => target.hit(x, dir).ok_or_else(|| {
                // A line misses a plane only by being parallel to it.
                let why = match target {
                    Target::Plane { .. } => "is parallel to the target",
                    Target::Round { .. } => "misses the target",
                };
                MeshError::new("PROJ", format!("the direction of projection {}", why))
            }),
            PointMap::Conical { apex, target } => {
                let ray = sub(x, apex);
                match norm(ray) > 0.0 {
                    true => target.hit(x, ray),
                    false => None,
                }
                .ok_or_else(|| {
                    MeshError::new("PROJ", format!("the ray from the apex through {:?} does not meet the target", x))
                })
            }
        }
    }

    /// Factor applied to the density of a node (a length).
    fn density_factor(&self) -> f64 {
        match *self {
            PointMap::Homothety { ratio, .. } => ratio.abs(),
            _ => 1.0,
        }
    }

    /// Whether the map reverses the orientation of `dim`-dimensional space.
    fn reverses(&self, dim: usize) -> bool {
        match *self {
            PointMap::Homothety { ratio, .. } => ratio < 0.0 && dim % 2 == 1,
            PointMap::Affinity { ratio, .. } => ratio < 0.0,
            _ => false,
        }
    }

    /// A homothety or affinity of ratio 0 flattens the mesh: allowed, as
    /// it is a projection, but its elements are degenerate.
    fn check(&self) -> Result<(), MeshError> {
        match *self {
            PointMap::Homothety { ratio, .. } | PointMap::Affinity { ratio, .. } if !ratio.is_finite() => {
                fail(self.op(), "the ratio is not a finite number")
            }
            _ => Ok(()),
        }
    }
}

/// The image of one point: a new node.
pub fn map_point(nodes: &mut Nodes, p: usize, map: PointMap) -> Result<usize, MeshError> {
    super::check_node(map.op(), nodes, p)?;
    map.check()?;
    let x = map.image(nodes.get(p))?;
    Ok(nodes.push(x, nodes.density[p] * map.density_factor()))
}

/// The image of a mesh on new nodes (see the module doc); `dim` is the
/// space dimension (OPTI DIME).
pub fn map_copy(nodes: &mut Nodes, mesh: &Mesh, map: PointMap, dim: usize) -> Result<Mesh, MeshError> {
    check_nodes(map.op(), nodes, mesh)?;
    map.check()?;
    let list = mesh.node_list();
    // Every image first, so that a failing point leaves the table untouched.
    let images = list.iter().map(|&n| map.image(nodes.get(n))).collect::<Result<Vec<_>, _>>()?;
    let mut nm = NodeMap::default();
    for (&n, x) in list.iter().zip(images) {
        nm.map.insert(n, nodes.push(x, nodes.density[n] * map.density_factor()));
    }
    let image = nm.apply(mesh);
    if !map.reverses(dim) {
        return Ok(image);
    }
    let parts = image
        .parts
        .into_iter()
        .map(|p| {
            if p.ty.dim() < 2 {
                return p;
            }
            let perm = turn_over(p.ty);
            let conn = p.elems().flat_map(|e| perm.iter().map(move |&k| e[k])).collect();
            Part { conn, ..p }
        })
        .collect();
    Ok(Mesh { parts })
}

/// `BARY GEO`: the barycentre of the distinct nodes of the mesh, each
/// node weighing the same whatever the elements around it.
pub fn barycentre(nodes: &Nodes, mesh: &Mesh) -> Result<V3, MeshError> {
    check_nodes("BARY", nodes, mesh)?;
    let list = mesh.node_list();
    if list.is_empty() {
        return fail("BARY", "the mesh is empty");
    }
    let s = list.iter().fold([0.0; 3], |s, &n| add(s, nodes.get(n)));
    Ok(scale(s, 1.0 / list.len() as f64))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fem::mesh::ElemType;

    fn close(a: V3, b: V3) -> bool {
        norm(sub(a, b)) < 1e-12
    }

    #[test]
    fn images_of_a_point() {
        let h = PointMap::Homothety { ratio: 2.0, centre: [1.0, 1.0, 0.0] };
        assert!(close(h.image([2.0, 3.0, 0.0]).unwrap(), [3.0, 5.0, 0.0]));
        let a = PointMap::affinity_2d(3.0, [0.0, 1.0, 0.0], [2.0, 1.0, 0.0]).unwrap();
        assert!(close(a.image([5.0, 2.0, 0.0]).unwrap(), [5.0, 4.0, 0.0]));
        let plane = Target::plane("PROJ", [0.0, 0.0, 2.0], [1.0, 0.0, 2.0], [0.0, 1.0, 2.0]).unwrap();
        let c = PointMap::Cylindrical { dir: [1.0, 0.0, 1.0], target: plane };
        assert!(close(c.image([0.0, 0.0, 0.0]).unwrap(), [2.0, 0.0, 2.0]));
        let k = PointMap::Conical { apex: [0.0, 0.0, 0.0], target: plane };
        assert!(close(k.image([1.0, 1.0, 1.0]).unwrap(), [2.0, 2.0, 2.0]));
        let par = PointMap::Cylindrical { dir: [1.0, 0.0, 0.0], target: plane };
        assert!(par.image([0.0; 3]).is_err());
        let ball = Target::sphere("PROJ", [0.0; 3], [0.0, 0.0, 2.0]).unwrap();
        let k = PointMap::Conical { apex: [0.0; 3], target: ball };
        assert!(close(k.image([3.0, 4.0, 0.0]).unwrap(), [1.2, 1.6, 0.0]));
        let c = PointMap::Cylindrical { dir: [0.0, 0.0, -1.0], target: ball };
        assert!(close(c.image([0.0, 0.0, 5.0]).unwrap(), [0.0, 0.0, 2.0]));
        assert!(c.image([3.0, 0.0, 5.0]).is_err());
        let tube = Target::cylinder("PROJ", [0.0; 3], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0]).unwrap();
        let c = PointMap::Cylindrical { dir: [1.0, 1.0, 0.0], target: tube };
        let h = 0.5f64.sqrt();
        assert!(close(c.image([0.0, 0.0, 7.0]).unwrap(), [h, h, 7.0]));
    }

    #[test]
    fn an_inversion_in_3d_keeps_volumes_positive() {
        let mut nodes = Nodes::default();
        for x in [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]] {
            nodes.push(x, 1.0);
        }
        let t = Mesh::single(Part::with(ElemType::Tet4, vec![0, 1, 2, 3]));
        let m = map_copy(&mut nodes, &t, PointMap::Homothety { ratio: -2.0, centre: [0.0; 3] }, 3).unwrap();
        let x: Vec<V3> = m.parts[0].elem(0).iter().map(|&n| nodes.get(n)).collect();
        let vol = dot(sub(x[1], x[0]), cross(sub(x[2], x[0]), sub(x[3], x[0])));
        assert!(vol > 0.0);
        assert_eq!(nodes.density[m.parts[0].conn[0]], 2.0);
    }
}
