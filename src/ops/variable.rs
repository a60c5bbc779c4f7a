//! VARI (vari.notice): a field that varies with another one. Three forms:
//! - a curve applied to a field: `VARI CHPO EVOL (name)`, and
//!   `VARI MODL (MCHAML|CHPO) EVOL (support)` at the element points;
//! - a material whose properties are curves of a parameter (MATE … 'YOUN'
//!   EVOLUTIO) evaluated against a field of that parameter:
//!   `VARI 'NUAG' MODL MAT (MCHAML|CHPO) (support) (subtype)`;
//! - the water and steam tables: `VARI 'HLS' p (T)` … on FLOTTANTs,
//!   LISTREELs or one-component CHPOINTs.
//!
//! The numbers live in `props` (water laws, curves); the element-field
//! forms are in `variable_fields.rs`.

use super::variable_fields as vf;
use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::props::water::{self, WaterError};
use crate::value::{Chpoint, Model, Value};
use std::rc::Rc;

pub(crate) use vf::{element_materials, law_of, no_unevaluated_law};

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "VARI",
    signature: "VARI CHPOINT EVOLUTIO (name) | VARI MMODEL MCHAML|CHPOINT EVOLUTIO (support) | VARI 'NUAG' MMODEL MCHAML_MAT MCHAML|CHPOINT (support) (subtype) | VARI law X1 (X2)",
    doc: "A field through a curve; a material whose properties are EVOLUTIOs of a parameter, evaluated against a field of it (support NOEUD, GRAVITE, RIGIDITE (default), MASSE, STRESSES); or a water/steam law (IAPWS-IF97, SI units) of FLOTTANTs, LISTREELs or CHPOINTs: HLS, HVS, ROVAP (p (T), saturation without T), LATENT, TSATP (p), PSATT, DPSAT, MULIQ (T), PVAP, ZVAP (rho T), CPLIQ, ROLIQ, TLIQUID (p h), DHVDT, DHVDP, DHLDP, DRVDP, DRVDT, DZVDP, DZVDT, LBDALIQ (p T).",
    example: "h = vari 'HLS' 1.e5 350. ;",
    f: vari,
}];

/// How many inputs a water law takes.
#[derive(Clone, Copy)]
enum Inputs {
    One(fn(f64) -> water::Result<f64>),
    Two(fn(f64, f64) -> water::Result<f64>),
    /// (p, T), or p alone for the saturated state.
    OneOrTwo(fn(f64) -> water::Result<f64>, fn(f64, f64) -> water::Result<f64>),
}

/// At saturation: the law of (p, Tsat(p)).
fn at_sat(p: f64, f: fn(f64, f64) -> water::Result<f64>) -> water::Result<f64> {
    f(p, water::tsat(p)?)
}

/// Cast3M's names of the water laws (vari.notice, 3rd form).
const WATER: &[(&str, Inputs)] = &[
    ("CPLIQ", Inputs::Two(|p, h| water::cp_liquid(p, water::t_liquid(p, h)?))),
    ("HLS", Inputs::OneOrTwo(|p| at_sat(p, water::h_liquid), water::h_liquid)),
    ("HVS", Inputs::OneOrTwo(|p| at_sat(p, water::h_steam), water::h_steam)),
    ("LATENT", Inputs::One(|p| Ok(at_sat(p, water::h_steam)? - at_sat(p, water::h_liquid)?))),
    ("PSATT", Inputs::One(water::psat)),
    ("TSATP", Inputs::One(water::tsat)),
    ("PVAP", Inputs::Two(water::p_steam)),
    ("ROLIQ", Inputs::Two(|p, h| water::rho_liquid(p, water::t_liquid(p, h)?))),
    ("ROVAP", Inputs::OneOrTwo(|p| at_sat(p, water::rho_steam), water::rho_steam)),
    ("TLIQUID", Inputs::Two(water::t_liquid)),
    ("ZVAP", Inputs::Two(water::z_steam)),
    ("DHVDT", Inputs::Two(water::cp_steam)),
    ("DHVDP", Inputs::Two(water::dh_steam_dp)),
    ("DHLDP", Inputs::Two(water::dh_liquid_dp)),
    ("DPSAT", Inputs::One(water::dpsat_dt)),
    ("DZVDP", Inputs::Two(water::dz_steam_dp)),
    ("DZVDT", Inputs::Two(water::dz_steam_dt)),
    ("DRVDP", Inputs::Two(water::drho_steam_dp)),
    ("DRVDT", Inputs::Two(water::drho_steam_dt)),
    ("MULIQ", Inputs::One(water::mu_liquid)),
    ("LBDALIQ", Inputs::Two(water::lambda_liquid)),
];

/// The law a word names: its full name, or a unique beginning of at least
/// four letters (the notice writes TLIQ for TLIQUID; DHVD is ambiguous).
fn water_law(word: &str) -> Option<(&'static str, Inputs)> {
    let w = word.to_uppercase();
    if let Some(l) = WATER.iter().find(|(n, _)| *n == w) {
        return Some(*l);
    }
    let hits: Vec<_> = WATER.iter().filter(|(n, _)| w.len() >= 4 && n.starts_with(&w)).collect();
    (hits.len() == 1).then(|| *hits[0])
}

