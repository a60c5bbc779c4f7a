//! The deformation gradients PICA and CAPI use when a second displacement
//! field is given (pica.notice's DEP2, for X-FEM): DEP2 carries the
//! undeformed geometry, where the crack is closed and the enrichment
//! functions are defined, to the reference configuration, and DEP1 the
//! reference configuration to the current one. Both gradients are taken
//! on the undeformed geometry, the mesh's nodes less DEP2 there (on an
//! X-FEM zone, its physical value at the node, as XFEM 'RECO' gives it,
//! which is what a deck moved the mesh by); then F = I + G₁ (I + G₂)⁻¹.
//! On an X-FEM zone without DEP2 the gradient of DEP1 includes the
//! enriched unknowns, at the points of the X-FEM fields.

use super::model::{formulation, material_for, zone_mode};
use super::xfem_model::{el_displacement, elem_data, element_dofs, is_c8, ElemData};
use super::Args;
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::element;
use crate::fem::finite_strain::{self as fs, M3};
use crate::fem::shape::ref_nodes;
use crate::fem::xfem::q4::{self, Field};
use crate::fem::xfem_c8r as c8r;
use crate::value::model::{MchamlZone, ModelZone};
use crate::value::Chpoint;

/// F at every point of every element of the field's zone `z`.
pub(super) fn gradients(
    it: &Interp,
    a: &Args,
    mz: &ModelZone,
    z: &MchamlZone,
    u1: &Chpoint,
    u2: Option<&Chpoint>,
) -> Result<Vec<Vec<M3>>> {
    let mode = zone_mode(mz)?;
    let mat = material_for(mz, &[]);
    let mut out = Vec::new();
    for part in &z.mesh.parts {
        for nodes in part.elems() {
            let e = out.len();
            let fail = |err: &dyn std::fmt::Display| a.err(format!("element {}: {}", e + 1, err));
            let (g1, g2) = match &mz.xfem {
                Some(x) => {
                    let enr = x.borrow();
                    let d = elem_data(it, a, &enr, nodes)?;
                    let ue1 = element_dofs(a, mz, u1, nodes, &d.kinds)?;
                    let (d0, ue2) = match u2 {
                        Some(u2) => {
                            let ue2 = element_dofs(a, mz, u2, nodes, &d.kinds)?;
                            let corners = ref_nodes(part.ty);
                            let mut x0 = d.x.clone();
                            for (l, p) in x0.iter_mut().enumerate() {
                                let v =
                                    el_displacement(mz, &d.elem(), corners[l], &ue2, None).map_err(|err| fail(&err))?;
                                for (c, vc) in v.iter().enumerate() {
                                    p[c] -= vc;
                                }
                            }
                            (ElemData { x: x0, ..d }, Some(ue2))
                        }
                        None => (d, None),
                    };
                    let grad = |ue: &[f64]| {
                        if is_c8(mz) {
                            c8r::field_of(&d0.elem(), &mat, ue, Field::Gradient)
                        } else {
                            q4::field(mode, &d0.elem(), &mat, ue, Field::Gradient)
                        }
                        .map(|g| g.values)
                        .map_err(|err| fail(&err))
                    };
                    let g1 = grad(&ue1)?;
                    let g2 = match &ue2 {
                        Some(ue2) => Some(grad(ue2)?),
                        None => None,
                    };
                    (g1, g2)
                }
                None => {
                    let form = formulation(mz);
                    let names = element::node_dofs(form, mode).map_err(|err| a.err(err.to_string()))?;
                    let at = |u: &Chpoint| -> Vec<f64> {
                        nodes.iter().flat_map(|n| names.iter().map(|c| u.get(*n, c).unwrap_or(0.0))).collect()
                    };
                    let mut x0: Vec<[f64; 3]> = nodes.iter().map(|n| it.nodes.get(*n)).collect();
                    if let Some(u2) = u2 {
                        for (p, n) in x0.iter_mut().zip(nodes) {
                            for (c, name) in ["UX", "UY", "UZ"].iter().enumerate() {
                                p[c] -= u2.get(*n, name).unwrap_or(0.0);
                            }
                        }
                    }
                    let grad = |ue: &[f64]| {
                        element::gradient(form, part.ty, mode, &x0, &mat, ue)
                            .map(|g| g.values)
                            .map_err(|err| fail(&err))
                    };
                    let g2 = match u2 {
                        Some(u2) => Some(grad(&at(u2))?),
                        None => None,
                    };
                    (grad(&at(u1))?, g2)
                }
            };
            let m3 = |g: &[f64]| -> M3 { [[g[0], g[1], g[2]], [g[3], g[4], g[5]], [g[6], g[7], g[8]]] };
            let mut fe = Vec::with_capacity(g1.len());
            for (p, g) in g1.iter().enumerate() {
                let f = match &g2 {
                    Some(g2) => fs::relative_gradient(&m3(g), &m3(&g2[p])),
                    None => fs::deformation_gradient(&m3(g)),
                };
                fe.push(f.map_err(|err| fail(&err))?);
            }
            out.push(fe);
        }
    }
    Ok(out)
}
