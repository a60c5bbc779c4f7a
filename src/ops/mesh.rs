//! Geometry: points and meshes. The algorithms live in `fem::meshing`;
//! this file reads Gibiane arguments and wraps results.

use super::{Args, OpDef, PointId};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::{ElemType, Mesh};
use crate::fem::meshing as mg;
use crate::value::{Chpoint, Nature, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef { name: "NOEU", signature: "NOEUD n", doc: "The point (node) number n, as numbered by gibi (LIST shows node numbers).", example: "p = noeud 5 ;", f: noeu },
    OpDef { name: "COOR", signature: "COOR POINT | COOR n POINT | COOR (n) MAILLAGE", doc: "Coordinates of a point (one result per dimension), one of them, or coordinate fields (SCAL) on a mesh: one per dimension, or the n-th.", example: "x y = coor p ;", f: coor },
    OpDef { name: "NBNO", signature: "NBNO MAILLAGE", doc: "Number of nodes of a mesh.", example: "n = nbno l ;", f: nbno },
    OpDef { name: "NBEL", signature: "NBEL MAILLAGE", doc: "Number of elements of a mesh.", example: "n = nbel s ;", f: nbel },
    OpDef { name: "POIN", signature: "POIN x (y) (z) | MAILLAGE POIN n | MAILLAGE POIN ('INIT'|'FINAL') | MAILLAGE POIN 'PROC' POINT | MAILLAGE POIN ('DROIT' P1 P2 | 'PLAN' P1 P2 P3) (crit) | CHPOINT POIN 'MAXI'|'MINI' ('ABS') | CHPOINT POIN 'SUPE'|'INFE'|'EGSU'|'EGIN'|'EGAL' v", doc: "A point, or nodes of a mesh, or the nodes where a field meets a test (a POI1 mesh).", example: "p = l poin 'FINAL' ;", f: poin },
    OpDef { name: "DROI", signature: "DROI (n) P1|LINE P2 ('DINI' d1) ('DFIN' d2)", doc: "A straight line of n elements (SEG2 or SEG3 per OPTI ELEM).", example: "l = droi 10 p1 p2 ;", f: droi },
    // D and C are Cast3M's own abbreviations of DROI and CERC (`p1 d 10 p2`).
    OpDef { name: "D", signature: "D (n) P1|LINE P2 ('DINI' d1) ('DFIN' d2)", doc: "Abbreviation of DROI.", example: "l = p1 d 10 p2 ;", f: droi },
    OpDef { name: "DALL", signature: "DALL LINE1 LINE2 LINE3 LINE4 ('PLAN')", doc: "A structured surface (OPTI ELEM QUA4, TRI3, QUA8, TRI6) from four sides forming a closed contour.", example: "s = dall bas dro hau gau ;", f: dall },
    OpDef { name: "TRAN", signature: "GEO TRAN (n) ('DINI' d1) ('DFIN' d2) VECTOR", doc: "Sweep a line into a surface or a surface into a volume along a vector.", example: "s = l tran 4 (0. 1.) ;", f: tran },
    OpDef { name: "ROTA", signature: "GEO ROTA (n) ANGLE CENTRE (AXIS_POINT)", doc: "Sweep by rotation (angle in degrees) about a point (2D) or an axis (3D).", example: "s = l rota 8 90. o ;", f: rota },
    OpDef { name: "VOLU", signature: "VOLU (n) SURF1 SURF2 | VOLU (n) SURF 'TRAN' VECTOR | VOLU (n) SURF 'ROTA' ANGLE P1 (P2)", doc: "Volume between two compatible surfaces, or swept from a surface by a translation or a rotation (as TRAN and ROTA).", example: "v = volu 3 s1 s2 ;", f: volu },
    OpDef { name: "ELEM", signature: "GEO ELEM TYPE | GEO ELEM n|LISTENTI | GEO ELEM 'APPU' ('STRI'|'LARG') GEO2 | LINE ELEM 'COMP' P1 P2 | GEO ELEM 'TYPE'", doc: "Elements of a mesh by type, by number, or resting on another mesh; the part of a line between two of its points; the element types of a mesh (LISTMOTS).", example: "q = s elem qua4 ;", f: elem },
    OpDef { name: "COTE", signature: "COTE (n) SURFACE", doc: "Side n of a structured (DALL/TRAN) surface, or its four sides.", example: "b = cote 1 s ;", f: cote },
    OpDef { name: "FACE", signature: "FACE n VOLUME", doc: "Face n of a volume made by VOLU, TRAN or ROTA: 1 the base, 2 the opposite face, 3 the lateral surface.", example: "haut = face 2 v ;", f: face },
    OpDef { name: "ENVE", signature: "ENVE VOLUME", doc: "The envelope of a volume mesh: the faces that belong to one element only (TRI3/QUA4), oriented outwards as in their elements.", example: "peau = enve v ;", f: enve },
    OpDef { name: "CONT", signature: "CONT GEO", doc: "Contour: boundary edges of a surface, end points of a line.", example: "c = cont s ;", f: cont },
    OpDef { name: "ELIM", signature: "ELIM (crit) GEO (GEO2 …)", doc: "Merge nodes closer than crit, in every object (several meshes: their nodes with each other's).", example: "elim 1.e-5 l ;", f: elim },
    OpDef { name: "INTE", signature: "GEO1 INTE GEO2", doc: "Elements common to two meshes.", example: "c = s1 inte s2 ;", f: inte },
    OpDef { name: "DIFF", signature: "DIFF GEO1 GEO2", doc: "Symmetric difference of two meshes.", example: "d = diff s1 s2 ;", f: diff },
    OpDef { name: "PLUS", signature: "OBJ PLUS VECTOR | GEO PLUS CHPOINT", doc: "A translated copy (geometric, not arithmetic), or the mesh moved by a displacement field.", example: "l2 = l plus (0. 1.) ;", f: plus },
    OpDef { name: "MOIN", signature: "OBJ MOIN VECTOR", doc: "A copy translated by minus the vector.", example: "l2 = l moin (0. 1.) ;", f: moin },
    OpDef { name: "SYME", signature: "POINT|MAILLAGE SYME ('DROIT' P1 P2 | 'PLAN' P1 P2 P3 | 'POINT' P)", doc: "Mirror image on new nodes: about a line (2D; in 3D the half-turn about it), a plane (3D) or a point. Surfaces and volumes keep their orientation.", example: "s2 = s1 syme 'DROIT' p1 p2 ;", f: syme },
    OpDef { name: "TOUR", signature: "POINT|MAILLAGE TOUR angle P1 (P2)", doc: "A copy on new nodes turned by angle degrees about P1 (2D) or about the axis P1 P2 (3D).", example: "s2 = s1 tour 90. p0 ;", f: tour },
    OpDef { name: "INVE", signature: "INVE GEO", doc: "Reverse the orientation of a mesh.", example: "l2 = inve l ;", f: inve },
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
    Err(a.missing("POINT or MAILLAGE"))
}

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

