//! Curved and broken lines: CERC (C) in all its forms, CER3, LIGN,
//! QUELCONQUE. The algorithms are in `fem::meshing::{line, arcs, polyline}`.

use super::mesh::{elem_type_opt, mesh_val, more_spacing, spacing, vector};
use super::{Args, OpDef, PointId};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::{ElemType, Mesh};
use crate::fem::meshing as mg;
use crate::fem::meshing::arcs;
use crate::value::Value;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef { name: "CERC", signature: "CERC (n) ('CENT') P1|LINE1 CENTRE (P2|LINE2) | CERC (n) 'PASS' P1 P2 P3 | CERC (n) 'ROTA' angle P1 AXIS1 (AXIS2) ('DINI' d1) ('DFIN' d2)", doc: "An arc of circle: from P1 to P2 around CENTRE the short way (a line in place of P1 is prolonged, in place of P2 is joined, alone is closed), through three points ('PASS'), or P1 turned by an angle about a point (2D) or an axis ('ROTA').", example: "c = cerc 8 p1 o p2 ;", f: cerc },
    OpDef { name: "C", signature: "C (n) ('CENT') P1|LINE1 CENTRE (P2|LINE2) | C (n) 'PASS' P1 P2 P3 | C (n) 'ROTA' angle P1 AXIS1 (AXIS2)", doc: "Abbreviation of CERC.", example: "c = c 8 p1 o p2 ;", f: cerc },
    OpDef { name: "CER3", signature: "CER3 (n) P1 P2 P3 ('DINI' d1) ('DFIN' d2)", doc: "The arc of circle from P1 through P2 to P3.", example: "c = cer3 8 p1 p2 p3 ;", f: cer3 },
    OpDef { name: "LIGN", signature: "LIGN (n) CENTRE P1 (NORMAL) angle 'ROTA' | LIGN (n) P1 VECTOR 'TRAN' ('DINI' d1) ('DFIN' d2)", doc: "An arc from P1 turned by angle degrees about CENTRE (in 3D about NORMAL), or the straight line from P1 to P1 + VECTOR.", example: "c = lign 36 o p1 360. 'ROTA' ;", f: lign },
    OpDef { name: "QUEL", signature: "QUEL 'SEG2'|'SEG3' P1 P2 ... | LISTX (LISTY (LISTZ)) | POI1_MESH", doc: "A broken line through the points in order (SEG3: three by three, the middle one in the middle).", example: "l = quel seg2 p1 p2 p3 ;", f: quel },
];

/// A POINT or a line, whichever comes first.
enum Geo {
    Point(usize),
    Line(Rc<Mesh>),
}

fn opt_geo(a: &mut Args) -> Option<Geo> {
    a.opt_with(|v| match v {
        Value::Point(p) => Some(Geo::Point(*p)),
        Value::Mesh(m) => Some(Geo::Line(m.clone())),
        _ => None,
    })
}

fn cerc(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mut sp = spacing(a)?;
    let ty = elem_type_opt(it);
    match a.keyword(&["CENT", "PASS", "ROTA"]) {
        Some("PASS") => {
            let p = [a.req::<PointId>()?.0, a.req::<PointId>()?.0, a.req::<PointId>()?.0];
            more_spacing(a, &mut sp)?;
            return Ok(mesh_val(arcs::cer3("CERC", &mut it.nodes, p, &sp, ty)?));
        }
        Some("ROTA") => {
            let angle = a.req_num()?;
            let p1 = a.req::<PointId>()?.0;
            let c = vector(it, a).ok_or_else(|| a.missing("POINT (the axis)"))?;
            let dir = if it.opts.dime >= 3 {
                let c2 = vector(it, a).ok_or_else(|| a.missing("POINT (the second point of the axis)"))?;
                Some([c2[0] - c[0], c2[1] - c[1], c2[2] - c[2]])
            } else {
                None
            };
            more_spacing(a, &mut sp)?;
            let k = arcs::axis("CERC", dir)?;
            let m = arcs::arc("CERC", &mut it.nodes, p1, c, k, angle.to_radians(), None, &sp, ty)?;
            return Ok(mesh_val(m));
        }
        _ => {}
    }
    let first = opt_geo(a).ok_or_else(|| a.missing("POINT or MAILLAGE"))?;
    more_spacing(a, &mut sp)?;
    let c = a.req::<PointId>()?.0;
    more_spacing(a, &mut sp)?;
    let last = opt_geo(a);
    more_spacing(a, &mut sp)?;
    let arc = |it: &mut Interp, p1: usize, p2: usize| mg::cerc(&mut it.nodes, p1, c, p2, &sp, ty);
    let m = match (first, last) {
        (Geo::Point(p1), Some(Geo::Point(p2))) => arc(it, p1, p2)?,
        (Geo::Line(l), Some(Geo::Point(p2))) => l.union(&arc(it, mg::poin_final(&l)?, p2)?),
        (Geo::Point(p1), Some(Geo::Line(l))) => arc(it, p1, mg::poin_init(&l)?)?.union(&l),
        (Geo::Line(l1), Some(Geo::Line(l2))) => {
            l1.union(&arc(it, mg::poin_final(&l1)?, mg::poin_init(&l2)?)?).union(&l2)
        }
        (Geo::Line(l), None) => l.union(&arc(it, mg::poin_final(&l)?, mg::poin_init(&l)?)?),
        (Geo::Point(_), None) => return Err(a.missing("POINT or MAILLAGE (the end of the arc)")),
    };
    Ok(mesh_val(m))
}

