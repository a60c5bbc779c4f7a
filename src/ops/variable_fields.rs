//! The element-field forms of VARI (see `variable.rs`): a curve applied to
//! a field, and a material whose properties are curves of a parameter
//! (MATE … 'YOUN' EVOLUTIO) evaluated point by point; and how RIGI takes
//! such an evaluated material: a property given point by point enters an
//! element as its mean over the element's points (the element library
//! takes one material per element).

use super::model::formulation;
use super::post::zone_of;
use super::Args;
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::element::{gauss_points, Formulation};
use crate::fem::material::Material;
use crate::fem::mesh::{ElemType, Mesh, Part};
use crate::fem::shape;
use crate::props::curve;
use crate::value::model::{Curve, MchamlZone, ModelZone};
use crate::value::{Chpoint, Evolution, Mchaml, Model, Value};
use std::rc::Rc;

/// The curve of a property given as an EVOLUTIO (MATE): its abscissa must
/// name the parameter the property depends on.
pub(crate) fn law_of(a: &Args, prop: &str, ev: &Evolution) -> Result<Curve> {
    let c = match ev.curves.as_slice() {
        [c] => c,
        cs => return Err(a.err(format!("{}: give one curve, this EVOLUTIO has {}", prop, cs.len()))),
    };
    if c.x_name.trim().is_empty() {
        return Err(a.err(format!(
            "{}: the EVOLUTIO's abscissa has no name; name the parameter {} depends on: EVOL 'MANU' 'T' lx '{}' ly",
            prop, prop, prop
        )));
    }
    curve::check(&c.x, &c.y).map_err(|e| a.err(format!("{}: {}", prop, e)))?;
    Ok(c.clone())
}

/// RIGI (and any operator that needs numbers) cannot use a property that
/// is still a curve: say how to evaluate it.
pub(crate) fn no_unevaluated_law(a: &Args, zone: &ModelZone, fields: &[Rc<Mchaml>]) -> Result<()> {
    for z in fields.iter().flat_map(|f| f.zones.iter()) {
        let ours = z.mesh == zone.mesh || zone.mesh.parts.iter().any(|p| z.mesh.parts.first() == Some(p));
        if let (true, Some((k, c))) = (ours, z.laws.iter().next()) {
            return Err(a
                .err(format!("{} depends on {} (an EVOLUTIO): evaluate the material first", k, c.x_name))
                .note(format!("ma2 = VARI 'NUAG' model material field ; with a field of component {}", c.x_name)));
        }
    }
    Ok(())
}

/// Where a field puts values on one part: each zone that holds it, with
/// the index of the part's first element in that zone.
fn locate<'a>(m: &'a Mchaml, part: &'a Part) -> impl Iterator<Item = (&'a MchamlZone, usize)> + 'a {
    m.zones.iter().filter_map(move |z| {
        let mut off = 0;
        for p in &z.mesh.parts {
            if p == part {
                return Some((z, off));
            }
            off += p.len();
        }
        None
    })
}

/// The materials of the elements of one part: `base` with, element by
/// element, the mean over its points of each property a field gives point
/// by point (VARI 'NUAG', MANU 'CHML'). One material when none does.
pub(crate) fn element_materials(
    a: &Args,
    base: &Material,
    part: &Part,
    fields: &[Rc<Mchaml>],
) -> Result<Vec<Material>> {
    let mut mats: Vec<Material> = Vec::new();
    for (z, off) in fields.iter().flat_map(|f| locate(f, part)) {
        let props: Vec<(usize, &String)> =
            z.comps.iter().enumerate().filter(|(_, c)| Material::default().set(c, 0.0)).collect();
        if props.is_empty() || z.values.is_empty() {
            continue;
        }
        if z.values.len() < off + part.len() {
            return Err(a.err("the material field has fewer elements than the model"));
        }
        if mats.is_empty() {
            mats = vec![base.clone(); part.len()];
        }
        for (e, m) in mats.iter_mut().enumerate() {
            let pts = &z.values[off + e];
            for (k, name) in &props {
                let mean = pts.iter().map(|p| p[*k]).sum::<f64>() / pts.len().max(1) as f64;
                m.set(name, mean);
            }
        }
    }
    // Zones that cover some of the part's elements without holding the
    // part itself (a material made of pieces, REDU or ET of several, over
    // a model reduced to another set of elements): element by element.
    let pieces: Vec<&MchamlZone> = fields
        .iter()
        .flat_map(|f| f.zones.iter())
        .filter(|z| !z.mesh.parts.iter().any(|p| p == part) && z.mesh.parts.iter().any(|p| p.ty == part.ty))
        .collect();
    if !pieces.is_empty() {
        let found = by_element(part, &pieces);
        if found.iter().any(Option::is_some) {
            if mats.is_empty() {
                mats = vec![base.clone(); part.len()];
            }
            for (m, hits) in mats.iter_mut().zip(&found) {
                for (z, k) in hits.iter().flatten() {
                    take_zone(m, z, *k);
                }
            }
        }
    }
    if mats.is_empty() {
        mats.push(base.clone());
    }
    Ok(mats)
}

