//! Geometry: points and meshes (COOR, POIN, MANU, DROI, … ; NBNO, NBEL).

use super::{Args, OpDef, PointId};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::value::Value;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "COOR",
        signature: "COOR POINT | COOR n POINT | COOR n MAILLAGE",
        doc: "Coordinates of a point (one result per dimension), one of them, or a coordinate field on a mesh.",
        example: "x y = coor p ;",
        f: coor,
    },
    OpDef {
        name: "NBNO",
        signature: "NBNO MAILLAGE",
        doc: "Number of nodes of a mesh.",
        example: "n = nbno l ;",
        f: nbno,
    },
    OpDef {
        name: "NBEL",
        signature: "NBEL MAILLAGE",
        doc: "Number of elements of a mesh.",
        example: "n = nbel s ;",
        f: nbel,
    },
];

fn coor(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let which = a.opt::<i64>();
    if let Some(p) = a.opt::<PointId>() {
        let x = it.nodes.get(p.0);
        let dim = it.opts.dime.max(1);
        return match which {
            None => Ok(x[..dim].iter().map(|c| Value::Float(*c)).collect()),
            Some(k) if (1..=dim as i64).contains(&k) => Ok(vec![Value::Float(x[k as usize - 1])]),
            Some(k) if k == dim as i64 + 1 => Ok(vec![Value::Float(it.nodes.density[p.0])]),
            Some(k) => Err(a.err(format!("coordinate {} does not exist in dimension {}", k, dim))),
        };
    }
    if let Some(m) = a.opt::<Rc<Mesh>>() {
        let k = which.ok_or_else(|| a.missing("the coordinate number"))?;
        let dim = it.opts.dime.max(1) as i64;
        if !(1..=dim + 1).contains(&k) {
            return Err(a.err(format!("coordinate {} does not exist in dimension {}", k, dim)));
        }
        let entries: Vec<(usize, f64)> = m
            .node_list()
            .into_iter()
            .map(|n| (n, if k == dim + 1 { it.nodes.density[n] } else { it.nodes.get(n)[k as usize - 1] }))
            .collect();
        let c = crate::value::Chpoint::from_entries(
            crate::value::Nature::Diffus,
            entries.iter().map(|(n, v)| (*n, "SCAL", *v)),
        );
        return Ok(vec![Value::Chpo(Rc::new(c))]);
    }
    Err(a.missing("POINT or MAILLAGE"))
}

fn mesh_arg(a: &mut Args) -> Result<Mesh> {
    if let Some(p) = a.opt::<PointId>() {
        return Ok(Mesh::points(&[p.0]));
    }
    a.req::<Rc<Mesh>>().map(|m| (*m).clone())
}

fn nbno(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let m = mesh_arg(a)?;
    Ok(vec![Value::Int(m.node_list().len() as i64)])
}

fn nbel(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let m = mesh_arg(a)?;
    Ok(vec![Value::Int(m.n_elements() as i64)])
}
