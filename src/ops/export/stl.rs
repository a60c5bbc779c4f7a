//! LIRE 'STL' and SORT 'STL': triangulated surfaces for CAD and printing
//! tools (format in `crate::io::stl`).

use super::{add_nodes, out_path, write_err, wrote};
use crate::error::Result;
use crate::eval::args::Args;
use crate::eval::Interp;
use crate::fem::mesh::{ElemType, Mesh, Part};
use crate::io::stl::{self, Triangles};
use crate::value::Value;
use std::collections::HashMap;
use std::rc::Rc;

/// LIRE 'STL' file: a MAILLAGE of TRI3 (vertices with equal coordinates
/// are one node).
pub(super) fn lire(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let file = a.req::<String>()?;
    let path = it.files.check_read(&file)?;
    let t = stl::read(&path).map_err(|e| a.err(format!("'{}': {}", file, e.0)))?;
    let base = add_nodes(it, a, &file, &t.coords, |i| format!("vertex {}", i + 1))?;
    let conn = t.tris.iter().flat_map(|tri| tri.map(|n| n + base)).collect();
    Ok(vec![Value::Mesh(Rc::new(Mesh::single(Part::with(ElemType::Tri3, conn))))])
}

/// SORT 'STL' MAILLAGE: its surface elements as triangles (a QUA4 as two,
/// the corners of TRI6 and QUA8), in the file named by OPTI SORT
/// (.stl added).
pub(super) fn sort(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mesh = a.req::<Rc<Mesh>>()?;
    let mut t = Triangles::default();
    let mut local: HashMap<usize, usize> = HashMap::new();
    for part in &mesh.parts {
        let corners: &[[usize; 3]] = match part.ty {
            ElemType::Tri3 | ElemType::Tri6 => &[[0, 1, 2]],
            ElemType::Qua4 | ElemType::Qua8 => &[[0, 1, 2], [0, 2, 3]],
            other => {
                return Err(a.err(format!(
                    "STL holds surfaces (TRI3, TRI6, QUA4, QUA8), the mesh has {} elements (ENVE gives the skin of a volume)",
                    other.name()
                )))
            }
        };
        for e in part.elems() {
            for c in corners {
                t.tris.push(c.map(|k| {
                    let n = e[k];
                    let next = t.coords.len();
                    *local.entry(n).or_insert_with(|| {
                        t.coords.push(it.nodes.get(n));
                        next
                    })
                }));
            }
        }
    }
    let name = super::avs::with_extension(it.opts.text("SORT"), "stl");
    let p = out_path(it, &name)?;
    stl::write(&p, &t).map_err(write_err)?;
    wrote(it, &p);
    Ok(vec![])
}
