//! X-FEM operators: TRIE (which nodes of a model's X-FEM zones the crack
//! enriches, from its level sets) and XFEM (physical displacements from
//! the enriched unknowns: 'RECO' at the nodes, 'FISS' on the crack lips).
//! The zone plumbing is `ops/xfem_model.rs`, the numerics `fem::xfem`.

use super::mesh::req_geo;
use super::xfem_model::{elem_data, element_dofs, Shared};
use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::locate::locate;
use crate::fem::mesh::{ElemType, Mesh};
use crate::fem::shape::ref_nodes;
use crate::fem::xfem::q4;
use crate::fem::xfem::{select, ElemLevels, Enrichment, NodeKind, ENRICHED_DOFS};
use crate::value::model::{MchamlZone, ModelZone};
use crate::value::{Chpoint, Mchaml, Model, Nature, Value};
use std::collections::HashSet;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "TRIE",
        signature: "TRIE MMODEL CHPO_PSI CHPO_PHI ('SAUT') | TRIE MMODEL MCHAML",
        doc: "Enrich the X-FEM zones (XQ4R) of a model, in place, by a crack given by its level sets (PSIP … 'DEUX': PSI along the crack, positive ahead of the tip, then PHI, the signed distance to it): the nodes of elements holding the tip get the four tip functions (unknowns B1X B1Y … E1X E1Y), the other nodes of elements the crack cuts through get the jump (AX AY). With 'SAUT', no tip function: the crack stops at the edge of the element holding its tip. Gives the enrichment field (PSI, PHI and ENRI at the element nodes: 0 classical, 1 jump, 2 tip, -1 no level set); TRIE MMODEL MCHAML puts such a field back on the model.",
        example: "opti dime 2 elem qua4 mode plan defo ; s = ((0. 0.) droi 4 (4. 0.)) tran 2 (0. 2.) ; c = (0. 1.1) droi 2 (2. 1.1) ; psi phi = psip s c 'DEUX' (2. 1.1) ; mo = mode s mecanique elastique xq4r ; en = trie mo psi phi ;",
        f: trie,
    },
    OpDef {
        name: "XFEM",
        signature: "XFEM 'RECO' CHPOINT MMODEL | XFEM 'FISS' CRACK_GEO CHPOINT MMODEL",
        doc: "Post-processing of an X-FEM solution. 'RECO': the physical displacement (UX UY) at the nodes, the enriched unknowns folded in. 'FISS': the displacements of the upper lip (the side where PHI > 0) and of the lower lip at the nodes of the crack mesh, two CHPOINTs.",
        example: "opti dime 2 elem qua4 mode plan defo ; s = ((0. 0.) droi 2 (2. 0.)) tran 1 (0. 1.) ; mo = mode s mecanique elastique xq4r ; u = manu chpo s 2 'UX' 1. 'UY' 0. ; ur = xfem 'RECO' u mo ;",
        f: xfem,
    },
];

fn xfem_zones(a: &Args, model: &Model) -> Result<Vec<(ModelZone, Shared)>> {
    let out: Vec<_> = model.zones.iter().filter_map(|z| z.xfem.as_ref().map(|x| (z.clone(), x.clone()))).collect();
    if out.is_empty() {
        return Err(a.err("the model has no X-FEM zone (MODE … 'XQ4R')"));
    }
    Ok(out)
}

/// The value of a level set at a node: its (first) component.
fn level(c: &Chpoint, node: usize) -> Option<f64> {
    c.get(node, c.comps.first()?)
}

fn trie(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let model = a.req::<Rc<Model>>()?;
    let zones = xfem_zones(a, &model)?;
    if let Some(f) = a.opt::<Rc<Mchaml>>() {
        for (z, x) in &zones {
            *x.borrow_mut() = restore(a, z, &f)?;
        }
        return Ok(vec![Value::Mchaml(f)]);
    }
    let psi = a.req::<Rc<Chpoint>>()?;
    let phi = a.req::<Rc<Chpoint>>()?;
    let jump_only = match a.keyword(&["SAUT", "DESE"]) {
        Some("DESE") => {
            return Err(a.err("TRIE 'DESE' (progressive removal of the tip enrichment) is not implemented"));
        }
        k => k.is_some(),
    };
    let mut out = Mchaml { subtype: "ENRICHISSEMENT".into(), zones: vec![] };
    for (zone, x) in &zones {
        let mut enr = Enrichment::default();
        let mut data = Vec::new();
        for part in &zone.mesh.parts {
            for nodes in part.elems() {
                let vals: Option<Vec<(f64, f64)>> =
                    nodes.iter().map(|n| Some((level(&psi, *n)?, level(&phi, *n)?))).collect();
                let Some(v) = vals else { continue };
                let xs: Vec<[f64; 3]> = nodes.iter().map(|n| it.nodes.get(*n)).collect();
                let size = xs
                    .iter()
                    .flat_map(|p| xs.iter().map(move |q| (0..3).map(|k| (p[k] - q[k]).powi(2)).sum::<f64>().sqrt()))
                    .fold(0.0, f64::max);
                for (n, l) in nodes.iter().zip(&v) {
                    enr.levels.insert(*n, *l);
                }
                let (s, f): (Vec<f64>, Vec<f64>) = v.into_iter().unzip();
                data.push((nodes.to_vec(), s, f, size));
            }
        }
        let sel: Vec<ElemLevels> =
            data.iter().map(|(n, s, f, size)| ElemLevels { nodes: n, psi: s, phi: f, size: *size }).collect();
        enr.kinds = select(&sel, jump_only);
        out.zones.extend(field_zones(zone, &enr));
        *x.borrow_mut() = enr;
    }
    Ok(vec![Value::Mchaml(Rc::new(out))])
}

