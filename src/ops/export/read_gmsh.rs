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
    a.req_keyword(&["GMSH"])?;
    let file = a.req::<String>()?;
    let path = it.files.check_read(&file)?;
    let g = gmsh::read(&path).map_err(io_err)?;
    let dime = it.opts.dime;
    for (i, x) in g.coords.iter().enumerate() {
        if let Some(k) = (dime.max(1)..3).find(|&k| dime > 0 && x[k].abs() > 1e-9 * (1.0 + x[0].abs() + x[1].abs())) {
            return Err(a.err(format!(
                "{}: node {} has {} = {} but OPTI DIME is {}",
                file,
                g.node_tags[i],
                ["x", "y", "z"][k],
                x[k],
                dime
            )));
        }
    }
    let base = it.nodes.len();
    for x in &g.coords {
        let mut p = *x;
        if dime > 0 {
            p[dime..].iter_mut().for_each(|c| *c = 0.0);
        }
        it.nodes.push(p, it.opts.dens);
    }
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
