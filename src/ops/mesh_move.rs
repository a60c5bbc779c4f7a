//! Moving geometry: the DEPLACER directive (nodes moved in place) and the
//! copies of several objects at once that PLUS, MOIN and TOUR make
//! (`a b = a b PLUS v`). The motions are `fem::meshing::motion`.

use super::mesh::vector;
use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::fem::meshing::motion::{copy_together, move_in_place, Motion};
use crate::fem::meshing::transform::PointMap;
use crate::fem::meshing::Mirror;
use crate::value::{Chpoint, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "DEPL",
    signature: "DEPL GEO (GEO2 …) 'PLUS'|'MOIN' VECTOR | 'TOUR' angle P1 (P2) | 'HOMO' ratio CENTRE | 'AFFI' ratio P1 P2 (P3) | 'SYME' 'DROIT' P1 P2|'PLAN' P1 P2 P3|'POINT' P | 'PROJ' …",
    doc: "Move the nodes of meshes or points in place (every object holding them sees them moved): translation, rotation, homothety, affinity, symmetry or projection, read as PLUS, TOUR, HOMO, AFFI, SYME and PROJ read them.",
    example: "depl s 'PLUS' (1. 0.) ;",
    f: depl,
}];

/// A POINT (as a POI1 mesh) or a MAILLAGE.
fn geo(v: &Value) -> Option<Mesh> {
    match v {
        Value::Chpo(_) => None,
        Value::Point(p) => Some(Mesh::points(&[*p])),
        Value::Mesh(m) => Some((**m).clone()),
        _ => None,
    }
}

fn depl(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mut objs = Vec::new();
    let kinds = ["PLUS", "MOIN", "TOUR", "HOMO", "AFFI", "SYME", "PROJ"];
    let kind = loop {
        if let Some(k) = a.keyword_next(&kinds) {
            break k;
        }
        match a.opt_with(geo) {
            Some(m) => objs.push(m),
            None => break a.req_keyword(&kinds)?,
        }
    };
    // `DEPL 'PLUS' GEO VECTOR`: the keyword first, then the meshes (a
    // point there would be the vector).
    while objs.is_empty() || matches!(a.peek_right(), Some(Value::Mesh(_))) {
        // With nothing to move yet, a POINT right after the keyword is
        // the object (`DEPL 'PLUS' P1 (1. 0.)`): the vector comes after.
        if objs.is_empty() {
            if let Some(Value::Point(p)) = a.peek_right() {
                a.right_any();
                objs.push(Mesh::points(&[p]));
                continue;
            }
        }
        match a.opt_right::<Rc<Mesh>>() {
            Some(m) => objs.push((*m).clone()),
            None => break,
        }
    }
    if objs.is_empty() {
        return Err(a.missing("POINT or MAILLAGE (what to move)"));
    }
    let dim = it.opts.dime.max(2);
    let motion = match kind {
        "PLUS" | "MOIN" if matches!(a.peek_right(), Some(Value::Chpo(_))) => {
            let field: Rc<crate::value::Chpoint> = a.req()?;
            let sign = if kind == "MOIN" { -1.0 } else { 1.0 };
            translate_by_field(it, &objs, &field, sign);
            return Ok(vec![]);
        }
        "PLUS" | "MOIN" => {
            let v = vector(it, a).ok_or_else(|| a.missing("a vector (POINT)"))?;
            Motion::Translate(if kind == "MOIN" { v.map(|c| -c) } else { v })
        }
        "TOUR" => read_turn(it, a)?,
        "HOMO" => {
            let ratio = a.req_num()?;
            let centre = vector(it, a).ok_or_else(|| a.missing("POINT (the centre)"))?;
            Motion::Map(PointMap::Homothety { ratio, centre })
        }
        "AFFI" => {
            let ratio = a.req_num()?;
            let p1 = vector(it, a).ok_or_else(|| a.missing("POINT"))?;
            let p2 = vector(it, a).ok_or_else(|| a.missing("POINT"))?;
            Motion::Map(if dim >= 3 {
                match vector(it, a) {
                    Some(p3) => PointMap::affinity_3d(ratio, p1, p2, p3)?,
                    None => PointMap::affinity_along(ratio, p1, p2)?,
                }
            } else {
                PointMap::affinity_2d(ratio, p1, p2)?
            })
        }
        "SYME" => Motion::Mirror(match a.req_keyword(&["DROIT", "PLAN", "POINT"])? {
            "DROIT" => {
                let p1 = vector(it, a).ok_or_else(|| a.missing("POINT"))?;
                Mirror::Line(p1, vector(it, a).ok_or_else(|| a.missing("POINT"))?)
            }
            "PLAN" => {
                let p1 = vector(it, a).ok_or_else(|| a.missing("POINT"))?;
                let p2 = vector(it, a).ok_or_else(|| a.missing("POINT"))?;
                Mirror::Plane(p1, p2, vector(it, a).ok_or_else(|| a.missing("POINT"))?)
            }
            _ => Mirror::Point(vector(it, a).ok_or_else(|| a.missing("POINT"))?),
        }),
        _ => Motion::Map(super::transform::read_proj(it, a)?),
    };
    let refs: Vec<&Mesh> = objs.iter().collect();
    move_in_place(&mut it.nodes, &refs, motion, dim)?;
    Ok(vec![])
}

