//! MANU: meshes from points, constant fields, hand-written matrices.

use super::{dofs, Args, OpDef, PointId};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::{ElemType, Mesh};
use crate::fem::meshing as mg;
use crate::value::rigidity::{Block, Subtype, Symmetry};
use crate::value::{Chpoint, Nature, Rigidite, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "MANU",
    signature: "MANU TYPE P1 P2 … | MANU 'SUPE' P1 P2 … | MANU 'CHPO' GEO (n) COMP1 V1 … ('NATURE' 'DIFFUS'|'DISCRET') | MANU 'RIGI' ('TYPE' 'RIGIDITE'|'MASSE'|'AMORTISSEMENT') GEO LISTMOTS ('DUAL' LISTMOTS) ('ANTI'|'QUEL') LISTREEL | MANU 'RIGI' CHPOINT 'DIAG' | MANU 'CHML' MMODEL|GEO COMP1 V1 … ('TYPE' word) (support word) | MANU 'CHAM' MMODEL ('TYPE' word) ('POSI' support) COMP ELEM POINT (ZONE) VALUE",
    doc: "Build a mesh from points, a field from values, a constant field by element on every zone of a model \
          (at the points SIGM uses, or the element nodes with 'NOEUD'; subtype from 'TYPE', default SCALAIRE; \
          other support words such as 'STRESSES' change nothing for a constant), or a matrix from a list of values.",
    example: "k = manu 'RIGI' m (mots 'UX') (prog 2. -1. -1. 2.) ;",
    f: manu,
}];

fn manu(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    // The support may be written before the keyword (`MANU GEO 'CHPO' …`):
    // it is then pushed back as the first operand of that form.
    let early_geo = match a.peek_right() {
        Some(Value::Mesh(_)) => a.opt_right::<Rc<Mesh>>(),
        _ => None,
    };
    let what = a.word().ok_or_else(|| a.missing("an element type, 'SUPE', 'CHPO' or 'RIGI'"))?.to_uppercase();
    if super::args::keyword_matches(&what, "CHPO") {
        return chpo(it, a, early_geo);
    }
    if super::args::keyword_matches(&what, "RIGIDITE") {
        return rigi(it, a);
    }
    if super::args::keyword_matches(&what, "CHAM") {
        return cham(a);
    }
    if super::args::keyword_matches(&what, "CHML") {
        return chml(a, early_geo);
    }
    let mut pts = Vec::new();
    while let Some(p) = a.opt::<PointId>() {
        pts.push(p.0);
    }
    if super::args::keyword_matches(&what, "SUPE") {
        // A super-element: one element over all its points. gibi keeps it
        // as the point set; MANU 'RIGI' then sees one element over them.
        if pts.is_empty() {
            return Err(a.missing("POINT"));
        }
        return Ok(vec![Value::Mesh(Rc::new(Mesh::points(&pts)))]);
    }
    let ty = ElemType::from_name(&what).ok_or_else(|| a.err(format!("unknown element type {}", what)))?;
    let m = mg::manu(&it.nodes, ty, &pts)?;
    // A colour name after the points colours the element (`… 'VERT'`).
    let colour = match a.peek_right() {
        Some(Value::Mot(w)) => crate::fem::mesh::Colour::from_name(&w.to_uppercase()),
        _ => None,
    };
    let m = match colour {
        Some(c) => {
            a.word();
            m.coloured(c)
        }
        None => m,
    };
    Ok(vec![Value::Mesh(Rc::new(m))])
}

