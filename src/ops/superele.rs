//! SUPER: static condensation (Guyan super-elements) by the same
//! interrupted factorisation RESO uses (`solve::bilateral::schur::schur_onto`).
//! The SUPERELE type is a host object: it shows how new object types plug
//! in without touching the evaluator.

use super::assemble::{self, explain, solution_field, Assembled};
use super::{dofs, Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::solve::bilateral::schur::{schur_onto, SchurOnto};
use crate::value::rigidity::{Block, Subtype, Symmetry};
use crate::value::{Chpoint, HostObject, Nature, Rigidite, Value};
use std::any::Any;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "SUPE",
    signature: "SUPER 'RIGIDITE' ('NOMU') RIGIDITE GEO|RIGIDITE|CHPOINT | SUPER 'CHARGE' SUPERELE CHPOINT | SUPER 'DEPLACEMENT' SUPERELE CHPOINT (CHPOINT) | SUPER 'MASSE' SUPERELE RIGIDITE ('LCHP')",
    doc: "Static condensation onto master unknowns (from a mesh, the unknowns of a rigidity, or a field): condensed stiffness (EXTR SUP 'RIGI'), condensed load, expansion of master displacements, reduced mass (with 'LCHP', first the static modes as a LISTCHPO).",
    example: "sup = super 'RIGIDITE' k interface ; kc = extr sup 'RIGI' ;",
    f: supe,
}];

/// A super-element: the condensed operator and how to expand it.
pub struct SuperElem {
    asm: Assembled,
    schur: SchurOnto,
    /// Master unknowns (node, component), in the order of the condensed matrix.
    masters: Vec<(usize, String)>,
}

impl std::fmt::Debug for SuperElem {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "SUPERELE over {} master unknown(s)", self.masters.len())
    }
}

impl HostObject for SuperElem {
    fn type_name(&self) -> &str {
        "SUPERELE"
    }
    fn as_any(&self) -> &dyn Any {
        self
    }
}

fn as_super(v: &Value) -> Option<&SuperElem> {
    match v {
        Value::Host(h) => h.as_any().downcast_ref::<SuperElem>(),
        _ => None,
    }
}

fn req_super(a: &mut Args) -> Result<Rc<dyn HostObject>> {
    let v = a.req::<Value>()?;
    match &v {
        Value::Host(h) if as_super(&v).is_some() => Ok(h.clone()),
        other => Err(a.err(format!("expected SUPERELE, found {}", other.type_name()))),
    }
}

fn supe(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    match a.req_keyword(&["RIGIDITE", "CHARGE", "DEPLACEMENT", "MASSE"])? {
        "RIGIDITE" => build(it, a),
        "CHARGE" => {
            let h = req_super(a)?;
            let s = h.as_any().downcast_ref::<SuperElem>().expect("checked");
            let f = a.req::<Rc<Chpoint>>()?;
            let load = assemble::load(it, &s.asm, &[&f]).map_err(|e| a.err(e.message))?;
            let fc = s.schur.load(&load);
            let mut out = Chpoint::new(Nature::Discret);
            for ((n, c), v) in s.masters.iter().zip(fc) {
                out.add(*n, &dofs::dual_of(c), v, true);
            }
            Ok(vec![Value::Chpo(Rc::new(out))])
        }
        "DEPLACEMENT" => {
            let h = req_super(a)?;
            let s = h.as_any().downcast_ref::<SuperElem>().expect("checked");
            let um = a.req::<Rc<Chpoint>>()?;
            let load = match a.opt::<Rc<Chpoint>>() {
                Some(f) => assemble::load(it, &s.asm, &[&f]).map_err(|e| a.err(e.message))?,
                None => assemble::load(it, &s.asm, &[]).map_err(|e| a.err(e.message))?,
            };
            let tail: Vec<f64> = s.masters.iter().map(|(n, c)| um.get(*n, c).unwrap_or(0.0)).collect();
            let sol = s.schur.expand(&load, &tail);
            Ok(vec![Value::Chpo(Rc::new(solution_field(&s.asm, &sol)))])
        }
        _ => masse(it, a),
    }
}

/// SUPER 'MASSE': the Guyan reduced mass Tᵀ M T, T holding the static
/// modes (the expansion of a unit value of each master with no load). With
/// 'LCHP' the static modes come first, as a LISTCHPO.
fn masse(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let h = req_super(a)?;
    let s = h.as_any().downcast_ref::<SuperElem>().expect("checked");
    let m = a.req::<Rc<Rigidite>>()?;
    let with_modes = a.keyword(&["LCHP"]).is_some();
    let load = assemble::load(it, &s.asm, &[]).map_err(|e| a.err(e.message))?;
    let d = s.masters.len();
    let modes: Vec<Rc<Chpoint>> = (0..d)
        .map(|j| {
            let tail: Vec<f64> = (0..d).map(|i| if i == j { 1.0 } else { 0.0 }).collect();
            Rc::new(solution_field(&s.asm, &s.schur.expand(&load, &tail)))
        })
        .collect();
    let mut mats = vec![0.0; d * d];
    for i in 0..d {
        for j in i..d {
            let v = quadratic(&m, &modes[i], &modes[j]);
            mats[i * d + j] = v;
            mats[j * d + i] = v;
        }
    }
    let mass = Value::Rigi(Rc::new(condensed(s, Subtype::Masse, mats)));
    Ok(if with_modes { vec![Value::ListChpo(Rc::new(modes)), mass] } else { vec![mass] })
}

