//! VIBR: eigenfrequencies and modes of K x = (2πf)² M x (vibration with a
//! mass, buckling with minus a geometric stiffness), under the equality
//! conditions K carries. The numerics are `solve::eigen` (dense); this
//! file reads the choice of modes and writes Cast3M's BASE_MODALE table.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::solve::eigen::{self, Pair};
use crate::solve::Kind;
use crate::value::{Chpoint, Key, Nature, Rigidite, Table, Value};
use std::cell::RefCell;
use std::f64::consts::TAU;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "VIBRATION",
    signature: "VIBR 'PROCHE' LISTREEL (LISTENTI) | 'INTERVALLE' F1 F2 ('BASSE'|'HAUTE' N) | 'SIMULTANE' F N | 'IRAM' F N, then RIGIDITE MASSE ('MULT') ('IMPR') (LOGIQUE)",
    doc: "Eigenmodes of K x = (2πf)² M x under K's equality conditions (BLOQ, RELA), solved densely: 'PROCHE' the N (default 1) modes closest to each frequency of the list, 'INTERVALLE' those with f1 ≤ f ≤ f2 (the N lowest or highest), 'SIMULTANE' and 'IRAM' the N closest to F. A negative (2πf)² gives a negative f unless LOGIQUE is FAUX. The result is a BASE_MODALE table: .'MODES'.i holds 'FREQUENCE', 'DEFORMEE_MODALE' (largest component 1), 'MASSE_GENERALISEE' (xᵀMx), 'NUMERO_MODE', 'POINT_REPERE' and 'DEPLACEMENTS_GENERALISES' (xᵀM·u_d for a unit translation along each axis).",
    example: "opti dime 2 elem seg2 mode plan cont ; l = (0. 0.) droi 4 (1. 0.) ; mo = mode l mecanique elastique barr ; ma = mate mo youn 1. nu 0.3 rho 1. sect 1. ; k = (rigi mo ma) et (bloq (l poin 1) depl) et (bloq l uy) ; m = mass mo ma ; t = vibr 'PROC' (prog 0.) (lect 2) k m ; f = t . 'MODES' . 1 . 'FREQUENCE' ;",
    f: vibr,
}];

/// Which modes to keep, from the sorted frequencies.
enum Choice {
    Closest(Vec<(f64, usize)>),
    Interval { lo: f64, hi: f64, count: Option<(bool, usize)> },
}

