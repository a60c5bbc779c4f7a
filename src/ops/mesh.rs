//! Making meshes: straight lines, structured surfaces, sweeps and volumes,
//! and the helpers every geometric operator reads its arguments with. The
//! algorithms live in `fem::meshing`; this file reads Gibiane arguments and
//! wraps results. Queries (COOR, POIN …) are in `mesh_query`, operations on
//! existing meshes (ELEM, CONT, SYME …) in `mesh_edit`; arcs and broken
//! lines in `mesh_lines`, free and ruled surfaces in `mesh_free` and
//! `mesh_ruled`, selections in `mesh_select`, moves in `mesh_move`, repair
//! in `mesh_repair`.

use super::{Args, OpDef, PointId};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::{ElemType, Mesh};
use crate::fem::meshing as mg;
use crate::value::{Chpoint, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef { name: "DROI", signature: "DROI (n) P1|LINE P2 ('DINI' d1) ('DFIN' d2) ('COULEUR' colour)", doc: "A straight line of n elements (SEG2 or SEG3 per OPTI ELEM).", example: "l = droi 10 p1 p2 ;", f: droi },
    // D and C are Cast3M's own abbreviations of DROI and CERC (`p1 d 10 p2`).
    OpDef { name: "D", signature: "D (n) P1|LINE P2 ('DINI' d1) ('DFIN' d2)", doc: "Abbreviation of DROI.", example: "l = p1 d 10 p2 ;", f: droi },
    OpDef { name: "DALL", signature: "DALL LINE1 LINE2 LINE3 LINE4 ('PLAN' | 'SPHE' CENTRE | 'CYLI' P1 P2 | 'CONI' APEX P2)", doc: "A structured surface (OPTI ELEM QUA4, TRI3, QUA8, TRI6) from four sides forming a closed contour.", example: "s = dall bas dro hau gau ;", f: dall },
    OpDef { name: "TRAN", signature: "GEO TRAN (n) ('DINI' d1) ('DFIN' d2) VECTOR", doc: "Sweep a line into a surface or a surface into a volume along a vector.", example: "s = l tran 4 (0. 1.) ;", f: tran },
    OpDef { name: "ROTA", signature: "GEO ROTA (n) ANGLE CENTRE (AXIS_POINT)", doc: "Sweep by rotation (angle in degrees) about a point (2D) or an axis (3D).", example: "s = l rota 8 90. o ;", f: rota },
    OpDef { name: "VOLU", signature: "VOLU SURF_CLOSED ('VERB') | VOLU (n) SURF1 SURF2 | VOLU (n) SURF 'TRAN' VECTOR | VOLU (n) SURF 'ROTA' ANGLE P1 (P2)", doc: "Tetrahedra filling a closed surface (TRI3, or QUA4 cut in two; no node added), the volume between two compatible surfaces, or swept from a surface by a translation or a rotation (as TRAN and ROTA).", example: "v = volu 3 s1 s2 ;", f: volu },
];

/// A POINT (as a POI1 mesh) or a MAILLAGE, whichever comes first
/// (`TRAN L (0. 1.) 3` reads L, not the vector).
pub(crate) fn opt_geo(a: &mut Args) -> Option<Mesh> {
    a.opt_with(|v| match v {
        Value::Point(p) => Some(Mesh::points(&[*p])),
        Value::Mesh(m) => Some((**m).clone()),
        _ => None,
    })
}

pub(crate) fn req_geo(a: &mut Args) -> Result<Mesh> {
    opt_geo(a).ok_or_else(|| a.missing("POINT or MAILLAGE"))
}

pub(crate) fn mesh_val(m: Mesh) -> Vec<Value> {
    vec![Value::Mesh(Rc::new(m))]
}

/// A POINT argument read as a vector.
pub(crate) fn vector(it: &Interp, a: &mut Args) -> Option<[f64; 3]> {
    a.opt::<PointId>().map(|p| it.nodes.get(p.0))
}

/// `(n) … ('DINI' d1) ('DFIN' d2)` read in any order around the geometry.
/// The count is among the operands written before, or the token just
/// after: looking further right would take the count of the next operator
/// of a chain written with quoted names (`p0 'DROI' n p1 'DROI' n p2`).
pub(crate) fn spacing(a: &mut Args) -> Result<mg::Spacing> {
    read_spacing(a, true)
}

/// More of the spacing after other arguments: a count only if none was
/// read yet (`VOLU s 3 'ROTA' 90 p1 p2`: 90 is the angle).
pub(crate) fn more_spacing(a: &mut Args, s: &mut mg::Spacing) -> Result<()> {
    let more = read_spacing(a, s.n.is_none())?;
    merge(s, more);
    Ok(())
}

