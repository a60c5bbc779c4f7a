//! PICA and CAPI: stresses and strains carried between the reference and
//! the current configuration (pica.notice, capi.notice). The tensor
//! algebra is `fem::finite_strain`; this file reads the arguments, gets the
//! displacement gradient at the field's points and rewrites the field.

use super::model::{formulation, material_for, zone_mode};
use super::post::zone_of;
use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::element::{self, Formulation, Mode};
use crate::fem::finite_strain::{self as fs, Kinematics, Measure, M3};
use crate::value::{Chpoint, Mchaml, Model, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "PICA",
        signature: "PICA MMODEL MCHAML_STRESS|MCHAML_STRAIN CHPOINT (CHPOINT2)",
        doc: "Cauchy stresses from second Piola-Kirchhoff ones (σ = F S Fᵀ / J), or Almansi-Euler strains from \
              Green-Lagrange ones (e = F⁻ᵀ E F⁻¹), F = I + ∂u/∂X the gradient of the displacement CHPOINT taken \
              on the current geometry, at the field's points of massive elements (OPTI EPSI QUADRATIQUE or \
              TRUESDELL). With OPTI EPSI JAUMANN, and with LINEAIRE (small strains: the stretch is neglected), only \
              the rotation of F turns the tensors; with 'UTILISATEUR' the field is returned as it is. Zones of \
              bars, beams and shells, whose values are in axes that follow the element, are returned as they are. \
              The arguments may come in any order. A second CHPOINT (X-FEM) carries the undeformed geometry, \
              where the crack is closed, to the reference configuration: both gradients are taken there and \
              F = I + ∂u₁/∂X₀ (I + ∂u₂/∂X₀)⁻¹. On X-FEM zones (XQ4R, XC8R) the gradients include the enriched \
              unknowns.",
        example: "sigc = pica mo sig u ;",
        f: pica,
    },
    OpDef {
        name: "CAPI",
        signature: "CAPI MMODEL MCHAML_STRESS|MCHAML_STRAIN CHPOINT (CHPOINT2)",
        doc: "The reverse of PICA: second Piola-Kirchhoff stresses from Cauchy ones (S = J F⁻¹ σ F⁻ᵀ), or \
              Green-Lagrange strains from Almansi-Euler ones (E = Fᵀ e F). A second CHPOINT is read as by PICA.",
        example: "sigp = capi mo sigc u ;",
        f: capi,
    },
];

fn pica(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    convert(it, a, true)
}

fn capi(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    convert(it, a, false)
}

/// The (row, column) of a tensor component and the factor from the stored
/// value to the tensor term (engineering shears GA.. are twice it).
fn slot(comp: &str, mode: Mode) -> Option<(usize, usize, f64)> {
    let axis = mode == Mode::Axis;
    Some(match (comp, axis) {
        ("SMXX", false) | ("SMRR", true) => (0, 0, 1.0),
        ("SMYY", false) => (1, 1, 1.0),
        ("SMZZ", false) | ("SMTT", true) => (2, 2, 1.0),
        ("SMZZ", true) => (1, 1, 1.0),
        ("SMXY", false) | ("SMRZ", true) => (0, 1, 1.0),
        ("SMXZ", false) => (0, 2, 1.0),
        ("SMYZ", false) => (1, 2, 1.0),
        ("EPXX", false) | ("EPRR", true) => (0, 0, 1.0),
        ("EPYY", false) => (1, 1, 1.0),
        ("EPZZ", false) | ("EPTT", true) => (2, 2, 1.0),
        ("EPZZ", true) => (1, 1, 1.0),
        ("GAXY", false) | ("GARZ", true) => (0, 1, 0.5),
        ("GAXZ", false) => (0, 2, 0.5),
        ("GAYZ", false) => (1, 2, 0.5),
        _ => return None,
    })
}

/// The kinematics of OPTI EPSI. Under 'LINEAIRE' strains are small by
/// hypothesis: the stretch of F, of their order, is neglected and only its
/// rotation turns the tensors (Cast3M's linear-strain stresses then match
/// PICA of SIGM to the strain's order, where the full push-forward would
/// differ by about twice the strain).
fn kinematics(it: &Interp) -> Kinematics {
    match it.opts.kept.get("EPSI") {
        Some(Value::Mot(m)) if m.starts_with("JAUM") || m.starts_with("LINE") => Kinematics::Jaumann,
        Some(Value::Mot(m)) if m.starts_with("UTIL") => Kinematics::User,
        _ => Kinematics::Truesdell,
    }
}

