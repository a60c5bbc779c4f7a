//! Closed contours: CCON (connected components in a table), SENS (which
//! way each contour of such a table runs) and DEDA (is a point inside a
//! closed boundary). The geometry is `fem::meshing::{partition, winding}`.

use super::{Args, OpDef, PointId};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::fem::meshing::partition;
use crate::fem::meshing::partition_more::{self, Separator};
use crate::fem::meshing::winding;
use crate::value::{Key, Table, Value};
use std::cell::RefCell;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "CCON",
        signature: "CCON ('STR1' | 'STR2') MESH",
        doc: "The connected components of a mesh in a TABLE indexed 1, 2, ...: elements joined through a shared node; with 'STR1' (lines) a node on more than two elements separates components; with 'STR2' (surfaces) elements are joined through edges on at most two elements.",
        example: "t = ccon (((0. 0.) droi 2 (1. 0.)) et ((3. 0.) droi 2 (4. 0.))) ;",
        f: ccon,
    },
    OpDef {
        name: "SENS",
        signature: "SENS TABLE",
        doc: "For a table of closed plane contours (as CCON gives), a table of the same indices holding +1 for a contour run counter-clockwise, -1 for one run clockwise.",
        example: "t = sens (ccon (((0. 0.) droi 1 (1. 0.) droi 1 (0. 1.) droi 1 (0. 0.)))) ;",
        f: sens,
    },
    OpDef {
        name: "DEDA",
        signature: "DEDA POINT MESH (tol)",
        doc: "VRAI when the point lies inside (or on) the closed oriented boundary MESH: a line of SEG2 in 2D, a surface of TRI3 in 3D (holes oriented against the outer boundary). The angles the boundary subtends from the point are summed; a total within tol (1E-9 by default) of zero means outside.",
        example: "l = deda (0.5 0.5) ((0. 0.) droi 1 (1. 0.) droi 1 (1. 1.) droi 1 (0. 1.) droi 1 (0. 0.)) ;",
        f: deda,
    },
];

fn table_of(items: impl IntoIterator<Item = Value>) -> Value {
    let mut t = Table::new();
    for (k, v) in items.into_iter().enumerate() {
        t.set(Key::Int(k as i64 + 1), v);
    }
    Value::Table(Rc::new(RefCell::new(t)))
}

fn ccon(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let how = a.keyword(&["STR1", "STR2"]);
    let mesh = a.req::<Rc<Mesh>>()?;
    let zones = match how {
        Some(_) => partition_more::separated(&mesh, &it.nodes, &[Separator::Junction]),
        None => partition::connected(&mesh),
    };
    Ok(vec![table_of(zones.into_iter().map(|z| Value::Mesh(Rc::new(z))))])
}

fn sens(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let t = a.req::<Rc<RefCell<Table>>>()?;
    let mut out = Table::new();
    for (k, v) in t.borrow().iter() {
        match (k, v) {
            (Key::Int(_), Value::Mesh(m)) => {
                out.set(k.clone(), Value::Int(winding::sense(&it.nodes, m)?));
            }
            (Key::Mot(w), _) if w == "SOUSTYPE" => {}
            _ => {
                return Err(a.err(format!(
                    "the table must hold contours (MAILLAGE) at integer indices; it holds a {} at an index of type {}",
                    v.ty().name(),
                    k.to_value().ty().name()
                )))
            }
        }
    }
    Ok(vec![Value::Table(Rc::new(RefCell::new(out)))])
}

fn deda(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let p = a.req::<PointId>()?;
    let mesh = a.req::<Rc<Mesh>>()?;
    let tol = a.opt_num().unwrap_or(1e-9);
    if !(tol.is_finite() && tol >= 0.0) {
        return Err(a.err(format!("the tolerance must be a non-negative number (got {tol})")));
    }
    let x = it.nodes.get(p.0);
    Ok(vec![Value::Bool(winding::inside(&it.nodes, &mesh, x, tol)?)])
}
