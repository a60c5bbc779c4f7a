//! From a RIGIDITE (elementary blocks over named unknowns, condition rows)
//! to the numbered `solve` problem, and back from a solution to a field.

use super::{Rigidite, Symmetry};
use crate::fem::element::dual_name;
use crate::solve::{Assembled, Condition, Solution};
use crate::value::{Chpoint, Nature};
use std::rc::Rc;

impl Rigidite {
    /// The numbered problem: unknowns in the order the blocks meet them,
    /// then those only the conditions name; one condition per row.
    pub fn number(&self) -> Assembled {
        let mut a = Assembled::default();
        let mut entries = Vec::new();
        let mut symmetric = true;
        for b in &self.blocks {
            symmetric &= b.symmetry == Symmetry::Symmetric;
            let nd = b.ndof();
            let mut idx = vec![0usize; nd];
            let ids: Vec<u16> = b.dofs.iter().zip(&b.duals).map(|((_, c), d)| a.intern(c, d)).collect();
            entries.reserve(b.n_elem() * nd * nd);
            for e in 0..b.n_elem() {
                let conn = &b.conn[e * b.nodes_per_elem..(e + 1) * b.nodes_per_elem];
                for (i, (l, _)) in b.dofs.iter().enumerate() {
                    idx[i] = a.unknown_id(conn[*l], ids[i]);
                }
                let m = b.mat(e);
                for i in 0..nd {
                    for j in 0..nd {
                        entries.push((idx[i], idx[j], m[i * nd + j]));
                    }
                }
            }
        }
        for c in &self.conds {
            let mut number = |t: &[(usize, String, f64)]| -> Vec<(usize, f64)> {
                t.iter()
                    .map(|(n, comp, coef)| {
                        let id = a.intern(comp, &dual_name(comp));
                        (a.unknown_id(*n, id), *coef)
                    })
                    .collect()
            };
            let terms = number(&c.terms);
            let dual = c.dual.as_deref().map(&mut number);
            // A non-associated condition makes the system non-symmetric
            // (the blocks give every entry of K, so LU can read them all).
            symmetric &= dual.is_none();
            a.push_condition(c.mult_node, Condition { terms, kind: c.kind, dual });
        }
        a.set_matrix(entries, symmetric);
        a
    }

    /// [`Rigidite::number`] with twin equality rows merged (RESO accepts a
    /// condition written twice), computed once per object and kept in its
    /// solver cache. Its condition `k` is `self.conds[asm.origin(k)]`.
    pub fn numbered(&self) -> Rc<Assembled> {
        let mut cache = self.cache.borrow_mut();
        cache
            .assembled
            .get_or_insert_with(|| {
                let mut a = self.number();
                a.merge_twins();
                Rc::new(a)
            })
            .clone()
    }
}

/// The RESO result: every primal unknown and the LX of active conditions.
pub fn solution_field(asm: &Assembled, s: &Solution) -> Chpoint {
    let mut out = Chpoint::new(Nature::Diffus);
    for ((n, c), v) in asm.dofs.iter().zip(&s.u) {
        out.add(*n, c, *v, false);
    }
    for (k, &node) in asm.mult_nodes.iter().enumerate() {
        if s.active[k] {
            out.add(node, "LX", s.lambda[k], false);
        }
    }
    out
}
