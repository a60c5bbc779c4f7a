//! SUPER: static condensation (Guyan super-elements) by the same
//! interrupted factorisation RESO uses (`solve::bilateral::schur::schur_onto`).
//! The SUPERELE type is a host object: it shows how new object types plug
//! in without touching the evaluator.

use super::assemble::{self, explain, solution_field, Assembled};
use super::{dofs, Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::solve::bilateral::mult_masters::MultiplierMasters;
use crate::solve::bilateral::schur::{schur_onto_signed, SchurOnto};
use crate::solve::{Load, Solution};
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
    /// When masters are multipliers (LX): the augmented system condensed.
    mult: Option<MultiplierMasters>,
    /// Physical value / condensed unknown of each master (1 but for a
    /// scaled multiplier).
    scale: Vec<f64>,
}

impl SuperElem {
    /// A load of the rigidity as one of the condensed system.
    fn load(&self, l: Load) -> Load {
        match &self.mult {
            Some(mm) => mm.load(&l),
            None => l,
        }
    }

    /// The expansion of master values as a solution of the rigidity.
    fn expand(&self, load: &Load, tail: &[f64]) -> Solution {
        let tail: Vec<f64> = tail.iter().zip(&self.scale).map(|(v, s)| v / s).collect();
        let s = self.schur.expand(load, &tail);
        match &self.mult {
            Some(mm) => mm.solution(&s),
            None => s,
        }
    }
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

/// The SUPERELE, wherever it stands among the arguments (`SUPER sup
/// 'CHARGE' f` as well as `SUPER 'CHARGE' sup f`).
fn req_super(a: &mut Args) -> Result<Rc<dyn HostObject>> {
    let found = a.opt_with(|v| match v {
        Value::Host(h) if as_super(v).is_some() => Some(h.clone()),
        _ => None,
    });
    found.ok_or_else(|| a.missing("SUPERELE"))
}

fn supe(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    match a.req_keyword(&["RIGIDITE", "CHARGE", "DEPLACEMENT", "MASSE"])? {
        "RIGIDITE" => build(it, a),
        "CHARGE" => {
            let h = req_super(a)?;
            let s = h.as_any().downcast_ref::<SuperElem>().expect("checked");
            let f = a.req::<Rc<Chpoint>>()?;
            let load = s.load(assemble::load(it, &s.asm, &[&f]).map_err(|e| a.err(e.message))?);
            let fc = s.schur.load(&load);
            let mut out = Chpoint::new(Nature::Discret);
            for (((n, c), v), sc) in s.masters.iter().zip(fc).zip(&s.scale) {
                out.add(*n, &dofs::dual_of(c), v / sc, true);
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
            let sol = s.expand(&s.load(load), &tail);
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
    let load = s.load(assemble::load(it, &s.asm, &[]).map_err(|e| a.err(e.message))?);
    let d = s.masters.len();
    let modes: Vec<Rc<Chpoint>> = (0..d)
        .map(|j| {
            let tail: Vec<f64> = (0..d).map(|i| if i == j { 1.0 } else { 0.0 }).collect();
            Rc::new(solution_field(&s.asm, &s.expand(&load, &tail)))
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
        let a2 = r2.number();
        let mut w = a2.dofs;
        w.extend(a2.mult_nodes.iter().map(|&n| (n, "LX".to_string())));
        w
    } else if let Some(ch) = a.opt::<Rc<Chpoint>>() {
        ch.entries().map(|(n, c, _)| (n, c.to_string())).collect()
    } else {
        let geo: Mesh = super::mesh::req_geo(a)?;
        let nodes: std::collections::HashSet<usize> = geo.node_list().into_iter().collect();
        let mut w: Vec<(usize, String)> = asm.dofs.iter().filter(|(n, _)| nodes.contains(n)).cloned().collect();
        w.extend(asm.mult_nodes.iter().filter(|n| nodes.contains(n)).map(|&n| (n, "LX".to_string())));
        w
    };
    let wanted: std::collections::HashSet<(usize, String)> = wanted.into_iter().collect();
    let mut keep: Vec<usize> =
        asm.dofs.iter().enumerate().filter(|(_, d)| wanted.contains(*d)).map(|(i, _)| i).collect();
    // Multiplier masters: the conditions whose LX is wanted.
    let conds: Vec<usize> =
        (0..asm.mult_nodes.len()).filter(|&k| wanted.contains(&(asm.mult_nodes[k], "LX".to_string()))).collect();
    if keep.is_empty() && conds.is_empty() {
        return Err(a.err("no master unknown: the masters share no unknown with the rigidity"));
    }
    let mult = (!conds.is_empty()).then(|| MultiplierMasters::new(&asm.problem, &conds));
    let n = asm.problem.k.n;
    let problem = match &mult {
        Some(mm) => {
            keep.extend((0..conds.len()).map(|t| mm.unknown(t)));
            &mm.problem
        }
        None => &asm.problem,
    };
    let schur = schur_onto_signed(problem, &keep, n).map_err(|e| explain(it, &r, &asm, e, &[]))?;
    if schur.unknowns().iter().any(|&j| j >= problem.k.n) {
        return Err(a.err("conditions acting on master unknowns are not supported: impose them after condensation"));
    }
    let masters: Vec<(usize, String)> = schur
        .unknowns()
        .iter()
        .map(|&j| if j < n { asm.dofs[j].clone() } else { (asm.mult_nodes[conds[j - n]], "LX".to_string()) })
        .collect();
    let scale = schur.unknowns().iter().map(|&j| mult.as_ref().map_or(1.0, |mm| mm.scale_of(j))).collect();
    let s = SuperElem { asm, schur, masters, mult, scale };
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
                mats.push(m[(i, j)] / (s.scale[i] * s.scale[j]));
            }
        }
        Ok(vec![Value::Rigi(Rc::new(condensed(s, Subtype::Rigidite, mats)))])
    }
}