fn nbno(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let m = req_geo(a)?;
    Ok(vec![Value::Int(mg::nbno(&m) as i64)])
}

fn nbel(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let m = req_geo(a)?;
    Ok(vec![Value::Int(mg::nbel(&m) as i64)])
}

/// A POINT argument read as a vector.
pub(crate) fn vector(it: &Interp, a: &mut Args) -> Option<[f64; 3]> {
    a.opt::<PointId>().map(|p| it.nodes.get(p.0))
}

fn poin(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if let Some(ch) = a.opt::<Rc<crate::value::Chpoint>>() {
        return poin_of_field(a, &ch);
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
    // POIN x (y) (z): a point from numbers (the only way in DIME 1).
    let mut x = [0.0; 3];
    let dim = it.opts.dime.max(1);
    for (k, c) in x.iter_mut().enumerate().take(dim) {
        *c = if k == 0 { a.req_num()? } else { a.opt_num().unwrap_or(0.0) };
    }
    let d = it.opts.dens;
    Ok(vec![Value::Point(it.nodes.push(x, d))])
}

/// `CHPO POIN 'MAXI'|'MINI' ('ABS') | 'SUPE'|'INFE'|'EGSU'|'EGIN'|'EGAL' v`:
/// the nodes where one value of the field meets the test, as a POI1 mesh
/// (where is the maximum?). MAXI/MINI and EGAL compare within 1e-10 of
/// the largest value.
fn poin_of_field(a: &mut Args, ch: &crate::value::Chpoint) -> Result<Vec<Value>> {
    let k = a.req_keyword(&["MAXI", "MINI", "SUPE", "INFE", "EGSU", "EGIN", "EGAL"])?;
    let abs = a.keyword(&["ABS"]).is_some();
    let value = |v: f64| if abs { v.abs() } else { v };
    let vals: Vec<(usize, f64)> = ch.entries().map(|(n, _, v)| (n, value(v))).collect();
    if vals.is_empty() {
        return Err(a.err("the field is empty"));
    }
    let scale = vals.iter().fold(0.0_f64, |m, e| m.max(e.1.abs()));
    let tol = 1e-10 * scale;
    let test: Box<dyn Fn(f64) -> bool> = match k {
        "MAXI" => {
            let top = vals.iter().fold(f64::NEG_INFINITY, |m, e| m.max(e.1));
            Box::new(move |v| v >= top - tol)
        }
        "MINI" => {
            let low = vals.iter().fold(f64::INFINITY, |m, e| m.min(e.1));
            Box::new(move |v| v <= low + tol)
        }
        _ => {
            let t = a.req_num()?;
            match k {
                "SUPE" => Box::new(move |v| v > t),
                "INFE" => Box::new(move |v| v < t),
                "EGSU" => Box::new(move |v| v >= t),
                "EGIN" => Box::new(move |v| v <= t),
                _ => Box::new(move |v| (v - t).abs() <= tol),
            }
        }
    };
    let mut seen = std::collections::HashSet::new();
    let nodes: Vec<usize> = vals.into_iter().filter(|&(n, v)| test(v) && seen.insert(n)).map(|e| e.0).collect();
    Ok(mesh_val(Mesh::points(&nodes)))
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
    let ty = elem_type_opt(it);
    if let Some(line) = a.opt::<Rc<Mesh>>() {
        let p2 = a.req::<PointId>()?;
        more_spacing(a, &mut sp)?;
        return Ok(mesh_val(mg::droi_extend(&mut it.nodes, &line, p2.0, &sp, ty)?));
    }
    let p1 = a.req::<PointId>()?;
    let p2 = a.req::<PointId>()?;
    more_spacing(a, &mut sp)?;
    Ok(mesh_val(mg::droi(&mut it.nodes, p1.0, p2.0, &sp, ty)?))
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
    a.keyword(&["PLAN"]);
    let ty = match ElemType::from_name(&it.opts.elem) {
        Some(t @ (ElemType::Qua4 | ElemType::Tri3 | ElemType::Qua8 | ElemType::Tri6)) => t,
        _ => ElemType::Qua4,
    };
    Ok(mesh_val(mg::dall(&mut it.nodes, [&sides[0], &sides[1], &sides[2], &sides[3]], ty)?))
}

fn tran(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let geo = req_geo(a)?;
    let mut sp = spacing(a)?;
    let v = vector(it, a).ok_or_else(|| a.missing("a vector (POINT)"))?;
    more_spacing(a, &mut sp)?;
    let m = mg::tran(&mut it.nodes, &geo, &sp, v)?;
    Ok(mesh_val(swept_surface(it, m)))
}

/// A line swept under `OPTI ELEM TRI3` gives triangles, as DALL does (each
/// quadrangle cut along its first diagonal); volumes are left as swept.
pub(crate) fn swept_surface(it: &Interp, m: Mesh) -> Mesh {
    let tri = ElemType::from_name(&it.opts.elem) == Some(ElemType::Tri3);
    if tri && m.parts.iter().any(|p| p.ty == ElemType::Qua4) {
        mg::change_to_triangles(&m)
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
            Ok(mesh_val(mg::tran(&mut it.nodes, &s, &sp, v)?))
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
            Ok(mesh_val(mg::rota(&mut it.nodes, &s, &sp, angle, c, axis)?))
        }
        None => {
            let s1 = match s1 {
                Some(s) => s,
                None => a.req::<Rc<Mesh>>()?,
            };
            let s2 = a.req::<Rc<Mesh>>()?;
            more_spacing(a, &mut sp)?;
            Ok(mesh_val(mg::volu(&mut it.nodes, &s1, &s2, &sp)?))
        }
    }
}

