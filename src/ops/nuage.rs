//! NUAGE objects (NUAG) and IPOL on a NUAGE: a field of n named variables
//! in, a field of the function's values out, the numbers computed in
//! `props::scatter` (grid, inverse distance, diffuse approximation).

use super::lists::short;
use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::props::scatter::{self, Weight};
use crate::value::model::MchamlZone;
use crate::value::{Chpoint, Mchaml, Nuage, Ty, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "NUAG",
    signature: "NUAG 'COMP' NAME1 OBJ … ('COMP' NAME2 OBJ …) | NUAG NAME1*TYPE1 … NAMEN*TYPEN TUPLE1 … TUPLEM | NUAG CHPOINT",
    doc: "Build a NUAGE: M tuples of N named components, given component by component ('COMP'), tuple by tuple after the names and types, or one tuple per node of a CHPOINT (a component missing at a node is 0).",
    example: "nu = nuag 'COMP' 'X' 0. 1. 'COMP' 'F' 2. 3. ;",
    f: nuag,
}];

fn nuag(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if let Some(c) = a.opt::<Rc<Chpoint>>() {
        let comps = c
            .comps
            .iter()
            .map(|name| (name.clone(), c.nodes.iter().map(|&n| Value::Float(c.get(n, name).unwrap_or(0.0))).collect()))
            .collect();
        return Ok(vec![Value::Nuage(Rc::new(Nuage { comps }))]);
    }
    let mut comps: Vec<(String, Vec<Value>)> = Vec::new();
    if a.keyword_next(&["COMP"]).is_some() {
        'comps: loop {
            let name = a.word().ok_or_else(|| a.missing("a component name after 'COMP'"))?;
            let mut col = Vec::new();
            loop {
                if a.keyword_next(&["COMP"]).is_some() {
                    comps.push((name, col));
                    continue 'comps;
                }
                match a.right_any() {
                    Some(v) => col.push(v),
                    None => {
                        comps.push((name, col));
                        break 'comps;
                    }
                }
            }
        }
    } else {
        // Names and types first, then the tuples in order.
        let mut types = Vec::new();
        while let Some(name) = a.word() {
            if !a.sign_like_star() {
                return Err(a.err(format!("'{}' must be followed by * and the type of its objects", name)));
            }
            let ty = a.word().ok_or_else(|| a.missing(&format!("the type of {} after '*'", name)))?;
            let ty = Ty::from_name(&ty).ok_or_else(|| a.err(format!("{} is not a type", ty)))?;
            comps.push((name, Vec::new()));
            types.push(ty);
            if a.peek_right().is_some_and(|v| !matches!(v, Value::Mot(_))) {
                break;
            }
        }
        // No NAME*TYPE read: no tuple to read either (an empty loop would spin).
        'tuples: while !types.is_empty() {
            for (k, ty) in types.iter().enumerate() {
                let v = match a.right_any() {
                    Some(v) => v,
                    None if k == 0 => break 'tuples,
                    None => {
                        return Err(a.missing(&format!(
                            "the {} of {} to complete the last tuple",
                            ty.name(),
                            comps[k].0
                        )))
                    }
                };
                let v = match (ty, v) {
                    (Ty::Flottant, Value::Int(i)) => Value::Float(i as f64),
                    (ty, v) if v.ty() == *ty => v,
                    (ty, v) => {
                        return Err(a.err(format!(
                            "{} holds {} objects, not a {}",
                            comps[k].0,
                            ty.name(),
                            v.type_name()
                        )))
                    }
                };
                comps[k].1.push(v);
            }
        }
    }
    if comps.is_empty() {
        return Err(a.missing("'COMP' and a component, NAME*TYPE, or a CHPOINT"));
    }
    if let Some((name, col)) = comps.iter().find(|c| c.1.len() != comps[0].1.len()) {
        return Err(a.err(format!("{} has {} objects and {} has {}", comps[0].0, comps[0].1.len(), name, col.len())));
    }
    Ok(vec![Value::Nuage(Rc::new(Nuage { comps }))])
}

/// How IPOL reads the NUAGE.
enum Method {
    Grid,
    Idw(f64),
    Diffuse(Weight),
}

