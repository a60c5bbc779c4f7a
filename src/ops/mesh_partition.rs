//! PART (a mesh split into disjoint zones, in a TABLE indexed 1..n) and
//! ETG (the union of the meshes of such a table). The splitting is
//! `fem::meshing::partition`.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::fem::meshing::partition;
use crate::fem::meshing::partition_more::{self, Separator};
use crate::value::{Key, Table, Value};
use std::cell::RefCell;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "PART",
        signature: "PART ('NESC') 'ARLE' MESH n | 'CONN' MESH | 'OPTI' MESH (n) | 'SEPA' MESH rule.. with rule 'LIGN' | 'FACE' | 'MAIL' SEP | 'ANGL' (deg) ('TELQ')",
        doc: "Partition of a mesh in a TABLE of meshes indexed 1..n: 'ARLE' deals the elements in turn to n zones (Arlequin pattern), 'CONN' gives the connected components, 'OPTI' n balanced zones (n a power of two, 1 by default) by recursive bisection, 'SEPA' the zones of elements joined through faces not cut by a rule: junctions of more than two elements ('LIGN', 'FACE'), faces inside an element of SEP ('MAIL'), or normals/tangents making an angle of deg degrees or more (20 by default; up to their sign unless 'TELQ').",
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

fn part(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    // Without 'NESC' Cast3M marks the table as a slave partition; gibi has
    // no assistants, so the mark makes no difference.
    let nesc = a.keyword(&["NESC"]).is_some();
    let how = a.req_keyword(&["ARLE", "CONN", "SEPA", "OPTI"])?;
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
        "SEPA" => separated(it, a)?,
        "OPTI" => {
            let mesh = a.req::<Rc<Mesh>>()?;
            // Cast3M's default is the power of two above its number of
            // assistants; gibi runs none, hence one zone.
            let n = a.opt::<i64>().unwrap_or(1);
            if n < 1 || (n & (n - 1)) != 0 {
                return Err(a.err(format!("the number of zones must be a positive power of 2 (got {n})")));
            }
            partition_more::bisected(&mesh, &it.nodes, n as usize)
        }
        _ => partition::connected(&*a.req::<Rc<Mesh>>()?),
    };
    let mut t = if nesc { Table::new() } else { Table::with_subtype("ESCLAVE") };
    for (k, z) in zones.into_iter().enumerate() {
        t.set(Key::Int(k as i64 + 1), Value::Mesh(Rc::new(z)));
    }
    Ok(vec![Value::Table(Rc::new(RefCell::new(t)))])
}

/// 'SEPA' MESH rule..: the rules are read until none follows.
fn separated(it: &mut Interp, a: &mut Args) -> Result<Vec<Mesh>> {
    let mesh = a.req::<Rc<Mesh>>()?;
    let mut rules = Vec::new();
    while let Some(k) = a.keyword(&["LIGN", "FACE", "MAIL", "ANGL"]) {
        rules.push(match k {
            "MAIL" => Separator::Mesh((*a.req::<Rc<Mesh>>()?).clone()),
            "ANGL" => {
                let degrees = a.opt_num().unwrap_or(20.0);
                if !(0.0..=180.0).contains(&degrees) {
                    return Err(a.err(format!("the angle must lie in 0..180 degrees (got {degrees})")));
                }
                let oriented = a.keyword(&["TELQ"]).is_some();
                Separator::Angle { degrees, oriented }
            }
            _ => Separator::Junction,
        });
    }
    if rules.is_empty() {
        return Err(a.missing("one of LIGN FACE MAIL ANGL"));
    }
    Ok(partition_more::separated(&mesh, &it.nodes, &rules))
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
