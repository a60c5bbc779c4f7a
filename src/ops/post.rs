//! Element fields and loads from models: SIGM, EPSI, VMIS, CHAN, PRES, MASS.

use super::model::{formulation, material_for, zone_mode};
use super::{dofs, Args, OpDef};
use crate::error::{Error, Result};
use crate::eval::Interp;
use crate::fem::element::{self, GaussField};
use crate::fem::mesh::{ElemType, Mesh};
use crate::fem::meshing as mg;
use crate::value::model::{MchamlZone, ModelZone};
use crate::value::rigidity::{Subtype, Symmetry};
use crate::value::{Chpoint, Mchaml, Model, Nature, Rigidite, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef { name: "SIGM", signature: "SIGM ('LINE') MMODEL MCHAML (MCHAML) CHPOINT", doc: "Elastic stresses (SMXX … for massive elements, EFFX … MOMZ resultants for bars and beams, N11 N22 N12 M11 M22 M12 V1 V2 for shells) at the element points.", example: "sig = sigm mo ma u ;", f: sigm },
    OpDef { name: "EPSI", signature: "EPSI ('LINE') MMODEL (MCHAML) CHPOINT", doc: "Strains (EPXX … GAXY; generalised strains for bars and beams; EPSS EPTT GAST RTSS RTTT RTST for shells).", example: "eps = epsi mo ma u ;", f: epsi },
    OpDef { name: "GRAD", signature: "GRAD MMODEL (MCHAML) CHPOINT|MCHAML_NOEUD (MCHAML)", doc: "Gradient of the displacements of a massive model at its stress points: the nine terms UX,X UX,Y UX,Z UY,X … UZ,Z (those along Z zero in the plane; UR,R UR,Z UR,T UZ,R … UT,T in AXIS, UT,T = UR/R). The displacements may be a CHPOINT or an element field at the nodes (CHAN 'CHAM' … 'NOEUD'). On a THERMIQUE model, the temperature gradient T,X T,Y (T,Z), or T,R T,Z in AXIS.", example: "g = grad mo u ;", f: grad },
    OpDef { name: "VMIS", signature: "VMIS MMODEL MCHAML_STRESS (MCHAML)", doc: "Von Mises equivalent stress (the beam formula for bars and beams).", example: "vm = vmis mo sig ma ;", f: vmis },
    OpDef { name: "CHAN", signature: "CHAN 'POI1'|QUA8|TRI6|SEG3|QUA4|TRI3|SEG2 GEO | CHAN 'CHPO'|'NOEUD'|'GRAVITE' MMODEL MCHAML ('MOYE'|'SOMM') | CHAN 'RIGIDITE'|'MASSE'|'STRESSES' MMODEL MCHAML (subtype) | CHAN 'INCO' RIGIDITE LISTMOTS LISTMOTS | CHAN 'ATTRIBUT' CHPOINT 'NATURE' word | CHAN 'CHAM' CHPOINT GEO|MMODEL ('NOEUD'|'GRAVITE'|'RIGIDITE'|'MASSE'|'STRESSES') (subtype) | CHAN 'TYPE' MCHAML word | CHAN 'MAJU'|'MINU' MOT | CHAN 'TABL' CHARGEMENT MOT", doc: "Change the type or attributes of an object.", example: "pts = chan 'POI1' l ;", f: chan },
    OpDef { name: "PRES", signature: "PRES 'MASS' MMODEL (MCHAML) VALUE GEO | PRES 'COQU' MMODEL VALUE ('NORM') | PRES MMODEL_PRESSION 'PRES' VALUE|CHPOINT", doc: "Of a pressure model (MODE … 'CHARGEMENT' 'PRESSION'): the pressure at the element nodes, an MCHAML for BSIG (positive along the left normal of each oriented line SEG2 SEG3 in 2D, along x_xi ^ x_eta of each surface TRI3 QUA4 TRI6 QUA8 in TRID). Otherwise: Nodal forces equivalent to a pressure on edges/faces of a massive model (positive towards the solid; in plane stress for the DIM3 thickness of the characteristics MCHAML when given, else per unit thickness), or on every element of a shell model (positive along the element normal).", example: "f = pres 'MASS' mo 10. haut ;", f: pres },
    OpDef { name: "MASS", signature: "MASS MMODEL MCHAML (MCHAML) ('LUMP') | MASS ('DEPL') ('ROTA') (comps) VALUE GEO", doc: "Mass matrix (consistent, or lumped with 'LUMP'), or point masses on the given unknowns of every node of GEO.", example: "m = mass mo ma ;", f: mass },
    OpDef { name: "LUMP", signature: "LUMP MMODEL MCHAML (MCHAML)", doc: "Lumped (diagonal) mass matrix of a model.", example: "m = lump mo ma ;", f: lump },
];

