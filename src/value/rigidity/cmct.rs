//! CMCT: the condensation of the multipliers of a system `[M Cᵀ; C 0]`
//! whose M is diagonal: H = C M⁻¹ Cᵀ, a matrix over the multiplier unknowns
//! (LX at each condition's node). Explicit dynamics (DREXUS) solves its
//! conditions this way, M⁻¹ given as a field.

use super::{Block, Rigidite, Subtype, Symmetry};
use std::collections::BTreeMap;

impl Rigidite {
    /// C M⁻¹ Cᵀ over the condition rows, `minv(node, component)` giving the
    /// diagonal of M⁻¹ (None: the unknown is missing from the field). Kept
    /// sparse: one 1-node block for the diagonal, one 2-node element per
    /// pair of conditions sharing an unknown.
    pub fn cmct(&self, minv: impl Fn(usize, &str) -> Option<f64>) -> Result<Rigidite, String> {
        // Unknown -> the conditions naming it, with their coefficient.
        let mut by_dof: BTreeMap<(usize, &str), Vec<(usize, f64)>> = BTreeMap::new();
        for (i, c) in self.conds.iter().enumerate() {
            for (n, comp, a) in &c.terms {
                by_dof.entry((*n, comp.as_str())).or_default().push((i, *a));
            }
        }
        let mut h: BTreeMap<(usize, usize), f64> = BTreeMap::new();
        for (&(n, comp), rows) in &by_dof {
            let w = minv(n, comp).ok_or_else(|| format!("the field gives no {comp} at node {n}"))?;
            if !w.is_finite() {
                return Err(format!("the value of {comp} at node {n} is not finite"));
            }
            for &(i, a) in rows {
                for &(j, b) in rows {
                    if i <= j {
                        *h.entry((i, j)).or_insert(0.0) += a * w * b;
                    }
                }
            }
        }
        let lx = || (vec![(0, "LX".to_string())], vec!["FLX".to_string()]);
        let (d1, u1) = lx();
        let mut diag =
            Block { nodes_per_elem: 1, conn: vec![], dofs: d1, duals: u1, mats: vec![], symmetry: Symmetry::Symmetric };
        let mut pairs = Block {
            nodes_per_elem: 2,
            conn: vec![],
            dofs: vec![(0, "LX".to_string()), (1, "LX".to_string())],
            duals: vec!["FLX".to_string(), "FLX".to_string()],
            mats: vec![],
            symmetry: Symmetry::Symmetric,
        };
        for (i, c) in self.conds.iter().enumerate() {
            diag.conn.push(c.mult_node);
            diag.mats.push(h.get(&(i, i)).copied().unwrap_or(0.0));
        }
        for (&(i, j), &v) in &h {
            if i != j {
                pairs.conn.extend([self.conds[i].mult_node, self.conds[j].mult_node]);
                pairs.mats.extend([0.0, v, v, 0.0]);
            }
        }
        let mut out = Rigidite::new(Subtype::Rigidite);
        out.blocks.push(diag);
        if !pairs.conn.is_empty() {
            out.blocks.push(pairs);
        }
        Ok(out)
    }
}
