//! PREC: the normal force along prestressing cables after their losses
//! (friction, anchorage slip, relaxation). The numerics are in
//! `fem::prestress`; here the model's segments are cut into cables and the
//! result is put back on their elements.

use super::model::material_for;
use super::{Args, OpDef, PointId};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::{ElemType, Mesh};
use crate::fem::prestress::{tension_profile, Losses, Relaxation};
use crate::value::model::MchamlZone;
use crate::value::table::Key;
use crate::value::{Mchaml, Model, Table, Value};
use rustc_hash::{FxHashMap, FxHashSet};
use std::cell::RefCell;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "PREC",
    signature: "PREC MMODEL MCHAML F1 (TABLE) (MAILLAGE | POINT) (MCHAML_PRE0)",
    doc: "Normal force EFFX (subtype CONTRAINTES, at both ends of every element) along the cables of a bar model (chains of SEG2 without branches) pulled with the force F1 at their anchored ends (the points given, by default the last point of each cable). With a TABLE the losses are taken into account: friction 'FF' (per radian, 0.18) and 'PHIF' (per length, 0.002), anchorage slip 'GANC' (0.), relaxation 'RMU0' (0.43), 'FPRG' (1.7E9), 'RH10' (relaxation at 1000 h in percent, 2.5). YOUN and SECT come from the material. PRE0, a field of the same model, is added.",
    example: "opti dime 2 elem seg2 ; l = (0. 0.) droi 10 (10. 0.) ; mo = mode l mecanique elastique barr ; ma = mate mo youn 2.e11 sect 1.e-3 ; t = table ; t.'PHIF' = 0.01 ; p = prec mo ma 1.e5 t (0. 0.) ;",
    f: prec,
}];

fn prec(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let model = a.req::<Rc<Model>>()?;
    let mate = a.req::<Rc<Mchaml>>()?;
    let force = a.req::<super::Num>()?.0;
    if !force.is_finite() {
        return Err(a.err("the tension F1 is not a finite number"));
    }
    let losses = match a.opt::<Rc<RefCell<Table>>>() {
        Some(t) => Some(read_losses(&t.borrow()).map_err(|e| a.err(e.to_string()))?),
        None => None,
    };
    let anchors: Option<FxHashSet<usize>> = if let Some(m) = a.opt::<Rc<Mesh>>() {
        Some(m.parts.iter().flat_map(|p| p.conn.iter().copied()).collect())
    } else {
        a.opt::<PointId>().map(|p| std::iter::once(p.0).collect())
    };
    let pre0 = a.opt::<Rc<Mchaml>>();

    // Every segment of the model, with the zone it belongs to.
    let mut segs: Vec<[usize; 2]> = Vec::new();
    let mut seg_zone: Vec<usize> = Vec::new();
    for (zi, z) in model.zones.iter().enumerate() {
        for p in &z.mesh.parts {
            if p.ty != ElemType::Seg2 {
                return Err(a.err(format!("the cables must be SEG2 elements, not {}", p.ty.name())));
            }
            for e in p.elems() {
                segs.push([e[0], e[1]]);
                seg_zone.push(zi);
            }
        }
    }
    let mut props = Vec::with_capacity(model.zones.len());
    for z in &model.zones {
        let m = material_for(z, std::slice::from_ref(&mate));
        props.push((m.youn, m.sect));
    }
    let mut tension: FxHashMap<usize, f64> = FxHashMap::default();
    for (k, chain) in chains(&segs).map_err(|e| a.err(e.to_string()))?.into_iter().enumerate() {
        let (nodes, first_seg) = chain;
        let (Some(youn), Some(sect)) = props[seg_zone[first_seg]] else {
            return Err(a.err("the material needs YOUN and SECT"));
        };
        let ends = [nodes[0], nodes[nodes.len() - 1]];
        let pulled: Vec<bool> = match &anchors {
            Some(set) => ends.iter().map(|n| set.contains(n)).collect(),
            None => vec![false, true],
        };
        if !pulled.iter().any(|b| *b) {
            return Err(a.err(format!("cable {} has no end among the anchorage points", k + 1)));
        }
        let no_loss = Losses { ff: 0.0, phif: 0.0, ganc: 0.0, relaxation: None };
        let l = losses.as_ref().unwrap_or(&no_loss);
        for (side, _) in pulled.iter().enumerate().filter(|(_, p)| **p) {
            let order: Vec<usize> = if side == 0 { nodes.clone() } else { nodes.iter().rev().copied().collect() };
            let x: Vec<[f64; 3]> = order.iter().map(|n| it.nodes.get(*n)).collect();
            let p =
                tension_profile(&x, force, youn * sect, sect, l).map_err(|e| a.err(format!("cable {}: {e}", k + 1)))?;
            // Pulled at both ends: each point keeps the larger tension.
            for (n, v) in order.iter().zip(p) {
                let t = tension.entry(*n).or_insert(v);
                *t = t.max(v);
            }
        }
    }
    let mut out = Mchaml { subtype: "CONTRAINTES".into(), zones: vec![] };
    for z in &model.zones {
        let mut nz = MchamlZone { mesh: z.mesh.clone(), element: z.element.clone(), ..Default::default() };
        nz.comps = vec!["EFFX".into()];
        for p in &z.mesh.parts {
            for e in p.elems() {
                nz.values.push(e.iter().map(|n| vec![tension[n]]).collect());
            }
        }
        out.zones.push(nz);
    }
    if let Some(p0) = pre0 {
        out = add_initial(out, &p0).map_err(|e| a.err(e.to_string()))?;
    }
    Ok(vec![Value::Mchaml(Rc::new(out))])
}