fn vari(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if let Some(Value::Mot(w)) = a.peek_right() {
        if let Some((name, law)) = water_law(&w) {
            a.word();
            return water_op(a, name, law);
        }
        if !super::args::keyword_matches(&w, "NUAG") {
            let names: Vec<&str> = WATER.iter().map(|(n, _)| *n).collect();
            return Err(a.err(format!(
                "{} is not a law of VARI: the water laws are {}; 'NUAG' evaluates a material",
                w,
                names.join(" ")
            )));
        }
    }
    if a.keyword(&["NUAG"]).is_some() {
        return vf::material(it, a);
    }
    match a.opt::<Rc<Model>>() {
        Some(model) => vf::model_curve(it, a, &model),
        None => vf::node_curve(a),
    }
}

/// One input of a water law: all inputs of a call are of one kind.
enum Input {
    Num(f64),
    List(Rc<Vec<f64>>),
    Field(Rc<Chpoint>),
}

impl Input {
    fn kind(&self) -> &'static str {
        match self {
            Input::Num(_) => "FLOTTANT",
            Input::List(_) => "LISTREEL",
            Input::Field(_) => "CHPOINT",
        }
    }
}

fn input(a: &mut Args) -> Option<Input> {
    a.opt_with(|v| match v {
        Value::Float(_) | Value::Int(_) => v.as_f64().map(Input::Num),
        Value::ListReel(l) => Some(Input::List(l.clone())),
        Value::Chpo(c) => Some(Input::Field(c.clone())),
        _ => None,
    })
}

/// The values of a one-component CHPOINT, node by node, with its component.
fn single(a: &Args, name: &str, c: &Chpoint) -> Result<(String, Vec<(usize, f64)>)> {
    let comps = c.components();
    if comps.len() != 1 {
        return Err(a.err(format!(
            "{}: a CHPOINT argument must have one component, this one has {}",
            name,
            if comps.is_empty() { "none".to_string() } else { comps.join(" ") }
        )));
    }
    let comp = comps[0].clone();
    let vals = c.entries().map(|(n, _, v)| (n, v)).collect();
    Ok((comp, vals))
}

fn water_op(a: &mut Args, name: &str, law: Inputs) -> Result<Vec<Value>> {
    const WHAT: &str = "FLOTTANT, LISTREEL or CHPOINT";
    let x1 = input(a).ok_or_else(|| a.missing(&format!("{} (the first input of {})", WHAT, name)))?;
    let x2 = match law {
        Inputs::One(_) => None,
        Inputs::Two(_) => Some(input(a).ok_or_else(|| a.missing(&format!("{} (the second input of {})", WHAT, name)))?),
        Inputs::OneOrTwo(..) => input(a),
    };
    if let Some(x2) = &x2 {
        if x2.kind() != x1.kind() {
            return Err(a.err(format!(
                "{}: the inputs must be of one type, not a {} and a {}",
                name,
                x1.kind(),
                x2.kind()
            )));
        }
    }
    let f = |x: f64, y: Option<f64>| -> std::result::Result<f64, WaterError> {
        match (law, y) {
            (Inputs::One(f), _) | (Inputs::OneOrTwo(f, _), None) => f(x),
            (Inputs::Two(f), Some(y)) | (Inputs::OneOrTwo(_, f), Some(y)) => f(x, y),
            (Inputs::Two(_), None) => unreachable!("a two-input law reads its second input"),
        }
    };
    let fail = |at: String, e: WaterError| a.err(format!("{}: {}{}", name, at, e));
    match (x1, x2) {
        (Input::Num(x), y) => {
            let y = y.map(|y| match y {
                Input::Num(y) => y,
                _ => unreachable!("same kinds"),
            });
            Ok(vec![Value::Float(f(x, y).map_err(|e| fail(String::new(), e))?)])
        }
        (Input::List(xs), y) => {
            let ys = match y {
                Some(Input::List(ys)) => Some(ys),
                _ => None,
            };
            if let Some(ys) = &ys {
                if ys.len() != xs.len() {
                    return Err(a.err(format!("{}: the lists have {} and {} values", name, xs.len(), ys.len())));
                }
            }
            let out = xs
                .iter()
                .enumerate()
                .map(|(i, x)| {
                    f(*x, ys.as_ref().map(|ys| ys[i])).map_err(|e| fail(format!("value {} of the list: ", i + 1), e))
                })
                .collect::<Result<Vec<f64>>>()?;
            Ok(vec![Value::ListReel(Rc::new(out))])
        }
        (Input::Field(c1), y) => {
            let (comp, v1) = single(a, name, &c1)?;
            let c2 = match y {
                Some(Input::Field(c2)) => {
                    Some(single(a, name, &c2)?.1.into_iter().collect::<std::collections::HashMap<_, _>>())
                }
                _ => None,
            };
            let mut out = Vec::with_capacity(v1.len());
            for (n, x) in v1 {
                let y = match &c2 {
                    Some(m) => Some(*m.get(&n).ok_or_else(|| {
                        a.err(format!(
                            "{}: node {} has a value in the first CHPOINT but not in the second",
                            name,
                            n + 1
                        ))
                    })?),
                    None => None,
                };
                out.push((n, f(x, y).map_err(|e| fail(format!("node {}: ", n + 1), e))?));
            }
            let c = Chpoint::from_entries(c1.nature, out.iter().map(|(n, v)| (*n, comp.as_str(), *v)));
            Ok(vec![Value::Chpo(Rc::new(c))])
        }
    }
}
