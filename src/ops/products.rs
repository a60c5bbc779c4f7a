//! Products and combinations: PSCA (scalar product of two vectors, two
//! node fields or two element fields) and XTY (of two node fields), each
//! over paired component lists; PVEC (vector product of two vectors); NORM
//! (Euclidean length of a vector); COLI
//! (linear combination of fields).

use super::arith;
use super::{Args, OpDef, PointId};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::arith::Bin;
use crate::value::model::MchamlZone;
use crate::value::{Chpoint, Mchaml, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "PSCA",
        signature: "PSCA POINT POINT | PSCA CHPOINT CHPOINT LISTMOTS LISTMOTS | PSCA MCHAML MCHAML LISTMOTS LISTMOTS",
        doc: "Scalar product: of two vectors (FLOTTANT), of two node fields over paired components, node by node (CHPOINT, component SCAL), or of two element fields point by point (MCHAML, component SCAL).",
        example: "w = psca u f (mots 'UX' 'UY') (mots 'FX' 'FY') ;",
        f: psca,
    },
    OpDef {
        name: "XTY",
        signature: "XTY CHPOINT CHPOINT LISTMOTS LISTMOTS",
        doc: "Scalar product of two node fields: the sum over nodes of the products of the paired components.",
        example: "w = xty u f (mots 'UX' 'UY') (mots 'FX' 'FY') ;",
        f: xty,
    },
    OpDef {
        name: "PVEC",
        signature: "PVEC POINT (POINT in 3D) | PVEC CHPOINT LISTMOTS (CHPOINT LISTMOTS in 3D) LISTMOTS",
        doc: "Vector product of n-1 vectors in dimension n (in 2D the vector turned a quarter turn), of points or of node fields over listed components.",
        example: "n = pvec (1. 0. 0.) (0. 1. 0.) ;",
        f: super::vector_product::pvec,
    },
    OpDef {
        name: "NORM",
        signature: "NORM POINT",
        doc: "Euclidean norm of a vector (a POINT read as its coordinates).",
        example: "l = norm (3. 4.) ;",
        f: norm,
    },
    OpDef {
        name: "DIST",
        signature: "DIST POINT POINT",
        doc: "Distance between two points.",
        example: "d = p1 dist p2 ;",
        f: dist,
    },
    OpDef {
        name: "COLI",
        signature: "COLI OBJ1 a1 (OBJ2 a2 …)",
        doc: "Linear combination a1 OBJ1 + a2 OBJ2 + … of CHPOINTs (or MCHAMLs), each weighed by the number after it.",
        example: "u = coli u1 0.5 u2 2. ;",
        f: coli,
    },
];

fn norm(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let p = a.req::<PointId>()?;
    Ok(vec![Value::Float(it.nodes.get(p.0).iter().map(|x| x * x).sum::<f64>().sqrt())])
}

fn dist(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let p = a.req::<PointId>()?;
    let q = a.req::<PointId>()?;
    let (x, y) = (it.nodes.get(p.0), it.nodes.get(q.0));
    let d = (0..it.opts.dime.clamp(1, 3)).map(|i| (x[i] - y[i]).powi(2)).sum::<f64>().sqrt();
    Ok(vec![Value::Float(d)])
}

/// Σ a_i OBJ_i with the field algebra of `*` and `+` (supports united,
/// a value missing on one side reading as 0).
fn coli(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let field = |v: &Value| matches!(v, Value::Chpo(_) | Value::Mchaml(_)).then(|| v.clone());
    let mut sum: Option<Value> = None;
    while let Some(obj) = a.opt_with(field) {
        let w = a.opt_num().ok_or_else(|| a.missing("FLOTTANT (the weight of the field before it)"))?;
        let term = arith::apply(it, a, Bin::Mul, &Value::Float(w), &obj)?;
        sum = Some(match sum {
            None => term,
            Some(s) => {
                if s.ty() != term.ty() {
                    return Err(a.err(format!("cannot combine a {} with a {}", s.type_name(), term.type_name())));
                }
                arith::apply(it, a, Bin::Add, &s, &term)?
            }
        });
    }
    sum.map(|s| vec![s]).ok_or_else(|| a.missing("CHPOINT or MCHAML"))
}

/// Either operand pair PSCA accepts, read in one go so that the first
/// operand's type decides which form is meant.
enum Pair {
    Points(PointId),
    Fields(Rc<Chpoint>),
    Elements(Rc<Mchaml>),
}

fn psca(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let first = a
        .opt_with(|v| match v {
            Value::Point(p) => Some(Pair::Points(PointId(*p))),
            Value::Chpo(c) => Some(Pair::Fields(c.clone())),
            Value::Mchaml(m) => Some(Pair::Elements(m.clone())),
            _ => None,
        })
        .ok_or_else(|| a.missing("POINT, CHPOINT or MCHAML"))?;
    match first {
        Pair::Points(p) => {
            let q = a.req::<PointId>()?;
            let (x, y) = (it.nodes.get(p.0), it.nodes.get(q.0));
            Ok(vec![Value::Float(x.iter().zip(y).map(|(u, v)| u * v).sum())])
        }
        Pair::Fields(c1) => {
            let c2 = a.req::<Rc<Chpoint>>()?;
            pointwise_product(a, &c1, &c2)
        }
        Pair::Elements(m1) => {
            let m2 = a.req::<Rc<Mchaml>>()?;
            element_product(a, &m1, &m2)
        }
    }
}

fn xty(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let c1 = a.req::<Rc<Chpoint>>()?;
    let c2 = a.req::<Rc<Chpoint>>()?;
    field_product(a, &c1, &c2)
}