/// The losses of the table, with their usual defaults.
fn read_losses(t: &Table) -> std::result::Result<Losses, String> {
    let get = |k: &str, d: f64| -> std::result::Result<f64, String> {
        match t.get(&Key::Mot(k.into())) {
            None => Ok(d),
            Some(v) => match v.as_f64() {
                Some(x) if x.is_finite() => Ok(x),
                _ => Err(format!("the table entry '{k}' must be a number")),
            },
        }
    };
    Ok(Losses {
        ff: get("FF", 0.18)?,
        phif: get("PHIF", 0.002)?,
        ganc: get("GANC", 0.0)?,
        relaxation: Some(Relaxation { mu0: get("RMU0", 0.43)?, fprg: get("FPRG", 1.7e9)?, rh1000: get("RH10", 2.5)? }),
    })
}

/// The cables: chains of segments without branches, as node lists (with
/// the index of one of their segments).
fn chains(segs: &[[usize; 2]]) -> std::result::Result<Vec<(Vec<usize>, usize)>, String> {
    let mut adj: FxHashMap<usize, Vec<(usize, usize)>> = FxHashMap::default();
    for (i, s) in segs.iter().enumerate() {
        adj.entry(s[0]).or_default().push((s[1], i));
        adj.entry(s[1]).or_default().push((s[0], i));
    }
    if let Some((n, _)) = adj.iter().find(|(_, v)| v.len() > 2) {
        return Err(format!("the cables branch at node {}", n + 1));
    }
    let mut used = vec![false; segs.len()];
    let mut out = Vec::new();
    // Start from the node of each chain that comes first in the elements'
    // order, so a cable keeps the direction it was meshed in.
    for (i, s) in segs.iter().enumerate() {
        if used[i] {
            continue;
        }
        // Walk back to the chain's start.
        let (mut node, mut seg) = (s[0], i);
        while let Some(&(prev, j)) = adj[&node].iter().find(|(_, j)| *j != seg) {
            if j == i {
                return Err("a cable is a closed loop: it has no end to pull".into());
            }
            node = prev;
            seg = j;
        }
        let mut nodes = vec![node];
        let mut last = usize::MAX;
        while let Some(&(next, j)) = adj[&node].iter().find(|(_, j)| *j != last && !used[*j]) {
            used[j] = true;
            nodes.push(next);
            node = next;
            last = j;
        }
        out.push((nodes, i));
    }
    Ok(out)
}

/// `out` plus an initial field given on the same elements.
fn add_initial(mut out: Mchaml, p0: &Mchaml) -> std::result::Result<Mchaml, String> {
    for z in &mut out.zones {
        let Some(z0) = p0.zones.iter().find(|z0| z0.mesh == z.mesh) else {
            return Err("the initial field PRE0 is not given on the model's elements".into());
        };
        let Some(c) = z0.comps.iter().position(|c| c == "EFFX") else {
            return Err("the initial field PRE0 has no component EFFX".into());
        };
        for (e, pts) in z.values.iter_mut().enumerate() {
            for (k, v) in pts.iter_mut().enumerate() {
                let add = z0.values.get(e).and_then(|p| p.get(k).or(p.first())).map(|p| p[c]);
                v[0] += add.ok_or("the initial field PRE0 does not match the model's elements")?;
            }
        }
    }
    Ok(out)
}