/// IPOL with a NUAGE among its operands: the field of the variables is
/// the other one.
pub(crate) fn ipol(a: &mut Args, nu: &Nuage) -> Result<Vec<Value>> {
    let field = a
        .opt_with(|v| matches!(v, Value::Chpo(_) | Value::Mchaml(_)).then(|| v.clone()))
        .ok_or_else(|| a.missing("the CHPOINT or MCHAML of the variables"))?;
    let method = match a.keyword(&["GRIL", "PID", "GAUS", "RATI"]) {
        Some("GRIL") => Method::Grid,
        Some("PID") => {
            let p = a.opt_num_right().unwrap_or(1.0);
            if p < 0.0 {
                return Err(a.err(format!("the power of 'PID' must not be negative ({})", p)));
            }
            Method::Idw(p)
        }
        Some("RATI") => Method::Diffuse(Weight::Ratio),
        _ => Method::Diffuse(Weight::Gauss),
    };
    let names: Vec<String> = match &field {
        Value::Chpo(f) => f.comps.clone(),
        Value::Mchaml(m) => {
            m.zones.iter().flat_map(|z| z.comps.iter().cloned().chain(z.constants.keys().cloned())).collect()
        }
        _ => Vec::new(),
    };
    // A field's components have 4-character names (NOMC): a longer name
    // of the NUAGE matches the component named by its first four.
    let field_name = |c: &str| -> Option<String> {
        names.iter().find(|x| *x == c).or_else(|| names.iter().find(|x| short(x) == short(c))).cloned()
    };
    let has = |c: &str| field_name(c).is_some();
    let mut f = Function::new(a, nu, &method, &has)?;
    f.inputs = f.inputs.iter().map(|c| field_name(c).unwrap_or_else(|| c.clone())).collect();
    let out = match &field {
        Value::Chpo(c) => Value::Chpo(Rc::new(on_chpoint(a, &f, c)?)),
        Value::Mchaml(m) => Value::Mchaml(Rc::new(on_mchaml(a, &f, m)?)),
        _ => unreachable!("the field is a CHPOINT or an MCHAML"),
    };
    Ok(vec![out])
}

/// The function a NUAGE defines, ready to evaluate.
struct Function {
    inputs: Vec<String>,
    outputs: Vec<String>,
    kind: Kind,
}

enum Kind {
    Grid { axes: Vec<Vec<f64>>, values: Vec<f64> },
    Scattered { points: Vec<Vec<f64>>, values: Vec<Vec<f64>>, idw: Option<f64>, weight: Weight },
}

impl Function {
    fn new(a: &Args, nu: &Nuage, method: &Method, has: &dyn Fn(&str) -> bool) -> Result<Function> {
        if let Method::Grid = method {
            let lists: Vec<Vec<f64>> = nu
                .comps
                .iter()
                .map(|(name, col)| match col.as_slice() {
                    [Value::ListReel(l)] => Ok(l.to_vec()),
                    _ => Err(a.err(format!("'GRILL' needs one LISTREEL per component; {} is not one", name))),
                })
                .collect::<Result<_>>()?;
            let n = lists
                .len()
                .checked_sub(1)
                .filter(|n| *n > 0)
                .ok_or_else(|| a.err("'GRILL' needs at least two components"))?;
            let axes = lists[..n].to_vec();
            if let Some(ax) = axes.iter().find(|ax| ax.is_empty() || ax.windows(2).any(|w| w[1] <= w[0])) {
                return Err(a.err(format!("a grid's coordinates must be strictly increasing ({} of them)", ax.len())));
            }
            let size: usize = axes.iter().map(Vec::len).product();
            if lists[n].len() != size {
                return Err(a.err(format!("the grid has {} points but {} values", size, lists[n].len())));
            }
            let inputs: Vec<String> = nu.comps[..n].iter().map(|c| c.0.clone()).collect();
            if let Some(c) = inputs.iter().find(|c| !has(c)) {
                return Err(a.err(format!("the field has no component {} (a variable of the grid)", c)));
            }
            return Ok(Function {
                inputs,
                outputs: vec![nu.comps[n].0.clone()],
                kind: Kind::Grid { axes, values: lists[n].clone() },
            });
        }
        let columns: Vec<(String, Vec<f64>)> = nu
            .comps
            .iter()
            .map(|(name, _)| {
                nu.numbers(name).map(|v| (name.clone(), v)).ok_or_else(|| {
                    a.err(format!("the component {} of the NUAGE holds objects that are not numbers", name))
                })
            })
            .collect::<Result<_>>()?;
        let (ins, outs): (Vec<_>, Vec<_>) = columns.into_iter().partition(|(name, _)| has(name));
        if ins.is_empty() || outs.is_empty() {
            return Err(a.err("the field must name some of the NUAGE's components (the variables), not all of them"));
        }
        if nu.is_empty() {
            return Err(a.err("the NUAGE is empty"));
        }
        let points = (0..nu.len()).map(|i| ins.iter().map(|c| c.1[i]).collect()).collect();
        let values = (0..nu.len()).map(|i| outs.iter().map(|c| c.1[i]).collect()).collect();
        let (idw, weight) = match method {
            Method::Idw(p) => (Some(*p), Weight::Gauss),
            Method::Diffuse(w) => (None, *w),
            Method::Grid => unreachable!("handled above"),
        };
        Ok(Function {
            inputs: ins.into_iter().map(|c| c.0).collect(),
            outputs: outs.into_iter().map(|c| c.0).collect(),
            kind: Kind::Scattered { points, values, idw, weight },
        })
    }

    fn eval(&self, a: &Args, x: &[f64]) -> Result<Vec<f64>> {
        match &self.kind {
            Kind::Grid { axes, values } => Ok(vec![scatter::grid(axes, values, x)]),
            Kind::Scattered { points, values, idw: Some(p), .. } => Ok(scatter::idw(points, values, x, *p)),
            Kind::Scattered { points, values, weight, .. } => scatter::diffuse(points, values, x, *weight)
                .ok_or_else(|| a.err("the NUAGE's points do not fix a first-order polynomial (use 'PID')")),
        }
    }
}