fn vibr(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let how = a.req_keyword(&["PROCHE", "INTERVALLE", "SIMULTANE", "IRAM"])?;
    let choice = match how {
        "PROCHE" => {
            let f = match a.opt::<Rc<Vec<f64>>>() {
                Some(l) => l.to_vec(),
                None => vec![a.req_num()?],
            };
            let n: Vec<i64> = match a.opt::<Rc<Vec<i64>>>() {
                Some(l) => l.to_vec(),
                None => vec![a.opt::<i64>().unwrap_or(1); f.len()],
            };
            if n.len() != f.len() {
                return Err(a.err(format!(
                    "'PROCHE': {} frequencies but {} numbers of modes (the lists go in pairs)",
                    f.len(),
                    n.len()
                )));
            }
            Choice::Closest(f.into_iter().zip(n).map(|(f, n)| (f, n.max(0) as usize)).collect())
        }
        "INTERVALLE" => {
            let lo = a.req_num()?;
            let hi = a.req_num()?;
            let count = match a.keyword(&["BASSE", "HAUTE"]) {
                Some(w) => Some((w == "BASSE", a.req::<i64>()?.max(0) as usize)),
                None => None,
            };
            Choice::Interval { lo, hi, count }
        }
        _ => {
            let f = a.req_num()?;
            let n = a.req::<i64>()?.max(0) as usize;
            Choice::Closest(vec![(f, n)])
        }
    };
    let k = a.req::<Rc<Rigidite>>()?;
    let m = a.req::<Rc<Rigidite>>()?;
    if a.opt::<Rc<Rigidite>>().is_some() {
        return Err(a.err("a damping matrix is not available (real modes of K and M only)"));
    }
    // The options come in any order ('IMPR' 'MULT' as well as 'MULT' 'IMPR').
    while a.keyword(&["MULT", "IMPR", "TBAS"]).is_some() {}
    let signed = a.opt::<bool>().unwrap_or(true);
    for v in [&choice] {
        if let Choice::Interval { lo, hi, .. } = v {
            if !lo.is_finite() || !hi.is_finite() {
                return Err(a.err("the interval bounds must be finite"));
            }
        }
    }

    let asm = k.number();
    if asm.problem.conditions.iter().any(|c| c.kind != Kind::Equal || c.dual.is_some()) {
        return Err(a.err("the stiffness holds unilateral or non-associated conditions"));
    }
    let mut mentries = Vec::new();
    for b in &m.blocks {
        let nd = b.ndof();
        for e in 0..b.n_elem() {
            let conn = &b.conn[e * b.nodes_per_elem..(e + 1) * b.nodes_per_elem];
            let mut idx = Vec::with_capacity(nd);
            for (l, c) in &b.dofs {
                idx.push(asm.position(conn[*l], c).ok_or_else(|| {
                    a.err(format!("the mass has the unknown {} at node {}, which the stiffness lacks", c, conn[*l] + 1))
                })?);
            }
            let mat = b.mat(e);
            for i in 0..nd {
                for j in 0..nd {
                    mentries.push((idx[i], idx[j], mat[i * nd + j]));
                }
            }
        }
    }
    let conds: Vec<Vec<(usize, f64)>> = asm.problem.conditions.iter().map(|c| c.terms.clone()).collect();
    let n = asm.dofs.len();
    let pairs = eigen::solve(n, &asm.problem.k.entries, &mentries, &conds).map_err(|e| a.err(e.to_string()))?;
    let freq = |p: &Pair| {
        let f = p.lambda.abs().sqrt() / TAU;
        if signed && p.lambda < 0.0 {
            -f
        } else {
            f
        }
    };
    let mut keep: Vec<usize> = Vec::new();
    match choice {
        Choice::Closest(list) => {
            for (f0, count) in list {
                let mut order: Vec<usize> = (0..pairs.len()).collect();
                order.sort_by(|&i, &j| (freq(&pairs[i]) - f0).abs().total_cmp(&(freq(&pairs[j]) - f0).abs()));
                keep.extend(order.into_iter().take(count));
            }
        }
        Choice::Interval { lo, hi, count } => {
            let inside: Vec<usize> = (0..pairs.len()).filter(|&i| (lo..=hi).contains(&freq(&pairs[i]))).collect();
            keep = match count {
                Some((true, c)) => inside.into_iter().take(c).collect(),
                Some((false, c)) => {
                    let skip = inside.len().saturating_sub(c);
                    inside.into_iter().skip(skip).collect()
                }
                None => inside,
            };
        }
    }
    keep.sort_by(|&i, &j| freq(&pairs[i]).total_cmp(&freq(&pairs[j])));
    keep.dedup();

    let dim = it.opts.dime.max(1);
    let mass = |x: &[f64], y: &[f64]| -> f64 { mentries.iter().map(|&(i, j, v)| x[i] * v * y[j]).sum() };
    let mut modes = Table::with_subtype("BASE_DE_MODES");
    let mut nodes = Vec::new();
    for (node, _) in &asm.dofs {
        if !nodes.contains(node) {
            nodes.push(*node);
        }
    }
    modes.set(Key::Mot("MAILLAGE".into()), Value::Mesh(Rc::new(Mesh::points(&nodes))));
    for (rank, &i) in keep.iter().enumerate() {
        let p = &pairs[i];
        // Largest component 1 (positive).
        let big = p.x.iter().copied().fold(0.0f64, |acc, v| if v.abs() > acc.abs() { v } else { acc });
        let x: Vec<f64> = if big != 0.0 { p.x.iter().map(|v| v / big).collect() } else { p.x.clone() };
        let mut field = Chpoint::new(Nature::Diffus);
        for ((node, comp), v) in asm.dofs.iter().zip(&x) {
            field.add(*node, comp, *v, false);
        }
        let mut gen = Table::with_subtype("DEPLACEMENTS_GENERALISES");
        for (d, comp) in ["UX", "UY", "UZ"].iter().enumerate().take(dim.min(3)) {
            let unit: Vec<f64> = asm.dofs.iter().map(|(_, c)| f64::from(u8::from(c == comp))).collect();
            gen.set(Key::Int(d as i64 + 1), Value::Float(mass(&x, &unit)));
        }
        let mut t = Table::with_subtype("MODE");
        let point = it.nodes.push([0.0; 3], 0.0);
        t.set(Key::Mot("POINT_REPERE".into()), Value::Point(point));
        t.set(Key::Mot("NUMERO_MODE".into()), Value::Int(rank as i64 + 1));
        t.set(Key::Mot("FREQUENCE".into()), Value::Float(freq(p)));
        t.set(Key::Mot("MASSE_GENERALISEE".into()), Value::Float(mass(&x, &x)));
        t.set(Key::Mot("DEFORMEE_MODALE".into()), Value::Chpo(Rc::new(field)));
        t.set(Key::Mot("DEPLACEMENTS_GENERALISES".into()), Value::Table(Rc::new(RefCell::new(gen))));
        modes.set(Key::Int(rank as i64 + 1), Value::Table(Rc::new(RefCell::new(t))));
    }
    let mut out = Table::with_subtype("BASE_MODALE");
    out.set(Key::Mot("MODES".into()), Value::Table(Rc::new(RefCell::new(modes))));
    Ok(vec![Value::Table(Rc::new(RefCell::new(out)))])
}
