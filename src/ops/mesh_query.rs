//! Questions asked of points and meshes: NOEUD, COOR, NBNO, NBEL, POIN.

use super::mesh::{mesh_val, req_geo, vector};
use super::{Args, OpDef, PointId};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::fem::meshing as mg;
use crate::value::{Chpoint, Nature, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef { name: "NOEU", signature: "NOEUD n | NOEUD POINT", doc: "The point (node) number n, as numbered by gibi (LIST shows node numbers); given a point, its number.", example: "p = noeud 5 ; n = noeud p ;", f: noeu },
    OpDef { name: "COOR", signature: "COOR POINT | COOR n POINT | COOR (n) MAILLAGE | COOR (n) MCHAML", doc: "Coordinates of a point (one result per dimension), one of them, or coordinate fields (SCAL) on a mesh: one per dimension, or the n-th; of an element field, its points' coordinates as element fields.", example: "x y = coor p ;", f: coor },
    OpDef { name: "NBNO", signature: "NBNO MAILLAGE", doc: "Number of nodes of a mesh.", example: "n = nbno l ;", f: nbno },
    OpDef { name: "NBEL", signature: "NBEL MAILLAGE", doc: "Number of elements of a mesh.", example: "n = nbel s ;", f: nbel },
    OpDef { name: "POIN", signature: "POIN x (y) (z) | POIN LISTREEL (LISTREEL) (LISTREEL) | MAILLAGE POIN n | MAILLAGE POIN ('INIT'|'FINAL') | MAILLAGE POIN 'PROC' POINT | MAILLAGE POIN ('DROIT' P1 P2 | 'PLAN' P1 P2 P3) (crit) | CHPOINT|MCHAML POIN ('ABS') ('AVEC'|'SANS' LISTMOTS) 'MAXI'|'MINI'|'SUPE'|'INFE'|'EGSU'|'EGIN'|'EGAL'|'DIFF' v|'COMP' v1 v2", doc: "A point, or nodes of a mesh, or the points where a field's values meet a test (a POI1 mesh; for an MCHAML at centres or Gauss points, new points there, in element order).", example: "p = l poin 'FINAL' ;", f: poin },
];

fn noeu(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if let Some(p) = a.opt::<PointId>() {
        return Ok(vec![Value::Int(it.nodes.numbering.number(p.0) as i64 + 1)]);
    }
    let n = a.req::<i64>()?;
    if n < 1 || n as usize > it.nodes.len() {
        return Err(a.err(format!("there is no node {} (nodes are numbered 1 to {})", n, it.nodes.len())));
    }
    Ok(vec![Value::Point(it.nodes.numbering.node(n as usize - 1))])
}

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
        let dim = it.opts.dime.max(1) as i64;
        let field = |k: i64| {
            let c = Chpoint::from_entries(
                Nature::Diffus,
                m.node_list().into_iter().map(|n| {
                    (n, "SCAL", if k == dim + 1 { it.nodes.density[n] } else { it.nodes.get(n)[k as usize - 1] })
                }),
            );
            Value::Chpo(Rc::new(c))
        };
        return match which {
            // Like the POINT form: one field per coordinate (`x y = COOR s`).
            None => Ok((1..=dim).map(field).collect()),
            Some(k) if (1..=dim + 1).contains(&k) => Ok(vec![field(k)]),
            Some(k) => Err(a.err(format!("coordinate {} does not exist in dimension {}", k, dim))),
        };
    }
    if let Some(m) = a.opt::<Rc<crate::value::Mchaml>>() {
        return super::coor_field::coor_of_mchaml(it, a, which, &m);
    }
    Err(a.missing("POINT, MAILLAGE or MCHAML"))
}

fn nbno(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let m = req_geo(a)?;
    Ok(vec![Value::Int(mg::nbno(&m) as i64)])
}

fn nbel(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let m = req_geo(a)?;
    Ok(vec![Value::Int(mg::nbel(&m) as i64)])
}

fn poin(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if let Some(ch) = a.opt::<Rc<crate::value::Chpoint>>() {
        return super::poin_field::poin_of_chpo(a, &ch);
    }
    if let Some(m) = a.opt::<Rc<crate::value::Mchaml>>() {
        return super::poin_field::poin_of_mchaml(it, a, &m);
    }
    if let Some(m) = a.opt::<Rc<Mesh>>() {
        if let Some(k) = a.keyword(&["SPHE", "CYLI", "CONE", "TORE", "JONC"]) {
            return super::mesh_select::poin_on(it, a, &m, k);
        }
        if let Some(k) = a.keyword(&["INIT", "FINAL", "PROC", "DROIT", "PLAN"]) {
            return Ok(vec![match k {
                "INIT" => Value::Point(mg::poin_init(&m)?),
                "FINAL" => Value::Point(mg::poin_final(&m)?),
                "PROC" => {
                    let x = vector(it, a).ok_or_else(|| a.missing("POINT"))?;
                    Value::Point(mg::poin_proc(&it.nodes, &m, x)?)
                }
                "DROIT" => {
                    let p1 = vector(it, a).ok_or_else(|| a.missing("POINT"))?;
                    let p2 = vector(it, a).ok_or_else(|| a.missing("POINT"))?;
                    let tol = a.opt_num().unwrap_or(super::mesh_select::default_crit(it));
                    Value::Mesh(Rc::new(mg::poin_droit(&it.nodes, &m, p1, p2, tol)?))
                }
                _ => {
                    let p1 = vector(it, a).ok_or_else(|| a.missing("POINT"))?;
                    let p2 = vector(it, a).ok_or_else(|| a.missing("POINT"))?;
                    let p3 = vector(it, a).ok_or_else(|| a.missing("POINT"))?;
                    let tol = a.opt_num().unwrap_or(super::mesh_select::default_crit(it));
                    Value::Mesh(Rc::new(mg::poin_plan(&it.nodes, &m, p1, p2, p3, tol)?))
                }
            }]);
        }
        let n = a.req::<i64>()?;
        return Ok(vec![Value::Point(mg::poin_nth(&m, n)?)]);
    }
    // POIN LX (LY) (LZ): a POI1 mesh of new points, one per abscissa.
    if let Some(lx) = a.opt::<Rc<Vec<f64>>>() {
        let mut lists = vec![lx];
        while lists.len() < it.opts.dime.max(1) {
            match a.opt::<Rc<Vec<f64>>>() {
                Some(l) => lists.push(l),
                None => break,
            }
        }
        let n = lists[0].len();
        if lists.iter().any(|l| l.len() != n) {
            return Err(a.err("the coordinate lists do not have the same length"));
        }
        let d = it.opts.dens;
        let pts: Vec<usize> = (0..n)
            .map(|i| {
                let mut x = [0.0; 3];
                for (k, l) in lists.iter().enumerate() {
                    x[k] = l[i];
                }
                it.nodes.push(x, d)
            })
            .collect();
        return Ok(mesh_val(Mesh::points(&pts)));
    }
    // POIN x (y) (z): a point from numbers (the only way in DIME 1).
    let mut x = [0.0; 3];
    let dim = it.opts.dime.max(1);
    for (k, c) in x.iter_mut().enumerate().take(dim) {
        *c = if k == 0 { a.req_num()? } else { a.opt_num().unwrap_or(0.0) };
    }
    let d = it.opts.dens;
    Ok(vec![Value::Point(it.nodes.push(x, d))])
}