fn fem_err(e: element::FemError) -> Error {
    Error::runtime(e.to_string())
}

/// The model, the material fields and (optionally) the displacement field.
/// A model, its material fields and an optional displacement field.
pub(crate) type ModelArgs = (Rc<Model>, Vec<Rc<Mchaml>>, Option<Rc<Chpoint>>);

pub(crate) fn model_args(a: &mut Args) -> Result<ModelArgs> {
    a.keyword(&["LINE"]);
    let model = a.req::<Rc<Model>>()?;
    let mut fields = Vec::new();
    while let Some(f) = a.opt::<Rc<Mchaml>>() {
        fields.push(f);
    }
    let u = a.opt::<Rc<Chpoint>>();
    // GRAD writes its characteristics after the field.
    while let Some(f) = a.opt::<Rc<Mchaml>>() {
        fields.push(f);
    }
    Ok((model, fields, u))
}

type PointFn = fn(
    element::Formulation,
    ElemType,
    element::Mode,
    &[[f64; 3]],
    &element::Material,
    &[f64],
) -> std::result::Result<GaussField, element::FemError>;

fn gauss_field(it: &Interp, a: &mut Args, subtype: &str, f: PointFn) -> Result<Vec<Value>> {
    let (model, mut fields, u) = model_args(a)?;
    let u = match u {
        Some(u) => u,
        None => super::nodal_field::take_displacements(&mut fields)
            .ok_or_else(|| a.missing("CHPOINT (the displacements)"))?,
    };
    let mut out = Mchaml { subtype: subtype.into(), zones: vec![] };
    let have = u.components();
    for zone in model.zones.iter().filter(|z| z.formulation != super::pres_model::FORMULATION) {
        if let Some(x) = &zone.xfem {
            out.zones.extend(super::xfem_model::gauss_zones(it, a, zone, x, &fields, &u, subtype)?);
            continue;
        }
        let form = formulation(zone);
        let mode = zone_mode(zone)?;
        let mat = material_for(zone, &fields);
        let names = element::node_dofs(form, mode).map_err(fem_err)?;
        // A force field or a field of another model would otherwise read
        // as zero displacements and give a silent zero stress.
        if !names.iter().any(|c| have.iter().any(|h| h == c)) {
            return Err(a.err(format!(
                "the CHPOINT has components {} but the model's displacements are {}: give the solution of RESO",
                have.join(" "),
                names.join(" ")
            )));
        }
        for part in &zone.mesh.parts {
            // A property given point by point (a density-scaled YOUN) enters
            // each element as RIGI takes it.
            let mats = super::variable_fields::element_materials(a, &mat, part, &fields)?;
            let mut z = MchamlZone {
                mesh: Mesh::single(part.clone()),
                element: zone.element.clone(),
                cons: zone.cons.clone(),
                ..Default::default()
            };
            for (e, nodes) in part.elems().enumerate() {
                let mat = if mats.len() == 1 { &mats[0] } else { &mats[e] };
                let mut x: Vec<[f64; 3]> = nodes.iter().map(|n| it.nodes.get(*n)).collect();
                let u = &u;
                // A missing component reads as 0 (a field given only in UX),
                // but a node with no displacement at all means the field
                // belongs to another mesh.
                if let Some(n) = nodes.iter().find(|n| names.iter().all(|c| u.get(**n, c).is_none())) {
                    return Err(a.err(format!(
                        "node {} of element {} has no displacement in the CHPOINT (is it the solution for this model?)",
                        n + 1,
                        e + 1
                    )));
                }
                let mut ue: Vec<f64> =
                    nodes.iter().flat_map(|n| names.iter().map(move |c| u.get(*n, c).unwrap_or(0.0))).collect();
                // Generalised plane strain: the zone's point and its unknowns.
                if let Some(p) = zone.dpge {
                    x.push(it.nodes.get(p));
                    let point = crate::fem::gen_plane_strain::POINT_DOFS;
                    ue.extend(point.iter().map(|c| u.get(p, c).unwrap_or(0.0)));
                }
                let g = f(form, part.ty, mode, &x, mat, &ue)
                    .map_err(|err| a.err(format!("element {}: {}", e + 1, fem_err(err).message)))?;
                if z.comps.is_empty() {
                    z.comps = g.comps.iter().map(|c| c.to_string()).collect();
                }
                z.values.push(g.values);
            }
            out.zones.push(z);
        }
    }
    Ok(vec![Value::Mchaml(Rc::new(out))])
}

