//! PRIM (prim.notice): the primitive of an EVOLUTIO, and the primitive
//! variables of compressible flow from conservative CHPOINTs ('PERFMONO',
//! 'PERFMULT', 'PERFTEMP', 'GFMP'). This file reads the arguments and the
//! gas table and walks the nodes; the equations of state are in
//! `fem::flow`.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::flow::{self, Conservative, PolyGas, Primitive, Stiffened};
use crate::value::{Chpoint, Evolution, Key, Table, Value};
use std::cell::RefCell;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "PRIM",
    signature: "PRIM EVOL1 | PRIM 'PERFMONO' RHO GN RHOE GAMMA | PRIM 'PERFMULT' TAB RHO GN RHOE RHOY | PRIM 'PERFTEMP' TAB RHO GN RHOE (RHOY) (RHOS) (TGUESS) | PRIM 'GFMP' TAB PHI RHO GN RHOE (RHOY ALPHA)",
    doc: "On an EVOLUTIO: the running integral of each curve (trapezoids, 0 at the first abscissa). Otherwise the primitive variables of the Euler equations from the conservative ones (density 'SCAL', momentum 'UX' 'UY' ('UZ'), total energy per volume 'SCAL', partial densities named by TAB.'ESPEULE'): 'PERFMONO' gives velocity and pressure of a perfect gas of given gamma; 'PERFMULT' (TAB.'CP', TAB.'CV' per species) and 'PERFTEMP' (TAB.species.'A' cv polynomial, .'R'; TAB.'SCALPASS' passive scalars) give velocity, pressure, temperature, mass fractions (passive scalars) and gamma; 'GFMP' (stiffened gases, TAB.'MGAM' 'MPIN' where PHI <= 0, 'PGAM' 'PPIN' where PHI > 0) gives velocity, pressure (and mass fractions).",
    example: "e = evol 'MANU' (prog 0. 1. 2.) (prog 1. 1. 1.) ; p = prim e ;",
    f: prim,
}];

const FORMS: &[&str] = &["PERFMONO", "PERFMULT", "PERFTEMP", "GFMP", "CONSPRIM", "TWOFLUID", "DEM"];

fn prim(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if let Some(e) = a.opt::<Rc<Evolution>>() {
        let curves = e.curves.iter().map(|c| c.primitive()).collect::<std::result::Result<Vec<_>, _>>();
        return Ok(vec![Value::Evol(Rc::new(Evolution { curves: curves.map_err(|m| a.err(m))? }))]);
    }
    // The forms share their first four letters: compare whole words.
    let form = a
        .opt::<String>()
        .map(|w| w.trim().to_uppercase())
        .ok_or_else(|| a.missing("EVOLUTIO or one of 'PERFMONO' 'PERFMULT' 'PERFTEMP' 'GFMP'"))?;
    let dim = it.opts.dime.clamp(1, 3);
    match FORMS.iter().find(|f| **f == form) {
        Some(&"PERFMONO") => perfmono(a, dim),
        Some(&"PERFMULT") => perfmult(a, dim),
        Some(&"PERFTEMP") => perftemp(a, dim),
        Some(&"GFMP") => gfmp(a, dim),
        Some(f) => Err(a.err(format!("the form '{}' of PRIM is not implemented in gibi", f))),
        None => Err(a.err(format!("unknown form '{}' (expected one of {})", form, FORMS.join(" ")))),
    }
}

/// The conservative fields and how to read them node by node.
struct Fields {
    rho: Rc<Chpoint>,
    momentum: Rc<Chpoint>,
    rho_e: Rc<Chpoint>,
    rho_y: Option<Rc<Chpoint>>,
    species: Vec<String>,
    dim: usize,
}

const MOMENTUM: [&str; 3] = ["UX", "UY", "UZ"];

/// A value of a field, the component compared without trailing blanks.
fn value_at(a: &Args, c: &Chpoint, what: &str, node: usize, comp: &str) -> Result<f64> {
    c.get(node, comp).or_else(|| c.comps.iter().find(|x| x.trim_end() == comp).and_then(|x| c.get(node, x))).ok_or_else(
        || {
            a.err(format!(
                "the {} has no component '{}' at node {}: the fields must share their support",
                what,
                comp,
                node + 1
            ))
        },
    )
}