/// For each element of `part`, the zones among `zones` holding an element
/// with the same type and nodes, and its index in the zone.
fn by_element<'a>(part: &Part, zones: &[&'a MchamlZone]) -> Vec<Option<Vec<(&'a MchamlZone, usize)>>> {
    let key = |ty: ElemType, e: &[usize]| {
        let mut k = e.to_vec();
        k.sort_unstable();
        (ty, k)
    };
    let mut found: Vec<Option<Vec<(&MchamlZone, usize)>>> = vec![None; part.len()];
    let mine: std::collections::HashMap<(ElemType, Vec<usize>), usize> =
        part.elems().enumerate().map(|(e, n)| (key(part.ty, n), e)).collect();
    for z in zones {
        let mut k = 0;
        for p in &z.mesh.parts {
            for n in p.elems() {
                if let Some(&e) = mine.get(&key(p.ty, n)) {
                    found[e].get_or_insert_with(Vec::new).push((*z, k));
                }
                k += 1;
            }
        }
    }
    found
}

/// What zone `z` says of its element `k`: its constants, its vector, and
/// the mean over the element's points of each property given point by point.
fn take_zone(m: &mut Material, z: &MchamlZone, k: usize) {
    for (name, v) in &z.constants {
        m.set(name, *v);
    }
    if let Some(v) = z.vectors.get("VECT") {
        m.vect = Some(*v);
    }
    let Some(pts) = z.values.get(k) else { return };
    for (c, name) in z.comps.iter().enumerate() {
        if Material::default().set(name, 0.0) {
            let mean = pts.iter().map(|p| p[c]).sum::<f64>() / pts.len().max(1) as f64;
            m.set(name, mean);
        }
    }
}

const SUPPORTS: &[&str] = &["NOEUD", "GRAVITE", "RIGIDITE", "MASSE", "STRESSES"];

/// The points of an element a result is given at.
#[derive(Clone, Copy, PartialEq)]
enum Support {
    Nodes,
    Centre,
    /// RIGIDITE, MASSE, STRESSES: gibi integrates and outputs at one set.
    Points,
}

fn support(a: &mut Args) -> Support {
    match a.keyword(SUPPORTS) {
        Some("NOEUD") => Support::Nodes,
        Some("GRAVITE") => Support::Centre,
        _ => Support::Points,
    }
}

/// Reference coordinates of the support points of one element type.
fn ref_points(form: Formulation, ty: ElemType, s: Support) -> Vec<[f64; 3]> {
    match s {
        Support::Nodes => shape::ref_nodes(ty),
        Support::Centre => {
            let nodes = shape::ref_nodes(ty);
            let mut c = [0.0; 3];
            for p in &nodes {
                (0..3).for_each(|i| c[i] += p[i] / nodes.len() as f64);
            }
            vec![c]
        }
        Support::Points => gauss_points(form, ty).into_iter().map(|(p, _)| p).collect(),
    }
}

/// The field a parameter is read from.
#[derive(Clone)]
enum Source {
    Nodes(Rc<Chpoint>),
    Elements(Rc<Mchaml>),
}

impl Source {
    fn read(a: &mut Args) -> Result<Source> {
        if let Some(m) = a.opt::<Rc<Mchaml>>() {
            return Ok(Source::Elements(m));
        }
        match a.opt::<Rc<Chpoint>>() {
            Some(c) => Ok(Source::Nodes(c)),
            None => Err(a.missing("MCHAML or CHPOINT (the field of the parameter)")),
        }
    }

    fn components(&self) -> Vec<String> {
        match self {
            Source::Nodes(c) => c.components(),
            Source::Elements(m) => {
                let mut v: Vec<String> = Vec::new();
                for c in m.zones.iter().flat_map(|z| z.comps.iter().chain(z.constants.keys())) {
                    if !v.contains(c) {
                        v.push(c.clone());
                    }
                }
                v
            }
        }
    }