fn sigm(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    gauss_field(it, a, "CONTRAINTES", element::stress)
}

fn epsi(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    gauss_field(it, a, "DEFORMATIONS", element::strain).map_err(|e| {
        // Strains need no material, except in plane stress where EPZZ comes
        // from Poisson's ratio: say so rather than just naming NU.
        if e.message.contains("property NU missing") {
            e.note("in plane stress (PLAN CONT) EPZZ = -nu/(1-nu) (EPXX + EPYY): give the material, EPSI mo ma u")
        } else {
            e
        }
    })
}

fn grad(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    gauss_field(it, a, "GRADIENT", element::gradient)
}

/// Component names as the element library wants them (`&'static str`).
fn intern(c: &str) -> &'static str {
    const NAMES: &[&str] = &[
        "SMXX", "SMYY", "SMZZ", "SMXY", "SMXZ", "SMYZ", "SMRR", "SMTT", "SMRZ", "EPXX", "EPYY", "EPZZ", "GAXY", "GAXZ",
        "GAYZ", "EPRR", "EPTT", "GARZ", "EFFX", "EFFY", "EFFZ", "MOMX", "MOMY", "MOMZ", "EPSS", "CURX", "CURY", "CURZ",
        "VMIS", "SCAL", "ENER", "TRES", "I1", "J2", "J3", "N11", "N22", "N12", "M11", "M22", "M12", "V1", "V2", "GAST",
        "RTSS", "RTTT", "RTST", "EPSN", "EPS1", "EPS2", "SIGS", "SIGN", "SIG1", "SIG2",
    ];
    NAMES.iter().find(|n| **n == c).copied().unwrap_or("?")
}

pub(crate) fn to_gauss(z: &MchamlZone, e: usize) -> GaussField {
    let comps: Vec<&'static str> = z.comps.iter().map(|c| intern(c)).collect();
    GaussField { comps, values: z.values[e].clone() }
}

pub(crate) fn zone_of<'a>(model: &'a Model, z: &MchamlZone) -> Option<&'a ModelZone> {
    model
        .zones
        .iter()
        .find(|m| m.mesh.parts.iter().any(|p| z.mesh.parts.first() == Some(p)) || m.mesh == z.mesh)
        .or_else(|| {
            // A field restricted to part of a zone (REDU MCHAML GEO, then
            // `+`): the zone holding all its elements.
            let first = z.mesh.parts.first()?;
            model.zones.iter().find(|m| {
                let own: std::collections::HashSet<&[usize]> =
                    m.mesh.parts.iter().filter(|p| p.ty == first.ty).flat_map(|p| p.elems()).collect();
                !own.is_empty() && first.elems().all(|e| own.contains(e))
            })
        })
}