/// MANU 'CHML' mo c1 v1 …: the same values at every point of every
/// element. Built with the points SIGM gives (or the element nodes with
/// 'NOEUD', or one point per element with 'GRAVITE'), so that VMIS, CHAN,
/// INTG and arithmetic treat it like a computed field; another support
/// word changes nothing for a constant.
fn chml(a: &mut Args, early: Option<Rc<Mesh>>) -> Result<Vec<Value>> {
    use crate::value::model::{Mchaml, MchamlZone};
    // On a mesh (no model) the values sit at the element nodes, as Cast3M
    // gives them (a gap field on contact elements: MANU 'CHML' mc 'JEU' j).
    let (model, mesh) = match (early, a.opt::<Rc<crate::value::Model>>()) {
        (Some(g), _) => (None, Some(g)),
        (None, Some(m)) => (Some(m), None),
        (None, None) => (None, Some(a.opt::<Rc<Mesh>>().ok_or_else(|| a.missing("MMODEL or MAILLAGE"))?)),
    };
    let mut comps: Vec<String> = Vec::new();
    // A value is a constant, or with 'REPA' a list spread one value per
    // element over every zone in turn (restarting when it runs out).
    let mut vals: Vec<Result<f64, Rc<Vec<f64>>>> = Vec::new();
    let mut subtype = "SCALAIRE".to_string();
    let mut at_nodes = false;
    let mut spread = false;
    let mut centre = false;
    let mut fields: Vec<(String, Rc<Mchaml>)> = Vec::new();
    let mut objects: Vec<(String, Value)> = Vec::new();
    const SUPPORTS: &[&str] = &["STRESSES", "GRAVITE", "RIGIDITE", "MASSE", "DEFORMATIONS"];
    loop {
        // TYPE unquoted is also an operator name: read as the keyword here.
        if a.keyword(&["TYPE"]).is_some() {
            subtype = subtype_word(a)?;
            continue;
        }
        let Some(w) = a.word_not_operator() else { break };
        let w = w.trim().to_uppercase();
        if super::args::keyword_matches(&w, "TYPE") {
            subtype = subtype_word(a)?;
        } else if super::args::keyword_matches(&w, "CONSTITUANT") {
            // gibi matches element fields to model zones by mesh, so the
            // constituent name is read and not kept.
            a.req::<String>()?;
        } else if super::args::keyword_matches(&w, "REPA") {
            spread = true;
        } else if super::args::keyword_matches(&w, "NOEUD") {
            at_nodes = true;
        } else if super::args::keyword_matches(&w, "GRAVITE") {
            // One point per element, its centre (as CHAN 'GRAVITE').
            centre = true;
        } else if SUPPORTS.iter().any(|k| super::args::keyword_matches(&w, k)) {
            continue;
        } else {
            let v = match a.opt_num_right() {
                Some(v) => Ok(v),
                None => match a.opt_right::<Rc<Vec<f64>>>() {
                    Some(l) if spread && !l.is_empty() => Err(l),
                    // Without 'REPA' a list is one object for the whole
                    // component (manu.notice: OBJi of any type).
                    Some(l) => {
                        objects.push((w, Value::ListReel(l)));
                        continue;
                    }
                    None => match a.opt_right::<Rc<Mchaml>>() {
                        // A one-component field gives its values, element
                        // by element (filled in once the zones are made).
                        Some(f) => {
                            fields.push((w.clone(), f));
                            Ok(0.0)
                        }
                        // Names and values alternate, so a word here is
                        // the value of the component just named.
                        None => match a.right_any() {
                            Some(v @ (Value::Mot(_) | Value::ListMots(_) | Value::ListEnti(_) | Value::Table(_))) => {
                                objects.push((w, v));
                                continue;
                            }
                            Some(Value::Bool(b)) => Ok(if b { 1.0 } else { 2.0 }),
                            _ => return Err(a.err(format!("component {} needs a value", w))),
                        },
                    },
                },
            };
            match comps.iter().position(|c| *c == w) {
                Some(i) => vals[i] = v,
                None => {
                    comps.push(w);
                    vals.push(v);
                }
            }
        }
    }
    if comps.is_empty() && objects.is_empty() {
        return Err(a.missing("a component name and its value"));
    }
    let objects: std::collections::BTreeMap<String, Value> = objects.into_iter().collect();
    let mut counter = 0usize;
    let mut values_for = |n_elems: usize, npts: usize| -> Vec<Vec<Vec<f64>>> {
        (0..n_elems)
            .map(|_| {
                let row: Vec<f64> = vals
                    .iter()
                    .map(|v| match v {
                        Ok(x) => *x,
                        Err(l) => l[counter % l.len()],
                    })
                    .collect();
                counter += 1;
                vec![row; npts]
            })
            .collect()
    };
    let mut zones = Vec::new();
    for part in mesh.iter().flat_map(|m| m.parts.iter()) {
        zones.push(MchamlZone {
            mesh: Mesh::single(part.clone()),
            element: part.ty.name().to_string(),
            comps: comps.clone(),
            values: values_for(part.elems().count(), part.ty.nodes()),
            at_nodes: true,
            objects: objects.clone(),
            ..Default::default()
        });
    }
    for z in model.iter().flat_map(|m| m.zones.iter()) {
        let form = super::model::formulation(z);
        for part in &z.mesh.parts {
            let npts = if at_nodes {
                part.ty.nodes()
            } else if centre {
                1
            } else {
                crate::fem::element::gauss_points(form, part.ty).len()
            };
            zones.push(MchamlZone {
                mesh: Mesh::single(part.clone()),
                element: z.element.clone(),
                comps: comps.clone(),
                values: values_for(part.elems().count(), npts),
                at_nodes,
                objects: objects.clone(),
                ..Default::default()
            });
        }
    }
    let mut out = Mchaml { subtype, zones };
    for (comp, f) in &fields {
        super::manu_chml_fields::fill(&mut out, comp, f).map_err(|m| a.err(format!("component {}: {}", comp, m)))?;
    }
    Ok(vec![Value::Mchaml(Rc::new(out))])
}

