//! SORT MAILLAGE and LIRE (the directive forms, sort.notice, lire.notice):
//! a mesh written with the named meshes it contains, read back under the
//! same names. The file is gibi's own ([`crate::io::named_meshes`]): the
//! point is that LIRE gives back what SORT wrote, not a Cast3M file.

use super::{out_path, wrote, Args};
use crate::error::{Error, ErrorKind, Result};
use crate::eval::Interp;
use crate::fem::mesh::{ElemType, Mesh};
use crate::io::named_meshes::{self, NamedMeshes};
use crate::value::Value;
use std::collections::{BTreeMap, HashMap, HashSet};
use std::rc::Rc;

/// `SORT MAIL1 ('NOOP')`: MAIL1 under its name, and every other named mesh
/// whose elements are all elements of MAIL1, to the OPTI SORT file.
pub(super) fn sort(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let name = a.next_name_span().map(|sp| it.source.slice(sp).to_uppercase());
    let mesh: Rc<Mesh> = a.req()?;
    // gibi numbers the nodes of the file as it meets them: there is no
    // numbering to optimise.
    a.keyword(&["NOOP"]);
    let name = name.ok_or_else(|| a.err("SORT writes a mesh under its name: give the mesh as a variable"))?;
    let elems: HashSet<(ElemType, &[usize])> =
        mesh.parts.iter().flat_map(|p| p.elems().map(move |e| (p.ty, e))).collect();
    let mut subs: BTreeMap<String, Rc<Mesh>> = BTreeMap::new();
    // The innermost frame's names hide the outer ones.
    for f in &it.store.frames {
        for (k, v) in &f.vars {
            match v {
                Value::Mesh(m)
                    if *k != name
                        && m.n_elements() > 0
                        && m.parts.iter().all(|p| p.elems().all(|e| elems.contains(&(p.ty, e)))) =>
                {
                    subs.insert(k.clone(), m.clone());
                }
                _ => {
                    subs.remove(k);
                }
            }
        }
    }
    let mut data = NamedMeshes::default();
    let mut local: HashMap<usize, usize> = HashMap::new();
    for (n, m) in std::iter::once((name, mesh)).chain(subs) {
        let mut m = (*m).clone();
        for p in &mut m.parts {
            for k in &mut p.conn {
                let next = local.len();
                *k = *local.entry(*k).or_insert_with(|| {
                    data.nodes.push((it.nodes.get(*k), it.nodes.density[*k]));
                    next
                });
            }
        }
        data.meshes.push((n, m));
    }
    let file = super::sort_file(it);
    let p = out_path(it, &file)?;
    std::fs::write(&p, named_meshes::write(&data))
        .map_err(|e| Error::new(ErrorKind::Write, format!("cannot write {}: {}", p.display(), e)))?;
    wrote(it, &p);
    Ok(vec![])
}

/// `LIRE (GEO1)`: the meshes of the OPTI LECT file, each under its name,
/// on new nodes; with GEO1, the file must hold a mesh of that name.
pub(super) fn lire(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let wanted = match a.unbound_word() {
        Some(w) => Some(w.to_uppercase()),
        None => {
            let n = a.next_name_span().map(|sp| it.source.slice(sp).to_uppercase());
            if n.is_some() {
                a.right_any();
            }
            n
        }
    };
    let file = super::lect_file(it, a, "LIRE")?;
    let path = it.files.check_read(&file)?;
    let text = std::fs::read_to_string(&path).map_err(|e| a.err(format!("cannot read '{}': {}", file, e)))?;
    let data = named_meshes::read(&text).map_err(|e| a.err(format!("'{}': {}", file, e)))?;
    if let Some(w) = &wanted {
        if !data.meshes.iter().any(|(n, _)| n == w) {
            return Err(a.err(format!("'{}' holds no mesh named {}", file, w)));
        }
    }
    let base = it.nodes.len();
    for (x, d) in &data.nodes {
        it.nodes.push(*x, *d);
    }
    for (name, mut m) in data.meshes {
        for p in &mut m.parts {
            p.conn.iter_mut().for_each(|k| *k += base);
        }
        it.store.set(&name, Value::Mesh(Rc::new(m)));
    }
    Ok(vec![])
}