/// `DEPL GEO 'PLUS' CHPO1` (depl.notice): each node moves by its own
/// displacement, the field's translation components (UX UY UZ, UR UZ in
/// AXIS); a node the field does not hold stays (a field is zero there).
fn translate_by_field(it: &mut Interp, objs: &[Mesh], field: &crate::value::Chpoint, sign: f64) {
    let comps = super::dofs::translations(it);
    let mut list: Vec<usize> = objs.iter().flat_map(|m| m.node_list()).collect();
    list.sort_unstable();
    list.dedup();
    for n in list {
        for (k, c) in comps.iter().enumerate().take(3) {
            if let Some(v) = field.get(n, c) {
                it.nodes.coords[n][k] += sign * v;
            }
        }
    }
}

/// `angle P1 (P2)`: P2 (the axis) in 3D only.
fn read_turn(it: &Interp, a: &mut Args) -> Result<Motion> {
    let angle_deg = a.req_num()?;
    let centre = vector(it, a).ok_or_else(|| a.missing("POINT (the centre)"))?;
    let axis_end =
        if it.opts.dime >= 3 { Some(vector(it, a).ok_or_else(|| a.missing("POINT (the axis)"))?) } else { None };
    Ok(Motion::Rotate { angle_deg, centre, axis_end })
}

/// PLUS, MOIN and TOUR of several objects (`a b c = a b c PLUS v`, `p q =
/// TOUR p q angle c`): `first` is the first object, already read; the
/// POINTs and MAILLAGEs written with it are read too, and the last `tail`
/// POINTs are the operator's own (the vector; the centre and in 3D the
/// axis). Returns the objects and those points.
pub(crate) fn gather(a: &mut Args, first: Value, tail: usize, what: &str) -> Result<(Vec<Value>, Vec<usize>)> {
    let mut all = vec![first];
    while let Some(v) = a.opt_with(|v| movable(v).then(|| v.clone())) {
        all.push(v);
    }
    let mut pts = Vec::with_capacity(tail);
    while pts.len() < tail && all.len() > 1 {
        match all.last() {
            Some(Value::Point(p)) => {
                pts.push(*p);
                all.pop();
            }
            _ => break,
        }
    }
    if pts.len() < tail {
        return Err(a.missing(what));
    }
    pts.reverse();
    Ok((all, pts))
}

/// What PLUS, MOIN and TOUR move: geometry, nodal and element fields,
/// models.
pub(crate) fn movable(v: &Value) -> bool {
    matches!(v, Value::Point(_) | Value::Mesh(_) | Value::Chpo(_) | Value::Model(_) | Value::Mchaml(_))
}

