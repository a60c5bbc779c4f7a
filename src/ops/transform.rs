//! Geometric maps of points and meshes: HOMO, AFFI, PROJ, and BARY. The
//! algorithms live in `fem::meshing::transform`; this file reads Gibiane
//! arguments and wraps results.

use super::mesh::{mesh_val, req_geo, vector};
use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::fem::meshing::{self as mg, PointMap, Target};
use crate::value::Value;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "HOMO",
        signature: "POINT|MAILLAGE HOMO ratio CENTRE",
        doc: "A copy on new nodes scaled by ratio about CENTRE (homothety).",
        example: "s2 = s1 homo 2. p0 ;",
        f: homo,
    },
    OpDef {
        name: "AFFI",
        signature: "POINT|MAILLAGE AFFI ratio P1 P2 (P3)",
        doc: "A copy on new nodes stretched by ratio across the line P1 P2 (2D) or the plane P1 P2 P3 (3D): distances to it are multiplied by ratio (affinity).",
        example: "s2 = s1 affi 0.5 p1 p2 ;",
        f: affi,
    },
    OpDef {
        name: "PROJ",
        signature: "POINT|MAILLAGE PROJ 'CYLI' VECTOR|'CONI' APEX  'PLAN' P1 P2 P3 | 'DROI' P1 P2",
        doc: "A copy on new nodes projected on a plane (3D) or a line (2D), along a direction (CYLI) or from an apex (CONI).",
        example: "s2 = s1 proj 'CYLI' (0. 0. 1.) 'PLAN' p1 p2 p3 ;",
        f: proj,
    },
    OpDef {
        name: "ORIE",
        signature: "ORIE MAILLAGE (('DIRECTION') VECTOR | 'POINT' POINT)",
        doc: "The mesh with one orientation: lines head to tail, plane surfaces counter-clockwise, surfaces in space consistent across edges, volumes positive (each connected piece follows its first element). In 3D, surface elements can be turned so that their normal has a positive component along a vector, or points to the side of a point.",
        example: "l2 = orie l ;",
        f: orie,
    },
    OpDef {
        name: "BARY",
        signature: "BARY MAILLAGE|POINT",
        doc: "The barycentre of the nodes of a mesh (every node weighs the same), as a new point.",
        example: "g = bary s ;",
        f: bary,
    },
];

/// The object mapped: the operand before the operator (`s2 = s1 homo 2.
/// p`), else the first value after it.
fn object(a: &mut Args) -> Result<Value> {
    match a.left_value() {
        Some(v) => Ok(v),
        None => a.right_any().ok_or_else(|| a.missing("POINT or MAILLAGE")),
    }
}

fn point(it: &Interp, a: &mut Args, what: &str) -> Result<[f64; 3]> {
    vector(it, a).ok_or_else(|| a.missing(&format!("POINT ({})", what)))
}

fn apply(it: &mut Interp, a: &Args, obj: Value, map: PointMap) -> Result<Vec<Value>> {
    let dim = it.opts.dime.max(2);
    match obj {
        Value::Point(p) => Ok(vec![Value::Point(mg::map_point(&mut it.nodes, p, map)?)]),
        Value::Mesh(m) => Ok(mesh_val(mg::map_copy(&mut it.nodes, &m, map, dim)?)),
        other => Err(a.err(format!("expected a POINT or a MAILLAGE to map, found a {}", other.type_name()))),
    }
}

fn homo(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let obj = object(a)?;
    let ratio = a.req_num()?;
    let centre = point(it, a, "the centre")?;
    apply(it, a, obj, PointMap::Homothety { ratio, centre })
}

fn affi(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let obj = object(a)?;
    let ratio = a.req_num()?;
    let p1 = point(it, a, "the first point of the base")?;
    let p2 = point(it, a, "the second point of the base")?;
    let map = if it.opts.dime >= 3 {
        let p3 = point(it, a, "the third point of the base plane")?;
        PointMap::affinity_3d(ratio, p1, p2, p3)?
    } else {
        PointMap::affinity_2d(ratio, p1, p2)?
    };
    apply(it, a, obj, map)
}