/// uᵀ M v over the element blocks of M (a mass carries no conditions).
fn quadratic(m: &Rigidite, u: &Chpoint, v: &Chpoint) -> f64 {
    let mut sum = 0.0;
    for b in &m.blocks {
        let nd = b.ndof();
        for e in 0..b.n_elem() {
            let conn = &b.conn[e * b.nodes_per_elem..(e + 1) * b.nodes_per_elem];
            let k = b.mat(e);
            let at = |f: &Chpoint, i: usize| f.get(conn[b.dofs[i].0], &b.dofs[i].1).unwrap_or(0.0);
            for i in 0..nd {
                let ui = at(u, i);
                if ui != 0.0 {
                    sum += ui * (0..nd).map(|j| k[i * nd + j] * at(v, j)).sum::<f64>();
                }
            }
        }
    }
    sum
}

/// A dense matrix over the masters of a super-element, as one block.
fn condensed(s: &SuperElem, subtype: Subtype, mats: Vec<f64>) -> Rigidite {
    let mut nodes: Vec<usize> = Vec::new();
    for (n, _) in &s.masters {
        if !nodes.contains(n) {
            nodes.push(*n);
        }
    }
    let mut rig = Rigidite::new(subtype);
    rig.blocks.push(Block {
        nodes_per_elem: nodes.len(),
        conn: nodes.clone(),
        dofs: s.masters.iter().map(|(n, c)| (nodes.iter().position(|x| x == n).unwrap_or(0), c.clone())).collect(),
        duals: s.masters.iter().map(|(_, c)| dofs::dual_of(c)).collect(),
        mats,
        symmetry: Symmetry::Symmetric,
    });
    rig
}

fn build(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    a.keyword(&["NOMU"]);
    let r = a.req::<Rc<Rigidite>>()?;
    let asm = r.number();
    // Masters: every unknown of the rigidity at the nodes of a mesh, the
    // unknowns of a second rigidity, or the (node, component) of a field.
    let wanted: Vec<(usize, String)> = if let Some(r2) = a.opt::<Rc<Rigidite>>() {
        r2.number().dofs
    } else if let Some(ch) = a.opt::<Rc<Chpoint>>() {
        ch.entries().map(|(n, c, _)| (n, c.to_string())).collect()
    } else {
        let geo: Mesh = super::mesh::req_geo(a)?;
        let nodes: std::collections::HashSet<usize> = geo.node_list().into_iter().collect();
        asm.dofs.iter().filter(|(n, _)| nodes.contains(n)).cloned().collect()
    };
    let keep: Vec<usize> = asm.dofs.iter().enumerate().filter(|(_, d)| wanted.contains(d)).map(|(i, _)| i).collect();
    if keep.is_empty() {
        return Err(a.err("no master unknown: the masters share no unknown with the rigidity"));
    }
    let schur = schur_onto(&asm.problem, &keep).map_err(|e| explain(it, &r, &asm, e, &[]))?;
    let n = asm.problem.k.n;
    if schur.unknowns().iter().any(|&j| j >= n) {
        return Err(a.err("conditions acting on master unknowns are not supported: impose them after condensation"));
    }
    let masters: Vec<(usize, String)> = schur.unknowns().iter().map(|&j| asm.dofs[j].clone()).collect();
    let s = SuperElem { asm, schur, masters };
    Ok(vec![Value::Host(Rc::new(s))])
}

/// EXTR SUP 'RIGI': the condensed stiffness as a RIGIDITE over the masters.
pub(crate) fn extr(a: &mut Args, v: &Value) -> Result<Vec<Value>> {
    let Some(s) = as_super(v) else { return Err(a.err(format!("cannot extract from a {}", v.type_name()))) };
    let k = a.req_keyword(&["RIGI", "MAIL"])?;
    {
        let mut nodes: Vec<usize> = Vec::new();
        for (n, _) in &s.masters {
            if !nodes.contains(n) {
                nodes.push(*n);
            }
        }
        if k == "MAIL" {
            return Ok(vec![Value::Mesh(Rc::new(Mesh::points(&nodes)))]);
        }
        let m = s.schur.matrix();
        let d = s.masters.len();
        let mut mats = Vec::with_capacity(d * d);
        for i in 0..d {
            for j in 0..d {
                mats.push(m[(i, j)]);
            }
        }
        Ok(vec![Value::Rigi(Rc::new(condensed(s, Subtype::Rigidite, mats)))])
    }
}