fn vmis(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let (model, fields, _) = model_args(a)?;
    let sig = fields
        .iter()
        .find(|f| f.subtype == "CONTRAINTES")
        .cloned()
        .ok_or_else(|| a.missing("MCHAML of stresses (from SIGM)"))?;
    let mut out = Mchaml { subtype: "SCALAIRE".into(), zones: vec![] };
    for z in &sig.zones {
        let mz = zone_of(&model, z).ok_or_else(|| a.err("the stress field does not belong to this model"))?;
        let (form, mode) = (formulation(mz), zone_mode(mz)?);
        let mat = material_for(mz, &fields);
        let mut nz = MchamlZone { mesh: z.mesh.clone(), element: z.element.clone(), ..Default::default() };
        nz.comps = vec!["SCAL".into()];
        for e in 0..z.values.len() {
            let g = crate::fem::stress::von_mises(form, mode, &mat, &to_gauss(z, e)).map_err(fem_err)?;
            nz.values.push(g.values);
        }
        out.zones.push(nz);
    }
    Ok(vec![Value::Mchaml(Rc::new(out))])
}

fn chan(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    const KW: &[&str] = &[
        "POI1", "QUA8", "TRI6", "SEG3", "QUA4", "TRI3", "SEG2", "CHPO", "NOEUD", "INCO", "ATTRIBUT", "COMP", "TYPE",
        "GRAVITE", "MAJU", "MINU", "QUAD", "LIGN", "CHAM", "LINE", "RIGIDITE", "MASSE", "STRESSES", "TABL",
    ];
    // CHAN (TYPE) POI1_MESH LISTENTI: elements joining the mesh's points.
    if let Some(r) = super::chan_cham::connect(it, a)? {
        return Ok(r);
    }
    // The field may come before the keyword (`CHAN CHPO1 'ATTRIBUT' …`).
    let early = match a.peek_right() {
        Some(Value::Chpo(_)) => a.opt_right::<Rc<Chpoint>>(),
        _ => None,
    };
    let k = a.req_keyword(KW)?;
    match k {
        "MAJU" => Ok(vec![Value::mot(a.req::<String>()?.to_uppercase())]),
        // Cast3M's table layout of a CHARGEMENT is a storage choice for
        // TIRE's speed: gibi's loads already give the same values.
        "TABL" => {
            let Some(c) = a.opt_with(|v| match v {
                Value::Charge(c) => Some(c.clone()),
                _ => None,
            }) else {
                return Err(a.missing("CHARGEMENT"));
            };
            let _kind = a.req::<String>()?;
            Ok(vec![Value::Charge(c)])
        }
        "MINU" => Ok(vec![Value::mot(a.req::<String>()?.to_lowercase())]),
        "POI1" => Ok(vec![Value::Mesh(Rc::new(mg::change_to_poi1(&super::mesh::req_geo(a)?)))]),
        "LIGN" => Ok(vec![Value::Mesh(Rc::new(mg::edges::all_edges(&super::mesh::req_geo(a)?)))]),
        "QUA8" | "TRI6" | "SEG3" | "QUAD" => {
            let m = super::mesh::req_geo(a)?;
            Ok(vec![Value::Mesh(Rc::new(mg::change_to_quadratic(&mut it.nodes, &m)?))])
        }
        "TRI3" => Ok(vec![Value::Mesh(Rc::new(mg::change_to_triangles(&super::mesh::req_geo(a)?)))]),
        "SEG2" => Ok(vec![Value::Mesh(Rc::new(mg::change_to_seg2(&super::mesh::req_geo(a)?)))]),
        "QUA4" | "LINE" => Ok(vec![Value::Mesh(Rc::new(mg::change_to_linear(&super::mesh::req_geo(a)?)))]),
        "INCO" => {
            let r = a.req::<Rc<Rigidite>>()?;
            let old = a.req::<Rc<Vec<String>>>()?;
            let new = a.req::<Rc<Vec<String>>>()?;
            if old.len() != new.len() {
                return Err(a.err("as many new names as old ones are needed"));
            }
            let (dold, dnew) = match a.opt::<Rc<Vec<String>>>() {
                Some(d1) => (d1.to_vec(), a.req::<Rc<Vec<String>>>()?.to_vec()),
                None => {
                    (old.iter().map(|c| dofs::dual_of(c)).collect(), new.iter().map(|c| dofs::dual_of(c)).collect())
                }
            };
            let ren = |c: &String, from: &[String], to: &[String]| {
                from.iter().position(|x| x == c).map_or_else(|| c.clone(), |i| to[i].clone())
            };
            let mut out = Rigidite::new(r.subtype);
            out.blocks = r.blocks.clone();
            for b in out.blocks.iter_mut() {
                for d in b.dofs.iter_mut() {
                    d.1 = ren(&d.1, &old, &new);
                }
                for d in b.duals.iter_mut() {
                    *d = ren(d, &dold, &dnew);
                }
            }
            out.conds = r.conds.clone();
            for c in out.conds.iter_mut() {
                for t in c.terms.iter_mut().chain(c.dual.iter_mut().flatten()) {
                    t.1 = ren(&t.1, &old, &new);
                }
            }
            Ok(vec![Value::Rigi(Rc::new(out))])
        }
        "ATTRIBUT" => {
            let ch = match early {
                Some(c) => c,
                None => a.req::<Rc<Chpoint>>()?,
            };
            a.keyword(&["NATURE"]);
            let mut c = (*ch).clone();
            c.nature = match a.req_keyword(&["DIFFUS", "DISCRET", "INDETER"])? {
                "DIFFUS" => Nature::Diffus,
                "DISCRET" => Nature::Discret,
                _ => Nature::Indeter,
            };
            Ok(vec![Value::Chpo(Rc::new(c))])
        }
        // From a node field, whether it comes before or after the model
        // or mesh (`CHAN 'CHAM' ch mo`, `CHAN 'CHAM' mo ch`).
        "CHAM" if early.is_some() || a.has_any::<Rc<Chpoint>>() => {
            let ch = match early {
                Some(c) => c,
                None => a.req::<Rc<Chpoint>>()?,
            };
            super::chan_cham::from_chpoint(it, a, &ch)
        }
        "RIGIDITE" | "MASSE" | "STRESSES" => super::chan_support::to_integration_points(a),
        "COMP" => {
            if let Some(c) = early {
                a.unread(Value::Chpo(c));
            }
            super::chan_comp::rename_components(a)
        }
        "TYPE" => {
            // Relabel a field by element (chan.notice): a field built by
            // arithmetic becomes CONTRAINTES again for VMIS or PRIN, which
            // look for stresses by this label.
            // `CHAN CHE1 'TYPE' word`: the keyword read past the field
            // brings the word to the front, so the two come in either order.
            let m = a.opt::<Rc<Mchaml>>();
            let w = a.req::<String>()?;
            let m = match m {
                Some(m) => m,
                None => a.req::<Rc<Mchaml>>()?,
            };
            let mut c = (*m).clone();
            c.subtype = w.trim().to_uppercase();
            Ok(vec![Value::Mchaml(Rc::new(c))])
        }
        _ => {
            // CHPO / NOEUD / GRAVITE: element values to nodes (averaged over
            // the elements for CHPO), or to each element's centre.
            // `CHAN 'CHAM' 'RIGIDITE' CHAM1 MODL1`: the support may also
            // come right after 'CHAM'.
            // CHAN 'CHPO' CHPO1 (MODL1) (chan.notice table): a node field
            // is already one; it is given back as it is.
            if k == "CHPO" {
                if let Some(c) = early.clone().or_else(|| a.opt::<Rc<Chpoint>>()) {
                    a.opt::<Rc<Model>>();
                    return Ok(vec![Value::Chpo(c)]);
                }
            }
            let support_first =
                if k == "CHAM" { a.keyword(&["NOEUD", "GRAVITE", "STRESSES", "RIGIDITE", "MASSE"]) } else { None };
            let model = a.req::<Rc<Model>>()?;
            let m = a.req::<Rc<Mchaml>>()?;
            // CHAN 'CHAM' of an element field: to the support named after
            // it, the nodes by default.
            let k = match k {
                "CHAM" => support_first
                    .or_else(|| a.keyword(&["NOEUD", "GRAVITE", "STRESSES", "RIGIDITE", "MASSE"]))
                    .unwrap_or("NOEUD"),
                _ => k,
            };
            if matches!(k, "STRESSES" | "RIGIDITE" | "MASSE") {
                return super::chan_support::to_points(a, &model, &m);
            }
            // CHPO: the nodal value is the mean of the elements' values
            // there ('MOYE', the default) or their sum ('SOMM').
            let how = if k == "CHPO" { a.keyword(&["MOYE", "SOMM", "SUPP"]) } else { None };
            if how == Some("SUPP") {
                return super::chan_supp::on_points(it, a, &model, &m);
            }
            let summed = how == Some("SOMM");
            let mut sum = Chpoint::new(Nature::Diffus);
            let mut count = std::collections::HashMap::<(usize, String), f64>::new();
            let mut out_m = Mchaml { subtype: m.subtype.clone(), zones: vec![] };
            // The new field's subtype (TYP1), kept when blank.
            if k != "CHPO" {
                if let Some(sub) = a.opt::<String>().filter(|s| !s.trim().is_empty()) {
                    out_m.subtype = sub.trim().to_uppercase();
                }
            }
            for z in &m.zones {
                // Material data (constants, as MATE or EXCO of it give):
                // the same values at every node.
                let held;
                let z = if z.values.is_empty() && !z.constants.is_empty() {
                    held = constants_at_nodes(z);
                    &held
                } else {
                    z
                };
                let mz = zone_of(&model, z).ok_or_else(|| a.err("the field does not belong to this model"))?;
                let form = formulation(mz);
                let part = z.mesh.parts.first().ok_or_else(|| a.err("empty zone"))?;
                let mut nz = MchamlZone {
                    mesh: z.mesh.clone(),
                    element: z.element.clone(),
                    comps: z.comps.clone(),
                    at_nodes: true,
                    ..Default::default()
                };
                // The element centre in reference coordinates (the mean of
                // the reference nodes), for CHAN 'GRAVITE'.
                let refs = crate::fem::shape::ref_nodes(part.ty);
                let centre = refs.iter().fold([0.0; 3], |acc, p| [0, 1, 2].map(|i| acc[i] + p[i] / refs.len() as f64));
                let at_centre = crate::fem::shape::eval(part.ty, centre).n;
                let npts = crate::fem::element::gauss_points(form, part.ty).len();
                for (e, nodes) in part.elems().enumerate() {
                    let g = match z.values.get(e) {
                        // A field at the element centres (CHAN 'GRAVITE'):
                        // the one value holds for every node.
                        Some(v) if v.len() == 1 && npts != 1 && !z.at_nodes => crate::fem::element::GaussField {
                            comps: to_gauss(z, e).comps,
                            values: vec![v[0].clone(); part.ty.nodes()],
                        },
                        // Already at the nodes (CHAN 'NOEUD' before 'CHPO').
                        Some(v) if z.at_nodes && v.len() == part.ty.nodes() => to_gauss(z, e),
                        _ => crate::fem::stress::to_nodes(form, part.ty, &to_gauss(z, e)).map_err(fem_err)?,
                    };
                    for (k, n) in nodes.iter().enumerate() {
                        for (c, name) in z.comps.iter().enumerate() {
                            let v = g.values[k][c];
                            sum.add(*n, name, v, true);
                            *count.entry((*n, name.clone())).or_insert(0.0) += 1.0;
                        }
                    }
                    if k == "GRAVITE" {
                        // One point per element: the field interpolated from
                        // its nodal values at the centre.
                        let v: Vec<f64> = (0..z.comps.len())
                            .map(|c| at_centre.iter().zip(&g.values).map(|(w, row)| w * row[c]).sum())
                            .collect();
                        nz.values.push(vec![v]);
                    } else {
                        nz.values.push(g.values);
                    }
                }
                if k == "GRAVITE" {
                    nz.at_nodes = false;
                }
                out_m.zones.push(nz);
            }
            if k != "CHPO" {
                return Ok(vec![Value::Mchaml(Rc::new(out_m))]);
            }
            let avg = Chpoint::from_entries(
                Nature::Diffus,
                sum.entries()
                    .map(|(n, c, v)| (n, c, if summed { v } else { v / count[&(n, c.to_string())] }))
                    .collect::<Vec<_>>(),
            );
            Ok(vec![Value::Chpo(Rc::new(avg))])
        }
    }
}

