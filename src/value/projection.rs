//! PROI: the values of an element field at other points, interpolated in
//! the element that contains each point with its shape functions
//! (proi.notice).

use super::model::{Mchaml, MchamlZone, Model, ModelZone};
use super::{Chpoint, Nature};
use crate::fem::element::{gauss_positions, Formulation};
use crate::fem::locate::locate;
use crate::fem::mesh::{ElemType, Mesh, Nodes};
use crate::fem::shape;
use std::collections::HashMap;

/// Component names and their values at a point.
type Named = (Vec<String>, Vec<f64>);

/// One element of the field: its type, nodes, and where its values are.
struct Cell<'a> {
    ty: ElemType,
    conn: &'a [usize],
    zone: &'a MchamlZone,
    /// The element's number in its zone (values index), None for a zone
    /// of constants.
    at: Option<usize>,
}

/// The field's elements, bucketed on a regular grid of their bounding
/// boxes so that each point is tried against the few elements near it.
pub struct Locator<'a> {
    cells: Vec<Cell<'a>>,
    lo: [f64; 3],
    step: f64,
    grid: HashMap<[i64; 3], Vec<usize>>,
}

impl<'a> Locator<'a> {
    pub fn new(field: &'a Mchaml, nodes: &Nodes) -> Self {
        let mut cells = Vec::new();
        for z in &field.zones {
            let constant = z.values.is_empty();
            let mut e = 0;
            for p in &z.mesh.parts {
                for conn in p.elems() {
                    if p.ty.dim() > 0 {
                        cells.push(Cell { ty: p.ty, conn, zone: z, at: (!constant).then_some(e) });
                    }
                    e += 1;
                }
            }
        }
        let boxes: Vec<([f64; 3], [f64; 3])> = cells.iter().map(|c| bbox(c.conn, nodes)).collect();
        let mut lo = [f64::INFINITY; 3];
        let mut mean = 0.0;
        for (l, h) in &boxes {
            (0..3).for_each(|k| lo[k] = lo[k].min(l[k]));
            mean += (0..3).map(|k| h[k] - l[k]).fold(0.0, f64::max);
        }
        let step = if boxes.is_empty() { 1.0 } else { (mean / boxes.len() as f64).max(1e-300) };
        let mut loc = Locator { cells, lo, step, grid: HashMap::new() };
        for (i, (l, h)) in boxes.iter().enumerate() {
            let (a, b) = (loc.key(*l), loc.key(*h));
            for x in a[0]..=b[0] {
                for y in a[1]..=b[1] {
                    for z in a[2]..=b[2] {
                        loc.grid.entry([x, y, z]).or_default().push(i);
                    }
                }
            }
        }
        loc
    }

    fn key(&self, x: [f64; 3]) -> [i64; 3] {
        let k = |c: usize| if self.lo[c].is_finite() { ((x[c] - self.lo[c]) / self.step).floor() as i64 } else { 0 };
        [k(0), k(1), k(2)]
    }

    /// The field's components and values at `x`, from the first element
    /// that contains it; None when no element does.
    pub fn values_at(&self, x: [f64; 3], nodes: &Nodes) -> Result<Option<Named>, String> {
        let Some(cands) = self.grid.get(&self.key(x)) else { return Ok(None) };
        for &i in cands {
            let c = &self.cells[i];
            let xs: Vec<[f64; 3]> = c.conn.iter().map(|&n| nodes.get(n)).collect();
            let Some(xi) = locate(c.ty, &xs, x) else { continue };
            let z = c.zone;
            let Some(e) = c.at else {
                let names: Vec<String> = z.constants.keys().cloned().collect();
                return Ok(Some((names, z.constants.values().copied().collect())));
            };
            let pts = &z.values[e];
            let vals = if z.at_nodes && pts.len() == c.conn.len() {
                let s = shape::eval(c.ty, xi);
                (0..z.comps.len()).map(|k| pts.iter().zip(&s.n).map(|(p, n)| p[k] * n).sum()).collect()
            } else if pts.len() == 1 {
                pts[0].clone()
            } else {
                return Err(format!(
                    "the field has {} points in a {} of {} nodes: it must be at the nodes (CHAN 'NOEUD')",
                    pts.len(),
                    c.ty.name(),
                    c.conn.len()
                ));
            };
            return Ok(Some((z.comps.clone(), vals)));
        }
        Ok(None)
    }
}

