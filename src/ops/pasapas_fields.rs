//! PASAPAS results as Gibiane objects: displacements and reactions
//! (CHPOINT), strains and stresses (MCHAML laid out as SIGM and EPSI lay
//! them out, so decks can subtract one from the other), and the contact
//! status and pressure at the contact nodes.

use super::dofs::dual_of;
use super::pasapas_model::Structure;
use crate::analysis::body::SetFields;
use crate::fem::mesh::Mesh;
use crate::solve::Solution;
use crate::value::model::MchamlZone;
use crate::value::{Chpoint, Mchaml, Nature};
use rustc_hash::FxHashMap as HashMap;

/// The displacements, without the multipliers.
pub(crate) fn displacements(s: &Structure, u: &[f64]) -> Chpoint {
    let mut out = Chpoint::new(Nature::Diffus);
    for ((n, c), v) in s.asm.dofs.iter().zip(u) {
        out.add(*n, c, *v, false);
    }
    out
}

/// The reactions −Cᵀλ of every condition (BLOCAGES_MECANIQUES and
/// contact), as REAC gives them: the forces the conditions exert, with an
/// explicit 0 where a condition is inactive.
pub(crate) fn reactions(s: &Structure, lambda: &[f64]) -> Chpoint {
    let mut out = Chpoint::new(Nature::Discret);
    for (c, l) in s.rig.conds.iter().zip(lambda) {
        for (n, comp, coef) in c.reaction_terms() {
            out.add(*n, &dual_of(comp), -coef * l + 0.0, true);
        }
    }
    out
}

/// Strains (`stresses` false) or stresses of every element set, one zone
/// per mesh part as SIGM gives them. The values are moved out of `fields`.
pub(crate) fn element_field(s: &Structure, fields: &mut [SetFields], stresses: bool) -> Mchaml {
    let mut out = Mchaml { subtype: if stresses { "CONTRAINTES" } else { "DEFORMATIONS" }.into(), zones: vec![] };
    for ((zone, part), f) in s.parts.iter().zip(fields.iter_mut()) {
        let g = std::mem::take(if stresses { &mut f.stresses } else { &mut f.strains });
        out.zones.push(MchamlZone {
            mesh: Mesh::single(part.clone()),
            element: zone.element.clone(),
            comps: g.first().map(|x| x.comps.iter().map(|c| c.to_string()).collect()).unwrap_or_default(),
            values: g.into_iter().map(|x| x.values).collect(),
            ..Default::default()
        });
    }
    out
}

/// At every node of a contact condition: its status (STAT 1 where an
/// active contact condition acts on it, else 0) and its pressure (PRES,
/// the normal contact force at the node divided by its share of the
/// contact facets: half of each facing segment in 2D, a third of each
/// facing triangle in 3D; the force itself where the node has no facet).
pub(crate) fn contact(s: &Structure, sol: &Solution) -> (Chpoint, Chpoint) {
    let mut status: HashMap<usize, bool> = HashMap::default();
    let mut force: HashMap<usize, Vec<(String, f64)>> = HashMap::default();
    let mut order: Vec<usize> = Vec::new();
    for &k in &s.contact {
        let c = &s.rig.conds[k];
        let big = c.terms.iter().fold(0.0_f64, |m, t| m.max(t.2.abs()));
        for (n, comp, coef) in &c.terms {
            if coef.abs() <= 1e-9 * big {
                continue;
            }
            if !status.contains_key(n) {
                order.push(*n);
            }
            let st = status.entry(*n).or_insert(false);
            *st |= sol.active[k];
            let f = force.entry(*n).or_default();
            let v = -coef * sol.lambda[k];
            match f.iter_mut().find(|(c, _)| c == comp) {
                Some(e) => e.1 += v,
                None => f.push((comp.clone(), v)),
            }
        }
    }
    let mut st = Chpoint::new(Nature::Diffus);
    let mut pr = Chpoint::new(Nature::Diffus);
    for n in order {
        st.add(n, "STAT", if status[&n] { 1.0 } else { 0.0 }, false);
        let f = force[&n].iter().map(|(_, v)| v * v).sum::<f64>().sqrt();
        let a = s.contact_measure.get(&n).copied().filter(|a| *a > 0.0).unwrap_or(1.0);
        pr.add(n, "PRES", f / a + 0.0, false);
    }
    (st, pr)
}
