//! SORT 'AVS' and LIRE 'AVS': a mesh with a nodal field, an element field
//! (one value per element) and the time, as AVS UCD structures; 'SUIT'
//! appends one per step and each LIRE reads the next (format in
//! `crate::io::avs`).

use super::{add_nodes, out_path, write_err, wrote};
use crate::error::Result;
use crate::eval::args::Args;
use crate::eval::Interp;
use crate::fem::mesh::{Mesh, Part};
use crate::io::avs::{self, Cell, Ucd};
use crate::value::model::MchamlZone;
use crate::value::{Chpoint, Key, Mchaml, Nature, Table, Value};
use std::cell::RefCell;
use std::collections::HashMap;
use std::rc::Rc;

/// SORT 'AVS' (MAILLAGE) (CHPOINT) (MCHAML) ('SUIT') ('TEMP' t).
pub(super) fn sort(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let (mut mesh, mut chpo, mut chml) = (None::<Rc<Mesh>>, None::<Rc<Chpoint>>, None::<Rc<Mchaml>>);
    let (mut suit, mut time) = (false, None);
    loop {
        match a.keyword(&["SUIT", "TEMP"]) {
            Some("SUIT") => suit = true,
            Some(_) => time = Some(a.req_num()?),
            None => match a.right_any() {
                Some(Value::Mesh(m)) if mesh.is_none() => mesh = Some(m),
                Some(Value::Chpo(c)) if chpo.is_none() => chpo = Some(c),
                Some(Value::Mchaml(c)) if chml.is_none() => chml = Some(c),
                Some(v) => {
                    return Err(a.err(format!(
                        "cannot write a {} here (one MAILLAGE, CHPOINT and MCHAML at most)",
                        v.type_name()
                    )))
                }
                None => break,
            },
        }
    }
    // The geometry: the mesh, else the element field's support, else the
    // nodes of the nodal field.
    let geo = match (&mesh, &chml, &chpo) {
        (Some(m), _, _) => (**m).clone(),
        (None, Some(c), _) => Mesh { parts: c.zones.iter().flat_map(|z| z.mesh.parts.iter().cloned()).collect() },
        (None, None, Some(c)) => Mesh::points(&c.nodes),
        (None, None, None) => return Err(a.missing("a MAILLAGE, a CHPOINT or an MCHAML")),
    };
    let nodes = geo.node_list();
    let local: HashMap<usize, usize> = nodes.iter().enumerate().map(|(i, n)| (*n, i)).collect();
    let mut u = Ucd { coords: nodes.iter().map(|n| it.nodes.get(*n)).collect(), ..Default::default() };
    for (k, part) in geo.parts.iter().enumerate() {
        for e in part.elems() {
            u.cells.push(Cell { material: k as i64 + 1, ty: part.ty, nodes: e.iter().map(|n| local[n]).collect() });
        }
    }
    if let Some(c) = &chpo {
        // Extended by zeros over the rest of the geometry.
        // Components with no value on the geometry (the multipliers LX of
        // a solution) are left out.
        for comp in c.components() {
            let v: Vec<Option<f64>> = nodes.iter().map(|n| c.get(*n, &comp)).collect();
            if v.iter().any(Option::is_some) {
                u.node_data.push((comp, v.into_iter().map(|x| x.unwrap_or(0.0)).collect()));
            }
        }
    }
    if let Some(c) = &chml {
        u.cell_data = cell_values(a, &geo, c)?;
    }
    u.model_data.extend(time.map(|t| ("time".to_string(), t)));
    let name = with_extension(it.opts.text("SORT"), "inp");
    let p = out_path(it, &name)?;
    let append = suit && it.exports.avs_written.as_deref() == Some(name.as_str());
    avs::write(&p, &u, append).map_err(write_err)?;
    it.exports.avs_written = Some(name);
    wrote(it, &p);
    Ok(vec![])
}

/// `name` (default gibi) with `.ext` added unless it has it already.
pub(super) fn with_extension(name: Option<&str>, ext: &str) -> String {
    let name = name.map(str::trim).filter(|s| !s.is_empty()).unwrap_or("gibi");
    if name.to_lowercase().ends_with(&format!(".{}", ext)) {
        name.to_string()
    } else {
        format!("{}.{}", name, ext)
    }
}

