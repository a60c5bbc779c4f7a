//! Conditions: BLOQ, RELA, DEPI. Each condition is a row `Σ c·u ⋈ d`
//! carried by its own multiplier node (`LX`), as in Cast3M; the limit `d`
//! comes with the right-hand side as the `FLX` of that node (DEPI).

use super::mesh::{opt_geo, req_geo};
use super::{dofs, Args, OpDef, PointId};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::solve::Kind;
use crate::value::rigidity::{CondRow, Subtype};
use crate::value::{Chpoint, Nature, Rigidite, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "BLOQ",
        signature: "BLOQ ('MINI'|'MAXI') (comps|LISTMOTS|'DEPL'|'ROTA'|'DIRECTION' VEC|'RADIAL' P1|'ORTHO' P1) GEO",
        doc: "Block unknowns of a point or mesh: one condition per node and component (MINI: u >= d, MAXI: u <= d).",
        example: "cl = bloq 'UX' 'UY' p1 ;",
        f: bloq,
    },
    OpDef {
        name: "RELA",
        signature: "RELA ('MINI'|'MAXI') (c1) comp1 GEO1 (+|-) (c2) comp2 GEO2 … | RELA ('MINI'|'MAXI') CHPOINT ('DUAL' CHPOINT) | RELA 'ENSE' comp… GEO | RELA 'MILI' (LISTMOTS) GEO | RELA 'CORI' 'DEPL' 'ROTA' GEO1 (GEO2) | RELA GEO1 'ACCRO' GEO2 (LISTMOTS) (FLOT) | RELA MMODEL",
        doc: "Linear relations between unknowns, node by node (MINI: >= d, MAXI: <= d). From a field, one relation whose coefficients are the field's values; 'DUAL' gives a non-associated reaction direction (the system is then solved as non-symmetric). 'ENSE': each listed component takes one common value on all the nodes. 'MILI': mid-side nodes of quadratic elements follow the mean of their edge's vertices (default: the displacements). 'CORI' 'DEPL' 'ROTA': the nodes of GEO1 (with rotations) and GEO2 move as one rigid body with GEO1's first node. GEO1 'ACCRO' GEO2: each node of GEO1 inside an element of GEO2 follows the interpolation of that element's nodes. Of a model: each relation element (MULT, from RAFF) of its meshes ties its hanging node to the side it lies on.",
        example: "r = rela 'MINI' 1. 'UX' pb - 1. 'UX' pa ;",
        f: rela,
    },
    OpDef {
        name: "DEPI",
        signature: "DEPI RIGIDITE (FLOT|CHPOINT)",
        doc: "Imposed values (limits) of conditions, as the FLX field to add to the right-hand side.",
        example: "d = depi cl 0.3 ;",
        f: depi,
    },
];

fn kind_keyword(a: &mut Args) -> Kind {
    match a.keyword(&["MINI", "MAXI"]) {
        Some("MINI") => Kind::Mini,
        Some("MAXI") => Kind::Maxi,
        _ => Kind::Equal,
    }
}

/// A new multiplier node at the position of a physical node (Cast3M puts
/// the LX node on the node it blocks).
pub(super) fn mult_node(it: &mut Interp, at: usize) -> usize {
    let x = it.nodes.get(at);
    let d = it.nodes.density[at];
    it.nodes.push(x, d)
}

enum Direction {
    Comps(Vec<String>),
    Vector([f64; 3]),
    Radial([f64; 3], bool),
}