fn on_chpoint(a: &Args, f: &Function, c: &Chpoint) -> Result<Chpoint> {
    let mut out = Vec::new();
    for &n in &c.nodes {
        let x: Option<Vec<f64>> = f.inputs.iter().map(|i| c.get(n, i)).collect();
        let Some(x) = x else { continue };
        for (name, v) in f.outputs.iter().zip(f.eval(a, &x)?) {
            out.push((n, name.as_str(), v));
        }
    }
    Ok(Chpoint::from_entries(c.nature, out))
}

fn on_mchaml(a: &Args, f: &Function, m: &Mchaml) -> Result<Mchaml> {
    let mut zones = Vec::new();
    for z in &m.zones {
        let at = |e: usize, p: usize, c: &str| -> Option<f64> {
            match z.comps.iter().position(|x| x == c) {
                Some(k) => z.values.get(e)?.get(p)?.get(k).copied(),
                None => z.constants.get(c).copied(),
            }
        };
        if !f.inputs.iter().all(|c| z.comps.contains(c) || z.constants.contains_key(c)) {
            continue;
        }
        let mut zone =
            MchamlZone { mesh: z.mesh.clone(), element: z.element.clone(), at_nodes: z.at_nodes, ..Default::default() };
        if z.values.is_empty() {
            // Constant inputs: constant outputs.
            let x: Vec<f64> = f.inputs.iter().filter_map(|c| z.constants.get(c).copied()).collect();
            for (name, v) in f.outputs.iter().zip(f.eval(a, &x)?) {
                zone.constants.insert(name.clone(), v);
            }
        } else {
            zone.comps = f.outputs.clone();
            for (e, pts) in z.values.iter().enumerate() {
                let mut row = Vec::with_capacity(pts.len());
                for p in 0..pts.len() {
                    let x: Option<Vec<f64>> = f.inputs.iter().map(|c| at(e, p, c)).collect();
                    let x = x.ok_or_else(|| a.err(format!("element {}: a variable is missing", e + 1)))?;
                    row.push(f.eval(a, &x)?);
                }
                zone.values.push(row);
            }
        }
        zones.push(zone);
    }
    Ok(Mchaml { subtype: m.subtype.clone(), zones })
}

/// EXTR on a NUAGE: 'COMP' (the component names); the object of a
/// component of a one-tuple NUAGE; the tuple where a component is the
/// greatest, the least ('MAXI', 'MINI'), the nearest below or above a
/// value ('INFE', 'SUPE'); the tuples where it lies between two values
/// ('ENTR').
pub(crate) fn extr(a: &mut Args, nu: &Nuage) -> Result<Vec<Value>> {
    if a.keyword_next(&["COMP"]).is_some() {
        return Ok(vec![Value::ListMots(Rc::new(nu.comps.iter().map(|c| c.0.clone()).collect()))]);
    }
    let select = a.keyword(&["MAXI", "MINI", "INFE", "SUPE", "ENTR"]);
    let name = a.word().ok_or_else(|| a.missing("a component of the NUAGE"))?;
    let col = nu.column(&name).ok_or_else(|| {
        let names: Vec<&str> = nu.comps.iter().map(|c| c.0.as_str()).collect();
        a.err(format!("the NUAGE has no component {} (it has {})", name, names.join(" ")))
    })?;
    let Some(k) = select else {
        return match col {
            [v] => Ok(vec![v.clone()]),
            _ => Err(a.err(format!("the NUAGE has {} tuples: EXTR of a component needs one", col.len()))),
        };
    };
    let xs =
        nu.numbers(&name).ok_or_else(|| a.err(format!("the component {} holds objects that are not numbers", name)))?;
    let by = |better: &dyn Fn(f64, f64) -> bool, ok: &dyn Fn(f64) -> bool| {
        (0..xs.len()).filter(|&i| ok(xs[i])).fold(None, |best: Option<usize>, i| match best {
            Some(b) if !better(xs[i], xs[b]) => Some(b),
            _ => Some(i),
        })
    };
    let keep: Vec<usize> = match k {
        "MAXI" => by(&|x, y| x > y, &|_| true).into_iter().collect(),
        "MINI" => by(&|x, y| x < y, &|_| true).into_iter().collect(),
        "INFE" | "SUPE" => {
            let t = a.req_num()?;
            let found = if k == "INFE" { by(&|x, y| x > y, &|x| x <= t) } else { by(&|x, y| x < y, &|x| x >= t) };
            found.into_iter().collect()
        }
        _ => {
            let (lo, hi) = (a.req_num()?, a.req_num()?);
            let (lo, hi) = (lo.min(hi), lo.max(hi));
            (0..xs.len()).filter(|&i| (lo..=hi).contains(&xs[i])).collect()
        }
    };
    let comps = nu.comps.iter().map(|(n, c)| (n.clone(), keep.iter().map(|&i| c[i].clone()).collect())).collect();
    Ok(vec![Value::Nuage(Rc::new(Nuage { comps }))])
}
