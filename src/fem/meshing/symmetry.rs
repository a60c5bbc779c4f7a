//! SYME: the mirror image of a point or a mesh.
//!
//! Every node gets a new node at its image, nodes on the mirror included,
//! as Cast3M does (decks join the halves with `ET` and merge the nodes on
//! the mirror with `ELIM`). Elements keep their place in the mesh. Lines
//! keep their node order, so the image of a line runs from the image of
//! its first point. Elements of the space's dimension (surfaces in 2D,
//! volumes in 3D) are turned over when the symmetry reverses orientation
//! (a mirror line in 2D, a plane or a point in 3D), so that the image of
//! a counter-clockwise surface is counter-clockwise and the image of a
//! positive volume is positive. Surfaces in 3D keep their node order, as
//! Cast3M's crack decks expect (the lower lip is INVE of the upper one's
//! image).

use super::vec3::{add, cross, dot, norm, scale, sub, V3};
use super::{check_nodes, fail, MeshError, NodeMap};
use crate::fem::mesh::{ElemType, Mesh, Nodes, Part};

/// The symmetry element.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Mirror {
    /// `'DROIT' P1 P2`: a mirror line in 2D; in 3D the half-turn about the line.
    Line(V3, V3),
    /// `'PLAN' P1 P2 P3` (3D).
    Plane(V3, V3, V3),
    /// `'POINT' P`: the half-turn about P in 2D, the inversion through P in 3D.
    Point(V3),
}

impl Mirror {
    /// The image of `x` (in 2D, z stays 0).
    pub fn image(&self, x: V3) -> V3 {
        match *self {
            Mirror::Line(a, b) => {
                let d = sub(b, a);
                let t = dot(sub(x, a), d) / dot(d, d);
                let foot = add(a, scale(d, t));
                sub(scale(foot, 2.0), x)
            }
            Mirror::Plane(a, b, c) => {
                let n = cross(sub(b, a), sub(c, a));
                let h = dot(sub(x, a), n) / dot(n, n);
                sub(x, scale(n, 2.0 * h))
            }
            Mirror::Point(p) => sub(scale(p, 2.0), x),
        }
    }

    /// Whether the symmetry reverses orientation in dimension `dim`.
    pub fn reverses(&self, dim: usize) -> bool {
        match self {
            Mirror::Line(..) => dim == 2,
            Mirror::Plane(..) => true,
            Mirror::Point(_) => dim == 3,
        }
    }

    /// Check that the points define the element.
    pub fn check(&self, dim: usize) -> Result<(), MeshError> {
        const OP: &str = "SYME";
        match *self {
            Mirror::Line(a, b) if norm(sub(b, a)) == 0.0 => fail(OP, "the two points of the line coincide"),
            Mirror::Plane(..) if dim != 3 => fail(OP, "'PLAN' needs OPTI DIME 3; in 2D use 'DROIT' P1 P2"),
            Mirror::Plane(a, b, c) if norm(cross(sub(b, a), sub(c, a))) == 0.0 => {
                fail(OP, "the three points of the plane are aligned")
            }
            _ => Ok(()),
        }
    }
}

/// Node permutation that turns an element over, keeping its first node.
pub(crate) fn turn_over(ty: ElemType) -> &'static [usize] {
    match ty {
        ElemType::Poi1 => &[0],
        ElemType::Seg2 => &[0, 1],
        ElemType::Seg3 => &[0, 1, 2],
        ElemType::Tri3 => &[0, 2, 1],
        ElemType::Qua4 => &[0, 3, 2, 1],
        ElemType::Tri6 => &[0, 5, 4, 3, 2, 1],
        ElemType::Qua8 => &[0, 7, 6, 5, 4, 3, 2, 1],
        ElemType::Cub8 => &[0, 3, 2, 1, 4, 7, 6, 5],
        ElemType::Tet4 => &[0, 2, 1, 3],
        ElemType::Pri6 => &[0, 2, 1, 3, 5, 4],
        ElemType::Pyr5 => &[0, 3, 2, 1, 4],
        ElemType::Cu20 => &[0, 7, 6, 5, 4, 3, 2, 1, 8, 11, 10, 9, 12, 19, 18, 17, 16, 15, 14, 13],
        ElemType::Pr15 => &[0, 5, 4, 3, 2, 1, 6, 8, 7, 9, 14, 13, 12, 11, 10],
        ElemType::Rac2 => &[0, 1, 2, 3],
        ElemType::Rac3 => &[0, 1, 2, 3, 4, 5],
        ElemType::Lia3 => &[0, 2, 1, 3, 5, 4],
        ElemType::Lia4 => &[0, 3, 2, 1, 4, 7, 6, 5],
        ElemType::Mult3 => &[0, 1, 2],
        ElemType::Mult4 => &[0, 1, 2, 3],
        ElemType::Mult5 => &[0, 1, 2, 3, 4],
    }
}