fn bloq(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mut kind = kind_keyword(a);
    let mut comps: Vec<String> = Vec::new();
    let mut dir: Option<Direction> = None;
    let mut geo: Option<Mesh> = None;
    loop {
        // 'MINI'/'MAXI' after the components (`BLOQ 'UY' 'MINI' l`) is the
        // same condition, not a component named MINI.
        if let Some(k) = a.keyword(&["MINI", "MAXI"]) {
            let k = if k == "MINI" { Kind::Mini } else { Kind::Maxi };
            if kind != Kind::Equal && kind != k {
                return Err(a.err("a condition is either 'MINI' or 'MAXI', not both"));
            }
            kind = k;
            continue;
        }
        if let Some(k) = a.keyword(&["DEPL", "ROTA", "DIRECTION", "RADIAL", "ORTHO", "FROT"]) {
            match k {
                "DEPL" => comps.extend(dofs::translations(it).iter().map(|s| s.to_string())),
                "ROTA" => comps.extend(dofs::rotations(it).iter().map(|s| s.to_string())),
                "DIRECTION" => {
                    let v = a.req::<PointId>()?;
                    dir = Some(Direction::Vector(it.nodes.get(v.0)));
                }
                "RADIAL" | "ORTHO" => {
                    let p = a.req::<PointId>()?;
                    dir = Some(Direction::Radial(it.nodes.get(p.0), k == "ORTHO"));
                }
                _ => return Err(a.err("friction conditions ('FROT') are not supported")),
            }
            continue;
        }
        if let Some(l) = a.opt_right::<Rc<Vec<String>>>() {
            comps.extend(l.iter().cloned());
            continue;
        }
        if geo.is_none() {
            if let Some(g) = opt_geo(a) {
                geo = Some(g);
                continue;
            }
        }
        match a.word_not_operator() {
            Some(w) => comps.push(w),
            None => break,
        }
    }
    let geo = geo.ok_or_else(|| a.missing("POINT or MAILLAGE"))?;
    let dir = match dir {
        Some(d) => d,
        None if comps.is_empty() => return Err(a.missing("components to block")),
        None => Direction::Comps(comps),
    };
    let mut rig = Rigidite::new(Subtype::Blocage);
    for n in geo.node_list() {
        match &dir {
            Direction::Comps(cs) => {
                for c in cs {
                    let m = mult_node(it, n);
                    rig.conds.push(CondRow::new(m, vec![(n, c.clone(), 1.0)], kind));
                }
            }
            Direction::Vector(v) => {
                let terms = direction_terms(it, n, *v).map_err(|e| a.err(e))?;
                let m = mult_node(it, n);
                rig.conds.push(CondRow::new(m, terms, kind));
            }
            Direction::Radial(c, ortho) => {
                let x = it.nodes.get(n);
                let mut v = [x[0] - c[0], x[1] - c[1], x[2] - c[2]];
                if *ortho {
                    v = [-v[1], v[0], 0.0];
                }
                let terms = direction_terms(it, n, v).map_err(|e| a.err(format!("node {}: {}", n + 1, e)))?;
                let m = mult_node(it, n);
                rig.conds.push(CondRow::new(m, terms, kind));
            }
        }
    }
    Ok(vec![Value::Rigi(Rc::new(rig))])
}

/// `n·u` over the translations of the mode, with n normalised.
fn direction_terms(it: &Interp, node: usize, v: [f64; 3]) -> std::result::Result<Vec<(usize, String, f64)>, String> {
    let t = dofs::translations(it);
    let norm = v[..t.len()].iter().map(|x| x * x).sum::<f64>().sqrt();
    if norm == 0.0 {
        return Err("the direction is a zero vector".into());
    }
    Ok(t.iter().enumerate().filter(|(k, _)| v[*k] != 0.0).map(|(k, c)| (node, c.to_string(), v[k] / norm)).collect())
}

/// The non-zero values of a field as relation terms over primal unknowns.
fn field_terms(ch: &Chpoint) -> Vec<(usize, String, f64)> {
    ch.entries().filter(|e| e.2 != 0.0).map(|(n, c, v)| (n, c.to_string(), v)).collect()
}

/// One written term of RELA: coefficient, weighted components, nodes.
type RelaTerm = (f64, Vec<(String, f64)>, Vec<usize>);