fn proj(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let obj = object(a)?;
    let how = a.req_keyword(&["CYLI", "CONI"])?;
    let v = point(it, a, if how == "CYLI" { "the direction" } else { "the apex" })?;
    let target = match a.req_keyword(&["PLAN", "DROI", "SPHE", "CYLI", "CONI", "TORI"])? {
        "PLAN" => {
            if it.opts.dime < 3 {
                return Err(a.err("'PLAN' needs OPTI DIME 3; in 2D project on a line with 'DROI' P1 P2"));
            }
            let p1 = point(it, a, "the first point of the plane")?;
            let p2 = point(it, a, "the second point of the plane")?;
            Target::plane("PROJ", p1, p2, point(it, a, "the third point of the plane")?)?
        }
        "DROI" => {
            if it.opts.dime >= 3 {
                return Err(a.err("'DROI' is the 2D target; in 3D project on a plane with 'PLAN' P1 P2 P3"));
            }
            let p1 = point(it, a, "the first point of the line")?;
            Target::line2d("PROJ", p1, point(it, a, "the second point of the line")?)?
        }
        other => {
            return Err(a.err(format!("projection on a {} is not implemented in gibi (only 'PLAN' and 'DROI')", other)))
        }
    };
    let map =
        if how == "CYLI" { PointMap::Cylindrical { dir: v, target } } else { PointMap::Conical { apex: v, target } };
    apply(it, a, obj, map)
}

fn bary(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let m = req_geo(a)?;
    let g = mg::barycentre(&it.nodes, &m)?;
    let d = it.opts.dens;
    Ok(vec![Value::Point(it.nodes.push(g, d))])
}

fn orie(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let m = a.req::<Rc<Mesh>>()?;
    let towards_point = match a.keyword(&["POIN", "DIRE", "VECT"]) {
        Some("POIN") => Some(true),
        Some(_) => Some(false),
        None => None,
    };
    let target = match towards_point {
        Some(_) => Some(a.req::<super::PointId>()?),
        None => a.opt::<super::PointId>(),
    };
    let Some(p) = target else {
        return Ok(mesh_val(mg::orie(&it.nodes, &m, it.opts.dime.max(1))?));
    };
    let q = it.nodes.get(p.0);
    Ok(mesh_val(orient_surface(it, a, &m, q, towards_point == Some(true))?))
}

/// Surface elements in 3D turned so that their normal has a positive
/// component along `q` (a vector), or, with `point`, points to the side of
/// the point `q` (orie.notice). Reversing keeps the first node and runs
/// the others backwards (corners and mid-side nodes alike).
fn orient_surface(it: &Interp, a: &Args, m: &Mesh, q: [f64; 3], point: bool) -> Result<Mesh> {
    use crate::fem::mesh::ElemType;
    use crate::fem::vec3::{cross, dot, sub};
    let mut out = m.clone();
    for part in &mut out.parts {
        let corners: &[usize] = match part.ty {
            ElemType::Tri3 => &[0, 1, 2],
            ElemType::Tri6 => &[0, 2, 4],
            ElemType::Qua4 => &[0, 1, 2, 3],
            ElemType::Qua8 => &[0, 2, 4, 6],
            t => return Err(a.err(format!("a direction orients surface elements, not {}", t.name()))),
        };
        let npe = part.ty.nodes();
        for e in part.conn.chunks_mut(npe) {
            let x: Vec<[f64; 3]> = corners.iter().map(|&k| it.nodes.get(e[k])).collect();
            let n = match x.len() {
                3 => cross(sub(x[1], x[0]), sub(x[2], x[0])),
                _ => cross(sub(x[2], x[0]), sub(x[3], x[1])),
            };
            let dir = if point {
                let c = x.iter().fold([0.0; 3], |s, p| [s[0] + p[0], s[1] + p[1], s[2] + p[2]]);
                let k = x.len() as f64;
                sub(q, [c[0] / k, c[1] / k, c[2] / k])
            } else {
                q
            };
            if dot(n, dir) < 0.0 {
                e[1..].reverse();
            }
        }
    }
    Ok(out)
}
