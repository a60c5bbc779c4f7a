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
}

impl ElementSet {
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
            for e in 0..s.n_elem() {
                let nodes = s.nodes(e);
                let ue: Vec<f64> = s.elem_dofs(e).iter().map(|d| d.map_or(0.0, |i| u[i])).collect();
                let dt: Option<Vec<f64>> =
                    heat.map(|h| nodes.iter().map(|&n| h.get(n).copied().unwrap_or(0.0)).collect());
                let (eps, sig) = s
                    .material
                    .respond(s.kind, &self.x(nodes), &ue, dt.as_deref())
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
            let props = s.material.props();
            if props.alph.is_none() {
                continue;
            }
            let mut m0 = props.clone();
            m0.tref = Some(0.0);
            let k = s.kind;
            for e in 0..s.n_elem() {
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
