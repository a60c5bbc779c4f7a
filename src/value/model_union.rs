//! Element fields of different layouts combined zone by zone (`+`, `-`):
//! the zones of both, components united where two zones lie on the same
//! elements. Components pair by name only: a component one side lacks is
//! joined to the result (aaa5.notice, aaa4.notice: "sinon il realise
//! l'adjonction"), so SI11 + SI22 holds both.

use super::model::{Mchaml, MchamlZone};

const MISMATCH: &str = "the element fields do not have the same zones, elements and components";

/// The number of points of each element, the layout two zones must share.
fn points(z: &MchamlZone) -> Vec<usize> {
    z.values.iter().map(|e| e.len()).collect()
}

type Key = (crate::fem::mesh::ElemType, Vec<usize>);

/// Element key -> (zone, element in the zone).
type ElementIndex = std::collections::HashMap<Key, (usize, usize)>;

fn key(ty: crate::fem::mesh::ElemType, e: &[usize]) -> Key {
    let mut k = e.to_vec();
    k.sort_unstable();
    (ty, k)
}

impl Mchaml {
    /// Where each element's values sit: (zone, element in the zone), keyed
    /// by type and sorted nodes, with the number of elements; None when a
    /// zone holds no point values.
    fn element_index(&self) -> Option<(ElementIndex, usize)> {
        let mut at = std::collections::HashMap::new();
        let mut total = 0;
        for (zi, z) in self.zones.iter().enumerate() {
            if z.values.is_empty() {
                return None;
            }
            let mut e = 0;
            for p in &z.mesh.parts {
                for el in p.elems() {
                    at.entry(key(p.ty, el)).or_insert((zi, e));
                    e += 1;
                }
            }
            total += e;
        }
        Some((at, total))
    }

    /// This field's point values laid out on the zones of `target`, element
    /// by element (the same elements cut into other zones, or in another
    /// order), when every element of `target` has values here under one
    /// set of components per target zone.
    pub fn realign(&self, target: &Mchaml) -> Option<Mchaml> {
        let (at, _) = self.element_index()?;
        let mut out = Mchaml { subtype: self.subtype.clone(), zones: Vec::new() };
        for t in &target.zones {
            if t.values.is_empty() {
                return None;
            }
            let mut src: Option<usize> = None;
            let mut values = Vec::new();
            for p in &t.mesh.parts {
                for el in p.elems() {
                    let &(zi, ze) = at.get(&key(p.ty, el))?;
                    let s = &self.zones[zi];
                    match src {
                        Some(k) if self.zones[k].comps != s.comps || self.zones[k].at_nodes != s.at_nodes => {
                            return None
                        }
                        _ => src = Some(zi),
                    }
                    values.push(s.values.get(ze)?.clone());
                }
            }
            let s = &self.zones[src?];
            out.zones.push(MchamlZone {
                mesh: t.mesh.clone(),
                element: t.element.clone(),
                comps: s.comps.clone(),
                values,
                at_nodes: s.at_nodes,
                ..Default::default()
            });
        }
        Some(out)
    }