/// `GEO SYME …`: the image of `mesh` on new nodes (see the module doc).
pub fn syme(nodes: &mut Nodes, mesh: &Mesh, mirror: Mirror, dim: usize) -> Result<Mesh, MeshError> {
    Ok(syme_together(nodes, &[mesh], mirror, dim)?.remove(0))
}

/// The mirror images of several meshes at once (`m2 f2 = m1 f1 SYME …`):
/// a node they share has one image.
pub fn syme_together(nodes: &mut Nodes, meshes: &[&Mesh], mirror: Mirror, dim: usize) -> Result<Vec<Mesh>, MeshError> {
    mirror.check(dim)?;
    let mut map = NodeMap::default();
    for mesh in meshes {
        check_nodes("SYME", nodes, mesh)?;
        for n in mesh.node_list() {
            if let std::collections::hash_map::Entry::Vacant(e) = map.map.entry(n) {
                e.insert(nodes.push(mirror.image(nodes.get(n)), nodes.density[n]));
            }
        }
    }
    Ok(meshes
        .iter()
        .map(|mesh| {
            let image = map.apply(mesh);
            if !mirror.reverses(dim) {
                return image;
            }
            let parts = image
                .parts
                .into_iter()
                // Only elements of the space's own dimension (surfaces in
                // 2D, volumes in 3D) are turned over: their measure must stay
                // positive. A surface in 3D keeps its node order, as a line
                // does: a face in the mirror plane keeps its normal, and a
                // crack's other lip is INVE of its image.
                .map(|p| {
                    if p.ty.dim() != dim {
                        return p;
                    }
                    let perm = turn_over(p.ty);
                    let conn = p.elems().flat_map(|e| perm.iter().map(move |&k| e[k])).collect();
                    Part { conn, ..p }
                })
                .collect();
            Mesh { parts }
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn images_of_a_point() {
        let x = [3.0, 1.0, 2.0];
        let line = Mirror::Line([0.0, 0.0, 0.0], [1.0, 1.0, 0.0]);
        assert_eq!(line.image([3.0, 1.0, 0.0]), [1.0, 3.0, 0.0]);
        let plane = Mirror::Plane([0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [0.0, 1.0, 1.0]);
        assert_eq!(plane.image(x), [3.0, 1.0, 0.0]);
        assert_eq!(Mirror::Point([1.0, 1.0, 1.0]).image(x), [-1.0, 1.0, 0.0]);
        // In 3D a line is the axis of a half-turn.
        let axis = Mirror::Line([0.0, 0.0, 0.0], [0.0, 0.0, 5.0]);
        assert_eq!(axis.image(x), [-3.0, -1.0, 2.0]);
    }

    #[test]
    fn a_mirrored_surface_keeps_its_orientation_and_a_line_its_direction() {
        let mut nodes = Nodes::default();
        for x in [[1.0, 0.0, 0.0], [2.0, 0.0, 0.0], [2.0, 1.0, 0.0], [1.0, 1.0, 0.0]] {
            nodes.push(x, 1.0);
        }
        let q = Mesh::single(Part::with(ElemType::Qua4, vec![0, 1, 2, 3]));
        let m = syme(&mut nodes, &q, Mirror::Line([0.0, 0.0, 0.0], [0.0, 1.0, 0.0]), 2).unwrap();
        let e = m.parts[0].elem(0);
        let x: Vec<V3> = e.iter().map(|&n| nodes.get(n)).collect();
        // Signed area (shoelace) stays positive.
        let area: f64 = (0..4).map(|i| x[i][0] * x[(i + 1) % 4][1] - x[(i + 1) % 4][0] * x[i][1]).sum::<f64>() / 2.0;
        assert_eq!(area, 1.0);
        assert_eq!(nodes.get(e[0]), [-1.0, 0.0, 0.0]);
        let l = Mesh::single(Part::with(ElemType::Seg2, vec![0, 1]));
        let ml = syme(&mut nodes, &l, Mirror::Line([0.0, 0.0, 0.0], [0.0, 1.0, 0.0]), 2).unwrap();
        assert_eq!(nodes.get(ml.parts[0].conn[1]), [-2.0, 0.0, 0.0]);
    }
}
