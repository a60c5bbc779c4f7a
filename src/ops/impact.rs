//! IMPO 'IMPA' (impo.notice, forms e and f): impacts in explicit dynamics.
//! `IMPO 'IMPA' 'MAIT' L1 'ESCL' L2|P1` lists every link that may come
//! into play; `IMPO 'IMPA' LINKS (nose)` gives, on the current geometry,
//! the conditions of the links in contact. The geometry of the projectile
//! noses is in `fem::impact`.

use super::bc::mult_node;
use super::{dofs, Args, PointId};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::contact;
use crate::fem::impact::{self as fi, Nose};
use crate::fem::mesh::{ElemType, Mesh, Part};
use crate::solve::Kind;
use crate::value::rigidity::{CondRow, Subtype};
use crate::value::{HostObject, Rigidite, Value};
use std::any::Any;
use std::rc::Rc;

/// What an operator gives when it has nothing to give (Cast3M's type
/// ANNULE): EXIS of it is false, so a procedure tests whether there was a
/// result. IMPO 'IMPA' gives it when no link is in contact.
#[derive(Debug)]
pub(crate) struct Annule;

impl HostObject for Annule {
    fn type_name(&self) -> &str {
        "ANNULE"
    }
    fn describe(&self) -> String {
        "ANNULE (no object)".into()
    }
    fn as_any(&self) -> &dyn Any {
        self
    }
}

/// Whether a value is the ANNULE of an operator that gave nothing.
pub(crate) fn is_annule(v: &Value) -> bool {
    matches!(v, Value::Host(h) if h.as_any().is::<Annule>())
}

/// `IMPO 'IMPA' …` (the word IMPA already read).
pub(crate) fn impa(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if it.opts.dime != 2 {
        return Err(a.err(format!("IMPO 'IMPA' is available in 2D (OPTI DIME 2), not in dimension {}", it.opts.dime)));
    }
    if a.keyword(&["MAIT"]).is_some() {
        return links(a);
    }
    let m = a.req::<Rc<Mesh>>()?;
    let nose = nose(it, a)?;
    let rig = match (m.parts.first().map(|p| p.ty), nose) {
        (None, _) => Rigidite::new(Subtype::Blocage),
        (Some(ElemType::Tri3), None) => line_line(it, a, &m)?,
        (Some(ElemType::Seg2), Some(nose)) => projectile(it, a, &m, nose)?,
        (Some(ElemType::Seg2), None) => {
            return Err(a.err(
                "links with a projectile point need its nose: 'HEMI' radius | 'PLAT' width | 'CONE' width 'ANGL' angle, then 'VECT' axis",
            ))
        }
        (Some(ElemType::Tri3), Some(_)) => {
            return Err(a.err("a nose ('HEMI', 'PLAT', 'CONE') is for links with a projectile point, not between two lines"))
        }
        (Some(t), _) => {
            return Err(a.err(format!(
                "IMPO 'IMPA' reads the links made by IMPO 'IMPA' 'MAIT' … 'ESCL' (TRI3 or SEG2 elements), found {}",
                t.name()
            )))
        }
    };
    if rig.conds.is_empty() {
        return Ok(vec![Value::Host(Rc::new(Annule))]);
    }
    Ok(vec![Value::Rigi(Rc::new(rig))])
}

/// 'MAIT' L1 'ESCL' L2|P1: every (slave node, master segment) as a TRI3
/// (slave node first, then the segment), or every (master node,
/// projectile) as a SEG2. The multipliers get their nodes when the
/// conditions are made.
fn links(a: &mut Args) -> Result<Vec<Value>> {
    let master = a.req::<Rc<Mesh>>()?;
    a.req_keyword(&["ESCL"])?;
    let slave = super::mesh::req_geo(a)?;
    if let Some(t) = master.parts.iter().map(|p| p.ty).find(|t| *t != ElemType::Seg2) {
        return Err(a.err(format!("the master line ('MAIT') must be made of SEG2 elements, found {}", t.name())));
    }
    let segs: Vec<[usize; 2]> = master.parts.iter().flat_map(|p| p.elems()).map(|e| [e[0], e[1]]).collect();
    let slave_nodes = slave.node_list();
    let point = slave.parts.iter().all(|p| p.ty == ElemType::Poi1) && slave_nodes.len() == 1;
    let part = if point {
        let p = slave_nodes[0];
        let conn = master.node_list().into_iter().filter(|n| *n != p).flat_map(|n| [n, p]).collect();
        Part::with(ElemType::Seg2, conn)
    } else {
        if let Some(t) = slave.parts.iter().map(|p| p.ty).find(|t| *t != ElemType::Seg2) {
            return Err(a.err(format!(
                "the slave side ('ESCL') must be a SEG2 line or one point (the projectile), found {}",
                t.name()
            )));
        }
        let conn = slave_nodes
            .iter()
            .flat_map(|&s| segs.iter().filter(move |g| !g.contains(&s)).map(move |g| [s, g[0], g[1]]))
            .flatten()
            .collect();
        Part::with(ElemType::Tri3, conn)
    };
    Ok(vec![Value::Mesh(Rc::new(Mesh::single(part)))])
}

