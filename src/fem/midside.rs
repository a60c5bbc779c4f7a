//! Mid-side nodes of quadratic elements and the two vertices each one
//! lies between, in the node order of [`super::mesh::ElemType`]
//! (RELA 'MILI' ties a mid-side node's unknowns to their mean).

use super::mesh::ElemType;

/// `(mid, a, b)`: local indices of a mid-side node and its edge's ends.
/// Linear elements have none.
pub fn midside(ty: ElemType) -> Vec<(usize, usize, usize)> {
    // A contour of 2n nodes, vertices at the even places.
    let ring = |n: usize, off: usize| (0..n).map(move |k| (off + 2 * k + 1, off + 2 * k, off + (2 * k + 2) % (2 * n)));
    match ty {
        ElemType::Seg3 => vec![(1, 0, 2)],
        ElemType::Tri6 => ring(3, 0).collect(),
        ElemType::Qua8 => ring(4, 0).collect(),
        // Bottom contour, mid-height nodes under each bottom corner, top
        // contour numbered as the bottom one.
        ElemType::Cu20 | ElemType::Pr15 => {
            let n = if ty == ElemType::Cu20 { 4 } else { 3 };
            let top = 3 * n;
            let mut v: Vec<_> = ring(n, 0).collect();
            v.extend((0..n).map(|k| (2 * n + k, 2 * k, top + 2 * k)));
            v.extend((0..n).map(|k| (top + 2 * k + 1, top + 2 * k, top + (2 * k + 2) % (2 * n))));
            v
        }
        _ => Vec::new(),
    }
}