fn read_spacing(a: &mut Args, count: bool) -> Result<mg::Spacing> {
    let mut s = mg::Spacing { n: None, dini: None, dfin: None };
    loop {
        if let Some(k) = a.keyword(&["DINI", "DFIN"]) {
            let d = a.req_num()?;
            if k == "DINI" {
                s.dini = Some(d)
            } else {
                s.dfin = Some(d)
            }
        } else if count && s.n.is_none() {
            let n = if a.left_len() > 0 { a.opt::<i64>() } else { a.opt_right::<i64>() };
            match n {
                Some(n) => s.n = Some(n),
                None => break,
            }
        } else {
            break;
        }
    }
    Ok(s)
}

/// The angle of a turn, which may be written as an ENTIER (`ROTA 90 p`):
/// when no other number follows, an ENTIER read as the count was the
/// angle.
fn angle_after_count(a: &mut Args, sp: &mut mg::Spacing) -> Result<f64> {
    match a.opt_num() {
        Some(x) => Ok(x),
        None => match sp.n.take() {
            Some(n) => Ok(n as f64),
            None => Err(a.missing("FLOTTANT (the angle)")),
        },
    }
}

pub(crate) fn elem_type_opt(it: &Interp) -> ElemType {
    ElemType::from_name(&it.opts.elem).unwrap_or(ElemType::Seg2)
}

fn droi(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mut sp = spacing(a)?;
    // ('COULEUR' colour), read where it stands: once DINI and DFIN have
    // brought it to the front, the points come after it.
    let mut colour = match a.keyword(&["COULEUR"]) {
        Some(_) => Some(super::colour::colour_word(a)?),
        None => None,
    };
    let ty = elem_type_opt(it);
    if let Some(line) = a.opt::<Rc<Mesh>>() {
        let p2 = a.req::<PointId>()?;
        more_spacing(a, &mut sp)?;
        return Ok(mesh_val(mg::droi_extend(&mut it.nodes, &line, p2.0, &sp, ty)?));
    }
    let p1 = a.req::<PointId>()?;
    let p2 = a.req::<PointId>()?;
    more_spacing(a, &mut sp)?;
    let m = mg::droi(&mut it.nodes, p1.0, p2.0, &sp, ty)?;
    if colour.is_none() && a.keyword(&["COULEUR"]).is_some() {
        colour = Some(super::colour::colour_word(a)?);
    }
    Ok(mesh_val(match colour {
        Some(c) => m.coloured(c),
        None => m,
    }))
}

fn merge(s: &mut mg::Spacing, more: mg::Spacing) {
    s.n = s.n.or(more.n);
    s.dini = s.dini.or(more.dini);
    s.dfin = s.dfin.or(more.dfin);
}

fn dall(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mut sides = Vec::new();
    for _ in 0..4 {
        sides.push(a.req::<Rc<Mesh>>()?);
    }
    use mg::dall_support::Support;
    let point = |a: &mut Args| a.req::<PointId>().map(|p| it.nodes.get(p.0));
    let support = match a.keyword(&["PLAN", "SPHE", "CYLI", "CONI"]) {
        Some("SPHE") => Some(Support::Sphere(point(a)?)),
        Some("CYLI") => Some(Support::Cylinder(point(a)?, point(a)?)),
        Some("CONI") => Some(Support::Cone(point(a)?, point(a)?)),
        _ => None,
    };
    let ty = match ElemType::from_name(&it.opts.elem) {
        Some(t @ (ElemType::Qua4 | ElemType::Tri3 | ElemType::Qua8 | ElemType::Tri6)) => t,
        Some(ElemType::Cu20) => ElemType::Qua8,
        Some(ElemType::Pr15) => ElemType::Tri6,
        _ => ElemType::Qua4,
    };
    let first = it.nodes.len();
    let m = mg::dall(&mut it.nodes, [&sides[0], &sides[1], &sides[2], &sides[3]], ty)?;
    if let Some(support) = support {
        let contour: Vec<usize> = sides.iter().flat_map(|s| s.node_list()).collect();
        mg::dall_support::project(&mut it.nodes, first, &contour, support)?;
    }
    Ok(mesh_val(m))
}

fn tran(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let geo = req_geo(a)?;
    let mut sp = spacing(a)?;
    let v = vector(it, a).ok_or_else(|| a.missing("a vector (POINT)"))?;
    more_spacing(a, &mut sp)?;
    let m = mg::tran(&mut it.nodes, &geo, &sp, v)?;
    Ok(mesh_val(swept_surface(it, m)))
}

/// A line swept under `OPTI ELEM TRI3` (TRI6) gives triangles, as DALL
/// does (each quadrangle cut along its first diagonal); volumes are left
/// as swept.
pub(crate) fn swept_surface(it: &mut Interp, m: Mesh) -> Mesh {
    let ty = ElemType::from_name(&it.opts.elem);
    if ty == Some(ElemType::Tri3) && m.parts.iter().any(|p| p.ty == ElemType::Qua4) {
        mg::change_to_triangles(&m)
    } else if ty == Some(ElemType::Tri6) && m.parts.iter().any(|p| p.ty == ElemType::Qua8) {
        mg::tri6_split::qua8_to_tri6(&mut it.nodes, &m)
    } else {
        m
    }
}

