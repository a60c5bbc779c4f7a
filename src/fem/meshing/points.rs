//! `POINT ET MESH`: a point joined to a mesh of points.
//!
//! Unlike the union of two meshes, which drops elements already present,
//! a point always becomes one more POI1 element: decks collect points in
//! order with `m = m ET p` (or `p ET m`) and count on repeats being kept.

use crate::fem::mesh::{Colour, ElemType, Mesh};

/// `mesh` with the POI1 element of `p` added first (`front`) or last in
/// its POI1 part of the default colour (a new part when it has none).
pub fn add_point(mesh: &Mesh, p: usize, front: bool) -> Mesh {
    let mut out = mesh.clone();
    match out.parts.iter_mut().find(|q| q.ty == ElemType::Poi1 && q.colour == Colour::default()) {
        Some(q) if front => q.conn.insert(0, p),
        Some(q) => q.conn.push(p),
        None if front => return Mesh::points(&[p]).union(mesh),
        None => return mesh.union(&Mesh::points(&[p])),
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_point_already_there_is_added_again() {
        let m = Mesh::points(&[3, 4]);
        assert_eq!(add_point(&m, 3, true).parts[0].conn, vec![3, 3, 4]);
        assert_eq!(add_point(&m, 4, false).parts[0].conn, vec![3, 4, 4]);
    }
}