    /// The parameter `comp` at the points `refs` of element `e` of `part`.
    fn at(&self, a: &Args, comp: &str, part: &Part, e: usize, refs: &[[f64; 3]], s: Support) -> Result<Vec<f64>> {
        match self {
            Source::Nodes(c) => {
                let vals = part
                    .elem(e)
                    .iter()
                    .map(|n| c.get(*n, comp).ok_or_else(|| a.err(format!("node {} has no {} value", n + 1, comp))))
                    .collect::<Result<Vec<f64>>>()?;
                Ok(refs
                    .iter()
                    .map(|p| shape::eval(part.ty, *p).n.iter().zip(&vals).map(|(n, v)| n * v).sum())
                    .collect())
            }
            Source::Elements(m) => {
                let (z, off) = locate(m, part)
                    .find(|(z, _)| z.constants.contains_key(comp) || z.comps.iter().any(|c| c == comp))
                    .ok_or_else(|| {
                        a.err(format!(
                            "the field has no {} value on the {} elements of the model",
                            comp,
                            part.ty.name()
                        ))
                    })?;
                if let Some(v) = z.constants.get(comp) {
                    return Ok(vec![*v; refs.len()]);
                }
                let k = z.comps.iter().position(|c| c == comp).expect("the zone was chosen for this component");
                let pts = z.values.get(off + e).ok_or_else(|| a.err("the field has fewer elements than the model"))?;
                let vals: Vec<f64> = pts.iter().map(|p| p[k]).collect();
                match vals.len() {
                    n if n == refs.len() => Ok(vals),
                    1 => Ok(vec![vals[0]; refs.len()]),
                    n if s == Support::Centre => Ok(vec![vals.iter().sum::<f64>() / n as f64]),
                    n => Err(a.err(format!(
                        "the field gives {} {} values per element where the result needs {}: give it at the same points (NOEUD, GRAVITE, or RIGIDITE by default)",
                        n,
                        comp,
                        refs.len()
                    ))),
                }
            }
        }
    }
}

/// The component a curve reads: the field's only one, or the one its
/// abscissa names.
fn pick(a: &Args, src: &Source, c: &Curve) -> Result<String> {
    let comps = src.components();
    if comps.len() == 1 {
        return Ok(comps[0].clone());
    }
    comps.iter().find(|x| **x == c.x_name).cloned().ok_or_else(|| {
        a.err(format!(
            "the field has components {}: name the one to use as the curve's abscissa (it is '{}')",
            comps.join(" "),
            c.x_name
        ))
    })
}

fn one_curve(a: &mut Args) -> Result<Curve> {
    let ev = a.req::<Rc<Evolution>>()?;
    let c = ev.curves.first().ok_or_else(|| a.err("the EVOLUTIO has no curve"))?;
    curve::check(&c.x, &c.y).map_err(|e| a.err(e))?;
    Ok(c.clone())
}

/// The curve at `x`; `label` names the property in errors ("YOUN: ").
fn eval(a: &Args, label: &str, c: &Curve, x: f64) -> Result<f64> {
    curve::eval(&c.x, &c.y, x).map_err(|e| a.err(format!("{}{} = {}: {}", label, c.x_name, x, e)))
}

/// `VARI CHPO EVOL (name)`: the curve of each node's value.
pub(crate) fn node_curve(a: &mut Args) -> Result<Vec<Value>> {
    let ch = a.req::<Rc<Chpoint>>()?;
    let c = one_curve(a)?;
    let name = a.opt_mot().unwrap_or_else(|| if c.y_name.is_empty() { "SCAL".into() } else { c.y_name.clone() });
    let comp = pick(a, &Source::Nodes(ch.clone()), &c)?;
    let mut out = Vec::new();
    for (n, k, v) in ch.entries() {
        if k == comp {
            out.push((n, eval(a, "", &c, v)?));
        }
    }
    let res = Chpoint::from_entries(ch.nature, out.iter().map(|(n, v)| (*n, name.as_str(), *v)));
    Ok(vec![Value::Chpo(Rc::new(res))])
}

/// `VARI MODL (MCHAML|CHPO) EVOL (support)`: a SCALAIRE element field.
pub(crate) fn model_curve(_: &mut Interp, a: &mut Args, model: &Model) -> Result<Vec<Value>> {
    let src = Source::read(a)?;
    let c = one_curve(a)?;
    let s = support(a);
    let comp = pick(a, &src, &c)?;
    let mut out = Mchaml { subtype: "SCALAIRE".into(), zones: vec![] };
    for zone in &model.zones {
        let form = formulation(zone);
        for part in &zone.mesh.parts {
            let refs = ref_points(form, part.ty, s);
            let mut z = MchamlZone {
                mesh: Mesh::single(part.clone()),
                element: zone.element.clone(),
                comps: vec!["SCAL".into()],
                at_nodes: s == Support::Nodes,
                ..Default::default()
            };
            for e in 0..part.len() {
                let xs = src.at(a, &comp, part, e, &refs, s)?;
                z.values.push(xs.iter().map(|x| eval(a, "", &c, *x).map(|y| vec![y])).collect::<Result<_>>()?);
            }
            out.zones.push(z);
        }
    }
    Ok(vec![Value::Mchaml(Rc::new(out))])
}

