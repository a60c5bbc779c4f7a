//! Twin equality conditions: the same row written twice (two BLOQ of one
//! unknown, a RELA repeated, or one a multiple of the other). Cast3M's RESO
//! accepts them as long as the imposed values agree, so the numbered system
//! keeps one row of each family: a twin's multiplier node still takes an
//! imposed value (FLX), which must then equal the kept row's value scaled by
//! the ratio of the rows, else the data conflict. Two rows on one unknown
//! with different values stay an error, found when the load is read.

use super::numbering::Assembled;
use super::problem::{Condition, Kind};
use rustc_hash::FxHashMap as HashMap;

/// A condition row merged into an earlier one: `c_twin = ratio · c_kept`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Twin {
    /// The kept condition, in the merged numbering.
    pub kept: usize,
    pub ratio: f64,
    /// The twin's own number in the unmerged numbering.
    pub origin: usize,
}

/// A normalised row: (unknown, coefficient), sorted by unknown.
type Row = Vec<(usize, f64)>;

/// Relative tolerance for two rows (or two imposed values) to count as
/// proportional.
const TOL: f64 = 1e-10;

/// Sorted by unknown, duplicates summed, zeros dropped: two writings of a
/// row compare term by term.
fn normalised(c: &Condition) -> Row {
    let mut t = c.terms.clone();
    t.sort_by_key(|x| x.0);
    let mut out: Vec<(usize, f64)> = Vec::with_capacity(t.len());
    for (j, v) in t {
        match out.last_mut() {
            Some(l) if l.0 == j => l.1 += v,
            _ => out.push((j, v)),
        }
    }
    out.retain(|x| x.1 != 0.0);
    out
}

/// `Some(r)` when `a = r · b` term by term (same unknowns).
fn ratio(a: &[(usize, f64)], b: &[(usize, f64)]) -> Option<f64> {
    let r = a.first()?.1 / b.first()?.1;
    let scale = a.iter().fold(0.0f64, |m, x| m.max(x.1.abs()));
    let close = a.iter().zip(b).all(|(x, y)| x.0 == y.0 && (x.1 - r * y.1).abs() <= TOL * scale);
    (close && r.is_finite() && r != 0.0).then_some(r)
}

/// Whether two imposed values agree: `twin = ratio · kept`.
pub fn agree(kept: f64, twin: f64, ratio: f64) -> bool {
    let want = ratio * kept;
    (twin - want).abs() <= TOL * twin.abs().max(want.abs())
}

impl Assembled {
    /// Keeps one equality row of each proportional family (unilateral and
    /// non-associated rows are left alone: the unilateral solver groups its
    /// own). Condition numbers after this are those of the merged system;
    /// [`Assembled::origin`] gives back the unmerged one.
    pub fn merge_twins(&mut self) {
        let conds = std::mem::take(&mut self.problem.conditions);
        let nodes = std::mem::take(&mut self.mult_nodes);
        let mut families: HashMap<Vec<usize>, Vec<(usize, Row)>> = HashMap::default();
        self.mult.clear();
        for (k, (c, node)) in conds.into_iter().zip(nodes).enumerate() {
            if c.kind == Kind::Equal && c.dual.is_none() {
                let row = normalised(&c);
                let key: Vec<usize> = row.iter().map(|x| x.0).collect();
                let fam = families.entry(key).or_default();
                if let Some((kept, r)) = fam.iter().find_map(|(i, b)| ratio(&row, b).map(|r| (*i, r))) {
                    self.twins.insert(node, Twin { kept, ratio: r, origin: k });
                    continue;
                }
                if !row.is_empty() {
                    fam.push((self.problem.conditions.len(), row));
                }
            }
            self.origin.push(k);
            self.push_condition(node, c);
        }
        if self.twins.is_empty() {
            self.origin.clear();
        }
    }

    /// The unmerged number of condition `k`.
    pub fn origin(&self, k: usize) -> usize {
        self.origin.get(k).copied().unwrap_or(k)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solve::{LoadError, Matrix};

    fn eq(t: &[(usize, f64)]) -> Condition {
        Condition { terms: t.to_vec(), kind: Kind::Equal, dual: None }
    }

    fn system(conds: Vec<Condition>) -> Assembled {
        let mut a = Assembled::default();
        let id = a.intern("UX", "FX");
        for n in 0..3 {
            a.unknown_id(n, id);
        }
        for (i, c) in conds.into_iter().enumerate() {
            a.push_condition(100 + i, c);
        }
        a.problem.k = Matrix { n: 3, entries: vec![], symmetric: true };
        a
    }

    #[test]
    fn proportional_rows_merge_and_values_must_agree() {
        let mut a = system(vec![
            eq(&[(0, 1.0)]),
            eq(&[(1, 1.0), (2, -1.0)]),
            eq(&[(0, 2.0)]),
            eq(&[(2, 3.0), (1, -3.0)]),
            eq(&[(1, 1.0), (2, 1.0)]),
        ]);
        a.merge_twins();
        assert_eq!(a.problem.conditions.len(), 3);
        assert_eq!((a.origin(0), a.origin(1), a.origin(2)), (0, 1, 4));
        assert_eq!(a.mult_nodes, vec![100, 101, 104]);
        // u0 = 0.5 twice (2·u0 = 1), u1 − u2 = 1 and 3(u2 − u1) = −3.
        let l = a.load([(100, "FLX", 0.5), (102, "FLX", 1.0), (101, "FLX", 1.0), (103, "FLX", -3.0)]).unwrap();
        assert_eq!(l.d, vec![0.5, 1.0, 0.0]);
        assert_eq!(
            a.load([(100, "FLX", 0.5), (102, "FLX", 2.0)]).unwrap_err(),
            LoadError::Conflicting { kept: 0, twin: 2 }
        );
    }

    #[test]
    fn unilateral_rows_stay() {
        let mut a = system(vec![eq(&[(0, 1.0)]), Condition { terms: vec![(0, 1.0)], kind: Kind::Mini, dual: None }]);
        a.merge_twins();
        assert_eq!(a.problem.conditions.len(), 2);
    }
}