fn rela(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let kind = kind_keyword(a);
    if a.keyword(&["ENSE"]).is_some() {
        return rela_ense(it, a, kind);
    }
    if a.keyword(&["MILI"]).is_some() {
        return super::rela_mili::rela_mili(it, a, kind);
    }
    if a.keyword(&["CORI"]).is_some() {
        return super::rela_cori::rela_cori(it, a, kind);
    }
    if let Some(m) = a.opt::<Rc<crate::value::Model>>() {
        return super::rela_model::rela_model(it, a, kind, &m);
    }
    if let Some(Value::Mesh(g1)) = a.peek_right() {
        let taken = a.right_any();
        if a.keyword_next(&["ACCRO"]).is_some() {
            return super::rela_accro::rela_accro(it, a, kind, &g1);
        }
        a.unread(taken.expect("the value just peeked"));
    }
    if let Some(ch) = a.opt::<Rc<Chpoint>>() {
        let terms = field_terms(&ch);
        let first = terms.first().map(|t| t.0).ok_or_else(|| a.err("the field is empty"))?;
        // 'DUAL' CHPO2: a non-associated reaction direction (rela.notice
        // 2024); the relation itself stays the one of the first field.
        let dual = match a.keyword(&["DUAL"]) {
            Some(_) => {
                let d = field_terms(&*a.req::<Rc<Chpoint>>()?);
                if d.is_empty() {
                    return Err(a.err("the DUAL field is empty"));
                }
                Some(d)
            }
            None => None,
        };
        let m = mult_node(it, first);
        let mut rig = Rigidite::new(Subtype::Blocage);
        rig.conds.push(CondRow { mult_node: m, terms, kind, dual });
        return Ok(vec![Value::Rigi(Rc::new(rig))]);
    }
    // Terms: (sign) (coef) comp geo, repeated.
    let mut terms: Vec<RelaTerm> = Vec::new();
    loop {
        let sign = a.sign();
        if sign.is_none() && !terms.is_empty() {
            break;
        }
        let sign = sign.unwrap_or(1.0);
        let coef = a.opt_num_right().unwrap_or(1.0) * sign;
        let comps: Vec<(String, f64)> = if let Some(k) = a.keyword(&["DEPL", "ROTA"]) {
            a.req_keyword(&["DIRECTION"])?;
            let v = a.req::<PointId>()?;
            let names = if k == "DEPL" { dofs::translations(it) } else { dofs::rotations(it) };
            let x = it.nodes.get(v.0);
            let norm = x[..names.len()].iter().map(|c| c * c).sum::<f64>().sqrt().max(f64::MIN_POSITIVE);
            names.iter().enumerate().map(|(i, c)| (c.to_string(), x[i] / norm)).collect()
        } else {
            vec![(a.word_not_operator().ok_or_else(|| a.missing("a component name"))?, 1.0)]
        };
        let geo = req_geo(a)?;
        terms.push((coef, comps, geo.node_list()));
    }
    let n = terms.iter().map(|t| t.2.len()).max().unwrap_or(0);
    if let Some(t) = terms.iter().find(|t| t.2.len() != n && t.2.len() != 1) {
        return Err(a.err(format!(
            "the meshes of a relation must have the same number of nodes or a single node ({} and {})",
            n,
            t.2.len()
        )));
    }
    let mut rig = Rigidite::new(Subtype::Blocage);
    for k in 0..n {
        let mut row: Vec<(usize, String, f64)> = Vec::new();
        for (coef, comps, nodes) in &terms {
            let node = if nodes.len() == 1 { nodes[0] } else { nodes[k] };
            for (c, w) in comps {
                if w.abs() > 0.0 {
                    row.push((node, c.clone(), coef * w));
                }
            }
        }
        let m = mult_node(it, row[0].0);
        rig.conds.push(CondRow::new(m, row, kind));
    }
    Ok(vec![Value::Rigi(Rc::new(rig))])
}

/// `RELA 'ENSE' comp… GEO`: every node of GEO moves as its first node on
/// the listed components (u_first - u_i = 0, one row per node and
/// component).
fn rela_ense(it: &mut Interp, a: &mut Args, kind: Kind) -> Result<Vec<Value>> {
    let mut comps = Vec::new();
    while let Some(c) = a.word_not_operator() {
        comps.push(c.to_uppercase());
    }
    if comps.is_empty() {
        return Err(a.missing("a component name"));
    }
    let nodes = req_geo(a)?.node_list();
    let mut rig = Rigidite::new(Subtype::Blocage);
    for c in &comps {
        for &n in nodes.iter().skip(1) {
            let row = vec![(nodes[0], c.clone(), 1.0), (n, c.clone(), -1.0)];
            let m = mult_node(it, nodes[0]);
            rig.conds.push(CondRow::new(m, row, kind));
        }
    }
    Ok(vec![Value::Rigi(Rc::new(rig))])
}

fn depi(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let rig = a.req::<Rc<Rigidite>>()?;
    let mut out = Chpoint::new(Nature::Discret);
    if let Some(ch) = a.opt::<Rc<Chpoint>>() {
        for c in &rig.conds {
            if let [(node, comp, coef)] = c.terms.as_slice() {
                if let Some(v) = ch.get(*node, comp) {
                    out.add(c.mult_node, "FLX", v * coef, true);
                }
            } else {
                return Err(
                    a.err("per-node values apply to single-unknown conditions (BLOQ); give a number for relations")
                );
            }
        }
    } else {
        let v = a.opt_num().unwrap_or(0.0);
        for c in &rig.conds {
            out.add(c.mult_node, "FLX", v, true);
        }
    }
    if rig.conds.is_empty() {
        return Err(a.err("this RIGIDITE holds no condition"));
    }
    Ok(vec![Value::Chpo(Rc::new(out))])
}