fn nose(it: &Interp, a: &mut Args) -> Result<Option<Nose>> {
    let it_coords = |_: &Args, p: PointId| it.nodes.get(p.0);
    let Some(k) = a.keyword(&["HEMI", "PLAT", "CONE"]) else {
        if a.keyword(&["VECT"]).is_some() {
            return Err(a.err("'VECT' gives the axis of a nose: 'HEMI', 'PLAT' or 'CONE' comes first"));
        }
        return Ok(None);
    };
    let size = a.req_num()?;
    if size <= 0.0 || !size.is_finite() {
        return Err(a.err(format!("the size of the nose must be positive, not {}", size)));
    }
    let angle = if k == "CONE" {
        a.req_keyword(&["ANGL"])?;
        let alpha = a.req_num()?;
        if !(alpha > 0.0 && alpha < 90.0) {
            return Err(a.err(format!("the angle of the cone must be between 0 and 90 degrees, not {}", alpha)));
        }
        alpha
    } else {
        0.0
    };
    a.req_keyword(&["VECT"])?;
    let v = a.req::<PointId>()?;
    let axis = it_coords(a, v);
    let n = (axis[0] * axis[0] + axis[1] * axis[1]).sqrt();
    if n == 0.0 {
        return Err(a.err("the axis of the projectile ('VECT') has no length"));
    }
    let axis = [axis[0] / n, axis[1] / n];
    Ok(Some(match k {
        "HEMI" => Nose::Hemisphere { radius: size, axis },
        "PLAT" => Nose::Flat { width: size, axis },
        _ => Nose::Cone { width: size, half_angle: angle.to_radians(), axis },
    }))
}

/// A condition on the approach speed of a link, `c·v = 0`, its multiplier
/// a compression when positive: the terms are minus the derivative of the
/// gap (drexus keeps the positive multipliers and adds −Cᵀλ).
fn push(it: &mut Interp, rig: &mut Rigidite, at: usize, terms: Vec<(usize, [f64; 2])>) {
    let names = dofs::translations(it);
    let rows = terms
        .into_iter()
        .flat_map(|(n, c)| (0..2).filter(move |k| c[*k].abs() > 1e-14).map(move |k| (n, k, c[k])))
        .map(|(n, k, c)| (n, names[k].to_string(), -c))
        .collect();
    let m = mult_node(it, at);
    rig.conds.push(CondRow::new(m, rows, Kind::Equal));
}

/// Slave nodes that have crossed a master segment they project onto, each
/// with the segment it is least deep behind. A node deeper than the
/// segment is long is taken to be behind another part of the master line,
/// not through this segment.
fn line_line(it: &mut Interp, a: &Args, m: &Mesh) -> Result<Rigidite> {
    let mut best: std::collections::BTreeMap<usize, contact::Pair> = std::collections::BTreeMap::new();
    for (e, el) in m.parts.iter().flat_map(|p| p.elems()).enumerate() {
        let p = match contact::project(&it.nodes.coords, el[0], &el[1..], true) {
            Ok(p) => p,
            Err(contact::Miss::Outside) => continue,
            Err(contact::Miss::Degenerate) => {
                return Err(a.err(format!("link {}: its master segment has no length", e + 1)));
            }
        };
        let (xa, xb) = (it.nodes.get(el[1]), it.nodes.get(el[2]));
        let len = ((xb[0] - xa[0]).powi(2) + (xb[1] - xa[1]).powi(2)).sqrt();
        if p.gap > 0.0 || -p.gap > len {
            continue;
        }
        match best.get(&p.slave) {
            Some(q) if q.gap >= p.gap => {}
            _ => {
                best.insert(p.slave, p);
            }
        }
    }
    let mut rig = Rigidite::new(Subtype::Blocage);
    for p in best.values() {
        let n = [p.normal[0], p.normal[1]];
        let mut terms = vec![(p.slave, n)];
        terms.extend(p.facet.iter().zip(&p.weights).map(|(&f, &w)| (f, [-w * n[0], -w * n[1]])));
        push(it, &mut rig, p.slave, terms);
    }
    Ok(rig)
}

/// Master nodes inside the projectile's nose.
fn projectile(it: &mut Interp, a: &Args, m: &Mesh, nose: Nose) -> Result<Rigidite> {
    let mut rig = Rigidite::new(Subtype::Blocage);
    for el in m.parts.iter().flat_map(|p| p.elems()) {
        let (node, tip) = (el[0], el[1]);
        let (x, t) = (it.nodes.get(node), it.nodes.get(tip));
        let d = [x[0] - t[0], x[1] - t[1]];
        if let Some(n) = fi::inside(&nose, d).map_err(|e| a.err(e))? {
            // The gap grows as the node moves along n away from the tip.
            push(it, &mut rig, node, vec![(node, n), (tip, [-n[0], -n[1]])]);
        }
    }
    Ok(rig)
}