fn face(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let n = a.req::<i64>()?;
    let v = a.req::<Rc<Mesh>>()?;
    Ok(mesh_val(mg::face(&v, n)?))
}

fn elem(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let m = a.req::<Rc<Mesh>>()?;
    if let Some(k) = a.keyword(&["COMP", "TYPE"]) {
        return super::mesh_select::elem_keyword(it, a, &m, k);
    }
    if a.keyword(&["APPU"]).is_some() {
        let strict = a.keyword(&["STRI", "LARG"]) != Some("LARG");
        let support = req_geo(a)?;
        return Ok(mesh_val(mg::elem_appui(&m, &support, strict)));
    }
    if let Some(n) = a.opt::<i64>() {
        return Ok(mesh_val(mg::elem_numbers(&m, None, &[n])?));
    }
    if let Some(l) = a.opt::<Rc<Vec<i64>>>() {
        return Ok(mesh_val(mg::elem_numbers(&m, None, &l)?));
    }
    let w = a.word().ok_or_else(|| a.missing("an element type, a number or APPU"))?;
    let ty = ElemType::from_name(&w.to_uppercase()).ok_or_else(|| a.err(format!("unknown element type {}", w)))?;
    Ok(mesh_val(mg::elem_type(&m, ty)))
}

fn cote(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let n = a.opt::<i64>();
    let s = a.req::<Rc<Mesh>>()?;
    match n {
        Some(n) => Ok(mesh_val(mg::cote(&s, n)?)),
        // `l1 l2 l3 l4 = COTE s`: the four sides.
        None => (1..=4).map(|k| Ok(Value::Mesh(Rc::new(mg::cote(&s, k)?)))).collect(),
    }
}

