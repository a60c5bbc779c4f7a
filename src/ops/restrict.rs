//! REDU: restrict a node field to a mesh, an element field to a model,
//! a rigidity or a model to a mesh (redu.notice).

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::{ElemType, Mesh};
use crate::value::model::{MchamlZone, ModelZone};
use crate::value::rigidity::Block;
use crate::value::{Chpoint, Mchaml, Model, Rigidite, Value};
use std::collections::{HashMap, HashSet};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "REDU",
    signature: "REDU CHPOINT GEO | REDU MCHAML MMODEL|GEO | REDU RIGIDITE GEO | REDU MMODEL GEO",
    doc: "Restrict a node field to the nodes of a mesh or point, an element field (material, stresses) to the elements of a model, a rigidity or a model to the elements lying on a mesh.",
    example: "u2 = redu u l ;",
    f: redu,
}];

fn redu(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    // Two objects, by type, in either order.
    let x = a.req::<Value>()?;
    let y = a.req::<Value>()?;
    let geo_of = |v: &Value| matches!(v, Value::Mesh(_) | Value::Point(_));
    let (obj, other) =
        if geo_of(&x) || matches!(x, Value::Model(_)) && matches!(y, Value::Mchaml(_)) { (y, x) } else { (x, y) };
    let geo = |a: &mut Args, v: Value| -> Result<Mesh> {
        match v {
            Value::Mesh(m) => Ok((*m).clone()),
            Value::Point(p) => Ok(Mesh::points(&[p])),
            _ => Err(a.err(format!("restricts to a MAILLAGE or a POINT, not a {}", v.type_name()))),
        }
    };
    Ok(vec![match obj {
        Value::Chpo(c) => {
            let keep: HashSet<usize> = geo(a, other)?.node_list().into_iter().collect();
            Value::Chpo(Rc::new(Chpoint::from_entries(c.nature, c.entries().filter(|(n, _, _)| keep.contains(n)))))
        }
        Value::Mchaml(m) => match other {
            Value::Model(mo) => Value::Mchaml(Rc::new(mchaml_to_model(a, &m, &mo)?)),
            v @ (Value::Mesh(_) | Value::Point(_)) => Value::Mchaml(Rc::new(mchaml_to_mesh(&m, &geo(a, v)?))),
            v => {
                return Err(a.err(format!("restricts an MCHAML to an MMODEL or a MAILLAGE, not to a {}", v.type_name())))
            }
        },
        Value::Rigi(r) => {
            let keep: HashSet<usize> = geo(a, other)?.node_list().into_iter().collect();
            Value::Rigi(Rc::new(rigidity_on(&r, &keep)))
        }
        Value::Model(mo) => {
            let g = geo(a, other)?;
            let keep: HashSet<usize> = g.node_list().into_iter().collect();
            let own: HashSet<(ElemType, Vec<usize>)> =
                g.parts.iter().flat_map(|p| p.elems().map(move |e| key(p.ty, e))).collect();
            let types: HashSet<ElemType> = g.parts.iter().map(|p| p.ty).collect();
            let zones: Vec<ModelZone> = mo
                .zones
                .iter()
                .map(|z| ModelZone { mesh: model_elements_on(&z.mesh, &own, &types, &keep), ..z.clone() })
                .filter(|z| z.mesh.n_elements() > 0)
                .collect();
            // No element on the mesh: an empty model, as Cast3M gives
            // (its integrals are zero).
            let ties = mo.ties_within(&zones);
            Value::Model(Rc::new(Model { zones, ties }))
        }
        v => return Err(a.missing(&format!("CHPOINT, MCHAML, RIGIDITE or MMODEL (found a {})", v.type_name()))),
    }])
}

