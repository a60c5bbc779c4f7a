//! MMODEL, MCHAML and EVOLUTIO objects.

use crate::fem::mesh::Mesh;
use std::collections::BTreeMap;

/// A model: a mesh tied to a formulation and an element type (`MODE`).
#[derive(Debug, Clone)]
pub struct Model {
    pub zones: Vec<ModelZone>,
}

#[derive(Debug, Clone)]
pub struct ModelZone {
    pub mesh: Mesh,
    /// MECANIQUE, THERMIQUE, ...
    pub formulation: String,
    /// ELASTIQUE ISOTROPE ...
    pub behaviour: Vec<String>,
    /// BARR, POUT, TIMO, QUA4, Q4RI, ... (the element of the formulation).
    pub element: String,
    /// Analysis mode at the time of MODE (PLAN CONT, AXIS, TRID, ...).
    pub mode: String,
}

/// A field by element: per zone, per element, per point, named components.
/// Material and section data (MATE, CARA) are constant MCHAMLs.
#[derive(Debug, Clone, Default)]
pub struct Mchaml {
    /// CARACTERISTIQUES, CONTRAINTES, DEFORMATIONS, ...
    pub subtype: String,
    pub zones: Vec<MchamlZone>,
}

#[derive(Debug, Clone, Default)]
pub struct MchamlZone {
    pub mesh: Mesh,
    pub element: String,
    /// Constant values (material and geometric data): name -> value.
    pub constants: BTreeMap<String, f64>,
    /// Vector data (CARA 'VECT').
    pub vectors: BTreeMap<String, [f64; 3]>,
    /// Properties that depend on a parameter (MATE … 'YOUN' EVOLUTIO):
    /// name -> curve whose abscissa names the parameter. VARI evaluates
    /// them against a field of that parameter.
    pub laws: BTreeMap<String, Curve>,
    /// Point values: component names, then values[element][point][component].
    pub comps: Vec<String>,
    pub values: Vec<Vec<Vec<f64>>>,
    /// The points are the element's nodes (CHAN 'NOEUD'), not the points
    /// where the element gives its stresses.
    pub at_nodes: bool,
}

/// EVOLUTIO: curves y(x).
#[derive(Debug, Clone, Default)]
pub struct Evolution {
    pub curves: Vec<Curve>,
}

#[derive(Debug, Clone, Default)]
pub struct Curve {
    pub legend: String,
    pub x_name: String,
    pub y_name: String,
    pub x: Vec<f64>,
    pub y: Vec<f64>,
}