/// `VARI 'NUAG' MODL MAT (MCHAML|CHPO) (support) (subtype)`: the material
/// with each property that is a curve replaced by its values at the
/// support points; constant properties stay constants.
pub(crate) fn material(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let model = a.req::<Rc<Model>>()?;
    let mat = a.req::<Rc<Mchaml>>()?;
    let src = Source::read(a)?;
    let s = support(a);
    let subtype = a.opt_mot().unwrap_or_else(|| mat.subtype.clone());
    let mut out = Mchaml { subtype, zones: vec![] };
    for z in &mat.zones {
        if z.laws.is_empty() {
            out.zones.push(z.clone());
            continue;
        }
        let mz = zone_of(&model, z).ok_or_else(|| a.err("the material does not belong to this model"))?;
        let form = formulation(mz);
        if !z.constants.is_empty() || !z.vectors.is_empty() {
            out.zones.push(MchamlZone { laws: Default::default(), ..z.clone() });
        }
        for part in &z.mesh.parts {
            let refs = ref_points(form, part.ty, s);
            let mut nz = MchamlZone {
                mesh: Mesh::single(part.clone()),
                element: z.element.clone(),
                comps: z.laws.keys().cloned().collect(),
                at_nodes: s == Support::Nodes,
                ..Default::default()
            };
            for e in 0..part.len() {
                let mut pts = vec![Vec::with_capacity(z.laws.len()); refs.len()];
                for (name, c) in &z.laws {
                    let xs = src.at(a, &c.x_name, part, e, &refs, s)?;
                    for (p, x) in pts.iter_mut().zip(xs) {
                        p.push(eval(a, &format!("{}: ", name), c, x)?);
                    }
                }
                nz.values.push(pts);
            }
            out.zones.push(nz);
        }
    }
    Ok(vec![Value::Mchaml(Rc::new(out))])
}

/// The material `mat` with each property that is a curve replaced by its
/// values at the element points, the parameter each curve names read from
/// the field `param` gives for that name (PASAPAS: the CHARGEMENT's part
/// of that name at the step's time). Zones without curves are kept.
pub(crate) fn material_with(
    a: &Args,
    model: &Model,
    mat: &Mchaml,
    param: &mut dyn FnMut(&str) -> Result<Value>,
) -> Result<Mchaml> {
    let mut out = Mchaml { subtype: mat.subtype.clone(), zones: vec![] };
    let mut sources: Vec<(String, Source)> = Vec::new();
    for z in &mat.zones {
        if z.laws.is_empty() {
            out.zones.push(z.clone());
            continue;
        }
        let mz = zone_of(model, z).ok_or_else(|| a.err("the material does not belong to this model"))?;
        let form = formulation(mz);
        if !z.constants.is_empty() || !z.vectors.is_empty() {
            out.zones.push(MchamlZone { laws: Default::default(), ..z.clone() });
        }
        for c in z.laws.values() {
            if sources.iter().all(|(n, _)| *n != c.x_name) {
                let src = match param(&c.x_name)? {
                    Value::Chpo(f) => Source::Nodes(f),
                    Value::Mchaml(f) => Source::Elements(f),
                    v => {
                        return Err(a.err(format!(
                            "the {} field is a {}, not a CHPOINT or MCHAML",
                            c.x_name,
                            v.type_name()
                        )))
                    }
                };
                sources.push((c.x_name.clone(), src));
            }
        }
        for part in &z.mesh.parts {
            let refs = ref_points(form, part.ty, Support::Points);
            let mut nz = MchamlZone {
                mesh: Mesh::single(part.clone()),
                element: z.element.clone(),
                comps: z.laws.keys().cloned().collect(),
                ..Default::default()
            };
            for e in 0..part.len() {
                let mut pts = vec![Vec::with_capacity(z.laws.len()); refs.len()];
                for (name, c) in &z.laws {
                    let src = &sources.iter().find(|(n, _)| *n == c.x_name).expect("read above").1;
                    let comps = src.components();
                    let comp = if comps.len() == 1 { comps[0].clone() } else { c.x_name.clone() };
                    let xs = src.at(a, &comp, part, e, &refs, Support::Points)?;
                    for (p, x) in pts.iter_mut().zip(xs) {
                        p.push(eval(a, &format!("{}: ", name), c, x)?);
                    }
                }
                nz.values.push(pts);
            }
            out.zones.push(nz);
        }
    }
    Ok(out)
}