/// The copies of `objs` moved together; a POINT alone becomes a new point,
/// a CHPOINT is carried to the images of its nodes (its vector components
/// turned with a rotation, tour.notice); models and element fields move
/// zone by zone (see [`super::move_models`]).
pub(crate) fn copies(it: &mut Interp, a: &Args, objs: &[Value], motion: Motion) -> Result<Vec<Value>> {
    let mut groups: Vec<Vec<Mesh>> = Vec::with_capacity(objs.len());
    for o in objs {
        groups.push(match super::move_models::zone_meshes(o) {
            Some(z) => z,
            None => supports(a, std::slice::from_ref(o))?,
        });
    }
    let refs: Vec<&Mesh> = groups.iter().flatten().collect();
    let turn = match &motion {
        Motion::Rotate { .. } => Some(motion),
        _ => None,
    };
    let mut out = copy_together(&mut it.nodes, &refs, motion, it.opts.dime.max(2))?.into_iter();
    let mut vals = Vec::with_capacity(objs.len());
    for (o, g) in objs.iter().zip(&groups) {
        let moved: Vec<Mesh> = out.by_ref().take(g.len()).collect();
        if matches!(o, Value::Model(_) | Value::Mchaml(_)) {
            vals.push(super::move_models::moved(o, moved, turn.as_ref()).map_err(|e| a.err(e))?);
            continue;
        }
        let m = moved.into_iter().next().unwrap_or_default();
        vals.push(match o {
            Value::Chpo(c) => {
                let turned = match &turn {
                    Some(t) => turn_components(c, t).map_err(|e| a.err(e))?,
                    None => (**c).clone(),
                };
                Value::Chpo(Rc::new(carried(&turned, &m)))
            }
            _ => image_value(o, m),
        });
    }
    Ok(vals)
}

/// The mesh each object moves: a CHPOINT's is its nodes, in its order.
pub(crate) fn supports(a: &Args, objs: &[Value]) -> Result<Vec<Mesh>> {
    objs.iter()
        .map(|o| match o {
            Value::Chpo(c) => Ok(Mesh::points(&c.nodes)),
            _ => geo(o).ok_or_else(|| a.err(format!("cannot move a {}", o.type_name()))),
        })
        .collect()
}

/// The moved object: a POINT alone is a new point, a mesh a MAILLAGE.
pub(crate) fn image_value(o: &Value, m: Mesh) -> Value {
    match o {
        Value::Point(_) => Value::Point(m.parts[0].conn[0]),
        _ => Value::Mesh(Rc::new(m)),
    }
}

/// The field on the images of its nodes: `image` is its nodes' POI1 mesh
/// moved, node k of the field going to the k-th point of it.
pub(crate) fn carried(c: &Chpoint, image: &Mesh) -> Chpoint {
    let to: std::collections::HashMap<usize, usize> =
        c.nodes.iter().copied().zip(image.parts.iter().flat_map(|p| p.conn.iter().copied())).collect();
    Chpoint::from_entries(c.nature, c.entries().map(|(n, comp, v)| (to[&n], comp, v)))
}

/// The vector components (UX UY UZ, FX FY FZ, RX RY RZ, MX MY MZ) turned
/// by the rotation's linear part; the others unchanged.
pub(crate) fn turn_components(c: &Chpoint, t: &Motion) -> std::result::Result<Chpoint, String> {
    let o = [0.0; 3];
    let o2 = t.image(o).map_err(|e| e.to_string())?;
    let lin = |v: [f64; 3]| -> std::result::Result<[f64; 3], String> {
        let p = t.image(v).map_err(|e| e.to_string())?;
        Ok([p[0] - o2[0], p[1] - o2[1], p[2] - o2[2]])
    };
    let mut out = c.clone();
    for pre in ["U", "F", "R", "M"] {
        let names: Vec<String> = ["X", "Y", "Z"].iter().map(|x| format!("{pre}{x}")).collect();
        if !names.iter().any(|n| c.comps.contains(n)) {
            continue;
        }
        for &n in &c.nodes {
            let v = [0, 1, 2].map(|k| c.get(n, &names[k]));
            if v.iter().all(|x| x.is_none()) {
                continue;
            }
            let w = lin(v.map(|x| x.unwrap_or(0.0)))?;
            for k in 0..3 {
                if v[k].is_some() || w[k] != 0.0 {
                    out.add(n, &names[k], w[k], false);
                }
            }
        }
    }
    Ok(out)
}