/// MANU 'CHPO' GEO ((n) C1 V1 … | LISTMOTS LISTREEL) ('NATURE' w) ('TITRE' t):
/// the count and the values are read right after what they follow, so that
/// an ENTIER value is not taken for the count (`'SCAL' 1`).
/// MANU 'CHAM' MODL ('TYPE' w) ('POSI' support) COMP ELEM POINT (ZONE) VAL:
/// a field on one zone of the model (the first by default), zero but at
/// one point of one element.
fn cham(a: &mut Args) -> Result<Vec<Value>> {
    use crate::value::model::{Mchaml, MchamlZone};
    let model = a.req::<Rc<crate::value::Model>>()?;
    let mut subtype = "SCALAIRE".to_string();
    let mut at_nodes = true;
    loop {
        if a.keyword(&["TYPE"]).is_some() {
            subtype = subtype_word(a)?;
        } else if a.keyword(&["POSI"]).is_some() {
            let w = a.req_keyword(&["NOEUD", "GRAVITE", "RIGIDITE", "MASSE", "STRESSES"])?;
            at_nodes = w == "NOEUD";
        } else {
            break;
        }
    }
    let comp = a.word_not_operator().ok_or_else(|| a.missing("a component name"))?.trim().to_uppercase();
    let elem = a.opt_right::<i64>().ok_or_else(|| a.missing("ENTIER (element number)"))?;
    let point = a.opt_right::<i64>().ok_or_else(|| a.missing("ENTIER (point number)"))?;
    let third = a.opt_right::<i64>();
    let (zone, val) = match (third, a.opt_num_right()) {
        (Some(z), Some(v)) => (z, v),
        (Some(v), None) => (1, v as f64),
        (None, Some(v)) => (1, v),
        (None, None) => return Err(a.missing("FLOTTANT")),
    };
    let z = usize::try_from(zone - 1)
        .ok()
        .and_then(|i| model.zones.get(i))
        .ok_or_else(|| a.err(format!("zone {} is out of range (the model has {} zones)", zone, model.zones.len())))?;
    let form = super::model::formulation(z);
    let mut zones = Vec::new();
    let mut first = 0usize;
    for part in &z.mesh.parts {
        let npts = if at_nodes { part.ty.nodes() } else { crate::fem::element::gauss_points(form, part.ty).len() };
        let n = part.elems().count();
        let mut values = vec![vec![vec![0.0]; npts]; n];
        if elem >= 1 && (elem as usize) > first && (elem as usize) <= first + n {
            let row = &mut values[elem as usize - 1 - first];
            let p = usize::try_from(point - 1)
                .ok()
                .filter(|&p| p < npts)
                .ok_or_else(|| a.err(format!("point {} is out of range (the element has {} points)", point, npts)))?;
            row[p][0] = val;
        }
        first += n;
        zones.push(MchamlZone {
            mesh: Mesh::single(part.clone()),
            element: z.element.clone(),
            comps: vec![comp.clone()],
            values,
            at_nodes,
            ..Default::default()
        });
    }
    if elem < 1 || elem as usize > first {
        return Err(a.err(format!("element number {} is out of range (the zone has {} elements)", elem, first)));
    }
    Ok(vec![Value::Mchaml(Rc::new(Mchaml { subtype, zones }))])
}

