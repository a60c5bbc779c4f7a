//! A RIGIDITE as a dense matrix over a chosen list of unknowns, for the
//! small eigenproblems (VIBC) that work on whole matrices.

use super::Rigidite;
use std::collections::HashMap;

impl Rigidite {
    /// The assembled blocks (conditions left out) as an n×n row-major
    /// matrix, `index` numbering the (node, component) unknowns. Err names
    /// an unknown of the blocks missing from `index`.
    pub fn dense(&self, index: &HashMap<(usize, String), usize>) -> Result<Vec<f64>, (usize, String)> {
        let n = index.len();
        let mut out = vec![0.0; n * n];
        for b in &self.blocks {
            let nd = b.ndof();
            for e in 0..b.n_elem() {
                let glob: Vec<usize> = b
                    .dofs
                    .iter()
                    .map(|(l, c)| {
                        let node = b.conn[e * b.nodes_per_elem + l];
                        index.get(&(node, c.clone())).copied().ok_or((node, c.clone()))
                    })
                    .collect::<Result<_, _>>()?;
                let m = b.mat(e);
                for (r, gr) in glob.iter().enumerate() {
                    for (c, gc) in glob.iter().enumerate() {
                        out[gr * n + gc] += m[r * nd + c];
                    }
                }
            }
        }
        Ok(out)
    }
}