/// The elements of a model's mesh kept by `REDU MMODEL GEO`: where the mesh
/// has elements of a part's type, those of them that are elements of the
/// mesh (an element of a hole whose nodes all lie on the mesh stays out,
/// so the model pairs with a field reduced to the same mesh); otherwise
/// (a mesh of points, of lines on a surface model) those whose nodes all
/// lie on the mesh.
fn model_elements_on(
    mesh: &Mesh,
    own: &HashSet<(ElemType, Vec<usize>)>,
    types: &HashSet<ElemType>,
    keep: &HashSet<usize>,
) -> Mesh {
    let parts = mesh
        .parts
        .iter()
        .map(|p| {
            let by_elem = types.contains(&p.ty);
            let conn = p
                .elems()
                .filter(|e| if by_elem { own.contains(&key(p.ty, e)) } else { e.iter().all(|n| keep.contains(n)) })
                .flatten()
                .copied()
                .collect();
            crate::fem::mesh::Part { conn, ..p.clone() }
        })
        .filter(|p| !p.is_empty())
        .collect();
    Mesh { parts }
}

/// The elementary matrices and conditions whose nodes all lie in `keep`.
fn rigidity_on(r: &Rigidite, keep: &HashSet<usize>) -> Rigidite {
    let mut out = Rigidite::new(r.subtype);
    for b in &r.blocks {
        let nd2 = b.ndof() * b.ndof();
        let mut nb = Block { conn: Vec::new(), mats: Vec::new(), ..b.clone() };
        for e in 0..b.n_elem() {
            let conn = &b.conn[e * b.nodes_per_elem..(e + 1) * b.nodes_per_elem];
            if conn.iter().all(|n| keep.contains(n)) {
                nb.conn.extend_from_slice(conn);
                nb.mats.extend_from_slice(&b.mats[e * nd2..(e + 1) * nd2]);
            }
        }
        if !nb.conn.is_empty() {
            out.blocks.push(nb);
        }
    }
    out.conds = r.conds.iter().filter(|c| c.terms.iter().all(|(n, _, _)| keep.contains(n))).cloned().collect();
    out
}

/// `REDU MCHAML GEO`: the field on those of its elements that are elements
/// of the mesh (or, for a mesh of points, whose nodes all lie in it).
fn mchaml_to_mesh(m: &Mchaml, geo: &Mesh) -> Mchaml {
    let own: HashSet<(ElemType, Vec<usize>)> =
        geo.parts.iter().flat_map(|p| p.elems().map(move |e| key(p.ty, e))).collect();
    let points = geo.parts.iter().all(|p| p.ty == ElemType::Poi1);
    let nodes: HashSet<usize> = geo.node_list().into_iter().collect();
    let keep = |ty: ElemType, e: &[usize]| {
        if points {
            e.iter().all(|n| nodes.contains(n))
        } else {
            own.contains(&key(ty, e))
        }
    };
    let mut out = Mchaml { subtype: m.subtype.clone(), zones: Vec::new() };
    for z in &m.zones {
        let mut parts = Vec::new();
        let mut values = Vec::new();
        let mut e = 0;
        for p in &z.mesh.parts {
            let mut conn = Vec::new();
            for el in p.elems() {
                if keep(p.ty, el) {
                    conn.extend_from_slice(el);
                    if let Some(v) = z.values.get(e) {
                        values.push(v.clone());
                    }
                }
                e += 1;
            }
            if !conn.is_empty() {
                parts.push(crate::fem::mesh::Part { conn, ..p.clone() });
            }
        }
        if !parts.is_empty() {
            out.zones.push(MchamlZone { mesh: Mesh { parts }, values, ..z.clone() });
        }
    }
    out
}

/// An element's identity: its type and its set of nodes.
fn key(ty: ElemType, e: &[usize]) -> (ElemType, Vec<usize>) {
    let mut k = e.to_vec();
    k.sort_unstable();
    (ty, k)
}