fn chpo(it: &mut Interp, a: &mut Args, early: Option<Rc<Mesh>>) -> Result<Vec<Value>> {
    let mut nature = Nature::Diffus;
    let read_attr = |a: &mut Args, nature: &mut Nature| -> Result<bool> {
        if a.keyword(&["NATURE"]).is_some() {
            *nature = match a.req_keyword(&["DIFFUS", "DISCRET", "INDETERMINE"])? {
                "DIFFUS" => Nature::Diffus,
                "DISCRET" => Nature::Discret,
                _ => Nature::Indeter,
            };
            return Ok(true);
        }
        if a.keyword(&["TITRE"]).is_some() {
            a.req::<String>()?;
            return Ok(true);
        }
        Ok(false)
    };
    while read_attr(a, &mut nature)? {}
    let geo = match early {
        Some(m) => (*m).clone(),
        None => super::mesh::req_geo(a)?,
    };
    let nodes = geo.node_list();
    let mut c = Chpoint::new(nature);
    // Syntax 1: component names and one value each (missing ones are 0).
    if let Some(names) = a.opt_right::<Rc<Vec<String>>>() {
        let vals = a.opt_right::<Rc<Vec<f64>>>().ok_or_else(|| a.missing("LISTREEL"))?;
        if vals.len() > names.len() {
            return Err(a.err(format!("{} values for {} components", vals.len(), names.len())));
        }
        for (i, comp) in names.iter().enumerate() {
            let v = vals.get(i).copied().unwrap_or(0.0);
            for n in &nodes {
                c.add(*n, comp, v, false);
            }
        }
    } else {
        let count = a.opt_right::<i64>();
        let mut read = 0i64;
        loop {
            if count.is_none_or(|n| read < n) {
                if read_attr(a, &mut nature)? {
                    continue;
                }
            } else {
                break;
            }
            let Some(comp) = a.word_not_operator() else { break };
            read += 1;
            if let Some(l) = a.opt_right::<Rc<Vec<f64>>>() {
                // One value per element of a POI1 mesh (duplicates summed
                // for a DISCRET field), else one per distinct node.
                let per_elem: Vec<usize> = geo.parts.iter().flat_map(|p| p.elems().flat_map(|e| e.to_vec())).collect();
                let (targets, sum) = if l.len() == nodes.len() {
                    (nodes.clone(), false)
                } else if geo.parts.iter().all(|p| p.ty.nodes() == 1) && l.len() == per_elem.len() {
                    (per_elem, nature == Nature::Discret)
                } else {
                    return Err(a.err(format!("{} values for {} nodes", l.len(), nodes.len())));
                };
                for (n, v) in targets.iter().zip(l.iter()) {
                    c.add(*n, &comp, *v, sum);
                }
            } else {
                let v = a.opt_num_right().ok_or_else(|| a.missing("FLOTTANT"))?;
                for n in &nodes {
                    c.add(*n, &comp, v, false);
                }
            }
        }
    }
    while read_attr(a, &mut nature)? {}
    c.nature = nature;
    let _ = it;
    Ok(vec![Value::Chpo(Rc::new(c))])
}

