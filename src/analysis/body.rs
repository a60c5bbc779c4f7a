//! The deformable body: element sets on numbered unknowns, each with its
//! material. It gives what a step needs beyond the linear solve: strains
//! and stresses at the element points, and the nodal forces of a thermal
//! strain.

use super::material::{ElemKind, Material};
use crate::fem::constitutive;
use crate::fem::element::{self, FemError, GaussField};

/// Elements of one type, formulation and material.
#[derive(Debug)]
pub struct ElementSet {
    pub kind: ElemKind,
    /// Nodes of each element (`ty.nodes()` per element).
    pub conn: Vec<usize>,
    /// For each element, the unknown of each element dof (node by node, in
    /// the order of `element::node_dofs`), or None when no stiffness or
    /// condition reached it (its displacement is then 0).
    pub dofs: Vec<Option<usize>>,
    pub material: Box<dyn Material>,
    /// For a linear material, each element's strains and stresses as
    /// matrices on its displacements, built at the first use: a step then
    /// costs two small products per element, not the element routines.
    linear: std::cell::OnceCell<Option<Vec<LinearElem>>>,
}

/// The strains and stresses of one element as linear maps of its dofs
/// (row-major, one row per point and component).
#[derive(Debug)]
struct LinearElem {
    eps_comps: Vec<&'static str>,
    sig_comps: Vec<&'static str>,
    npts: usize,
    eps: Vec<f64>,
    sig: Vec<f64>,
}

/// Above this many stored coefficients the maps are not kept (memory):
/// the element routines run at each step instead.
const LINEAR_MAX: usize = 20_000_000;

impl ElementSet {
    pub fn new(kind: ElemKind, conn: Vec<usize>, dofs: Vec<Option<usize>>, material: Box<dyn Material>) -> Self {
        ElementSet { kind, conn, dofs, material, linear: Default::default() }
    }

    /// The linear maps of every element, built from the element routines
    /// applied to unit displacements (None when the material is not linear
    /// or the maps would be too big).
    fn linear(&self, x: &dyn Fn(&[usize]) -> Vec<[f64; 3]>) -> Result<Option<&Vec<LinearElem>>, (usize, FemError)> {
        if let Some(l) = self.linear.get() {
            return Ok(l.as_ref());
        }
        let ne = self.n_elem();
        let nd = self.dofs.len() / ne.max(1);
        let mut built = None;
        if self.material.is_linear() && ne > 0 {
            let mut out = Vec::with_capacity(ne);
            let mut total = 0usize;
            for e in 0..ne {
                let xe = x(self.nodes(e));
                let mut unit = vec![0.0; nd];
                let mut cols: Vec<(GaussField, GaussField)> = Vec::with_capacity(nd);
                for j in 0..nd {
                    unit[j] = 1.0;
                    cols.push(self.material.respond(e, self.kind, &xe, &unit, None).map_err(|err| (e, err))?);
                    unit[j] = 0.0;
                }
                let (e0, s0) = &cols[0];
                let npts = e0.values.len();
                let (ne_c, ns_c) = (e0.comps.len(), s0.comps.len());
                let mut eps = vec![0.0; npts * ne_c * nd];
                let mut sig = vec![0.0; npts * ns_c * nd];
                for (j, (ej, sj)) in cols.iter().enumerate() {
                    for p in 0..npts {
                        for c in 0..ne_c {
                            eps[(p * ne_c + c) * nd + j] = ej.values[p][c];
                        }
                        for c in 0..ns_c {
                            sig[(p * ns_c + c) * nd + j] = sj.values[p][c];
                        }
                    }
                }
                total += eps.len() + sig.len();
                if total > LINEAR_MAX {
                    out.clear();
                    break;
                }
                out.push(LinearElem { eps_comps: e0.comps.clone(), sig_comps: s0.comps.clone(), npts, eps, sig });
            }
            if out.len() == ne {
                built = Some(out);
            }
        }
        let _ = self.linear.set(built);
        Ok(self.linear.get().and_then(|l| l.as_ref()))
    }
    pub fn n_elem(&self) -> usize {
        self.conn.len() / self.kind.ty.nodes().max(1)
    }
    fn nodes(&self, e: usize) -> &[usize] {
        let npe = self.kind.ty.nodes();
        &self.conn[e * npe..(e + 1) * npe]
    }
    fn elem_dofs(&self, e: usize) -> &[Option<usize>] {
        let nd = self.dofs.len() / self.n_elem().max(1);
        &self.dofs[e * nd..(e + 1) * nd]
    }
}

/// An element routine failed: which set, which element.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyError {
    pub set: usize,
    pub elem: usize,
    pub error: FemError,
}

