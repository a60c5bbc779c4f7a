//! Temperatures given as an element field (MCHAML with a component T)
//! rather than a CHPOINT: `EPTH mo ma chT`, `THET mo ma chT`. Cast3M's
//! fracture procedures build them with `MANU 'CHML' mesh 'T' value` (a
//! constant per zone) or carry them to the nodes with CHAN 'NOEUD'.

use crate::value::Mchaml;
use std::collections::HashMap;
use std::rc::Rc;

/// Temperatures at the nodes of each element, keyed by the element's sorted
/// node list so a field built on another mesh object with the same elements
/// still pairs with the model's elements.
pub(crate) struct ElementTemps {
    by_elem: HashMap<Vec<usize>, Vec<(usize, f64)>>,
}

fn holds_t(f: &Mchaml) -> bool {
    f.zones.iter().any(|z| z.constants.contains_key("T") || z.comps.iter().any(|c| c == "T"))
}

impl ElementTemps {
    /// The first field that holds T; the others stay material fields.
    pub(crate) fn find(fields: &[Rc<Mchaml>]) -> Option<(usize, ElementTemps)> {
        let i = fields.iter().position(|f| holds_t(f))?;
        let mut by_elem = HashMap::new();
        for z in &fields[i].zones {
            let ci = z.comps.iter().position(|c| c == "T");
            for part in &z.mesh.parts {
                for (e, nodes) in part.elems().enumerate() {
                    let temps: Option<Vec<f64>> = match (ci, z.values.get(e)) {
                        // Values at the nodes: one per node, in order.
                        (Some(c), Some(pts)) if z.at_nodes && pts.len() == nodes.len() => {
                            pts.iter().map(|p| p.get(c).copied()).collect()
                        }
                        // Values at the element's own points: their mean is the
                        // element's temperature (the strain is then uniform,
                        // which is what a constant-per-point field describes).
                        (Some(c), Some(pts)) if !pts.is_empty() => {
                            let s: Option<f64> = pts.iter().map(|p| p.get(c).copied()).sum();
                            s.map(|s| vec![s / pts.len() as f64; nodes.len()])
                        }
                        _ => z.constants.get("T").map(|t| vec![*t; nodes.len()]),
                    };
                    if let Some(t) = temps {
                        let mut key = nodes.to_vec();
                        key.sort_unstable();
                        by_elem.insert(key, nodes.iter().copied().zip(t).collect());
                    }
                }
            }
        }
        Some((i, ElementTemps { by_elem }))
    }

    /// T at each node of an element of the model, in the element's order.
    pub(crate) fn at(&self, nodes: &[usize]) -> Option<Vec<f64>> {
        let mut key = nodes.to_vec();
        key.sort_unstable();
        let known = self.by_elem.get(&key)?;
        nodes.iter().map(|n| known.iter().find(|(m, _)| m == n).map(|(_, t)| *t)).collect()
    }
}