/// `REDU MCHAML MMODEL`: the field on the elements of the model, zone by
/// zone in the model's order, so that the result pairs with the model
/// (RIGI, SIGM …) as a field made on it would. Constant zones (MATE,
/// CARA) become one zone per model zone; zones of point values one per
/// part, element by element.
pub(crate) fn mchaml_to_model(a: &Args, m: &Mchaml, mo: &Model) -> Result<Mchaml> {
    let constant: Vec<&MchamlZone> = m.zones.iter().filter(|z| z.values.is_empty()).collect();
    let valued: Vec<&MchamlZone> = m.zones.iter().filter(|z| !z.values.is_empty()).collect();
    let mut out = Mchaml { subtype: m.subtype.clone(), zones: Vec::new() };
    let mut any_covered = false;
    for mz in &mo.zones {
        // Where each element of the field is: (zone, element number in
        // it), among the zones of this model zone's constituent.
        let mut at: HashMap<(ElemType, Vec<usize>), (usize, usize)> = HashMap::new();
        for (zi, z) in valued.iter().enumerate() {
            if !(z.cons.is_empty() || mz.cons.is_empty() || z.cons == mz.cons) {
                continue;
            }
            let mut e = 0;
            for p in &z.mesh.parts {
                for el in p.elems() {
                    at.entry(key(p.ty, el)).or_insert((zi, e));
                    e += 1;
                }
            }
        }
        let elems: Vec<(ElemType, Vec<usize>)> =
            mz.mesh.parts.iter().flat_map(|p| p.elems().map(move |e| key(p.ty, e))).collect();
        let mut covered = vec![false; elems.len()];
        for z in constant.iter().filter(|z| z.cons.is_empty() || mz.cons.is_empty() || z.cons == mz.cons) {
            let own: HashSet<(ElemType, Vec<usize>)> =
                z.mesh.parts.iter().flat_map(|p| p.elems().map(move |e| key(p.ty, e))).collect();
            let hit: Vec<bool> = elems.iter().map(|k| own.contains(k)).collect();
            if hit.iter().any(|h| *h) {
                covered.iter_mut().zip(&hit).for_each(|(c, h)| *c |= *h);
                match out.zones.iter_mut().find(|x| x.values.is_empty() && x.mesh == mz.mesh && x.cons == mz.cons) {
                    Some(x) => {
                        x.constants.extend(z.constants.clone());
                        x.vectors.extend(z.vectors.clone());
                        x.laws.extend(z.laws.clone());
                        x.objects.extend(z.objects.clone());
                    }
                    None => out.zones.push(MchamlZone {
                        mesh: mz.mesh.clone(),
                        cons: mz.cons.clone(),
                        element: mz.element.clone(),
                        constants: z.constants.clone(),
                        vectors: z.vectors.clone(),
                        laws: z.laws.clone(),
                        objects: z.objects.clone(),
                        ..Default::default()
                    }),
                }
            }
        }
        let mut e = 0;
        for p in &mz.mesh.parts {
            let mut nz: Option<MchamlZone> = None;
            let mut conn = Vec::new();
            for el in p.elems() {
                if let Some(&(zi, ze)) = at.get(&key(p.ty, el)) {
                    let src = valued[zi];
                    let z = nz.get_or_insert_with(|| MchamlZone {
                        mesh: Mesh::single(p.clone()),
                        cons: src.cons.clone(),
                        element: mz.element.clone(),
                        comps: src.comps.clone(),
                        at_nodes: src.at_nodes,
                        ..Default::default()
                    });
                    if z.comps != src.comps || z.at_nodes != src.at_nodes {
                        return Err(a.err("the field's zones under one zone of the model have different components"));
                    }
                    let v = src.values.get(ze).ok_or_else(|| a.err("the field has fewer values than elements"))?;
                    z.values.push(v.clone());
                    conn.extend_from_slice(el);
                    covered[e] = true;
                }
                e += 1;
            }
            if let Some(z) = nz.as_mut().filter(|_| conn.len() != p.conn.len()) {
                z.mesh = Mesh::single(crate::fem::mesh::Part { conn, ..p.clone() });
            }
            out.zones.extend(nz);
        }
        // A field on part of the model (the elements still active) stays
        // on that part; one on none of its elements is a mistake.
        any_covered |= covered.iter().any(|c| *c);
    }
    if !any_covered && mo.zones.iter().any(|z| !z.mesh.parts.is_empty()) {
        return Err(a.err("element 1 of the model is not in the field"));
    }
    Ok(out)
}
