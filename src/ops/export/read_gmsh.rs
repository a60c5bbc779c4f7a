//! LIRE 'GMSH': a Gmsh mesh as a TABLE of MAILLAGE by physical group.

use super::io_err;
use crate::error::Result;
use crate::eval::args::Args;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::io::gmsh;
use crate::value::{Key, Table, Value};
use std::cell::RefCell;
use std::rc::Rc;

pub(super) fn lire(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let file = a.req::<String>()?;
    let path = it.files.check_read(&file)?;
    let g = gmsh::read(&path).map_err(io_err)?;
    let tags = &g.node_tags;
    let base = super::add_nodes(it, a, &file, &g.coords, |i| format!("node {}", tags[i]))?;
    let shift = |mut m: Mesh| {
        m.parts.iter_mut().for_each(|p| p.conn.iter_mut().for_each(|n| *n += base));
        Value::Mesh(Rc::new(m))
    };
    let mut t = Table::new();
    for grp in &g.groups {
        let key = match &grp.name {
            Some(n) => Key::Mot(n.clone()),
            None => Key::Int(grp.tag),
        };
        t.set(key, shift(g.group_mesh(grp.dim, grp.tag)));
    }
    t.set(Key::Mot("TOUT".into()), shift(g.all_mesh()));
    Ok(vec![Value::Table(Rc::new(RefCell::new(t)))])
}
