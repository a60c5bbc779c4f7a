//! PART (a mesh split into disjoint zones, in a TABLE indexed 1..n) and
//! ETG (the union of the meshes of such a table). The splitting is
//! `fem::meshing::partition`.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::fem::meshing::partition;
use crate::value::{Key, Table, Value};
use std::cell::RefCell;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "PART",
        signature: "PART ('NESC') 'ARLE' n MESH | PART ('NESC') 'CONN' MESH",
        doc: "Partition of a mesh in a TABLE of meshes indexed 1..n: 'ARLE' deals the elements in turn to n zones (Arlequin pattern), 'CONN' gives the connected components.",
        example: "t = part 'ARLE' 2 ((0. 0.) droi 4 (1. 0.)) ;",
        f: part,
    },
    OpDef {
        name: "ETG",
        signature: "ETG TABLE",
        doc: "The union (ET) of the meshes that are the values of a table, in the order of their integer indices.",
        example: "m = etg (part 'ARLE' 2 ((0. 0.) droi 4 (1. 0.))) ;",
        f: etg,
    },
];

fn part(_it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    // Without 'NESC' Cast3M marks the table as a slave partition; gibi has
    // no assistants, so the mark makes no difference.
    let nesc = a.keyword(&["NESC"]).is_some();
    let how = a.req_keyword(&["ARLE", "CONN"])?;
    a.keyword(&["NESC"]);
    let zones = match how {
        "ARLE" => {
            let n = a.req::<i64>()?;
            if n < 1 {
                return Err(a.err(format!("the number of zones must be positive (got {n})")));
            }
            let mesh = a.req::<Rc<Mesh>>()?;
            partition::arlequin(&mesh, n as usize)
        }
        _ => partition::connected(&*a.req::<Rc<Mesh>>()?),
    };
    let mut t = if nesc { Table::new() } else { Table::with_subtype("ESCLAVE") };
    for (k, z) in zones.into_iter().enumerate() {
        t.set(Key::Int(k as i64 + 1), Value::Mesh(Rc::new(z)));
    }
    Ok(vec![Value::Table(Rc::new(RefCell::new(t)))])
}

fn etg(_it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let t = a.req::<Rc<RefCell<Table>>>()?;
    let t = t.borrow();
    let mut items: Vec<(i64, Rc<Mesh>)> = Vec::new();
    for (k, v) in t.iter() {
        match (k, v) {
            (Key::Int(i), Value::Mesh(m)) => items.push((*i, m.clone())),
            // PART's mark of a slave partition.
            (Key::Mot(w), _) if w == "SOUSTYPE" => {}
            _ => {
                return Err(a.err(format!(
                    "the table must hold meshes at integer indices; it holds a {} at an index of type {}",
                    v.ty().name(),
                    k.to_value().ty().name()
                )))
            }
        }
    }
    items.sort_by_key(|(i, _)| *i);
    let out = items.iter().fold(Mesh::default(), |acc, (_, m)| acc.union(m));
    Ok(vec![Value::Mesh(Rc::new(out))])
}