impl Fields {
    fn read(a: &mut Args, dim: usize) -> Result<Fields> {
        Ok(Fields { rho: a.req()?, momentum: a.req()?, rho_e: a.req()?, rho_y: None, species: vec![], dim })
    }

    /// Run `f` at every node of the density field; gather its results.
    fn each(
        &self,
        a: &Args,
        mut f: impl FnMut(usize, Conservative) -> std::result::Result<Primitive, String>,
    ) -> Result<Vec<(usize, Primitive)>> {
        let mut out = Vec::with_capacity(self.rho.nodes.len());
        for &n in &self.rho.nodes {
            let rho = value_at(a, &self.rho, "density", n, "SCAL")?;
            let momentum = MOMENTUM[..self.dim]
                .iter()
                .map(|c| value_at(a, &self.momentum, "momentum", n, c))
                .collect::<Result<Vec<_>>>()?;
            let rho_e = value_at(a, &self.rho_e, "total energy", n, "SCAL")?;
            let rho_y = match &self.rho_y {
                Some(c) => self
                    .species
                    .iter()
                    .map(|s| value_at(a, c, "partial densities", n, s))
                    .collect::<Result<Vec<_>>>()?,
                None => vec![],
            };
            let s = Conservative { rho, momentum: &momentum, rho_e, rho_y: &rho_y };
            let p = f(n, s).map_err(|m| a.err(format!("at node {}: {}", n + 1, m)))?;
            out.push((n, p));
        }
        Ok(out)
    }

    fn field(&self, res: &[(usize, Primitive)], comps: &[String], get: impl Fn(&Primitive) -> Vec<f64>) -> Value {
        let nature = self.rho.nature;
        let mut c = Chpoint::new(nature);
        for (n, p) in res {
            for (comp, v) in comps.iter().zip(get(p)) {
                c.add(*n, comp, v, false);
            }
        }
        Value::Chpo(Rc::new(c))
    }

    fn velocity(&self, res: &[(usize, Primitive)]) -> Value {
        let comps: Vec<String> = MOMENTUM[..self.dim].iter().map(|s| s.to_string()).collect();
        self.field(res, &comps, |p| p.velocity.clone())
    }

    fn scalar(&self, res: &[(usize, Primitive)], get: impl Fn(&Primitive) -> f64) -> Value {
        self.field(res, &["SCAL".to_string()], |p| vec![get(p)])
    }

    fn fractions(&self, res: &[(usize, Primitive)]) -> Value {
        self.field(res, &self.species, |p| p.y.clone())
    }
}

fn perfmono(a: &mut Args, dim: usize) -> Result<Vec<Value>> {
    let f = Fields::read(a, dim)?;
    let gamma: Rc<Chpoint> = a.req()?;
    let res = f.each(a, |n, s| {
        let g = gamma.get(n, "SCAL").ok_or_else(|| format!("gamma has no 'SCAL' at node {}", n + 1))?;
        flow::perfect_mono(s, g)
    })?;
    Ok(vec![f.velocity(&res), f.scalar(&res, |p| p.pressure)])
}

/// An entry of the gas table.
fn entry(t: &Table, key: &str) -> Option<Value> {
    t.get(&Key::Mot(key.trim_end().to_string())).cloned()
}

fn req_entry(a: &Args, t: &Table, key: &str, what: &str) -> Result<Value> {
    entry(t, key).ok_or_else(|| a.err(format!("the gas TABLE has no index '{}' ({})", key.trim_end(), what)))
}

fn number(a: &Args, v: Value, what: &str) -> Result<f64> {
    match v {
        Value::Float(x) => Ok(x),
        Value::Int(i) => Ok(i as f64),
        other => Err(a.err(format!("{} must be a FLOTTANT, found {}", what, other.ty().name()))),
    }
}

