//! Arithmetic between a one-constant element field (material data such as
//! `EXCO 'YOUN' mat`) and a one-component field of point values on the
//! same meshes: the constant holds at every point of every element.

use super::model::{Mchaml, MchamlZone};

/// `a op b` zone by zone when each pair is a lone constant facing lone
/// point values (or two matching layouts); the result has the point layout
/// and the first operand's component name. None when the fields differ in
/// any other way.
pub fn combine_scalar(a: &Mchaml, b: &Mchaml, f: impl Fn(f64, f64) -> f64) -> Option<Mchaml> {
    if a.zones.len() != b.zones.len() {
        return None;
    }
    let mut out = a.clone();
    for (z, (p, q)) in out.zones.iter_mut().zip(a.zones.iter().zip(&b.zones)) {
        if p.mesh != q.mesh {
            return None;
        }
        *z = match (lone_constant(p), lone_constant(q)) {
            (Some((name, c)), None) if q.comps.len() == 1 => spread(q, name, |v| f(c, v)),
            (None, Some((_, c))) if p.comps.len() == 1 => spread(p, &p.comps[0], |v| f(v, c)),
            _ => return None,
        };
    }
    Some(out)
}

fn lone_constant(z: &MchamlZone) -> Option<(&String, f64)> {
    if !z.values.is_empty() || z.constants.len() != 1 {
        return None;
    }
    z.constants.iter().next().map(|(k, v)| (k, *v))
}

/// The point values of `z` mapped by `g`, under the component `name`.
fn spread(z: &MchamlZone, name: &str, g: impl Fn(f64) -> f64) -> MchamlZone {
    let mut out = z.clone();
    out.comps = vec![name.to_string()];
    for v in out.values.iter_mut().flatten().flatten() {
        *v = g(*v);
    }
    out
}