fn pres(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let kw = a.keyword(&["MASS", "COQU"]);
    if kw.is_none() {
        if let Some(m) = a.opt::<Rc<Model>>() {
            if super::pres_model::is_pressure_model(&m) {
                return super::pres_model::field(a, &m);
            }
        }
        a.req_keyword(&["MASS", "COQU"])?;
    }
    if kw == Some("COQU") {
        return pres_shell(it, a);
    }
    let model = a.req::<Rc<Model>>()?;
    // Optional characteristics (CARA … DIM3): in plane stress the forces are
    // then for the thickness, as RIGI's stiffness is; without them they are
    // per unit thickness.
    let mut fields: Vec<Rc<Mchaml>> = Vec::new();
    while let Some(f) = a.opt::<Rc<Mchaml>>() {
        fields.push(f);
    }
    // A pressure given as a field: at the nodes of the model's faces, or
    // at the nodes of the face elements of an element field.
    if let Some(ch) = a.opt::<Rc<Chpoint>>() {
        return super::pres_field::from_chpoint(it, a, &model, &ch, &fields);
    }
    if let Some(i) = fields.iter().position(|f| super::pres_field::on_faces(&model, f)) {
        let f = fields.remove(i);
        return super::pres_field::from_mchaml(it, a, &model, &f, &fields);
    }
    let p = a.req_num()?;
    let geo = super::mesh::req_geo(a)?;
    while let Some(f) = a.opt::<Rc<Mchaml>>() {
        fields.push(f);
    }
    let mode = model.zones.first().map(zone_mode).transpose()?.ok_or_else(|| a.err("empty model"))?;
    let names = dofs::forces(it);
    let mut out = Chpoint::new(Nature::Discret);
    for part in &geo.parts {
        for face in part.elems() {
            let (zone, inside) = inside_point(it, &model, face).ok_or_else(|| {
                a.err(format!("the face through node {} belongs to no element of the model", face[0] + 1))
            })?;
            let t = if fields.is_empty() {
                1.0
            } else {
                super::model::material_for(&model.zones[zone], &fields)
                    .thickness(mode, part.ty.name())
                    .map_err(fem_err)?
            };
            let x: Vec<[f64; 3]> = face.iter().map(|n| it.nodes.get(*n)).collect();
            let f = crate::fem::loads::pressure_load(part.ty, mode, &x, p * t, inside).map_err(fem_err)?;
            for (n, v) in face.iter().zip(f) {
                for (k, c) in names.iter().enumerate() {
                    out.add(*n, c, v[k], true);
                }
            }
        }
    }
    Ok(vec![Value::Chpo(Rc::new(out))])
}

