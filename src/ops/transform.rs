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
        signature: "POINT|MAILLAGE PROJ 'CYLI' VECTOR|'CONI' APEX  'PLAN' P1 P2 P3 | 'DROI' P1 P2 | 'SPHE' CENTRE P | 'CERC' CENTRE P | 'CYLI' C1 C2 P",
        doc: "A copy on new nodes projected on a plane (3D) or a line (2D), a sphere (3D) or a circle (2D) of that centre through P, or the cylinder of axis C1 C2 through P, along a direction (CYLI) or from an apex (CONI). On a sphere, circle or cylinder the image is the nearer of the two points where the line of projection meets it.",
        example: "s2 = s1 proj 'CYLI' (0. 0. 1.) 'PLAN' p1 p2 p3 ;",
        f: proj,
    },
    OpDef {
        name: "ORIE",
        signature: "ORIE MAILLAGE (('DIRECTION') VECTOR | 'POINT' POINT)",
        doc: "The mesh with one orientation: lines head to tail, plane surfaces counter-clockwise, surfaces in space consistent across edges, volumes positive (each connected piece follows its first element). With a vector (or 'POINT' a point), each surface element (TRI3, TRI6, QUA4, QUA8) is turned so that its normal has a positive component along the vector (or points to the side of the point); other elements are kept.",
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
        match vector(it, a) {
            Some(p3) => PointMap::affinity_3d(ratio, p1, p2, p3)?,
            None => PointMap::affinity_along(ratio, p1, p2)?,
        }
    } else {
        PointMap::affinity_2d(ratio, p1, p2)?
    };
    apply(it, a, obj, map)
}

fn proj(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let obj = object(a)?;
    let map = read_proj(it, a)?;
    apply(it, a, obj, map)
}

/// PROJ's arguments after the object (DEPL 'PROJ' reads the same).
pub(crate) fn read_proj(it: &Interp, a: &mut Args) -> Result<PointMap> {
    // proj.notice: 'CYLI' (along a vector) is the default.
    let how = a.keyword(&["CYLI", "CONI"]).unwrap_or("CYLI");
    let v = point(it, a, if how == "CYLI" { "the direction" } else { "the apex" })?;
    let target = match a.req_keyword(&["PLAN", "DROI", "SPHE", "CERC", "CYLI", "CONI", "TORI"])? {
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
        "SPHE" | "CERC" => {
            let c = point(it, a, "the centre")?;
            Target::sphere("PROJ", c, point(it, a, "a point of the sphere")?)?
        }
        "CYLI" => {
            let c1 = point(it, a, "the first point of the axis")?;
            let c2 = point(it, a, "the second point of the axis")?;
            Target::cylinder("PROJ", c1, c2, point(it, a, "a point of the cylinder")?)?
        }
        other => {
            return Err(a.err(format!(
                "projection on a {} is not implemented in gibi ('PLAN', 'DROI', 'SPHE', 'CERC', 'CYLI')",
                other
            )))
        }
    };
    Ok(if how == "CYLI" { PointMap::Cylindrical { dir: v, target } } else { PointMap::Conical { apex: v, target } })
}

fn bary(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let m = req_geo(a)?;
    let g = mg::barycentre(&it.nodes, &m)?;
    let d = it.opts.dens;
    Ok(vec![Value::Point(it.nodes.push(g, d))])
}

fn orie(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let m = a.req::<Rc<Mesh>>()?;
    if let Some(to) = super::mesh_select::towards(it, a)? {
        return Ok(mesh_val(mg::orient_to::orie_towards(&it.nodes, &m, to)?));
    }
    Ok(mesh_val(mg::orie(&it.nodes, &m, it.opts.dime.max(1))?))
}