fn sub_table(a: &Args, t: &Table, key: &str, what: &str) -> Result<Rc<RefCell<Table>>> {
    match req_entry(a, t, key, what)? {
        Value::Table(s) => Ok(s),
        other => {
            Err(a.err(format!("'{}' of the gas TABLE must be a TABLE, found {}", key.trim_end(), other.ty().name())))
        }
    }
}

fn list(a: &Args, t: &Table, key: &str, what: &str) -> Result<Rc<Vec<f64>>> {
    match req_entry(a, t, key, what)? {
        Value::ListReel(l) => Ok(l),
        other => {
            Err(a.err(format!("'{}' of the gas TABLE must be a LISTREEL, found {}", key.trim_end(), other.ty().name())))
        }
    }
}

/// The carried species ('ESPEULE', possibly absent) and the last one.
fn species(a: &Args, t: &Table, need_carried: bool) -> Result<(Vec<String>, String)> {
    let carried = match entry(t, "ESPEULE") {
        Some(Value::ListMots(l)) => l.iter().map(|s| s.trim_end().to_string()).collect(),
        Some(other) => {
            return Err(a.err(format!("'ESPEULE' of the gas TABLE must be a LISTMOTS, found {}", other.ty().name())))
        }
        None if need_carried => {
            return Err(a.err("the gas TABLE has no index 'ESPEULE' (the species of the equations)"))
        }
        None => vec![],
    };
    let last = match req_entry(a, t, "ESPNEULE", "the species not in the equations")? {
        Value::Mot(m) => m.trim_end().to_string(),
        other => return Err(a.err(format!("'ESPNEULE' of the gas TABLE must be a MOT, found {}", other.ty().name()))),
    };
    Ok((carried, last))
}

fn perfmult(a: &mut Args, dim: usize) -> Result<Vec<Value>> {
    let t: Rc<RefCell<Table>> = a.req()?;
    let mut f = Fields::read(a, dim)?;
    f.rho_y = Some(a.req()?);
    let t = t.borrow();
    let (carried, last) = species(a, &t, true)?;
    let (cp_t, cv_t) = (sub_table(a, &t, "CP", "cp per species")?, sub_table(a, &t, "CV", "cv per species")?);
    let all: Vec<&String> = carried.iter().chain(std::iter::once(&last)).collect();
    let heat = |tab: &Rc<RefCell<Table>>, name: &str| -> Result<Vec<f64>> {
        let tab = tab.borrow();
        all.iter().map(|s| number(a, req_entry(a, &tab, s, name)?, &format!("{} of '{}'", name, s))).collect()
    };
    let (cp, cv) = (heat(&cp_t, "CP")?, heat(&cv_t, "CV")?);
    f.species = carried;
    let res = f.each(a, |_, s| flow::perfect_mixture(s, &cp, &cv))?;
    Ok(vec![
        f.velocity(&res),
        f.scalar(&res, |p| p.pressure),
        f.scalar(&res, |p| p.temperature),
        f.fractions(&res),
        f.scalar(&res, |p| p.gamma),
    ])
}