fn cer3(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mut sp = spacing(a)?;
    let ty = elem_type_opt(it);
    let first = opt_geo(a).ok_or_else(|| a.missing("POINT or MAILLAGE"))?;
    more_spacing(a, &mut sp)?;
    let p2 = a.req::<PointId>()?.0;
    more_spacing(a, &mut sp)?;
    let last = opt_geo(a);
    more_spacing(a, &mut sp)?;
    // A line in place of P1 is prolonged from its end; without P3 the arc
    // closes on the line's first point.
    let (line, p1) = match first {
        Geo::Point(p) => (None, p),
        Geo::Line(l) => {
            let end = mg::poin_final(&l)?;
            (Some(l), end)
        }
    };
    let (p3, after) = match (last, &line) {
        (Some(Geo::Point(p)), _) => (p, None),
        (Some(Geo::Line(l)), _) => (mg::poin_init(&l)?, Some(l)),
        (None, Some(l)) => (mg::poin_init(l)?, None),
        (None, None) => return Err(a.missing("POINT (the third point)")),
    };
    let mut m = arcs::cer3("CER3", &mut it.nodes, [p1, p2, p3], &sp, ty)?;
    if let Some(l) = line {
        m = l.union(&m);
    }
    if let Some(l) = after {
        m = m.union(&l);
    }
    Ok(mesh_val(m))
}

fn lign(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mut sp = spacing(a)?;
    let ty = elem_type_opt(it);
    let kind = a.req_keyword(&["ROTA", "TRAN"])?;
    more_spacing(a, &mut sp)?;
    let m = if kind == "ROTA" {
        let c = vector(it, a).ok_or_else(|| a.missing("POINT (the centre)"))?;
        let p1 = a.req::<PointId>()?.0;
        let normal =
            if it.opts.dime >= 3 { Some(vector(it, a).ok_or_else(|| a.missing("POINT (the normal)"))?) } else { None };
        let angle = a.req_num()?;
        more_spacing(a, &mut sp)?;
        let k = arcs::axis("LIGN", normal)?;
        arcs::arc("LIGN", &mut it.nodes, p1, c, k, angle.to_radians(), None, &sp, ty)?
    } else {
        let p1 = a.req::<PointId>()?.0;
        let v = vector(it, a).ok_or_else(|| a.missing("POINT (the vector)"))?;
        more_spacing(a, &mut sp)?;
        let x = it.nodes.get(p1);
        let d = it.opts.dens;
        let p2 = it.nodes.push([x[0] + v[0], x[1] + v[1], x[2] + v[2]], d);
        mg::droi(&mut it.nodes, p1, p2, &sp, ty)?
    };
    Ok(mesh_val(m))
}

fn quel(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let ty = match a.req_keyword(&["SEG2", "SEG3"])? {
        "SEG3" => ElemType::Seg3,
        _ => ElemType::Seg2,
    };
    let mut pts: Vec<usize> = Vec::new();
    if let Some(lx) = a.opt::<Rc<Vec<f64>>>() {
        let ly = a.opt::<Rc<Vec<f64>>>();
        let lz = a.opt::<Rc<Vec<f64>>>();
        for (k, l) in [Some(&lx), ly.as_ref(), lz.as_ref()].into_iter().flatten().enumerate() {
            if l.len() != lx.len() {
                return Err(a.err(format!(
                    "list {} has {} values but the abscissae have {}",
                    k + 1,
                    l.len(),
                    lx.len()
                )));
            }
        }
        let d = it.opts.dens;
        for i in 0..lx.len() {
            let y = ly.as_ref().map_or(0.0, |l| l[i]);
            let z = lz.as_ref().map_or(0.0, |l| l[i]);
            if ![lx[i], y, z].iter().all(|c| c.is_finite()) {
                return Err(a.err(format!("point {} has a coordinate that is not finite", i + 1)));
            }
            pts.push(it.nodes.push([lx[i], y, z], d));
        }
    } else if let Some(m) = a.opt::<Rc<Mesh>>() {
        if let Some(p) = m.parts.iter().find(|p| p.ty != ElemType::Poi1 && !p.is_empty()) {
            return Err(a.err(format!("the mesh must be made of points (POI1), not {}", p.ty.name())));
        }
        pts = m.parts.iter().flat_map(|p| p.conn.iter().copied()).collect();
    } else {
        while let Some(p) = a.opt::<PointId>() {
            pts.push(p.0);
        }
    }
    Ok(mesh_val(mg::polyline::quel(&it.nodes, &pts, ty)?))
}