/// A list of component names.
type Comps = Rc<Vec<String>>;

/// The two component lists, of equal length.
fn comp_lists(a: &mut Args) -> Result<(Comps, Comps)> {
    let l1 = a.req::<Rc<Vec<String>>>()?;
    let l2 = a.req::<Rc<Vec<String>>>()?;
    if l1.len() != l2.len() {
        return Err(a.err(format!(
            "the component lists have {} and {} words: they pair components one to one",
            l1.len(),
            l2.len()
        )));
    }
    Ok((l1, l2))
}

/// A component of the lists that a field lacks adds nothing (psca.notice:
/// the sum runs over the components each field defines; G_THETA pairs
/// the model's full list of displacement names with a field of
/// translations only), but some pair must exist in both fields.
fn check_comps(a: &Args, c1: &Chpoint, c2: &Chpoint, l1: &[String], l2: &[String]) -> Result<()> {
    let (h1, h2) = (c1.components(), c2.components());
    if l1.iter().zip(l2).any(|(x, y)| h1.contains(x) && h2.contains(y)) {
        return Ok(());
    }
    let (which, missing, have) = match l1.iter().find(|c| !h1.contains(c)) {
        Some(c) => ("first", Some(c), h1),
        None => ("second", l2.iter().find(|c| !h2.contains(c)), h2),
    };
    match missing {
        Some(c) => Err(a.err(format!("the {} field has no component {} (it has {})", which, c, have.join(" ")))),
        None => Ok(()),
    }
}

/// PSCA on node fields (psca.notice): at every node, Σ_i c1[l1_i] c2[l2_i]
/// as a 'SCAL' field, over the nodes where some pair is defined in both.
fn pointwise_product(a: &mut Args, c1: &Chpoint, c2: &Chpoint) -> Result<Vec<Value>> {
    let (l1, l2) = comp_lists(a)?;
    check_comps(a, c1, c2, &l1, &l2)?;
    let mut out = Chpoint::new(c1.nature);
    for &n in &c1.nodes {
        let mut s = None;
        for (k1, k2) in l1.iter().zip(l2.iter()) {
            if let (Some(x), Some(y)) = (c1.get(n, k1), c2.get(n, k2)) {
                s = Some(s.unwrap_or(0.0) + x * y);
            }
        }
        if let Some(s) = s {
            out.add(n, "SCAL", s, false);
        }
    }
    Ok(vec![Value::Chpo(Rc::new(out))])
}

/// Σ over nodes of Σ_i c1[l1_i] c2[l2_i]. A node where either value is
/// missing adds nothing (a field is zero where it is not defined); a
/// component that the field does not have at all is a mistake in the deck.
fn field_product(a: &mut Args, c1: &Chpoint, c2: &Chpoint) -> Result<Vec<Value>> {
    let (l1, l2) = comp_lists(a)?;
    check_comps(a, c1, c2, &l1, &l2)?;
    let mut s = 0.0;
    for (n, comp, v) in c1.entries() {
        for (k, _) in l1.iter().enumerate().filter(|(_, c)| *c == comp) {
            s += v * c2.get(n, &l2[k]).unwrap_or(0.0);
        }
    }
    Ok(vec![Value::Float(s)])
}

/// A value of an element field at (element, point): a point value, else
/// a constant of the zone (material data).
fn zone_value(z: &MchamlZone, comp: &str, e: usize, p: usize) -> Option<f64> {
    match z.comps.iter().position(|c| c == comp) {
        Some(i) => z.values.get(e)?.get(p)?.get(i).copied(),
        None => z.constants.get(comp).copied(),
    }
}

/// Point by point over zones that match one to one (same elements, same
/// points), as Cast3M requires of the two fields.
fn element_product(a: &mut Args, m1: &Mchaml, m2: &Mchaml) -> Result<Vec<Value>> {
    let (l1, l2) = comp_lists(a)?;
    if m1.zones.len() != m2.zones.len() {
        return Err(a.err(format!("the fields have {} and {} zones", m1.zones.len(), m2.zones.len())));
    }
    let mut out = Mchaml { subtype: "SCALAIRE".into(), zones: vec![] };
    for (k, (z1, z2)) in m1.zones.iter().zip(&m2.zones).enumerate() {
        let shape = |z: &MchamlZone| z.values.iter().map(Vec::len).collect::<Vec<_>>();
        if z1.mesh.parts != z2.mesh.parts || shape(z1) != shape(z2) {
            return Err(a.err(format!("zone {} of the two fields is not on the same elements and points", k + 1)));
        }
        for (z, list, which) in [(z1, &l1, "first"), (z2, &l2, "second")] {
            if let Some(c) = list.iter().find(|c| !z.comps.contains(c) && !z.constants.contains_key(*c)) {
                return Err(a.err(format!("the {} field has no component {}", which, c)));
            }
        }
        let mut nz = MchamlZone { mesh: z1.mesh.clone(), element: z1.element.clone(), ..Default::default() };
        nz.comps = vec!["SCAL".into()];
        nz.at_nodes = z1.at_nodes;
        for (e, pts) in z1.values.iter().enumerate() {
            let row = (0..pts.len())
                .map(|p| {
                    let s = l1.iter().zip(l2.iter()).map(|(c1, c2)| {
                        zone_value(z1, c1, e, p).unwrap_or(0.0) * zone_value(z2, c2, e, p).unwrap_or(0.0)
                    });
                    vec![s.sum()]
                })
                .collect();
            nz.values.push(row);
        }
        out.zones.push(nz);
    }
    Ok(vec![Value::Mchaml(Rc::new(out))])
}