/// TRIE's field: PSI, PHI and the enrichment code at every element node.
fn field_zones(zone: &ModelZone, enr: &Enrichment) -> Vec<MchamlZone> {
    zone.mesh
        .parts
        .iter()
        .map(|part| MchamlZone {
            mesh: Mesh::single(part.clone()),
            element: zone.element.clone(),
            comps: vec!["PSI".into(), "PHI".into(), "ENRI".into()],
            values: part
                .elems()
                .map(|nodes| {
                    nodes
                        .iter()
                        .map(|n| match enr.levels.get(n) {
                            Some((s, f)) => vec![*s, *f, NodeKind::code(enr.kind(*n))],
                            None => vec![0.0, 0.0, -1.0],
                        })
                        .collect()
                })
                .collect(),
            at_nodes: true,
            ..Default::default()
        })
        .collect()
}

/// The enrichment of a zone read back from TRIE's field.
fn restore(a: &Args, zone: &ModelZone, f: &Mchaml) -> Result<Enrichment> {
    let own: HashSet<usize> = zone.mesh.node_list().into_iter().collect();
    let mut enr = Enrichment::default();
    for z in &f.zones {
        let idx: Option<Vec<usize>> =
            ["PSI", "PHI", "ENRI"].iter().map(|c| z.comps.iter().position(|n| n == c)).collect();
        let Some(idx) = idx else {
            return Err(a.err("the MCHAML is not an enrichment field of TRIE (components PSI PHI ENRI)"));
        };
        let elems = z.mesh.parts.iter().flat_map(|p| p.elems());
        for (nodes, vals) in elems.zip(&z.values) {
            for (n, v) in nodes.iter().zip(vals) {
                if !own.contains(n) || v[idx[2]] < 0.0 {
                    continue;
                }
                enr.levels.insert(*n, (v[idx[0]], v[idx[1]]));
                if let Some(k) = NodeKind::from_code(v[idx[2]]) {
                    enr.kinds.insert(*n, k);
                }
            }
        }
    }
    Ok(enr)
}

fn xfem(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    match a.req_keyword(&["RECO", "FISS"])? {
        "RECO" => {
            let u = a.req::<Rc<Chpoint>>()?;
            let model = a.req::<Rc<Model>>()?;
            reco(it, a, &u, &model)
        }
        _ => {
            let geo = req_geo(a)?;
            let u = a.req::<Rc<Chpoint>>()?;
            let model = a.req::<Rc<Model>>()?;
            lips(it, a, &geo, &u, &model)
        }
    }
}

/// The physical displacement at every node: u + H a + Σ F b there.
fn reco(it: &Interp, a: &Args, u: &Chpoint, model: &Model) -> Result<Vec<Value>> {
    let zones = xfem_zones(a, model)?;
    let mut out = Chpoint::from_entries(u.nature, u.entries().filter(|(_, c, _)| !ENRICHED_DOFS.contains(c)));
    let corners = ref_nodes(ElemType::Qua4);
    for (zone, x) in &zones {
        let enr = x.borrow();
        let mut done = HashSet::new();
        for part in &zone.mesh.parts {
            for nodes in part.elems() {
                if nodes.iter().all(|n| enr.kind(*n).is_none()) {
                    continue;
                }
                let d = elem_data(it, a, &enr, nodes)?;
                let ue = element_dofs(a, u, nodes, &d.kinds)?;
                for (l, n) in nodes.iter().enumerate() {
                    if d.kinds[l].is_none() || !done.insert(*n) {
                        continue;
                    }
                    let v = q4::displacement(&d.elem(), corners[l], &ue, None).map_err(|e| a.err(e))?;
                    out.add(*n, "UX", v[0], false);
                    out.add(*n, "UY", v[1], false);
                }
            }
        }
    }
    Ok(vec![Value::Chpo(Rc::new(out))])
}

/// The displacements of both lips at the nodes of the crack mesh.
fn lips(it: &Interp, a: &Args, geo: &Mesh, u: &Chpoint, model: &Model) -> Result<Vec<Value>> {
    let zones = xfem_zones(a, model)?;
    let (mut up, mut down) = (Chpoint::new(Nature::Diffus), Chpoint::new(Nature::Diffus));
    for n in geo.node_list() {
        let p = it.nodes.get(n);
        'search: for (zone, x) in &zones {
            let enr = x.borrow();
            for part in &zone.mesh.parts {
                for nodes in part.elems() {
                    let xs: Vec<[f64; 3]> = nodes.iter().map(|m| it.nodes.get(*m)).collect();
                    let Some(xi) = locate(ElemType::Qua4, &xs, p) else { continue };
                    let d = elem_data(it, a, &enr, nodes)?;
                    let ue = element_dofs(a, u, nodes, &d.kinds)?;
                    for (side, f) in [(1.0, &mut up), (-1.0, &mut down)] {
                        let v = q4::displacement(&d.elem(), xi, &ue, Some(side)).map_err(|e| a.err(e))?;
                        f.add(n, "UX", v[0], false);
                        f.add(n, "UY", v[1], false);
                    }
                    break 'search;
                }
            }
        }
    }
    Ok(vec![Value::Chpo(Rc::new(up)), Value::Chpo(Rc::new(down))])
}