/// One value per element of `geo` and per component of the field: each
/// element is found in the field's support by its nodes.
fn cell_values(a: &Args, geo: &Mesh, c: &Mchaml) -> Result<Vec<(String, Vec<f64>)>> {
    let mut comps: Vec<String> = Vec::new();
    let mut at: HashMap<Vec<usize>, (usize, usize)> = HashMap::new();
    for (z, zone) in c.zones.iter().enumerate() {
        for name in zone.comps.iter().chain(zone.constants.keys()) {
            if !comps.contains(name) {
                comps.push(name.clone());
            }
        }
        if zone.values.iter().any(|pts| pts.len() != 1) {
            return Err(
                a.err("AVS takes one value per element: change the MCHAML to its centres first (CHAN 'GRAVITE')")
            );
        }
        let mut e = 0;
        for part in &zone.mesh.parts {
            for el in part.elems() {
                let mut key = el.to_vec();
                key.sort_unstable();
                at.insert(key, (z, e));
                e += 1;
            }
        }
    }
    let mut cols = vec![Vec::new(); comps.len()];
    for part in &geo.parts {
        for el in part.elems() {
            let mut key = el.to_vec();
            key.sort_unstable();
            let &(z, e) = at
                .get(&key)
                .ok_or_else(|| a.err("the MCHAML's support does not hold every element of the MAILLAGE"))?;
            let zone = &c.zones[z];
            for (k, name) in comps.iter().enumerate() {
                let v = match zone.comps.iter().position(|n| n == name) {
                    Some(i) => zone.values.get(e).and_then(|p| p[0].get(i)).copied().unwrap_or(0.0),
                    None => zone.constants.get(name).copied().unwrap_or(0.0),
                };
                cols[k].push(v);
            }
        }
    }
    Ok(comps.into_iter().zip(cols).collect())
}

/// LIRE 'AVS': the next structure of the file named by OPTI LECT, as a
/// TABLE (MAILSUPP, LEMAILLA, SOUMAILA, LECHPOIN, LEMCHAML, and each
/// global value under its label cut to 4 characters, such as 'time').
pub(super) fn lire(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let file = super::lect_file(it, a, "LIRE 'AVS'")?;
    let (pos, line) = match &it.exports.avs_read {
        Some((f, pos, line)) if *f == file => (*pos, *line),
        _ => (0, 0),
    };
    let path = it.files.check_read(&file)?;
    let (u, pos, next_line) = avs::read_at(&path, pos, line)
        .map_err(|e| a.err(format!("'{}': {}", file, e.0)))?
        .ok_or_else(|| a.err(format!("'{}': no AVS structure left to read after line {}", file, line)))?;
    it.exports.avs_read = Some((file.clone(), pos, next_line));
    let base = add_nodes(it, a, &file, &u.coords, |i| format!("node {}", i + 1))?;
    let mut t = Table::new();
    let all: Vec<usize> = (base..base + u.coords.len()).collect();
    t.set(mot("MAILSUPP"), Value::Mesh(Rc::new(Mesh::points(&all))));
    // Sub-meshes by (type, material), in order of first appearance; each
    // cell's place in its sub-mesh, for the element field.
    let mut parts: Vec<(i64, Part)> = Vec::new();
    let mut place = Vec::with_capacity(u.cells.len());
    for c in &u.cells {
        let k = match parts.iter().position(|(m, p)| *m == c.material && p.ty == c.ty) {
            Some(k) => k,
            None => {
                parts.push((c.material, Part::new(c.ty)));
                parts.len() - 1
            }
        };
        place.push((k, parts[k].1.len()));
        parts[k].1.conn.extend(c.nodes.iter().map(|n| n + base));
    }
    let mut sub = Table::new();
    for (k, (_, p)) in parts.iter().enumerate() {
        sub.set(Key::Int(k as i64 + 1), Value::Mesh(Rc::new(Mesh::single(p.clone()))));
    }
    t.set(mot("LEMAILLA"), Value::Mesh(Rc::new(Mesh { parts: parts.iter().map(|(_, p)| p.clone()).collect() })));
    t.set(mot("SOUMAILA"), Value::Table(Rc::new(RefCell::new(sub))));
    if !u.node_data.is_empty() {
        let entries = u
            .node_data
            .iter()
            .flat_map(|(comp, v)| v.iter().enumerate().map(move |(i, x)| (base + i, comp.as_str(), *x)));
        t.set(mot("LECHPOIN"), Value::Chpo(Rc::new(Chpoint::from_entries(Nature::Diffus, entries))));
    }
    if !u.cell_data.is_empty() {
        let comps: Vec<String> = u.cell_data.iter().map(|(c, _)| c.clone()).collect();
        let mut zones: Vec<MchamlZone> = parts
            .iter()
            .map(|(_, p)| MchamlZone {
                mesh: Mesh::single(p.clone()),
                element: p.ty.name().to_string(),
                comps: comps.clone(),
                values: vec![vec![vec![0.0; comps.len()]]; p.len()],
                ..Default::default()
            })
            .collect();
        for (cell, &(k, e)) in place.iter().enumerate() {
            for (j, (_, v)) in u.cell_data.iter().enumerate() {
                zones[k].values[e][0][j] = v[cell];
            }
        }
        t.set(mot("LEMCHAML"), Value::Mchaml(Rc::new(Mchaml { subtype: String::new(), zones })));
    }
    for (label, v) in &u.model_data {
        t.set(Key::Mot(label.chars().take(4).collect::<String>()), Value::Float(*v));
    }
    Ok(vec![Value::Table(Rc::new(RefCell::new(t)))])
}

fn mot(s: &str) -> Key {
    Key::Mot(s.into())
}
