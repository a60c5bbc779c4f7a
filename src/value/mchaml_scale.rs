//! Products and quotients of an element field by a one-component one on
//! the same points (`NF2 / (XX ** 0.5)`: a vector field divided by its
//! norm): the lone component acts on every component of the other field,
//! which keeps its names.

use super::model::{Mchaml, MchamlZone};

/// `a op b` zone by zone when, in each pair of zones on the same mesh and
/// points, one side has a single component of point values. None when the
/// fields differ in any other way.
pub fn scale(a: &Mchaml, b: &Mchaml, f: impl Fn(f64, f64) -> f64) -> Option<Mchaml> {
    if a.zones.len() != b.zones.len() {
        return None;
    }
    let mut out = a.clone();
    for (z, (p, q)) in out.zones.iter_mut().zip(a.zones.iter().zip(&b.zones)) {
        if p.mesh != q.mesh || p.at_nodes != q.at_nodes || points(p) != points(q) || p.values.is_empty() {
            return None;
        }
        *z = if q.comps.len() == 1 {
            apply(p, q, &f)
        } else if p.comps.len() == 1 {
            apply(q, p, |x, s| f(s, x))
        } else {
            return None;
        };
    }
    Some(out)
}

fn points(z: &MchamlZone) -> Vec<usize> {
    z.values.iter().map(|e| e.len()).collect()
}

/// The values of `many` combined with the lone component of `one` at the
/// same element and point.
fn apply(many: &MchamlZone, one: &MchamlZone, g: impl Fn(f64, f64) -> f64) -> MchamlZone {
    let mut out = many.clone();
    for (e, pts) in out.values.iter_mut().enumerate() {
        for (k, vals) in pts.iter_mut().enumerate() {
            let s = one.values[e][k][0];
            for v in vals.iter_mut() {
                *v = g(*v, s);
            }
        }
    }
    out
}
