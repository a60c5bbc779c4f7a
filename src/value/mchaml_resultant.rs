//! The resultant of a field by element (RESU of an MCHAML): resu.notice
//! documents the CHPOINT case, a sum per component over every point; for
//! an element field the same sum runs over every point of every element.

use super::model::{Mchaml, MchamlZone};
use crate::fem::mesh::Mesh;

impl Mchaml {
    /// One POI1 element on the field's first node holding, per component,
    /// the sum of that component over all points of all zones (a constant
    /// counts once per element). None when the field has no element.
    pub fn resultant(&self) -> Option<Mchaml> {
        let first = self.zones.iter().flat_map(|z| z.mesh.node_list()).next()?;
        let mut comps: Vec<String> = Vec::new();
        let mut sums: Vec<f64> = Vec::new();
        let mut add = |c: &str, v: f64| match comps.iter().position(|x| x == c) {
            Some(i) => sums[i] += v,
            None => {
                comps.push(c.to_string());
                sums.push(v);
            }
        };
        for z in &self.zones {
            let n_elems = z.mesh.n_elements() as f64;
            for (c, v) in &z.constants {
                add(c, v * n_elems);
            }
            for pts in &z.values {
                for row in pts {
                    for (c, v) in z.comps.iter().zip(row) {
                        add(c, *v);
                    }
                }
            }
        }
        let zone = MchamlZone {
            mesh: Mesh::points(&[first]),
            element: "POI1".into(),
            comps,
            values: vec![vec![sums]],
            at_nodes: true,
            ..Default::default()
        };
        Some(Mchaml { subtype: self.subtype.clone(), zones: vec![zone] })
    }
}