fn perftemp(a: &mut Args, dim: usize) -> Result<Vec<Value>> {
    let t: Rc<RefCell<Table>> = a.req()?;
    let mut f = Fields::read(a, dim)?;
    let t = t.borrow();
    let (carried, last) = species(a, &t, false)?;
    let multi = entry(&t, "ESPEULE").is_some();
    if multi {
        f.rho_y = Some(a.req()?);
    }
    let passive: Option<Vec<String>> = match entry(&t, "SCALPASS") {
        Some(Value::ListMots(l)) => Some(l.iter().map(|s| s.trim_end().to_string()).collect()),
        Some(other) => {
            return Err(a.err(format!("'SCALPASS' of the gas TABLE must be a LISTMOTS, found {}", other.ty().name())))
        }
        None => None,
    };
    let rho_s: Option<Rc<Chpoint>> = match passive {
        Some(_) => Some(a.req()?),
        None => None,
    };
    let guess: Option<Rc<Chpoint>> = a.opt();
    let order = match req_entry(a, &t, "NORD", "degree of the cv polynomials")? {
        Value::Int(i) if i >= 0 => i as usize,
        other => return Err(a.err(format!("'NORD' of the gas TABLE must be an ENTIER >= 0, found {:?}", other))),
    };
    let gases = carried
        .iter()
        .chain(std::iter::once(&last))
        .map(|s| {
            let g = sub_table(a, &t, s, "the properties of a species")?;
            let g = g.borrow();
            let coefs = list(a, &g, "A", "cv polynomial")?;
            if coefs.len() != order + 1 {
                return Err(a.err(format!(
                    "'{}'.'A' must hold NORD + 1 = {} coefficients, found {}",
                    s,
                    order + 1,
                    coefs.len()
                )));
            }
            let r = number(a, req_entry(a, &g, "R", "gas constant")?, &format!("'{}'.'R'", s))?;
            Ok(PolyGas { a: coefs.to_vec(), r })
        })
        .collect::<Result<Vec<_>>>()?;
    f.species = carried;
    let res = f.each(a, |n, s| flow::perfect_poly(s, &gases, guess.as_ref().and_then(|g| g.get(n, "SCAL"))))?;
    let mut out = vec![f.velocity(&res), f.scalar(&res, |p| p.pressure), f.scalar(&res, |p| p.temperature)];
    if multi {
        out.push(f.fractions(&res));
    }
    if let (Some(names), Some(rs)) = (passive, rho_s) {
        let mut c = Chpoint::new(f.rho.nature);
        for &n in &f.rho.nodes {
            let rho = value_at(a, &f.rho, "density", n, "SCAL")?;
            for s in &names {
                c.add(n, s, value_at(a, &rs, "passive scalars", n, s)? / rho, false);
            }
        }
        out.push(Value::Chpo(Rc::new(c)));
    }
    out.push(f.scalar(&res, |p| p.gamma));
    Ok(out)
}

fn gfmp(a: &mut Args, dim: usize) -> Result<Vec<Value>> {
    let t: Rc<RefCell<Table>> = a.req()?;
    let phi: Rc<Chpoint> = a.req()?;
    let mut f = Fields::read(a, dim)?;
    let t = t.borrow();
    let (carried, _) = species(a, &t, true)?;
    let alpha: Option<Rc<Chpoint>> = match a.opt::<Rc<Chpoint>>() {
        Some(ry) => {
            f.rho_y = Some(ry);
            Some(a.req()?)
        }
        None if carried.is_empty() => None,
        None => return Err(a.missing("CHPOINT of partial densities (the TABLE names species in 'ESPEULE')")),
    };
    let phases = |g: &str, p: &str| -> Result<Vec<Stiffened>> {
        let (gam, pin) = (list(a, &t, g, "gamma of each species")?, list(a, &t, p, "p-infinity of each species")?);
        if gam.len() != carried.len() + 1 || pin.len() != carried.len() + 1 {
            return Err(a.err(format!(
                "'{}' and '{}' must hold {} values (the species not in the equations first)",
                g,
                p,
                carried.len() + 1
            )));
        }
        // The tables list the uncarried species first; fem::flow wants it last.
        let mut v: Vec<Stiffened> =
            gam.iter().zip(pin.iter()).map(|(&gamma, &p_inf)| Stiffened { gamma, p_inf }).collect();
        v.rotate_left(1);
        Ok(v)
    };
    let (minus, plus) = (phases("MGAM", "MPIN")?, phases("PGAM", "PPIN")?);
    f.species = carried;
    let species = f.species.clone();
    let res = f.each(a, |n, s| {
        let ph = phi.get(n, "SCAL").ok_or_else(|| format!("PHI has no 'SCAL' at node {}", n + 1))?;
        let al = match &alpha {
            Some(c) => species
                .iter()
                .map(|sp| {
                    c.get(n, sp).ok_or_else(|| format!("the volume fractions have no '{}' at node {}", sp, n + 1))
                })
                .collect::<std::result::Result<Vec<_>, _>>()?,
            None => vec![],
        };
        flow::stiffened(s, if ph <= 0.0 { &minus } else { &plus }, &al)
    })?;
    let mut out = vec![f.velocity(&res), f.scalar(&res, |p| p.pressure)];
    if alpha.is_some() {
        out.push(f.fractions(&res));
    }
    Ok(out)
}
