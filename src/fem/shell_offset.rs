//! Eccentric flat shells (MATE … 'EXCE' e): the mid-surface lies at e
//! along the element normal from the nodes' plane (the reference
//! surface). Under Kirchhoff's hypothesis a fibre at height e stretches
//! by ε + e κ, ε the reference membrane strains and κ the curvatures, so
//! the mid-surface's membrane strain is read through the element's own
//! curvature rows (DKT/DKQ), not through a rigid shift of the nodes: a
//! shift u + e θ would differentiate the linearly interpolated nodal
//! rotations, which the discrete Kirchhoff curvature does not tie to w,
//! and a stack of thin offset layers (a multilayer shell) would then
//! have almost no bending stiffness in w.

use super::plate::PlatePoint;

/// The mid-surface membrane strain rows over the element's local dofs
/// (6 per node): the membrane rows on the (u1, u2) dofs plus e times the
/// curvature rows on the (w, θ1, θ2) dofs. `mem` and `bend` map a
/// membrane or bending dof to its place among the local dofs.
pub(crate) fn membrane_rows(
    p: &PlatePoint,
    e: f64,
    mem: impl Fn(usize) -> usize,
    bend: impl Fn(usize) -> usize,
) -> [Vec<f64>; 3] {
    let n = 6 * (p.bm[0].len() / 2);
    std::array::from_fn(|r| {
        let mut row = vec![0.0; n];
        for (c, v) in p.bm[r].iter().enumerate() {
            row[mem(c)] += v;
        }
        if e != 0.0 {
            for (c, v) in p.bb[r].iter().enumerate() {
                row[bend(c)] += e * v;
            }
        }
        row
    })
}
