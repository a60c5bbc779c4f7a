//! Operations on existing meshes: parts (ELEM, COTE, FACE, ENVE, CONT),
//! set operations (INTE, DIFF), node merging (ELIM), and copies moved,
//! mirrored, turned or reversed (PLUS, MOIN, SYME, TOUR, INVE).

use super::mesh::{mesh_val, moved_by_field, opt_geo, req_geo, vector};
use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::{ElemType, Mesh};
use crate::fem::meshing as mg;
use crate::value::{Chpoint, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef { name: "ELEM", signature: "GEO ELEM TYPE|COLOUR | CHE1 ELEM (ABS) SUPE|INFE|EGSU|EGIN|EGAL|DIFF x|COMP x1 x2|MAXI|MINI (LARG|STRI) (AVEC|SANS LMOTS) | GEO ELEM n|LISTENTI | GEO ELEM 'APPU' ('STRI'|'LARG') GEO2 | GEO ELEM 'CONTENANT' P ('TOUS') ('NOVERIF') | LINE ELEM 'COMP' P1 P2 | GEO ELEM 'TYPE'", doc: "Elements of a mesh by type, by colour, by number, resting on another mesh, or containing a point; the part of a line between two of its points; the element types of a mesh (LISTMOTS); the elements of an MCHAML whose values meet a test.", example: "q = s elem qua4 ;", f: elem },
    OpDef { name: "COTE", signature: "COTE (n) SURFACE", doc: "Side n of a surface whose quadrilaterals form a grid (or of a DALL/TRAN surface of triangles), or its four sides.", example: "b = cote 1 s ;", f: cote },
    OpDef { name: "FACE", signature: "FACE (n) VOLUME", doc: "Face n of a volume made by VOLU, TRAN or ROTA: 1 the base, 2 the opposite face, 3 the lateral surface; without n, the three.", example: "haut = face 2 v ;", f: face },
    OpDef { name: "ENVE", signature: "ENVE VOLUME", doc: "The envelope of a volume mesh: the faces that belong to one element only (TRI3/QUA4), oriented outwards as in their elements.", example: "peau = enve v ;", f: enve },
    OpDef { name: "CONT", signature: "CONT ('NOID') ('EXTE'|'INTE'|'TOUT') GEO", doc: "Contour: boundary edges of a surface, end points of a line.", example: "c = cont s ;", f: cont },
    OpDef { name: "ELIM", signature: "ELIM (crit) GEO (GEO2 …)", doc: "Merge nodes closer than crit, in every object (with GEO2: only nodes of GEO with nodes of GEO2, never within one object).", example: "elim 1.e-5 l ;", f: elim },
    OpDef { name: "INTE", signature: "GEO1 INTE GEO2 ('NOVERIF') | S1B S2B C1 C2 = INTE 'GEOM' S1 S2 ('NOVERIF')", doc: "Elements common to two meshes (an empty mesh when there are none); with 'GEOM', two TRI3 surfaces cut along the curve where they cross, and that curve on the nodes of each.", example: "c = s1 inte s2 ;", f: inte },
    OpDef { name: "DIFF", signature: "DIFF GEO1 GEO2", doc: "Symmetric difference of two meshes.", example: "d = diff s1 s2 ;", f: diff },
    OpDef { name: "PLUS", signature: "OBJ PLUS VECTOR | GEO|POINT PLUS CHPOINT", doc: "A translated copy (geometric, not arithmetic), or the mesh moved by a displacement field.", example: "l2 = l plus (0. 1.) ;", f: plus },
    OpDef { name: "MOIN", signature: "OBJ MOIN VECTOR | GEO|POINT MOIN CHPOINT", doc: "A copy translated by minus the vector.", example: "l2 = l moin (0. 1.) ;", f: moin },
    OpDef { name: "SYME", signature: "POINT|MAILLAGE SYME ('DROIT' P1 P2 | 'PLAN' P1 P2 P3 | 'POINT' P)", doc: "Mirror image on new nodes: about a line (2D; in 3D the half-turn about it), a plane (3D) or a point. Surfaces and volumes keep their orientation.", example: "s2 = s1 syme 'DROIT' p1 p2 ;", f: syme },
    OpDef { name: "TOUR", signature: "POINT|MAILLAGE TOUR angle P1 (P2)", doc: "A copy on new nodes turned by angle degrees about P1 (2D) or about the axis P1 P2 (3D).", example: "s2 = s1 tour 90. p0 ;", f: tour },
    OpDef { name: "INVE", signature: "INVE GEO | INVE CHPOINT", doc: "Reverse the orientation of a mesh; the inverse of each value of a node field.", example: "l2 = inve l ;", f: inve },
];

