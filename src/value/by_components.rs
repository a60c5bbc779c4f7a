//! The component-wise forms of `+ - * /` (aaa2.notice, aaa_division.notice):
//! `X op Y L1 L2 L3` gives, for each i, component L3[i] = X.L1[i] op Y.L2[i].
//! Component lists name which component of each side meets which, so a
//! cross product or a vector times a scalar field is one operation.

use super::field::{Chpoint, Nature};
use super::model::{Mchaml, MchamlZone};
use std::collections::HashSet;

/// The three lists: same length, at least one name.
pub fn check_lists(l1: &[String], l2: &[String], l3: &[String]) -> Result<(), String> {
    if l1.is_empty() || l1.len() != l2.len() || l1.len() != l3.len() {
        return Err(format!(
            "the three component lists must have the same, non-zero length (found {}, {} and {})",
            l1.len(),
            l2.len(),
            l3.len()
        ));
    }
    Ok(())
}

impl Chpoint {
    /// Component-wise form on node fields. A node field is zero where it
    /// is not defined (aaa2.notice): a component is computed on the nodes
    /// where either side has its operand, except that a quotient needs its
    /// divisor (a missing divisor would be a division by zero).
    pub fn by_components(
        &self,
        y: &Chpoint,
        names: (&[String], &[String], &[String]),
        divisor_needed: bool,
        nature: Nature,
        f: impl Fn(f64, f64) -> f64,
    ) -> Chpoint {
        let (l1, l2, l3) = names;
        let mut out = Chpoint::new(nature);
        for ((c1, c2), c3) in l1.iter().zip(l2).zip(l3) {
            let mut seen = HashSet::new();
            let nodes = self.entries().filter(|e| e.1 == c1).map(|e| e.0);
            let nodes: Vec<usize> =
                nodes.chain(y.entries().filter(|e| e.1 == c2).map(|e| e.0)).filter(|n| seen.insert(*n)).collect();
            for n in nodes {
                let q = y.get(n, c2);
                if divisor_needed && q.is_none() {
                    continue;
                }
                let p = self.get(n, c1).unwrap_or(0.0);
                out.add(n, c3, f(p, q.unwrap_or(0.0)), false);
            }
        }
        out
    }
}

/// One component of a zone: its point values, or one constant.
enum Operand<'a> {
    Points(&'a [Vec<Vec<f64>>], usize),
    Constant(f64),
}

impl Operand<'_> {
    fn at(&self, e: usize, p: usize) -> f64 {
        match self {
            // A field with one point per element holds for every point.
            Operand::Points(v, c) => {
                let el = &v[e];
                el[p.min(el.len() - 1)][*c]
            }
            Operand::Constant(x) => *x,
        }
    }
}

fn operand<'a>(z: &'a MchamlZone, name: &str, side: &str) -> Result<Operand<'a>, String> {
    if let Some(c) = z.comps.iter().position(|n| n == name) {
        return Ok(Operand::Points(&z.values, c));
    }
    match z.constants.get(name) {
        Some(x) => Ok(Operand::Constant(*x)),
        None => Err(format!("the {} field has no component {} on zone {}", side, name, z.element)),
    }
}

impl Mchaml {
    /// Component-wise form on element fields: the zones must be the same
    /// (same meshes); the result has only the named components.
    pub fn by_components(
        &self,
        b: &Mchaml,
        names: (&[String], &[String], &[String]),
        f: impl Fn(f64, f64) -> f64,
    ) -> Result<Mchaml, String> {
        let (l1, l2, l3) = names;
        let mut out = Mchaml { subtype: self.subtype.clone(), zones: vec![] };
        for (k, z) in self.zones.iter().enumerate() {
            // The zone on the same mesh, else the one at the same place.
            let w = b
                .zones
                .iter()
                .find(|w| w.mesh == z.mesh)
                .or_else(|| b.zones.get(k).filter(|_| b.zones.len() == self.zones.len()))
                .ok_or_else(|| format!("the second field has no zone on the mesh of zone {} of the first", k + 1))?;
            out.zones.push(zone_by_components(z, w, (l1, l2, l3), &f)?);
        }
        Ok(out)
    }
}

fn zone_by_components(
    z: &MchamlZone,
    w: &MchamlZone,
    (l1, l2, l3): (&[String], &[String], &[String]),
    f: &impl Fn(f64, f64) -> f64,
) -> Result<MchamlZone, String> {
    let ops: Vec<(Operand, Operand)> = l1
        .iter()
        .zip(l2)
        .map(|(c1, c2)| Ok((operand(z, c1, "first")?, operand(w, c2, "second")?)))
        .collect::<Result<_, String>>()?;
    let mut r =
        MchamlZone { mesh: z.mesh.clone(), element: z.element.clone(), at_nodes: z.at_nodes, ..Default::default() };
    let with_points = ops.iter().any(|(p, q)| matches!(p, Operand::Points(..)) || matches!(q, Operand::Points(..)));
    if !with_points {
        for ((p, q), c3) in ops.iter().zip(l3) {
            r.constants.insert(c3.clone(), f(p.at(0, 0), q.at(0, 0)));
        }
        return Ok(r);
    }
    // The layout (elements, points) of the side that has point values,
    // the one with more points when both do.
    let layout = |s: &MchamlZone| s.values.iter().map(|e| e.len()).collect::<Vec<_>>();
    let (lz, lw) = (layout(z), layout(w));
    let shape = match (z.values.is_empty(), w.values.is_empty()) {
        (false, true) => lz,
        (true, false) => lw,
        _ => {
            if lz.len() != lw.len() {
                return Err(format!("the fields do not have the same elements ({} and {})", lz.len(), lw.len()));
            }
            let fits = |a: usize, b: usize| a == b || a == 1 || b == 1;
            if lz.iter().zip(&lw).any(|(a, b)| !fits(*a, *b)) {
                return Err("the fields do not have the same points in each element".into());
            }
            lz.iter().zip(&lw).map(|(a, b)| *a.max(b)).collect()
        }
    };
    r.at_nodes = if z.values.is_empty() { w.at_nodes } else { z.at_nodes };
    r.comps = l3.to_vec();
    r.values = shape
        .iter()
        .enumerate()
        .map(|(e, &np)| (0..np).map(|p| ops.iter().map(|(a, b)| f(a.at(e, p), b.at(e, p))).collect()).collect())
        .collect();
    Ok(r)
}