/// ENVE: the faces of the volume elements that no other element shares
/// (same node set), in element order, each with its element's outward
/// orientation (`shape::faces`).
fn enve(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let m = a.req::<Rc<Mesh>>()?;
    let mut faces: Vec<(ElemType, Vec<usize>)> = Vec::new();
    let mut count: std::collections::HashMap<Vec<usize>, usize> = std::collections::HashMap::new();
    for part in m.parts.iter().filter(|p| p.ty.dim() == 3) {
        for e in part.elems() {
            for (fty, loc) in crate::fem::shape::faces(part.ty) {
                let nodes: Vec<usize> = loc.iter().map(|&k| e[k]).collect();
                let mut key = nodes.clone();
                key.sort_unstable();
                *count.entry(key).or_default() += 1;
                faces.push((fty, nodes));
            }
        }
    }
    if faces.is_empty() {
        return Err(a.err("ENVE needs a volume mesh (the boundary of a surface or a line is CONT)"));
    }
    let mut parts: Vec<(ElemType, Vec<usize>)> = Vec::new();
    for (fty, nodes) in faces {
        let mut key = nodes.clone();
        key.sort_unstable();
        if count[&key] != 1 {
            continue;
        }
        match parts.iter_mut().find(|(t, _)| *t == fty) {
            Some((_, c)) => c.extend(nodes),
            None => parts.push((fty, nodes)),
        }
    }
    Ok(mesh_val(mg::mesh_of(parts)))
}

fn cont(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let m = a.req::<Rc<Mesh>>()?;
    Ok(mesh_val(mg::cont(&m)?))
}

/// ELIM works in place in Cast3M: every object holding a merged node sees
/// the kept one. We rewrite every mesh and point in the store.
fn elim(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    // The tolerance may come before or after the mesh (`ELIM 1.e-3 s`,
    // `ELIM s 1.e-3`).
    let tol = a.opt_num();
    let mut m = req_geo(a)?;
    // `ELIM crit GEO1 GEO2`: the nodes of both are merged with each other.
    while let Some(g) = opt_geo(a) {
        m = m.union(&g);
    }
    let tol = tol.or_else(|| a.opt_num()).unwrap_or(1e-6);
    let (merged, map) = mg::elim(&it.nodes, &m, tol)?;
    if !map.is_empty() {
        for f in it.store.frames.iter_mut() {
            for v in f.vars.values_mut() {
                match v {
                    Value::Mesh(x) => *x = Rc::new(map.apply(x)),
                    Value::Point(p) => *p = map.get(*p),
                    _ => {}
                }
            }
        }
    }
    Ok(mesh_val(merged))
}

fn inte(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let x = req_geo(a)?;
    let y = req_geo(a)?;
    Ok(mesh_val(mg::inte(&x, &y)))
}

fn diff(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let x = req_geo(a)?;
    let y = req_geo(a)?;
    Ok(mesh_val(mg::diff(&x, &y)))
}

