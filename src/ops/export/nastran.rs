//! LIRE 'NAS' and SORT 'NAS': Nastran bulk data (format in
//! `crate::io::nastran`).

use super::{add_nodes, out_path, write_err, wrote};
use crate::error::Result;
use crate::eval::args::Args;
use crate::eval::Interp;
use crate::fem::mesh::{ElemType, Mesh, Part};
use crate::io::nastran;
use crate::value::{Chpoint, Key, Nature, Table, Value};
use std::cell::RefCell;
use std::collections::{BTreeMap, HashMap};
use std::rc::Rc;

fn table(t: Table) -> Value {
    Value::Table(Rc::new(RefCell::new(t)))
}

fn mot(s: &str) -> Key {
    Key::Mot(s.into())
}

/// LIRE 'NAS' file: a TABLE with MAILLAGES (a MAILLAGE per property id),
/// BLOCAGES (POI1 per SPC set), FORCES, MOMENTS and TEMPERATURES (a
/// CHPOINT per load set), RBE2 (per element, a TABLE whose MAILLAGE holds
/// the independent point first) and SYSTEMES (empty: coordinate systems
/// are not read).
pub(super) fn lire(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let file = a.req::<String>()?;
    let path = it.files.check_read(&file)?;
    let fail = |m: String| a.err(format!("'{}': {}", file, m));
    let b = nastran::read(&path).map_err(|e| fail(e.0))?;
    let coords: Vec<[f64; 3]> = b.grids.iter().map(|g| g.1).collect();
    let base = add_nodes(it, a, &file, &coords, |i| format!("GRID {}", b.grids[i].0))?;
    let mut node: HashMap<i64, usize> = HashMap::new();
    for (i, (id, _)) in b.grids.iter().enumerate() {
        if node.insert(*id, base + i).is_some() {
            return Err(fail(format!("GRID {} is defined twice", id)));
        }
    }
    let at = |g: i64, what: &str| {
        node.get(&g).copied().ok_or_else(|| fail(format!("{} refers to GRID {}, which is not defined", what, g)))
    };
    // Elements by property, parts by type in order of first appearance.
    let mut by_pid: BTreeMap<i64, Vec<Part>> = BTreeMap::new();
    for (pid, ty, grids) in &b.elements {
        let parts = by_pid.entry(*pid).or_default();
        let k = match parts.iter().position(|p| p.ty == *ty) {
            Some(k) => k,
            None => {
                parts.push(Part::new(*ty));
                parts.len() - 1
            }
        };
        for g in grids {
            let n = at(*g, &format!("an element of property {}", pid))?;
            parts[k].conn.push(n);
        }
    }
    let mut meshes = Table::new();
    for (pid, parts) in by_pid {
        meshes.set(Key::Int(pid), Value::Mesh(Rc::new(Mesh { parts })));
    }
    let mut spcs = Table::new();
    for (sid, grids) in &b.spcs {
        let nodes = grids.iter().map(|g| at(*g, &format!("SPC set {}", sid))).collect::<Result<Vec<_>>>()?;
        spcs.set(Key::Int(*sid), Value::Mesh(Rc::new(Mesh::points(&nodes))));
    }
    let dime = it.opts.dime;
    let vectors = |sets: &BTreeMap<i64, Vec<(i64, [f64; 3])>>, names: [&str; 3], what: &str| -> Result<Table> {
        // In 2D a force keeps FX FY and a moment MZ only.
        let keep: Vec<usize> = match (dime, what) {
            (1 | 2, "FORCE") => vec![0, 1],
            (1 | 2, _) => vec![2],
            _ => vec![0, 1, 2],
        };
        let mut t = Table::new();
        for (sid, items) in sets {
            let mut entries = Vec::new();
            for (g, v) in items {
                let n = at(*g, &format!("{} set {}", what, sid))?;
                entries.extend(keep.iter().map(|&k| (n, names[k], v[k])));
            }
            t.set(Key::Int(*sid), Value::Chpo(Rc::new(Chpoint::from_entries(Nature::Discret, entries))));
        }
        Ok(t)
    };
    let forces = vectors(&b.forces, ["FX", "FY", "FZ"], "FORCE")?;
    let moments = vectors(&b.moments, ["MX", "MY", "MZ"], "MOMENT")?;
    let mut temps = Table::new();
    for (sid, items) in &b.temperatures {
        let mut entries = Vec::new();
        for (g, t) in items {
            entries.push((at(*g, &format!("TEMP set {}", sid))?, "T", *t));
        }
        temps.set(Key::Int(*sid), Value::Chpo(Rc::new(Chpoint::from_entries(Nature::Diffus, entries))));
    }
    let mut rbe2 = Table::new();
    for (eid, grids) in &b.rbe2 {
        let nodes = grids.iter().map(|g| at(*g, &format!("RBE2 {}", eid))).collect::<Result<Vec<_>>>()?;
        let mut e = Table::new();
        e.set(mot("MAILLAGE"), Value::Mesh(Rc::new(Mesh::points(&nodes))));
        rbe2.set(Key::Int(*eid), table(e));
    }
    let mut t = Table::new();
    t.set(mot("MAILLAGES"), table(meshes));
    t.set(mot("SYSTEMES"), table(Table::new()));
    t.set(mot("RBE2"), table(rbe2));
    t.set(mot("BLOCAGES"), table(spcs));
    t.set(mot("TEMPERATURES"), table(temps));
    t.set(mot("FORCES"), table(forces));
    t.set(mot("MOMENTS"), table(moments));
    Ok(vec![table(t)])
}

/// SORT 'NAS' MAILLAGE: GRIDs and elements (one property id per
/// sub-mesh) in the file named by OPTI SORT (.nas added).
pub(super) fn sort(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mesh = a.req::<Rc<Mesh>>()?;
    if let Some(p) = mesh.parts.iter().find(|p| !nastran::writable(p.ty)) {
        return Err(a.err(format!("no Nastran element card for {} elements", p.ty.name())));
    }
    let nodes = mesh.node_list();
    let local: HashMap<usize, usize> = nodes.iter().enumerate().map(|(i, n)| (*n, i)).collect();
    let coords: Vec<[f64; 3]> = nodes.iter().map(|n| it.nodes.get(*n)).collect();
    let mut elements: Vec<(i64, ElemType, Vec<usize>)> = Vec::new();
    for (k, part) in mesh.parts.iter().enumerate() {
        for e in part.elems() {
            elements.push((k as i64 + 1, part.ty, e.iter().map(|n| local[n]).collect()));
        }
    }
    let name = super::avs::with_extension(it.opts.text("SORT"), "nas");
    let p = out_path(it, &name)?;
    nastran::write(&p, &coords, &elements).map_err(write_err)?;
    wrote(it, &p);
    Ok(vec![])
}
