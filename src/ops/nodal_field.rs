//! An element field held at the nodes (CHAN 'CHAM' … 'NOEUD') read back as
//! a node field, for operators that take displacements as a CHPOINT but
//! are given them element by element (GRAD in G_THETA).

use crate::value::{Chpoint, Mchaml, Nature};
use std::rc::Rc;

/// Displacement names a node field of a massive model can carry.
const DISPLACEMENTS: &[&str] = &["UX", "UY", "UZ", "UR", "UT"];

/// The first of `fields` held at the nodes with displacement components,
/// removed from the list and turned into a CHPOINT. A node shared by
/// elements takes its last value: displacements are continuous.
pub(crate) fn take_displacements(fields: &mut Vec<Rc<Mchaml>>) -> Option<Rc<Chpoint>> {
    let i = fields.iter().position(|m| is_nodal_displacement(m))?;
    let m = fields.remove(i);
    let mut out = Chpoint::new(Nature::Diffus);
    for z in &m.zones {
        let part = z.mesh.parts.first()?;
        for (e, nodes) in part.elems().enumerate() {
            let vals = z.values.get(e)?;
            for (k, n) in nodes.iter().enumerate() {
                for (c, name) in z.comps.iter().enumerate() {
                    out.add(*n, name, *vals.get(k)?.get(c)?, false);
                }
            }
        }
    }
    Some(Rc::new(out))
}

fn is_nodal_displacement(m: &Mchaml) -> bool {
    !m.zones.is_empty()
        && m.zones.iter().all(|z| {
            z.at_nodes
                && z.mesh.parts.len() == 1
                && z.comps.iter().any(|c| DISPLACEMENTS.contains(&c.as_str()))
                && z.values.iter().all(|e| e.len() == z.mesh.parts[0].ty.nodes())
        })
}