fn bbox(conn: &[usize], nodes: &Nodes) -> ([f64; 3], [f64; 3]) {
    let mut l = [f64::INFINITY; 3];
    let mut h = [f64::NEG_INFINITY; 3];
    for &n in conn {
        let p = nodes.get(n);
        (0..3).for_each(|k| {
            l[k] = l[k].min(p[k]);
            h[k] = h[k].max(p[k]);
        });
    }
    // A margin so that a point on a face reaches both sides' buckets.
    let m = (0..3).map(|k| h[k] - l[k]).fold(0.0, f64::max) * 1e-6;
    ([l[0] - m, l[1] - m, l[2] - m], [h[0] + m, h[1] + m, h[2] + m])
}

/// `PROI GEO CHEL`: a diffuse CHPOINT on the nodes of `geo`, in their
/// order. A node outside the field's elements gets no value: Cast3M's
/// decks project a moving crack front to learn which of its points are
/// still in the body (EXTR then reads 0 there). When no node at all lies
/// in the field, the error names the first one (1-based in the mesh).
pub fn onto_mesh(field: &Mchaml, geo: &Mesh, nodes: &Nodes) -> Result<Chpoint, String> {
    let loc = Locator::new(field, nodes);
    let mut out = Chpoint::new(Nature::Diffus);
    let list = geo.node_list();
    let mut found = false;
    for &n in &list {
        let Some((names, vals)) = loc.values_at(nodes.get(n), nodes)? else { continue };
        found = true;
        for (c, v) in names.iter().zip(vals) {
            out.add(n, c, v, false);
        }
    }
    match list.first() {
        Some(&n) if !found => Err(not_found(0, n, nodes)),
        _ => Ok(out),
    }
}

fn not_found(i: usize, n: usize, nodes: &Nodes) -> String {
    let x = nodes.get(n);
    format!("point {} ({} {} {}) lies in no element of the field", i + 1, x[0], x[1], x[2])
}

/// The points of a model's elements that PROI projects onto.
pub enum Onto<'a> {
    /// The element's nodes ('NOEUD', the default).
    Nodes,
    /// The element's centre ('GRAVITE').
    Centres,
    /// The integration points ('RIGIDITE', 'MASSE', 'STRESSES': gibi
    /// integrates and outputs at one set), whose rule depends on the
    /// zone's formulation.
    Gauss(&'a dyn Fn(&ModelZone) -> Formulation),
}

/// `PROI MOD CHEL (MOT)`: an element field on the model, with the values
/// at each element's nodes, its centre, or its integration points.
pub fn onto_model(field: &Mchaml, model: &Model, onto: Onto, nodes: &Nodes) -> Result<Mchaml, String> {
    let loc = Locator::new(field, nodes);
    let mut out = Mchaml { subtype: field.subtype.clone(), zones: Vec::new() };
    for mz in &model.zones {
        for p in &mz.mesh.parts {
            let mut z = MchamlZone {
                mesh: Mesh::single(p.clone()),
                element: mz.element.clone(),
                at_nodes: matches!(onto, Onto::Nodes),
                ..Default::default()
            };
            for conn in p.elems() {
                let xs: Vec<[f64; 3]> = conn.iter().map(|&n| nodes.get(n)).collect();
                let points = match &onto {
                    Onto::Nodes => xs,
                    Onto::Centres => vec![centre_of(p.ty, &xs)],
                    Onto::Gauss(form) => gauss_positions(form(mz), p.ty, &xs),
                };
                let mut elem = Vec::new();
                for (k, x) in points.into_iter().enumerate() {
                    let (names, vals) =
                        loc.values_at(x, nodes)?.ok_or_else(|| not_found(k, conn[k.min(conn.len() - 1)], nodes))?;
                    if z.comps.is_empty() {
                        z.comps = names.clone();
                    }
                    if names != z.comps {
                        return Err("the field's zones have different components".into());
                    }
                    elem.push(vals);
                }
                z.values.push(elem);
            }
            out.zones.push(z);
        }
    }
    Ok(out)
}

/// The image of the reference element's centre.
fn centre_of(ty: ElemType, xs: &[[f64; 3]]) -> [f64; 3] {
    let refs = shape::ref_nodes(ty);
    let mut c = [0.0; 3];
    for r in &refs {
        (0..3).for_each(|k| c[k] += r[k] / refs.len() as f64);
    }
    let s = shape::eval(ty, c);
    let mut x = [0.0; 3];
    for (k, p) in xs.iter().enumerate() {
        (0..3).for_each(|d| x[d] += s.n[k] * p[d]);
    }
    x
}
