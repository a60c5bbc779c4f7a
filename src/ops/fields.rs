//! Node fields (CHPOINT): loads, extraction, renaming, algebra, and the
//! matrix-vector product `RIGIDITE * CHPOINT`.

use super::mesh::req_geo;
use super::{dofs, Args, OpDef, PointId};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::value::model::{MchamlZone, ZoneKey};
use crate::value::{Chpoint, Mchaml, Model, Nature, Rigidite, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "FORC",
        signature: "FORC ('FX' v 'FY' v …) | VECTOR  GEO",
        doc: "Nodal forces on a point, or a total force spread evenly over the nodes of a mesh (DISCRET field).",
        example: "f = forc 'FY' -3. p1 ;",
        f: forc,
    },
    OpDef {
        name: "MOME",
        signature: "MOME ('MZ' v …) | VECTOR | FLOTTANT (2D: MZ)  GEO",
        doc: "Nodal moments (in 2D a plain number is the moment MZ).",
        example: "m = mome 'MZ' 2. p1 ;",
        f: mome,
    },
    OpDef {
        name: "EXCO",
        signature: "EXCO COMP|LISTMOTS ('NOID') CHPOINT (NEWNAME|LISTMOTS)",
        doc: "Extract components (a single one is renamed SCAL unless a new name is given).",
        example: "ux = exco u 'UX' ;",
        f: exco,
    },
    OpDef {
        name: "NOMC",
        signature:
            "NOMC NEWNAME CHPOINT|MCHAML | NOMC LISTMOTS_OLD LISTMOTS_NEW CHPOINT|MCHAML ('NATU' 'INDETER'|'DIFFUS'|'DISCRET')",
        doc: "Rename components (and set the field's nature after 'NATU').",
        example: "c = nomc 'UX' (coor 1 l) ;",
        f: nomc,
    },
    OpDef { name: "XTX", signature: "XTX CHPOINT", doc: "Squared norm of a field.", example: "n = xtx r ;", f: xtx },
    OpDef {
        name: "XTMX",
        signature: "XTMX RIGIDITE CHPOINT",
        doc: "The quadratic form uᵀ K u (twice the strain energy of a displacement field).",
        example: "w = xtmx k u ;",
        f: xtmx,
    },
    OpDef {
        name: "SOMT",
        signature: "SOMT CHPOINT|LISTREEL",
        doc: "Sum of every value of a field or list.",
        example: "s = somt (exco r 'FY') ;",
        f: somt,
    },
    OpDef {
        name: "DEFO",
        signature: "DEFO GEO CHPOINT (SCALE) (VECTEUR) (COLOUR) (CHPOINT | MCHAML MMODEL) | DEFO CHPOINT GEO …",
        doc: "The deformed mesh: nodes moved by SCALE times the displacement field (for TRAC), in COLOUR if given. Arrows and a scalar field to colour it with are accepted and not drawn; other words are passed over.",
        example: "d = defo s u 100. ;",
        f: defo,
    },
    OpDef {
        name: "RESU",
        signature: "RESU CHPOINT|MCHAML",
        doc: "Resultant: the sum of each component, on the first node of the field (of an MCHAML: over every point of every element, as one POI1 element).",
        example: "r = resu f ;",
        f: resu,
    },
];