    /// This field laid on the zones of `target` when all its elements are
    /// among target's, with zeros on the elements it does not have: a sum
    /// of a field on every element and one on some of them (the elements
    /// still active in a topology optimisation) adds element by element.
    pub fn embed_in(&self, target: &Mchaml) -> Option<Mchaml> {
        let (at, total) = self.element_index()?;
        let mut found = 0;
        let mut out = Mchaml { subtype: self.subtype.clone(), zones: Vec::new() };
        for t in &target.zones {
            if t.values.is_empty() {
                return None;
            }
            let mut src: Option<usize> = None;
            let mut hits = Vec::new();
            let mut e = 0;
            for p in &t.mesh.parts {
                for el in p.elems() {
                    let hit = at.get(&key(p.ty, el)).copied();
                    if let Some((zi, ze)) = hit {
                        let s = &self.zones[zi];
                        match src {
                            Some(k) if self.zones[k].comps != s.comps || self.zones[k].at_nodes != s.at_nodes => {
                                return None
                            }
                            _ => src = Some(zi),
                        }
                        if s.values.get(ze)?.len() != t.values.get(e)?.len() {
                            return None;
                        }
                        found += 1;
                    }
                    hits.push(hit);
                    e += 1;
                }
            }
            let (comps, at_nodes) = match src {
                Some(k) => (self.zones[k].comps.clone(), self.zones[k].at_nodes),
                None => (t.comps.clone(), t.at_nodes),
            };
            let values = hits
                .iter()
                .zip(&t.values)
                .map(|(h, tv)| match h {
                    Some((zi, ze)) => self.zones[*zi].values[*ze].clone(),
                    None => vec![vec![0.0; comps.len()]; tv.len()],
                })
                .collect();
            out.zones.push(MchamlZone {
                mesh: t.mesh.clone(),
                element: t.element.clone(),
                comps,
                values,
                at_nodes,
                ..Default::default()
            });
        }
        (found == total).then_some(out)
    }

    /// `fill`: a zone or component on one side only is kept, as if the
    /// other side held 0 there (sums and differences); otherwise every zone
    /// must find its partner.
    pub fn combine_union(&self, b: &Mchaml, f: impl Fn(f64, f64) -> f64, fill: bool) -> Result<Mchaml, String> {
        let mut used = vec![false; b.zones.len()];
        let mut out = Mchaml { subtype: self.subtype.clone(), zones: Vec::new() };
        for za in &self.zones {
            let partner = b.zones.iter().enumerate().position(|(i, zb)| {
                !used[i]
                    && zb.mesh == za.mesh
                    && zb.values.is_empty() == za.values.is_empty()
                    && points(zb) == points(za)
                    && zb.at_nodes == za.at_nodes
            });
            let Some(i) = partner else {
                if !fill {
                    return Err(MISMATCH.into());
                }
                let mut z = za.clone();
                for v in z.constants.values_mut().chain(z.values.iter_mut().flatten().flatten()) {
                    *v = f(*v, 0.0);
                }
                out.zones.push(z);
                continue;
            };
            used[i] = true;
            let zb = &b.zones[i];
            let mut z = za.clone();
            for (k, w) in &zb.constants {
                match z.constants.get_mut(k) {
                    Some(v) => *v = f(*v, *w),
                    None if fill => {
                        z.constants.insert(k.clone(), f(0.0, *w));
                    }
                    None => return Err(MISMATCH.into()),
                }
            }
            // Where each component of b goes in the result.
            let mut to: Vec<usize> = Vec::new();
            for c in &zb.comps {
                let j = z.comps.iter().position(|x| x == c);
                to.push(match j {
                    Some(j) => j,
                    None if fill => {
                        z.comps.push(c.clone());
                        for v in z.values.iter_mut().flatten() {
                            v.push(0.0);
                        }
                        z.comps.len() - 1
                    }
                    None => return Err(MISMATCH.into()),
                });
            }
            if !fill && to.len() != z.comps.len() {
                return Err(MISMATCH.into());
            }
            let mut touched = vec![false; z.comps.len()];
            for &j in &to {
                touched[j] = true;
            }
            for (ea, eb) in z.values.iter_mut().zip(&zb.values) {
                for (pa, pb) in ea.iter_mut().zip(eb) {
                    for (k, &j) in to.iter().enumerate() {
                        pa[j] = f(pa[j], pb[k]);
                    }
                    for (j, t) in touched.iter().enumerate() {
                        if !t {
                            pa[j] = f(pa[j], 0.0);
                        }
                    }
                }
            }
            out.zones.push(z);
        }
        for (i, zb) in b.zones.iter().enumerate() {
            if used[i] {
                continue;
            }
            if !fill {
                return Err(MISMATCH.into());
            }
            let mut z = zb.clone();
            for v in z.constants.values_mut().chain(z.values.iter_mut().flatten().flatten()) {
                *v = f(0.0, *v);
            }
            out.zones.push(z);
        }
        Ok(out)
    }
}