/// PRES 'COQU' mo p: p ∫N_i dA along each shell element's normal.
fn pres_shell(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let model = a.req::<Rc<Model>>()?;
    let p = a.req_num()?;
    // 'NORM' names the default direction, the element normal (pres.notice);
    // decks write it explicitly, so it must not be left over as a result.
    a.keyword(&["NORM"]);
    let mut out = Chpoint::new(Nature::Discret);
    let mut any = false;
    for zone in &model.zones {
        let form = formulation(zone);
        if !form.is_shell() {
            continue;
        }
        any = true;
        for part in &zone.mesh.parts {
            for (e, nodes) in part.elems().enumerate() {
                let x: Vec<[f64; 3]> = nodes.iter().map(|n| it.nodes.get(*n)).collect();
                if form == crate::fem::element::Formulation::Coq2 {
                    // Along the left normal of the line, for the whole ring in AXIS.
                    let mode = zone_mode(zone)?;
                    let f = crate::fem::coq2::pressure_load(mode, &x, [p, p], 1.0, true)
                        .map_err(|err| a.err(format!("element {}: {}", e + 1, err)))?;
                    let names = if mode == crate::fem::element::Mode::Axis { ["FR", "FZ"] } else { ["FX", "FY"] };
                    for (k, n) in nodes.iter().enumerate() {
                        for (d, c) in names.iter().enumerate() {
                            out.add(*n, c, f[3 * k + d], true);
                        }
                    }
                    continue;
                }
                let f = crate::fem::shell::pressure_load(form, &x, p)
                    .map_err(|err| a.err(format!("element {}: {}", e + 1, err)))?;
                for (n, v) in nodes.iter().zip(f) {
                    for (k, c) in ["FX", "FY", "FZ"].iter().enumerate() {
                        out.add(*n, c, v[k], true);
                    }
                }
            }
        }
    }
    if !any {
        return Err(a.err("PRES 'COQU' needs a shell model (COQ2, COQ3, DKT, COQ4); use PRES 'MASS' for massive ones"));
    }
    Ok(vec![Value::Chpo(Rc::new(out))])
}