fn rigi(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mut subtype = Subtype::Rigidite;
    if a.keyword(&["TYPE"]).is_some() {
        subtype = match a.req_keyword(&["RIGIDITE", "MASSE", "AMORTISSEMENT"])? {
            "MASSE" => Subtype::Masse,
            "AMORTISSEMENT" => Subtype::Amortissement,
            _ => Subtype::Rigidite,
        };
    }
    if let Some(ch) = a.opt::<Rc<Chpoint>>() {
        a.keyword(&["DIAG"]);
        let mut rig = Rigidite::new(subtype);
        for (n, c, v) in ch.entries() {
            rig.blocks.push(Block {
                nodes_per_elem: 1,
                conn: vec![n],
                dofs: vec![(0, c.to_string())],
                duals: vec![dofs::dual_of(c)],
                mats: vec![v],
                symmetry: Symmetry::Symmetric,
            });
        }
        return Ok(vec![Value::Rigi(Rc::new(rig))]);
    }
    let geo = super::mesh::req_geo(a)?;
    let comps = a.req::<Rc<Vec<String>>>()?;
    let mut duals: Vec<String> = comps.iter().map(|c| dofs::dual_of(c)).collect();
    let mut symmetry = Symmetry::Symmetric;
    let mut values: Option<Rc<Vec<f64>>> = None;
    loop {
        if a.keyword(&["DUAL"]).is_some() {
            let d = a.req::<Rc<Vec<String>>>()?;
            if d.len() != comps.len() {
                return Err(a.err("the DUAL list must have as many names as the unknowns"));
            }
            duals = d.to_vec();
        } else if let Some(k) = a.keyword(&["ANTI", "QUEL", "SYME"]) {
            symmetry = match k {
                "ANTI" => Symmetry::Antisymmetric,
                "QUEL" => Symmetry::General,
                _ => Symmetry::Symmetric,
            };
        } else if values.is_none() {
            match a.opt::<Rc<Vec<f64>>>() {
                Some(v) => values = Some(v),
                None => break,
            }
        } else {
            break;
        }
    }
    let values = values.ok_or_else(|| a.missing("LISTREEL"))?;
    // One element per mesh element, or one super-element over every node
    // (MANU 'SUPE' meshes) when the list has that size.
    let nc = comps.len();
    let per_elem: Vec<Vec<usize>> = geo.parts.iter().flat_map(|p| p.elems().map(|e| e.to_vec())).collect();
    let npe = per_elem.first().map_or(0, |e| e.len());
    let fits = |nn: usize| {
        let d = nn * nc;
        values.len() == d * d || values.len() == d * (d + 1) / 2
    };
    let elems: Vec<Vec<usize>> = if fits(npe) && per_elem.iter().all(|e| e.len() == npe) {
        per_elem
    } else if fits(geo.node_list().len()) {
        vec![geo.node_list()]
    } else {
        return Err(a.err(format!(
            "{} values do not make a square (or lower-triangular) matrix over {} unknown(s) per element",
            values.len(),
            npe * nc
        )));
    };
    let nn = elems[0].len();
    let d = nn * nc;
    let mut mat = vec![0.0; d * d];
    if values.len() == d * d {
        mat.copy_from_slice(&values);
    } else {
        if symmetry == Symmetry::General {
            return Err(a.err("a general ('QUEL') matrix needs all its values"));
        }
        let sign = if symmetry == Symmetry::Antisymmetric { -1.0 } else { 1.0 };
        let mut k = 0;
        for i in 0..d {
            for j in 0..=i {
                mat[i * d + j] = values[k];
                mat[j * d + i] = if i == j { values[k] } else { sign * values[k] };
                k += 1;
            }
        }
    }
    let mut rig = Rigidite::new(subtype);
    let mut block = Block {
        nodes_per_elem: nn,
        conn: Vec::new(),
        dofs: (0..nn).flat_map(|l| comps.iter().map(move |c| (l, c.clone()))).collect(),
        duals: (0..nn).flat_map(|_| duals.iter().cloned()).collect(),
        mats: Vec::new(),
        symmetry,
    };
    for e in &elems {
        block.conn.extend_from_slice(e);
        block.mats.extend_from_slice(&mat);
    }
    rig.blocks.push(block);
    let _ = it;
    Ok(vec![Value::Rigi(Rc::new(rig))])
}

/// The subtype after 'TYPE': a MOT, or a bare word that also names an
/// operator (`TYPE RIGIDITE`), which Cast3M reads as a word there.
fn subtype_word(a: &mut Args) -> Result<String> {
    let w = match a.opt::<String>() {
        Some(w) => w,
        None => a.word().ok_or_else(|| a.missing("MOT (the subtype)"))?,
    };
    Ok(w.trim().to_uppercase())
}
