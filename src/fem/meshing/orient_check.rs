//! VERSENS: find two neighbouring elements run in opposite directions
//! (two line elements meeting end to end or start to start; two surface
//! elements running their shared edge the same way).
//!
//! The meeting places are ORIE's (`orient::connectors`): two neighbours
//! agree when they run through the place they share with opposite signs.
//! A place shared by more than two elements (a branching line, a
//! T-junction of surfaces) has no single consistent orientation and is
//! not checked; volumes carry no such orientation either.

use super::orient::connectors;
use crate::fem::mesh::Mesh;
use std::collections::HashMap;

/// A meeting place within one element dimension: (dimension, place).
type Place = (usize, (usize, usize));

/// Two opposed neighbours, as element numbers (0-based, counted over
/// the whole mesh in part order), if any.
pub fn opposed_neighbours(mesh: &Mesh) -> Option<(usize, usize)> {
    let mut at: HashMap<Place, Vec<(usize, i8)>> = HashMap::new();
    let mut n = 0;
    for p in &mesh.parts {
        for e in p.elems() {
            for (key, s) in connectors(p.ty, e) {
                at.entry((p.ty.dim(), key)).or_default().push((n, s));
            }
            n += 1;
        }
    }
    let mut found: Vec<(usize, usize)> = at
        .values()
        .filter(|v| v.len() == 2 && v[0].1 == v[1].1 && v[0].0 != v[1].0)
        .map(|v| (v[0].0.min(v[1].0), v[0].0.max(v[1].0)))
        .collect();
    found.sort_unstable();
    found.first().copied()
}