/// The zone and the centroid of a model element holding every node of
/// `face`.
pub(super) fn inside_point(it: &Interp, model: &Model, face: &[usize]) -> Option<(usize, [f64; 3])> {
    for (zi, z) in model.zones.iter().enumerate() {
        for p in &z.mesh.parts {
            for e in p.elems() {
                if face.iter().all(|n| e.contains(n)) && e.len() > face.len() {
                    let mut c = [0.0; 3];
                    for n in e {
                        let x = it.nodes.get(*n);
                        for k in 0..3 {
                            c[k] += x[k] / e.len() as f64;
                        }
                    }
                    return Some((zi, c));
                }
            }
        }
    }
    None
}

fn mass(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if a.peek_right().is_some_and(|v| !matches!(v, Value::Model(_))) {
        return super::model::springs(it, a, Subtype::Masse);
    }
    let (model, fields, _) = model_args(a)?;
    let lumped = a.keyword(&["LUMP", "DIAG"]).is_some();
    model_mass(it, model, fields, lumped)
}

fn lump(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let (model, fields, _) = model_args(a)?;
    model_mass(it, model, fields, true)
}

pub(crate) fn model_mass(it: &Interp, model: Rc<Model>, fields: Vec<Rc<Mchaml>>, lumped: bool) -> Result<Vec<Value>> {
    let mut rig = Rigidite::new(Subtype::Masse);
    for zone in model.zones.iter().filter(|z| z.formulation != super::pres_model::FORMULATION) {
        let (form, mode) = (formulation(zone), zone_mode(zone)?);
        let mat = material_for(zone, &fields);
        for part in &zone.mesh.parts {
            let block = super::element_block::part_block(it, part, None, Symmetry::Symmetric, |_, x| {
                element::mass(form, part.ty, mode, x, &mat, lumped).map_err(fem_err)
            })?;
            rig.blocks.extend(block);
        }
    }
    Ok(vec![Value::Rigi(Rc::new(rig))])
}

/// A zone of constants as point values at every node of every element.
fn constants_at_nodes(z: &MchamlZone) -> MchamlZone {
    let comps: Vec<String> = z.constants.keys().cloned().collect();
    let row: Vec<f64> = z.constants.values().copied().collect();
    let values = z.mesh.parts.iter().flat_map(|p| p.elems().map(|e| vec![row.clone(); e.len()])).collect();
    MchamlZone { comps, values, at_nodes: true, constants: Default::default(), ..z.clone() }
}