fn convert(it: &mut Interp, a: &mut Args, forward: bool) -> Result<Vec<Value>> {
    let model = a.req::<Rc<Model>>()?;
    let field = a.req::<Rc<Mchaml>>()?;
    let u = a.req::<Rc<Chpoint>>()?;
    // pica.notice's DEP2 (X-FEM): from the undeformed geometry to the
    // reference configuration.
    let u2 = a.opt::<Rc<Chpoint>>();
    let measure = match field.subtype.as_str() {
        "CONTRAINTES" => Measure::Stress,
        "DEFORMATIONS" => Measure::Strain,
        other => {
            return Err(a.err(format!(
                "the MCHAML must be of stresses (CONTRAINTES) or strains (DEFORMATIONS), not of subtype {}",
                if other.is_empty() { "none" } else { other }
            )))
        }
    };
    let kin = kinematics(it);
    let mut out = Mchaml { subtype: field.subtype.clone(), zones: vec![] };
    for z in &field.zones {
        let mz = zone_of(&model, z).ok_or_else(|| a.err("the field has a zone that is not in the model"))?;
        let form = formulation(mz);
        let massive = matches!(form, Formulation::Solid | Formulation::Q4ri | Formulation::Q8ri | Formulation::Incomp);
        if !massive || kin == Kinematics::User {
            out.zones.push(z.clone());
            continue;
        }
        if z.at_nodes {
            return Err(a.err("the field is given at the nodes (CHAN 'NOEUD'): give it at the stress points"));
        }
        let mode = zone_mode(mz)?;
        if mz.xfem.is_some() || u2.is_some() {
            let fs = super::pica_xfem::gradients(it, a, mz, z, &u, u2.as_deref())?;
            let mut nz = z.clone();
            for (e, (vals, fe)) in nz.values.iter_mut().zip(&fs).enumerate() {
                if fe.len() != vals.len() {
                    return Err(a.err(format!(
                        "element {}: the field has {} points, the element gives its stresses at {}",
                        e + 1,
                        vals.len(),
                        fe.len()
                    )));
                }
                for (v, f) in vals.iter_mut().zip(fe) {
                    transform_point(&z.comps, mode, v, |t| {
                        if forward {
                            fs::push_forward(kin, measure, f, t)
                        } else {
                            fs::pull_back(kin, measure, f, t)
                        }
                    });
                }
            }
            out.zones.push(nz);
            continue;
        }
        let mat = material_for(mz, &[]);
        let names = element::node_dofs(form, mode).map_err(|e| a.err(e.to_string()))?;
        let mut nz = z.clone();
        for part in &z.mesh.parts {
            for (e, nodes) in part.elems().enumerate() {
                let x: Vec<[f64; 3]> = nodes.iter().map(|n| it.nodes.get(*n)).collect();
                if let Some(n) = nodes.iter().find(|n| names.iter().all(|c| u.get(**n, c).is_none())) {
                    return Err(a.err(format!(
                        "node {} of element {} has no displacement in the CHPOINT",
                        n + 1,
                        e + 1
                    )));
                }
                let ue: Vec<f64> =
                    nodes.iter().flat_map(|n| names.iter().map(|c| u.get(*n, c).unwrap_or(0.0))).collect();
                let g = element::gradient(form, part.ty, mode, &x, &mat, &ue)
                    .map_err(|err| a.err(format!("element {}: {}", e + 1, err)))?;
                let vals = &mut nz.values[e];
                if g.values.len() != vals.len() {
                    return Err(a.err(format!(
                        "element {}: the field has {} points, the element gives its stresses at {}",
                        e + 1,
                        vals.len(),
                        g.values.len()
                    )));
                }
                for (p, gp) in g.values.iter().enumerate() {
                    let gm: M3 = [[gp[0], gp[1], gp[2]], [gp[3], gp[4], gp[5]], [gp[6], gp[7], gp[8]]];
                    let f =
                        fs::deformation_gradient(&gm).map_err(|err| a.err(format!("element {}: {}", e + 1, err)))?;
                    transform_point(&z.comps, mode, &mut vals[p], |t| {
                        if forward {
                            fs::push_forward(kin, measure, &f, t)
                        } else {
                            fs::pull_back(kin, measure, &f, t)
                        }
                    });
                }
            }
        }
        out.zones.push(nz);
    }
    Ok(vec![Value::Mchaml(Rc::new(out))])
}

/// Gather the tensor from the point's components, change it, and write
/// back the components the field has (others are left as they are).
fn transform_point(comps: &[String], mode: Mode, vals: &mut [f64], f: impl Fn(&M3) -> M3) {
    let mut t = [[0.0; 3]; 3];
    for (c, v) in comps.iter().zip(vals.iter()) {
        if let Some((i, j, k)) = slot(c, mode) {
            t[i][j] = v * k;
            t[j][i] = v * k;
        }
    }
    let r = f(&t);
    for (c, v) in comps.iter().zip(vals.iter_mut()) {
        if let Some((i, j, k)) = slot(c, mode) {
            *v = 0.5 * (r[i][j] + r[j][i]) / k;
        }
    }
}