fn loads(it: &mut Interp, a: &mut Args, vec_names: &[&'static str]) -> Result<Vec<Value>> {
    let mut comps: Vec<(String, f64)> = Vec::new();
    while let Some(w) = a.word_not_operator() {
        comps.push((w, a.req_num()?));
    }
    // In 2D a moment has one component: `MOME 5. p` is MZ = 5 (mome.notice).
    if let ([single], true) = (vec_names, comps.is_empty()) {
        if let Some(v) = a.opt_num() {
            comps.push((single.to_string(), v));
        }
    }
    let geo = if comps.is_empty() {
        let v = a.req::<PointId>()?;
        let x = it.nodes.get(v.0);
        comps = vec_names.iter().enumerate().map(|(k, c)| (c.to_string(), x[k])).collect();
        req_geo(a)?
    } else {
        req_geo(a)?
    };
    let nodes = geo.node_list();
    // A total load on a mesh is shared evenly by its nodes (forc.notice).
    let share = 1.0 / nodes.len().max(1) as f64;
    let mut c = Chpoint::new(Nature::Discret);
    for n in &nodes {
        for (comp, v) in &comps {
            c.add(*n, comp, v * share, true);
        }
    }
    Ok(vec![Value::Chpo(Rc::new(c))])
}

fn forc(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let names = dofs::forces(it);
    loads(it, a, names)
}

fn mome(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let names = dofs::moments(it);
    loads(it, a, names)
}

fn comp_list(a: &mut Args) -> Option<Vec<String>> {
    if let Some(l) = a.opt::<Rc<Vec<String>>>() {
        return Some(l.to_vec());
    }
    a.word_not_operator().map(|w| vec![w])
}

/// EXCO on an element field: the listed components (one alone keeps its
/// name unless a new one is given; Cast3M renames it SCAL only for nodes),
/// point values or constants alike. Zones that hold none of them (another
/// part of a material) are left out.
fn exco_mchaml(a: &mut Args, m: &Mchaml) -> Result<Vec<Value>> {
    let comps = comp_list(a).ok_or_else(|| a.missing("a component"))?;
    a.keyword(&["NOID"]);
    let names = comp_list(a).unwrap_or_else(|| comps.clone());
    if names.len() != comps.len() {
        return Err(a.err("as many new names as components are needed"));
    }
    let mut out = Mchaml { subtype: m.subtype.clone(), zones: vec![] };
    for z in &m.zones {
        let idx: Vec<Option<usize>> = comps.iter().map(|c| z.comps.iter().position(|x| x == c)).collect();
        let has = |i: usize| {
            let c = &comps[i];
            idx[i].is_some() || z.constants.contains_key(c) || z.vectors.contains_key(c) || z.laws.contains_key(c)
        };
        let found = (0..comps.len()).filter(|&i| has(i)).count();
        if found == 0 {
            continue;
        }
        if found < comps.len() {
            let absent: Vec<&str> = (0..comps.len()).filter(|&i| !has(i)).map(|i| comps[i].as_str()).collect();
            return Err(a.err(format!("a zone of the field has no component {}", absent.join(" "))));
        }
        let point: Vec<usize> = (0..comps.len()).filter(|&i| idx[i].is_some()).collect();
        let mut nz = MchamlZone {
            mesh: z.mesh.clone(),
            element: z.element.clone(),
            at_nodes: z.at_nodes,
            comps: point.iter().map(|&i| names[i].clone()).collect(),
            ..Default::default()
        };
        if !point.is_empty() {
            nz.values = z
                .values
                .iter()
                .map(|e| e.iter().map(|p| point.iter().map(|&i| p[idx[i].unwrap_or(0)]).collect()).collect())
                .collect();
        }
        for (i, c) in comps.iter().enumerate() {
            if idx[i].is_none() {
                if let Some(v) = z.constants.get(c) {
                    nz.constants.insert(names[i].clone(), *v);
                }
                if let Some(v) = z.vectors.get(c) {
                    nz.vectors.insert(names[i].clone(), *v);
                }
                if let Some(l) = z.laws.get(c) {
                    nz.laws.insert(names[i].clone(), l.clone());
                }
            }
        }
        out.zones.push(nz);
    }
    if out.zones.is_empty() {
        let mut present: Vec<&str> = Vec::new();
        for c in m.zones.iter().flat_map(|z| z.comps.iter().chain(z.constants.keys())) {
            if !present.contains(&c.as_str()) {
                present.push(c);
            }
        }
        return Err(a.err(format!("the field has no component {} (it has {})", comps.join(" "), present.join(" "))));
    }
    Ok(vec![Value::Mchaml(Rc::new(out))])
}

fn exco(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    // An MCHAML or a CHPOINT, whichever comes first.
    let ch = match a.opt_with(|v| match v {
        Value::Mchaml(m) => Some(Err(m.clone())),
        Value::Chpo(c) => Some(Ok(c.clone())),
        _ => None,
    }) {
        Some(Ok(c)) => c,
        Some(Err(m)) => return exco_mchaml(a, &m),
        None => return Err(a.missing("CHPOINT or MCHAML")),
    };
    let comps = comp_list(a).ok_or_else(|| a.missing("a component"))?;
    let noid = a.keyword(&["NOID"]).is_some();
    let new = comp_list(a);
    let names: Vec<String> = match &new {
        Some(n) if n.len() == comps.len() => n.clone(),
        Some(_) => return Err(a.err("as many new names as components are needed")),
        None if comps.len() == 1 => vec!["SCAL".into()],
        None => comps.clone(),
    };
    a.keyword(&["NATU"]).map(|_| a.word());
    let present = ch.components();
    if !noid {
        if let Some(c) = comps.iter().find(|c| !present.contains(c)) {
            return Err(a.err(format!("the field has no component {} (it has {})", c, present.join(" "))));
        }
    }
    let mut out = Chpoint::new(ch.nature);
    for (n, c, v) in ch.entries() {
        if let Some(i) = comps.iter().position(|x| x == c) {
            out.add(n, &names[i], v, false);
        }
    }
    Ok(vec![Value::Chpo(Rc::new(out))])
}

fn nomc(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if let Some(m) = a.opt::<Rc<Mchaml>>() {
        return super::nomc_mchaml::nomc(a, &m);
    }
    let ch = a.req_find::<Rc<Chpoint>>()?;
    let first = comp_list(a).ok_or_else(|| a.missing("new component names"))?;
    // A second list is read before 'NATU' (which may come after it).
    let second = a.opt::<Rc<Vec<String>>>().map(|l| l.to_vec());
    let mut nature = nature_word(a)?;
    let (old, new) = match second.or_else(|| comp_list(a).filter(|_| nature.is_none())) {
        Some(second) => (first, second),
        None => (ch.components(), first),
    };
    nature = nature.or(nature_word(a)?);
    // Component names are 4 characters, trailing blanks dropped ('H2  ').
    let new: Vec<String> = new.iter().map(|c| c.trim_end().to_string()).collect();
    if old.len() != new.len() {
        return Err(a.err(format!("{} component(s) to rename with {} name(s)", old.len(), new.len())));
    }
    // Names of the first list that the field lacks rename nothing (a
    // procedure renames whichever of a set of components a field has).
    let mut out = Chpoint::new(nature.unwrap_or(ch.nature));
    for (n, c, v) in ch.entries() {
        let name = old.iter().position(|x| x == c).map_or(c, |i| new[i].as_str());
        out.add(n, name, v, false);
    }
    Ok(vec![Value::Chpo(Rc::new(out))])
}

/// NOMC's `'NATU' 'INDETER'|'DIFFUS'|'DISCRET'`, if written.
pub(crate) fn nature_word(a: &mut Args) -> Result<Option<Nature>> {
    if a.keyword(&["NATU"]).is_none() {
        return Ok(None);
    }
    Ok(Some(match a.req_keyword(&["INDETER", "DIFFUS", "DISCRET"])? {
        "DIFFUS" => Nature::Diffus,
        "DISCRET" => Nature::Discret,
        _ => Nature::Indeter,
    }))
}

/// `ENLE CHPOINT COMP|LISTMOTS`: the field without those components.
pub(crate) fn enle_components(a: &mut Args, ch: &Chpoint) -> Result<Vec<Value>> {
    let comps = comp_list(a).ok_or_else(|| a.missing("components to remove"))?;
    let out = Chpoint::from_entries(ch.nature, ch.entries().filter(|(_, c, _)| !comps.iter().any(|x| x == c)));
    Ok(vec![Value::Chpo(Rc::new(out))])
}

fn xtmx(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let r = a.req::<Rc<Rigidite>>()?;
    let u = a.req::<Rc<Chpoint>>()?;
    let ku = r.matvec(&u);
    // Each unknown against the force (dual) component of K u.
    let s: f64 = u.entries().map(|(n, c, v)| v * ku.get(n, &dofs::dual_of(c)).unwrap_or(0.0)).sum();
    Ok(vec![Value::Float(s)])
}

fn xtx(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let ch = a.req::<Rc<Chpoint>>()?;
    Ok(vec![Value::Float(ch.entries().map(|(_, _, v)| v * v).sum())])
}

fn somt(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if let Some(l) = a.opt::<Rc<Vec<f64>>>() {
        return Ok(vec![Value::Float(l.iter().sum())]);
    }
    let ch = a.req::<Rc<Chpoint>>()?;
    Ok(vec![Value::Float(ch.entries().map(|(_, _, v)| v).sum())])
}

/// Cast3M's DEFORMEE, kept as a MAILLAGE whose nodes are moved copies.
fn defo(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    // The field may come before the mesh (`DEFO u s`, as ANIME writes it).
    let first = a.opt::<Rc<Chpoint>>();
    let geo = req_geo(a)?;
    let u = match first {
        Some(u) => u,
        None => a.req::<Rc<Chpoint>>()?,
    };
    let scale = a.opt_num().unwrap_or(1.0);
    let moved = super::mesh::moved_by_field(it, &geo, &u, scale);
    // Then, in any order: arrows to draw on the deformed mesh (VECT), a
    // scalar field to colour it with (a CHPOINT, or an MCHAML and its
    // model), a colour word. gibi draws neither arrows nor that field;
    // other words (blank texts ANIME builds) are Cast3M's drawing options.
    let mut colour = None;
    loop {
        let extra = a.opt_with(|v| match v {
            Value::Host(h) if h.type_name() == "VECTEUR" => Some(()),
            Value::Chpo(_) | Value::Mchaml(_) | Value::Model(_) => Some(()),
            _ => None,
        });
        if extra.is_some() {
            continue;
        }
        match a.word_not_operator() {
            Some(w) => {
                if let Some(c) = crate::fem::mesh::Colour::from_name(w.trim()) {
                    colour = Some(c);
                }
            }
            None => break,
        }
    }
    let moved = match colour {
        Some(c) => moved.coloured(c),
        None => moved,
    };
    Ok(vec![Value::Mesh(Rc::new(moved))])
}

fn resu(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if let Some(m) = a.opt::<Rc<Mchaml>>() {
        let r = m.resultant().ok_or_else(|| a.err("the field is empty"))?;
        return Ok(vec![Value::Mchaml(Rc::new(r))]);
    }
    let ch = a.req::<Rc<Chpoint>>()?;
    let first = *ch.nodes.first().ok_or_else(|| a.err("the field is empty"))?;
    let mut out = Chpoint::new(Nature::Discret);
    for (_, c, v) in ch.entries() {
        out.add(first, c, v, true);
    }
    Ok(vec![Value::Chpo(Rc::new(out))])
}

/// MAXI/MINI of a field ('ABS', 'AVEC'/'SANS' components).
pub(crate) fn extremum(a: &mut Args, max: bool, use_abs: bool) -> Result<Option<Value>> {
    let vals: Vec<f64> = if let Some(ch) = a.opt::<Rc<Chpoint>>() {
        let filter = match a.keyword(&["AVEC", "SANS"]) {
            Some(k) => Some((k == "AVEC", comp_list(a).ok_or_else(|| a.missing("components"))?)),
            None => None,
        };
        let use_abs = use_abs || a.keyword(&["ABS"]).is_some();
        ch.entries()
            .filter(|(_, c, _)| match &filter {
                Some((avec, l)) => l.iter().any(|x| x == c) == *avec,
                None => true,
            })
            .map(|(_, _, v)| if use_abs { v.abs() } else { v })
            .collect()
    } else if let Some(m) = a.opt::<Rc<Mchaml>>() {
        let filter = match a.keyword(&["AVEC", "SANS"]) {
            Some(k) => Some((k == "AVEC", comp_list(a).ok_or_else(|| a.missing("components"))?)),
            None => None,
        };
        let use_abs = use_abs || a.keyword(&["ABS"]).is_some();
        let mut out = Vec::new();
        for z in &m.zones {
            let keep: Vec<bool> = z
                .comps
                .iter()
                .map(|c| filter.as_ref().is_none_or(|(avec, l)| l.iter().any(|x| x == c) == *avec))
                .collect();
            for p in z.values.iter().flatten() {
                out.extend(p.iter().zip(&keep).filter(|(_, k)| **k).map(|(v, _)| if use_abs { v.abs() } else { *v }));
            }
            // Material data (MATE) are constants of the zone: values too.
            let kept = |c: &String| filter.as_ref().is_none_or(|(avec, l)| l.iter().any(|x| x == c) == *avec);
            out.extend(z.constants.iter().filter(|(c, _)| kept(c)).map(|(_, v)| if use_abs { v.abs() } else { *v }));
        }
        out
    } else {
        return Ok(None);
    };
    let r = vals.into_iter().reduce(|p, q| if max { p.max(q) } else { p.min(q) });
    r.map(|v| Some(Value::Float(v))).ok_or_else(|| a.err("the field is empty"))
}

/// EXTR on an element field: `'COMP'` (the component names), `'MAIL'`
/// (the mesh it lies on), or one value `COMP (zone (element (point)))`.
pub(crate) fn extr_mchaml(it: &mut Interp, a: &mut Args, m: &Mchaml) -> Result<Vec<Value>> {
    if a.keyword_next(&["MAIL"]).is_some() {
        let mesh = m.zones.iter().fold(Mesh::default(), |acc, z| acc.union(&z.mesh));
        return Ok(vec![Value::Mesh(Rc::new(mesh))]);
    }
    if a.keyword_next(&["COMP"]).is_some() {
        // The component names, every zone's, each once.
        let mut names: Vec<String> = Vec::new();
        for z in &m.zones {
            for c in z.comps.iter().chain(z.constants.keys()).chain(z.objects.keys()) {
                if !names.contains(c) {
                    names.push(c.clone());
                }
            }
        }
        return Ok(vec![Value::ListMots(Rc::new(names))]);
    }
    // A vector property (CARA/MATE 'VECT') is one component whose value is
    // a POINT. Its name is also an operator's (VECT), so it is matched
    // before words are read as component names.
    let has_vector = m.zones.iter().any(|z| z.vectors.contains_key("VECT"));
    let vector = if has_vector { a.keyword_next(&["VECT"]) } else { None };
    // The component may also follow the zone, element and point numbers
    // (Cast3M reads the arguments by type).
    let comp = if vector.is_some() { None } else { a.word_not_operator() };
    let mut idx = [1i64; 3];
    for k in idx.iter_mut() {
        match a.opt::<i64>() {
            Some(v) => *k = v,
            None => break,
        }
    }
    let z = m.zones.get((idx[0] - 1).max(0) as usize).ok_or_else(|| a.err(format!("no zone {}", idx[0])))?;
    if let Some(name) = vector {
        let v = *z.vectors.get(name).ok_or_else(|| a.err(format!("zone {} has no vector {}", idx[0], name)))?;
        return Ok(vec![Value::Point(it.nodes.push(v, 0.0))]);
    }
    let comp = comp.or_else(|| a.word_not_operator()).ok_or_else(|| a.missing("a component"))?;
    if let Some(v) = z.constants.get(&comp) {
        return Ok(vec![Value::Float(*v)]);
    }
    if let Some(v) = z.objects.get(&comp) {
        return Ok(vec![v.clone()]);
    }
    let c = z
        .comps
        .iter()
        .position(|x| *x == comp)
        .ok_or_else(|| a.err(format!("the field has no component {} (it has {})", comp, z.comps.join(" "))))?;
    let e = z.values.get((idx[1] - 1).max(0) as usize).ok_or_else(|| a.err(format!("no element {}", idx[1])))?;
    let p = e.get((idx[2] - 1).max(0) as usize).ok_or_else(|| a.err(format!("no point {}", idx[2])))?;
    Ok(vec![Value::Float(p[c])])
}

/// EXTR on a model: its mesh (`'MAIL'`), or the model of the zones of
/// some formulations, elements or behaviour words (`'FORM' 'MECANIQUE'`, `'ELEM' 'QUA4'`, `'COMP' 'PRESSION'`).
pub(crate) fn extr_model(a: &mut Args, m: &Model) -> Result<Vec<Value>> {
    if let Some(v) = super::model_zones::extr_zones(a, m) {
        return Ok(vec![v]);
    }
    if let Some((key, words)) = zone_selection(a, "COMP")? {
        return Ok(vec![Value::Model(Rc::new(m.zones_with(key, &words)))]);
    }
    if let Some(k) = a.keyword(&["DEPL", "FORC"]) {
        return Ok(vec![Value::ListMots(Rc::new(model_components(a, m, k == "FORC")?))]);
    }
    a.keyword(&["MAIL"]);
    let mut mesh = Mesh::default();
    for z in &m.zones {
        mesh = mesh.union(&z.mesh);
    }
    Ok(vec![Value::Mesh(Rc::new(mesh))])
}

/// The displacement (or force) component names of a model's mechanical
/// zones, each name once, in the order the zones give them.
fn model_components(a: &Args, m: &Model, forces: bool) -> Result<Vec<String>> {
    use crate::fem::element::{node_dofs, node_duals};
    let mut out: Vec<String> = Vec::new();
    for z in m.zones.iter().filter(|z| !z.formulation.starts_with("CONT")) {
        let (f, mode) = (super::model::formulation(z), super::model::zone_mode(z)?);
        let names = if forces { node_duals(f, mode) } else { node_dofs(f, mode) };
        for n in names.map_err(|e| a.err(e))? {
            if !out.iter().any(|o| o == n) {
                out.push(n.to_string());
            }
        }
    }
    Ok(out)
}

/// `'FORM' MOT1 (MOT2 …)`, `'ELEM' MOT1 …` or the behaviour keyword and words after a model (EXTR, EXIS).
/// `behaviour` is the keyword that selects by a behaviour word: EXIS says
/// 'MATE', EXTR 'COMP' (its 'MATE' lists material component names).
pub(crate) fn zone_selection(a: &mut Args, behaviour: &'static str) -> Result<Option<(ZoneKey, Vec<String>)>> {
    let key = match a.keyword(&["FORM", "ELEM", behaviour]) {
        Some("FORM") => ZoneKey::Formulation,
        Some("ELEM") => ZoneKey::Element,
        Some(_) => ZoneKey::Behaviour,
        None => return Ok(None),
    };
    let mut words = Vec::new();
    while let Some(w) = a.opt::<String>() {
        words.push(w);
    }
    if words.is_empty() {
        return Err(a.missing("a formulation or element name (MOT)"));
    }
    Ok(Some((key, words)))
}

pub(crate) fn extr_chpo(it: &Interp, a: &mut Args, ch: &Chpoint) -> Result<Vec<Value>> {
    if let Some(k) = a.keyword(&["MAIL", "VALE", "COMP", "NATU"]) {
        return Ok(vec![match k {
            "MAIL" => {
                let nomu = a.keyword(&["NOMU"]).is_some();
                let nodes: Vec<usize> = ch
                    .nodes
                    .iter()
                    .copied()
                    .filter(|n| !nomu || ch.get(*n, "LX").is_none() && ch.get(*n, "FLX").is_none())
                    .collect();
                Value::Mesh(Rc::new(Mesh::points(&nodes)))
            }
            "VALE" => {
                // Without a component, the field's only one.
                let comp = match a.word_not_operator() {
                    Some(c) => c,
                    None => match ch.components().as_slice() {
                        [c] => c.clone(),
                        cs => return Err(a.err(format!("say which component (the field has {})", cs.join(" ")))),
                    },
                };
                let geo = super::mesh::opt_geo(a);
                let nodes = geo.map_or_else(|| ch.nodes.clone(), |g| g.node_list());
                Value::ListReel(Rc::new(nodes.iter().filter_map(|n| ch.get(*n, &comp)).collect()))
            }
            "COMP" => Value::ListMots(Rc::new(ch.components())),
            _ => Value::mot(ch.nature.name()),
        }]);
    }
    let comp = a.word_not_operator();
    let p = a.req::<PointId>()?;
    let comp = match comp.or_else(|| a.word_not_operator()) {
        Some(c) => c,
        None => {
            let cs = ch.components();
            if cs.len() != 1 {
                return Err(a.missing("a component"));
            }
            cs[0].clone()
        }
    };
    // LX is absent when every condition is inactive: it reads as 0 like
    // any multiplier of an inactive condition. Other missing components
    // are more likely typing errors.
    if comp != "LX" && !ch.components().contains(&comp) {
        return Err(a.err(format!("the field has no component {} (it has {})", comp, ch.components().join(" "))));
    }
    // A node field is zero where it is not defined (aaa2.notice): an
    // inactive unilateral condition has no LX, which reads as 0.
    let v = ch.get(p.0, &comp).or_else(|| {
        let x = it.nodes.get(p.0);
        ch.nodes.iter().find(|n| it.nodes.get(**n) == x).and_then(|n| ch.get(*n, &comp))
    });
    Ok(vec![Value::Float(v.unwrap_or(0.0))])
}

pub(crate) fn extr_rigi(a: &mut Args, r: &Rigidite) -> Result<Vec<Value>> {
    match a.req_keyword(&["MAIL", "COMP", "DIAG", "CONT", "RIGI"])? {
        // The elementary matrices without the conditions, or the
        // conditions alone (extr.notice).
        "RIGI" => {
            let mult = a.req_keyword(&["NOMU", "MULT"])? == "MULT";
            let mut out = Rigidite::new(r.subtype);
            if mult {
                out.subtype = crate::value::rigidity::Subtype::Blocage;
                out.conds = r.conds.clone();
            } else {
                out.blocks = r.blocks.clone();
            }
            Ok(vec![Value::Rigi(Rc::new(out))])
        }
        // The unilateral solver's table of the last RESO/UNIL of this
        // object (the TABLE UNIL returns).
        "CONT" => match &r.cache.borrow().last_unil {
            Some((report, statuses)) => Ok(vec![super::reso::diagnostics(report, statuses)]),
            // No unilateral condition: nothing to report (DYNAMIC asks
            // every RIGIDITE whether it has contacts).
            None if r.n_unilateral() == 0 => {
                Ok(vec![Value::Table(Rc::new(std::cell::RefCell::new(crate::value::Table::new())))])
            }
            None => Err(a.err("this RIGIDITE has not been through a unilateral RESO or UNIL yet: no contact table")),
        },
        "MAIL" => {
            let nodes: Vec<usize> = match a.keyword(&["NOMU", "MULT", "UNIL"]) {
                Some("NOMU") => r.physical_nodes(),
                Some("MULT") => r.multiplier_nodes(false),
                Some(_) => r.multiplier_nodes(true),
                None => r.physical_nodes().into_iter().chain(r.multiplier_nodes(false)).collect(),
            };
            Ok(vec![Value::Mesh(Rc::new(Mesh::points(&nodes)))])
        }
        "COMP" => Ok(vec![Value::ListMots(Rc::new(r.component_names()))]),
        _ => Ok(vec![Value::Chpo(Rc::new(r.diagonal()))]),
    }
}
