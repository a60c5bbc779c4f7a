//! Nodes on the crack surface when the crack runs along element sides
//! (faces in 3D, edges in 2D): PHI is zero there, so no element has PHI of
//! both signs and the cut-element rule enriches nothing, yet such a node's
//! support lies on both sides of the crack. It gets the jump, which opens
//! the crack between the elements above and below it.

use super::ElemLevels;
use std::collections::{BTreeMap, BTreeSet};

/// Nodes with PHI = 0 (within the element's tolerance) whose elements lie
/// wholly behind the front (PSI < 0) and wholly on one side, with some on
/// each side.
pub fn nodes_on_crack(elems: &[ElemLevels]) -> BTreeSet<usize> {
    // node -> (an element above it, an element below it)
    let mut sides: BTreeMap<usize, (bool, bool)> = BTreeMap::new();
    for e in elems {
        let tol = 1e-9 * e.size;
        let (s1, f0, f1) = e
            .phi
            .iter()
            .zip(e.psi)
            .fold((f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY), |(s1, f0, f1), (&f, &s)| {
                (s1.max(s), f0.min(f), f1.max(f))
            });
        let above = f0 >= -tol && f1 > tol;
        let below = f1 <= tol && f0 < -tol;
        if s1 >= -tol || !(above || below) {
            continue;
        }
        for (n, f) in e.nodes.iter().zip(e.phi) {
            if f.abs() <= tol {
                let s = sides.entry(*n).or_default();
                s.0 |= above;
                s.1 |= below;
            }
        }
    }
    sides.into_iter().filter(|(_, (a, b))| *a && *b).map(|(n, _)| n).collect()
}

#[cfg(test)]
mod tests {
    use super::super::{select, ElemLevels, NodeKind};
    use super::nodes_on_crack;

    /// Four unit squares on x in [0,2], y in [-1,1]; the crack is y = 0
    /// (PHI = y) with its front at x = 1.5 (PSI = x - 1.5), so it runs along
    /// the squares' sides. Node (i, j) is numbered i + 3 j, y = j - 1.
    #[test]
    fn a_crack_along_element_sides_enriches_the_nodes_on_it() {
        let quads: Vec<[usize; 4]> = vec![[0, 1, 4, 3], [1, 2, 5, 4], [3, 4, 7, 6], [4, 5, 8, 7]];
        let x = |n: usize| (n % 3) as f64;
        let y = |n: usize| (n / 3) as f64 - 1.0;
        let phi: Vec<Vec<f64>> = quads.iter().map(|q| q.iter().map(|&n| y(n)).collect()).collect();
        let psi: Vec<Vec<f64>> = quads.iter().map(|q| q.iter().map(|&n| x(n) - 1.5).collect()).collect();
        let elems: Vec<ElemLevels> =
            (0..4).map(|k| ElemLevels { nodes: &quads[k], psi: &psi[k], phi: &phi[k], size: 1.0 }).collect();
        // Both crack nodes behind the front have elements above and below.
        assert_eq!(nodes_on_crack(&elems).into_iter().collect::<Vec<_>>(), vec![3, 4]);
        // Node 4 also touches the squares holding the tip: it takes the tip
        // functions, so only node 3 gets the jump.
        let kinds = select(&elems, false);
        assert_eq!(kinds.get(&3), Some(&NodeKind::Jump));
        assert_eq!(kinds.get(&4), Some(&NodeKind::Tip));
        assert_eq!(kinds.get(&0), None);
    }
}