fn rota(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let geo = req_geo(a)?;
    let mut sp = spacing(a)?;
    let angle = angle_after_count(a, &mut sp)?;
    let c = vector(it, a).ok_or_else(|| a.missing("the centre (POINT)"))?;
    let axis = vector(it, a);
    more_spacing(a, &mut sp)?;
    let m = mg::rota(&mut it.nodes, &geo, &sp, angle, c, axis)?;
    Ok(mesh_val(swept_surface(it, m)))
}

/// `VOLU (n) S1 S2`, or the sweeps of volu.notice written with VOLU:
/// `VOLU (n) S 'TRAN' VEC` and `VOLU (n) S 'ROTA' angle P1 (P2)`, the
/// count and the surface on either side of the keyword.
fn volu(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mut sp = spacing(a)?;
    let mut s1 = a.opt::<Rc<Mesh>>();
    more_spacing(a, &mut sp)?;
    match a.keyword(&["TRAN", "ROTA"]) {
        Some("TRAN") => {
            more_spacing(a, &mut sp)?;
            let v = vector(it, a).ok_or_else(|| a.missing("a vector (POINT)"))?;
            more_spacing(a, &mut sp)?;
            let s = match s1.take() {
                Some(s) => s,
                None => a.req::<Rc<Mesh>>()?,
            };
            let m = mg::tran(&mut it.nodes, &from_face(&s, 2)?, &sp, v)?;
            Ok(mesh_val(grown(&s, m, None)))
        }
        Some(_) => {
            more_spacing(a, &mut sp)?;
            let angle = angle_after_count(a, &mut sp)?;
            let c = vector(it, a).ok_or_else(|| a.missing("the centre (POINT)"))?;
            let axis = vector(it, a);
            more_spacing(a, &mut sp)?;
            let s = match s1.take() {
                Some(s) => s,
                None => a.req::<Rc<Mesh>>()?,
            };
            let m = mg::rota(&mut it.nodes, &from_face(&s, 2)?, &sp, angle, c, axis)?;
            Ok(mesh_val(grown(&s, m, None)))
        }
        None => {
            let s1 = match s1 {
                Some(s) => s,
                None => a.req::<Rc<Mesh>>()?,
            };
            let Some(s2) = a.opt::<Rc<Mesh>>() else { return super::mesh_fill::volu_closed(it, a, &s1) };
            more_spacing(a, &mut sp)?;
            let m = mg::volu(&mut it.nodes, &from_face(&s1, 2)?, &from_face(&s2, 1)?, &sp)?;
            Ok(mesh_val(grown(&s1, m, Some(&s2))))
        }
    }
}

fn is_volume(m: &Mesh) -> bool {
    m.n_elements() > 0 && m.parts.iter().filter(|p| !p.is_empty()).all(|p| p.ty.dim() == 3)
}

/// What VOLU sweeps from: a surface as given, or face `n` of a volume
/// (volu.notice: a volume grows from its face 2, towards the face 1 of a
/// second volume).
fn from_face(m: &Mesh, n: i64) -> std::result::Result<Mesh, mg::MeshError> {
    if is_volume(m) {
        mg::face(m, n)
    } else {
        Ok(m.clone())
    }
}

/// The swept elements, after the first volume and before the second
/// when they were volumes.
fn grown(s1: &Mesh, m: Mesh, s2: Option<&Mesh>) -> Mesh {
    let m = if is_volume(s1) { s1.union(&m) } else { m };
    match s2 {
        Some(s2) if is_volume(s2) => m.union(s2),
        _ => m,
    }
}

/// A copy of the mesh with nodes moved by a displacement field (deformed shape).
pub(crate) fn moved_by_field(it: &mut Interp, m: &Mesh, u: &Chpoint, scale: f64) -> Mesh {
    let axis = it.opts.mode.starts_with("AXIS") || it.opts.mode.starts_with("FOUR");
    let comps: [&str; 3] = if axis { ["UR", "UZ", "UT"] } else { ["UX", "UY", "UZ"] };
    let mut map = std::collections::HashMap::new();
    for n in m.node_list() {
        let mut x = it.nodes.get(n);
        for (xk, c) in x.iter_mut().zip(comps).take(it.opts.dime.max(1)) {
            *xk += scale * u.get(n, c).unwrap_or(0.0);
        }
        let d = it.nodes.density[n];
        map.insert(n, it.nodes.push(x, d));
    }
    let mut out = m.clone();
    for p in out.parts.iter_mut() {
        for n in p.conn.iter_mut() {
            *n = map[n];
        }
    }
    out
}