/// `m · u` laid out as a field of `npts` points over `comps`.
fn apply(m: &[f64], comps: &[&'static str], npts: usize, u: &[f64]) -> GaussField {
    let nd = u.len();
    let nc = comps.len();
    let values = (0..npts)
        .map(|p| {
            (0..nc)
                .map(|c| m[(p * nc + c) * nd..(p * nc + c + 1) * nd].iter().zip(u).map(|(a, b)| a * b).sum())
                .collect()
        })
        .collect();
    GaussField { comps: comps.to_vec(), values }
}

/// The strains and stresses of one set, element by element.
#[derive(Debug, Clone, Default)]
pub struct SetFields {
    pub strains: Vec<GaussField>,
    pub stresses: Vec<GaussField>,
}

/// The body: node coordinates (by node number) and element sets.
#[derive(Debug, Default)]
pub struct Body {
    pub coords: Vec<[f64; 3]>,
    pub sets: Vec<ElementSet>,
}

impl Body {
    /// Whether every material is linear elastic.
    pub fn is_linear(&self) -> bool {
        self.sets.iter().all(|s| s.material.is_linear())
    }

    fn x(&self, nodes: &[usize]) -> Vec<[f64; 3]> {
        nodes.iter().map(|&n| self.coords[n]).collect()
    }

    /// Strains and stresses for the displacements `u` (by unknown) and,
    /// when heated, the temperature rise of each node (by node number).
    pub fn fields(&self, u: &[f64], heat: Option<&[f64]>) -> Result<Vec<SetFields>, BodyError> {
        let mut out = Vec::with_capacity(self.sets.len());
        for (si, s) in self.sets.iter().enumerate() {
            let mut f = SetFields::default();
            let linear = match heat {
                None => s.linear(&|n| self.x(n)).map_err(|(elem, error)| BodyError { set: si, elem, error })?,
                Some(_) => None,
            };
            if let Some(ops) = linear {
                for (e, op) in ops.iter().enumerate() {
                    let ue: Vec<f64> = s.elem_dofs(e).iter().map(|d| d.map_or(0.0, |i| u[i])).collect();
                    f.strains.push(apply(&op.eps, &op.eps_comps, op.npts, &ue));
                    f.stresses.push(apply(&op.sig, &op.sig_comps, op.npts, &ue));
                }
                out.push(f);
                continue;
            }
            for e in 0..s.n_elem() {
                let nodes = s.nodes(e);
                let ue: Vec<f64> = s.elem_dofs(e).iter().map(|d| d.map_or(0.0, |i| u[i])).collect();
                let dt: Option<Vec<f64>> =
                    heat.map(|h| nodes.iter().map(|&n| h.get(n).copied().unwrap_or(0.0)).collect());
                let (eps, sig) = s
                    .material
                    .respond(e, s.kind, &self.x(nodes), &ue, dt.as_deref())
                    .map_err(|error| BodyError { set: si, elem: e, error })?;
                f.strains.push(eps);
                f.stresses.push(sig);
            }
            out.push(f);
        }
        Ok(out)
    }

    /// The nodal forces (by unknown, `n` of them) that a temperature rise
    /// `heat` (by node number) exerts: ∫ Bᵀ D α ΔT. Sets without thermal
    /// expansion (no 'ALPH') take none.
    pub fn thermal_forces(&self, n: usize, heat: &[f64]) -> Result<Vec<f64>, BodyError> {
        let mut f = vec![0.0; n];
        for (si, s) in self.sets.iter().enumerate() {
            let k = s.kind;
            for e in 0..s.n_elem() {
                let props = s.material.props_of(e);
                if props.alph.is_none() {
                    continue;
                }
                let mut m0 = props.clone();
                m0.tref = Some(0.0);
                let nodes = s.nodes(e);
                let dt: Vec<f64> = nodes.iter().map(|&n| heat.get(n).copied().unwrap_or(0.0)).collect();
                if dt.iter().all(|v| *v == 0.0) {
                    continue;
                }
                let err = |error| BodyError { set: si, elem: e, error };
                let x = self.x(nodes);
                let th = constitutive::thermal_strain(k.form, k.ty, k.mode, &m0, &dt).map_err(err)?;
                let sig = constitutive::hooke(k.form, k.ty, k.mode, props, &th).map_err(err)?;
                let fe = element::internal_forces(k.form, k.ty, k.mode, &x, props, &sig).map_err(err)?;
                for (d, v) in s.elem_dofs(e).iter().zip(&fe) {
                    if let Some(i) = d {
                        f[*i] += v;
                    }
                }
            }
        }
        Ok(f)
    }
}