fn elem(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if let Some(ch) = a.opt::<Rc<crate::value::Mchaml>>() {
        return super::elem_field::elem_of_mchaml(a, &ch);
    }
    let m = a.req::<Rc<Mesh>>()?;
    if let Some(k) = a.keyword(&["COMP", "TYPE"]) {
        return super::mesh_select::elem_keyword(it, a, &m, k);
    }
    if a.keyword(&["CONT"]).is_some() {
        return super::elem_containing::elem_containing(it, a, &m);
    }
    if a.keyword(&["APPU"]).is_some() {
        let strict = a.keyword(&["STRI", "LARG"]) != Some("LARG");
        let support = req_geo(a)?;
        return Ok(mesh_val(mg::elem_appui(&m, &support, strict)));
    }
    // The type word comes first (`GEO ELEM POI1 1`: the first POI1
    // element), the numbers, if any, count among that type's elements.
    let ty = ElemType::ALL.into_iter().find(|t| a.keyword_next(&[t.name()]).is_some());
    if let Some(n) = a.opt::<i64>() {
        return Ok(mesh_val(mg::elem_numbers(&m, ty, &[n])?));
    }
    if let Some(l) = a.opt::<Rc<Vec<i64>>>() {
        return Ok(mesh_val(mg::elem_numbers(&m, ty, &l)?));
    }
    if let Some(ty) = ty {
        return Ok(mesh_val(mg::elem_type(&m, ty)));
    }
    if a.keyword_next(&["MULT"]).is_some() {
        // Relation elements (RAFF's) come in three sizes, one type each.
        let parts = m.parts.iter().filter(|p| p.ty.tie_side().is_some()).cloned().collect();
        return Ok(mesh_val(Mesh { parts }));
    }
    let w = a.word().ok_or_else(|| a.missing("an element type, a colour, a number or APPU"))?;
    if let Some(ty) = ElemType::from_name(&w.to_uppercase()) {
        return Ok(mesh_val(mg::elem_type(&m, ty)));
    }
    // elem.notice: a colour word picks the elements of that colour (COUL).
    match crate::fem::mesh::Colour::from_name(&w) {
        Some(c) => Ok(mesh_val(m.of_colour(c))),
        None => Err(a.err(format!("unknown element type or colour {}", w))),
    }
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

fn face(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let n = a.opt::<i64>();
    let v = a.req::<Rc<Mesh>>()?;
    match n {
        Some(n) => Ok(mesh_val(mg::face(&v, n)?)),
        // `f1 f2 f3 = FACE v`: the three faces.
        None => (1..=3).map(|k| Ok(Value::Mesh(Rc::new(mg::face(&v, k)?)))).collect(),
    }
}

/// ENVE: the faces of the volume elements that no other element shares
/// (same node set), in element order, each with its element's outward
/// orientation (`shape::faces`).
fn enve(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let m = a.req::<Rc<Mesh>>()?;
    let faces = mg::edges::boundary_faces(m.parts.iter().filter(|p| p.ty.dim() == 3));
    if !m.parts.iter().any(|p| p.ty.dim() == 3) {
        return Err(a.err("ENVE needs a volume mesh (the boundary of a surface or a line is CONT)"));
    }
    let mut parts: Vec<(ElemType, Vec<usize>)> = Vec::new();
    for (fty, nodes) in faces {
        match parts.iter_mut().find(|(t, _)| *t == fty) {
            Some((_, c)) => c.extend(nodes),
            None => parts.push((fty, nodes)),
        }
    }
    Ok(mesh_val(mg::mesh_of(parts)))
}

fn cont(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    use crate::fem::meshing::extract::ContEdges;
    let noid = a.keyword(&["NOID"]).is_some();
    let which = match a.keyword(&["EXTE", "INTE", "TOUT"]) {
        Some("INTE") => ContEdges::Interior,
        Some("TOUT") => ContEdges::All,
        _ => ContEdges::Exterior,
    };
    let noid = noid || a.keyword(&["NOID"]).is_some();
    let m = a.req::<Rc<Mesh>>()?;
    let noid = noid || a.keyword(&["NOID"]).is_some();
    let outer = matches!(which, ContEdges::Exterior);
    let c = mg::extract::cont_with(&m, which, noid)?;
    Ok(mesh_val(if outer { mg::cont_order::outer_first(&c, &it.nodes) } else { c }))
}

/// ELIM works in place in Cast3M: every object holding a merged node sees
/// the kept one. We rewrite every mesh, point and nodal field in the
/// store, and those held in tables (a mesh read by LIRE sits in one).
fn elim(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    // The tolerance may come before or after the mesh (`ELIM 1.e-3 s`,
    // `ELIM s 1.e-3`).
    let tol = a.opt_num();
    let m = req_geo(a)?;
    // `ELIM crit GEO1 GEO2`: nodes of the first merge with nodes of the
    // others, never among themselves.
    let mut others: Option<Mesh> = None;
    while let Some(g) = opt_geo(a) {
        others = Some(match others {
            Some(o) => o.union(&g),
            None => g,
        });
    }
    let tol = tol.or_else(|| a.opt_num()).unwrap_or(1e-6);
    let (merged, map) = match &others {
        Some(g2) => mg::elim_between(&it.nodes, &m, g2, tol)?,
        None => mg::elim(&it.nodes, &m, tol)?,
    };
    if !map.is_empty() {
        let mut seen = std::collections::HashSet::new();
        for f in it.store.frames.iter_mut() {
            for v in f.vars.values_mut() {
                renumber(v, &map, &mut seen);
            }
        }
    }
    Ok(mesh_val(merged))
}

/// `v` with merged nodes renumbered; a table is visited once (tables may
/// hold themselves).
fn renumber(v: &mut Value, map: &mg::NodeMap, seen: &mut std::collections::HashSet<usize>) {
    match v {
        Value::Mesh(x) => *x = Rc::new(map.apply(x)),
        Value::Point(p) => *p = map.get(*p),
        Value::Chpo(c) if c.nodes.iter().any(|n| map.get(*n) != *n) => {
            let entries: Vec<(usize, String, f64)> =
                c.entries().map(|(n, k, x)| (map.get(n), k.to_string(), x)).collect();
            *c = Rc::new(Chpoint::from_entries(c.nature, entries.iter().map(|(n, k, x)| (*n, k.as_str(), *x))));
        }
        Value::Table(t) if seen.insert(Rc::as_ptr(t) as usize) => {
            for x in t.borrow_mut().values_mut() {
                renumber(x, map, seen);
            }
        }
        _ => {}
    }
}

fn inte(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if a.keyword(&["GEOM"]).is_some() {
        return super::mesh_cut::inte_geom(it, a);
    }
    let x = req_geo(a)?;
    let y = req_geo(a)?;
    // No common element gives an empty mesh: Cast3M's procedures
    // (G_THETA) intersect and then test the element count. 'NOVERIF'
    // (a check of the geometric form) is read and changes nothing here.
    a.keyword(&["NOVERIF"]);
    Ok(mesh_val(mg::inte(&x, &y)))
}

fn diff(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let x = req_geo(a)?;
    let y = req_geo(a)?;
    let d = mg::diff(&x, &y);
    // Nothing left: an empty mesh of the current element type, as Cast3M
    // gives (ELEM 'TYPE' names it).
    match ElemType::from_name(&it.opts.elem.to_uppercase()) {
        Some(ty) if d.n_elements() == 0 => Ok(mesh_val(Mesh::single(crate::fem::mesh::Part::new(ty)))),
        _ => Ok(mesh_val(d)),
    }
}

fn translate(it: &mut Interp, a: &mut Args, sign: f64) -> Result<Vec<Value>> {
    // The object comes first; the vector after it (both may be points).
    let obj = a.req::<Value>()?;
    // Several objects move together (`a b = a b PLUS v`); the last operand
    // is the vector (a POINT) or, after a mesh alone, a displacement field.
    let (mut objs, _) = super::mesh_move::gather(a, obj, 0, "")?;
    if let [Value::Mesh(m), Value::Chpo(u)] = objs.as_slice() {
        return Ok(mesh_val(moved_by_field(it, m, u, sign)));
    }
    if let [Value::Point(p), Value::Chpo(u)] = objs.as_slice() {
        // plus.notice: a POINT too is carried by a displacement field (a
        // crack tip moved by a propagation increment), to a new point.
        let m = Mesh { parts: vec![crate::fem::mesh::Part::with(ElemType::Poi1, vec![*p])] };
        let moved = moved_by_field(it, &m, u, sign);
        return Ok(vec![Value::Point(moved.parts[0].conn[0])]);
    }
    if let ([Value::Mesh(g2), Value::Mesh(g1)], true) = (objs.as_slice(), sign < 0.0) {
        return super::mesh_moin_geo::mesh_minus_mesh(it, a, g2, g1);
    }
    let v = match objs.pop() {
        Some(Value::Point(p)) if !objs.is_empty() => it.nodes.get(p).map(|c| c * sign),
        _ => return Err(a.missing("a vector (POINT)")),
    };
    if objs.len() > 1 || matches!(objs[0], Value::Chpo(_) | Value::Model(_) | Value::Mchaml(_)) {
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

fn plus(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    translate(it, a, 1.0)
}

fn moin(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    translate(it, a, -1.0)
}

fn syme(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    // The objects are the operands before SYME (`s2 = s1 syme …`, `m2 f2 =
    // m1 f1 syme …`), else the first value after it, else what follows the
    // symmetry element.
    let geo_or_field = |v: &Value| matches!(v, Value::Point(_) | Value::Mesh(_) | Value::Chpo(_));
    let mut objs = Vec::new();
    while let Some(v) = a.left_value() {
        if !geo_or_field(&v) {
            a.unread(v);
            break;
        }
        objs.push(v);
    }
    objs.reverse();
    // Written after SYME, several objects are imaged together too
    // (`t1 t2 = syme l1 l2 'DROIT' p q`).
    if objs.is_empty() {
        while a.peek_right().is_some_and(|v| geo_or_field(&v)) {
            objs.extend(a.right_any());
        }
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
    let obj = match objs.len() {
        0 => a.right_any().ok_or_else(|| a.missing("POINT or MAILLAGE"))?,
        1 if !matches!(objs[0], Value::Chpo(_)) => objs.remove(0),
        _ => {
            // Several objects (a field with its support): one image per node.
            let meshes = super::mesh_move::supports(a, &objs)?;
            let refs: Vec<&Mesh> = meshes.iter().collect();
            let out = mg::syme_together(&mut it.nodes, &refs, mirror, it.opts.dime.max(2))?;
            return Ok(objs
                .iter()
                .zip(out)
                .map(|(o, m)| match o {
                    Value::Chpo(c) => Value::Chpo(Rc::new(super::mesh_move::carried(c, &m))),
                    _ => super::mesh_move::image_value(o, m),
                })
                .collect());
        }
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
    let first = a.opt_with(|v| super::mesh_move::movable(v).then(|| v.clone()));
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
    if objs.len() > 1 || matches!(objs[0], Value::Chpo(_) | Value::Model(_) | Value::Mchaml(_)) {
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
    // On a node field: the inverse of each value (inve.notice), same nature.
    if let Some(c) = a.opt::<Rc<crate::value::Chpoint>>() {
        if let Some((n, comp, _)) = c.entries().find(|e| e.2 == 0.0) {
            return Err(a.err(format!("the field is zero at node {} on {}: it has no inverse", n + 1, comp)));
        }
        return Ok(vec![Value::Chpo(Rc::new(c.map(|v| 1.0 / v)))]);
    }
    let m = a.req::<Rc<Mesh>>()?;
    Ok(mesh_val(mg::inve(&m)?))
}