fn translate(it: &mut Interp, a: &mut Args, sign: f64) -> Result<Vec<Value>> {
    // The object comes first; the vector after it (both may be points).
    let obj = a.req::<Value>()?;
    if let (Value::Mesh(m), Some(u)) = (&obj, a.opt::<Rc<Chpoint>>()) {
        return Ok(mesh_val(moved_by_field(it, m, &u, sign)));
    }
    // Several objects move together (`a b = a b PLUS v`); the last POINT
    // is the vector.
    let (mut objs, tail) = super::mesh_move::gather(a, obj, 1, "a vector (POINT)")?;
    let v = it.nodes.get(tail[0]).map(|c| c * sign);
    if objs.len() > 1 {
        return super::mesh_move::copies(it, a, &objs, mg::motion::Motion::Translate(v));
    }
    Ok(match objs.remove(0) {
        Value::Point(p) => {
            // A translated point is a new point: the current density, as
            // Cast3M gives it (meshes keep their nodes' densities).
            let x = it.nodes.get(p);
            let d = it.opts.dens;
            vec![Value::Point(it.nodes.push([x[0] + v[0], x[1] + v[1], x[2] + v[2]], d))]
        }
        Value::Mesh(m) => mesh_val(mg::translate_copy(&mut it.nodes, &m, v)?),
        other => return Err(a.err(format!("cannot translate a {}", other.type_name()))),
    })
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

fn plus(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    translate(it, a, 1.0)
}

fn moin(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    translate(it, a, -1.0)
}

fn syme(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    // The object is the operand before SYME (`s2 = s1 syme …`), else the
    // first value after it, else what follows the symmetry element.
    let mut obj = a.left_value();
    if obj.is_none() && a.peek_right().is_some_and(|v| matches!(v, Value::Point(_) | Value::Mesh(_))) {
        obj = a.right_any();
    }
    let mirror = match a.req_keyword(&["DROIT", "PLAN", "POINT"])? {
        "DROIT" => {
            let p1 = vector(it, a).ok_or_else(|| a.missing("POINT"))?;
            mg::Mirror::Line(p1, vector(it, a).ok_or_else(|| a.missing("POINT"))?)
        }
        "PLAN" => {
            let p1 = vector(it, a).ok_or_else(|| a.missing("POINT"))?;
            let p2 = vector(it, a).ok_or_else(|| a.missing("POINT"))?;
            mg::Mirror::Plane(p1, p2, vector(it, a).ok_or_else(|| a.missing("POINT"))?)
        }
        _ => mg::Mirror::Point(vector(it, a).ok_or_else(|| a.missing("POINT"))?),
    };
    let obj = match obj {
        Some(v) => v,
        None => a.right_any().ok_or_else(|| a.missing("POINT or MAILLAGE"))?,
    };
    let dim = it.opts.dime.max(2);
    match obj {
        Value::Point(p) => {
            mirror.check(dim)?;
            let x = mirror.image(it.nodes.get(p));
            let d = it.nodes.density[p];
            Ok(vec![Value::Point(it.nodes.push(x, d))])
        }
        Value::Mesh(m) => Ok(mesh_val(mg::syme(&mut it.nodes, &m, mirror, dim)?)),
        other => Err(a.err(format!("cannot take the symmetric of a {}", other.type_name()))),
    }
}

fn tour(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    // The object is the operand before TOUR (`s2 = s1 tour 90. p`; the
    // first of several), else the first value after it.
    let first = a.opt_with(|v| matches!(v, Value::Point(_) | Value::Mesh(_)).then(|| v.clone()));
    let obj = match first.or_else(|| a.left_value()) {
        Some(v) => v,
        None => a.right_any().ok_or_else(|| a.missing("POINT or MAILLAGE"))?,
    };
    let angle = a.req_num()?;
    // Several objects turn together; the last POINTs are the centre and,
    // in 3D, the axis.
    let n = if it.opts.dime >= 3 { 2 } else { 1 };
    let (mut objs, tail) = super::mesh_move::gather(a, obj, n, "POINT (the centre, and the axis in 3D)")?;
    let centre = it.nodes.get(tail[0]);
    let axis_end = tail.get(1).map(|&p| it.nodes.get(p));
    if objs.len() > 1 {
        let turn = mg::motion::Motion::Rotate { angle_deg: angle, centre, axis_end };
        return super::mesh_move::copies(it, a, &objs, turn);
    }
    match objs.remove(0) {
        Value::Point(p) => Ok(vec![Value::Point(mg::rotate_point(&mut it.nodes, p, angle, centre, axis_end)?)]),
        Value::Mesh(m) => Ok(mesh_val(mg::rotate_copy(&mut it.nodes, &m, angle, centre, axis_end)?)),
        other => Err(a.err(format!("cannot turn a {}", other.type_name()))),
    }
}

fn inve(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let m = a.req::<Rc<Mesh>>()?;
    Ok(mesh_val(mg::inve(&m)?))
}

fn noeu(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let n = a.req::<i64>()?;
    if n < 1 || n as usize > it.nodes.len() {
        return Err(a.err(format!("there is no node {} (nodes are numbered 1 to {})", n, it.nodes.len())));
    }
    Ok(vec![Value::Point(n as usize - 1)])
}
