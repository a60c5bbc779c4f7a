//! MMODEL, MCHAML and EVOLUTIO objects.

use crate::fem::mesh::{Mesh, Part};
use std::collections::BTreeMap;

/// A model: a mesh tied to a formulation and an element type (`MODE`).
#[derive(Debug, Clone)]
pub struct Model {
    pub zones: Vec<ModelZone>,
    /// The relation elements (MULT, from RAFF) of the meshes the model was
    /// made on: they carry no mechanics and RELA of the model turns them
    /// into the conditions that tie hanging nodes.
    pub ties: Vec<crate::fem::mesh::Part>,
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
    /// The node carrying the out-of-plane strain of generalised plane
    /// strain (MODE … 'DPGE' P), which every element of the zone shares.
    pub dpge: Option<usize>,
    /// The crack enrichment of an X-FEM zone (XQ4R), set by TRIE; shared by
    /// every model holding the zone, as TRIE changes the model in place.
    pub xfem: Option<std::rc::Rc<std::cell::RefCell<crate::fem::xfem::Enrichment>>>,
    /// The constituent's name (MODE … 'CONS' name; empty when none was
    /// given): zones on one mesh (the layers of a multilayer shell) keep
    /// their own material data apart by it.
    pub cons: String,
}

impl ModelZone {
    /// The zone of one mesh part, as every MODE form makes them: the
    /// element named after the part's geometry unless one is given, and no
    /// generalised-plane-strain point.
    pub fn on_part(
        part: &Part,
        formulation: &str,
        behaviour: &[String],
        element: Option<&str>,
        mode: &str,
    ) -> ModelZone {
        ModelZone {
            mesh: Mesh::single(part.clone()),
            formulation: formulation.into(),
            behaviour: behaviour.to_vec(),
            element: element.unwrap_or(part.ty.name()).into(),
            mode: mode.into(),
            dpge: None,
            xfem: None,
            cons: String::new(),
        }
    }
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
    /// Components that hold objects, one per zone: the section model and
    /// material of a fibre beam (MATE … 'MODS' 'MATS'), which procedures
    /// read back with EXTR.
    pub objects: BTreeMap<String, super::Value>,
    /// Point values: component names, then values[element][point][component].
    pub comps: Vec<String>,
    pub values: Vec<Vec<Vec<f64>>>,
    /// The points are the element's nodes (CHAN 'NOEUD'), not the points
    /// where the element gives its stresses.
    pub at_nodes: bool,
    /// The constituent of the model zone the data was given on (MATE,
    /// CARA); empty for any constituent.
    pub cons: String,
}

impl MchamlZone {
    /// Whether this zone's data belongs to model zone `z`: the same mesh
    /// and no other constituent.
    pub fn belongs_to(&self, z: &ModelZone) -> bool {
        self.mesh == z.mesh && (self.cons.is_empty() || z.cons.is_empty() || self.cons == z.cons)
    }
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

impl Mchaml {
    /// `f` applied to every value (constants and point values).
    pub fn map(&self, f: &dyn Fn(f64) -> f64) -> Mchaml {
        let mut out = self.clone();
        for z in out.zones.iter_mut() {
            for v in z.constants.values_mut() {
                *v = f(*v);
            }
            for v in z.values.iter_mut().flatten().flatten() {
                *v = f(*v);
            }
        }
        out
    }

    /// Two element fields combine value by value when they have the same
    /// layout (zones, elements, points, components), as fields made on one
    /// model do.
    pub fn combine(&self, b: &Mchaml, f: impl Fn(f64, f64) -> f64) -> Result<Mchaml, String> {
        let shape = |z: &MchamlZone| {
            (
                z.comps.clone(),
                z.values.iter().map(|e| e.len()).collect::<Vec<_>>(),
                z.constants.keys().cloned().collect::<Vec<_>>(),
            )
        };
        if self.zones.len() != b.zones.len() || self.zones.iter().zip(&b.zones).any(|(p, q)| shape(p) != shape(q)) {
            return crate::value::mchaml_broadcast::combine_scalar(self, b, f)
                .ok_or_else(|| "the element fields do not have the same zones, elements and components".into());
        }
        let mut out = self.clone();
        for (z, w) in out.zones.iter_mut().zip(&b.zones) {
            for (k, v) in z.constants.iter_mut() {
                *v = f(*v, w.constants[k]);
            }
            for (p, q) in z.values.iter_mut().flatten().flatten().zip(w.values.iter().flatten().flatten()) {
                *p = f(*p, *q);
            }
        }
        Ok(out)
    }

    /// `ET`: the zones of both; material data given on the same mesh in
    /// two fields (MATE … ET CARA …) join into one zone, and so do point
    /// values on the same elements and points under other component names
    /// (N11 ET N22 is one field of two components, as Cast3M makes it).
    pub fn merge(&self, b: &Mchaml) -> Mchaml {
        let mut out = self.clone();
        for z in &b.zones {
            if let Some(x) = out
                .zones
                .iter_mut()
                .find(|x| x.mesh == z.mesh && x.cons == z.cons && x.values.is_empty() && z.values.is_empty())
            {
                x.constants.extend(z.constants.clone());
                x.vectors.extend(z.vectors.clone());
                x.laws.extend(z.laws.clone());
                x.objects.extend(z.objects.clone());
            } else if let Some(x) = out.zones.iter_mut().find(|x| x.joins_components(z)) {
                for (ex, ez) in x.values.iter_mut().zip(&z.values) {
                    for (px, pz) in ex.iter_mut().zip(ez) {
                        px.extend_from_slice(pz);
                    }
                }
                x.comps.extend(z.comps.iter().cloned());
            } else {
                out.zones.push(z.clone());
            }
        }
        out
    }
}

impl MchamlZone {
    /// Whether `z` holds point values on the same elements and points as
    /// this zone under component names this zone does not have.
    fn joins_components(&self, z: &MchamlZone) -> bool {
        self.mesh == z.mesh
            && !self.values.is_empty()
            && self.at_nodes == z.at_nodes
            && self.values.len() == z.values.len()
            && self.values.iter().zip(&z.values).all(|(p, q)| p.len() == q.len())
            && self.constants.is_empty()
            && z.constants.is_empty()
            && z.comps.iter().all(|c| !self.comps.contains(c))
    }
}

impl Evolution {
    /// Functions of a curve act on its ordinates.
    pub fn map(&self, f: &dyn Fn(f64) -> f64) -> Evolution {
        let mut out = self.clone();
        for c in out.curves.iter_mut() {
            for y in c.y.iter_mut() {
                *y = f(*y);
            }
        }
        out
    }

    /// Two curves combine point by point: same number of curves, same
    /// abscissae (a curve is a function sampled at its abscissae; adding
    /// two samplings of different points would need an interpolation the
    /// deck did not ask for).
    pub fn combine(&self, b: &Evolution, f: impl Fn(f64, f64) -> f64) -> Result<Evolution, String> {
        if self.curves.len() != b.curves.len() {
            return Err(format!("the curves do not match: {} curve(s) and {}", self.curves.len(), b.curves.len()));
        }
        let mut out = self.clone();
        for (k, (c, d)) in out.curves.iter_mut().zip(&b.curves).enumerate() {
            if !c.same_abscissae(d) {
                return Err(format!("curve {} of each side does not have the same abscissae", k + 1));
            }
            for (p, q) in c.y.iter_mut().zip(&d.y) {
                *p = f(*p, *q);
            }
        }
        Ok(out)
    }
}

impl Curve {
    fn same_abscissae(&self, d: &Curve) -> bool {
        let scale = self.x.iter().chain(&d.x).fold(0.0f64, |m, x| m.max(x.abs())).max(1e-300);
        self.x.len() == d.x.len() && self.x.iter().zip(&d.x).all(|(p, q)| (p - q).abs() <= 1e-12 * scale)
    }
}

/// What EXTR and EXIS select the zones of a model by.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ZoneKey {
    /// 'FORM': the formulation (MECANIQUE, CONTACT, ...).
    Formulation,
    /// 'ELEM': the finite element (QUA4, POUT, ...).
    Element,
    /// A word of the behaviour (ELASTIQUE, PRESSION, ...): `EXIS m 'MATE'
    /// w`, `EXTR m 'COMP' w`.
    Behaviour,
}

impl Model {
    /// The zones of both models, and the relation elements of both.
    pub fn union(&self, other: &Model) -> Model {
        let ties = Mesh { parts: self.ties.clone() }.union(&Mesh { parts: other.ties.clone() });
        Model { zones: self.zones.iter().chain(other.zones.iter()).cloned().collect(), ties: ties.parts }
    }

    /// The relation elements all of whose nodes are nodes of `zones` (a
    /// model reduced to part of its mesh keeps the ties inside that part).
    pub fn ties_within(&self, zones: &[ModelZone]) -> Vec<crate::fem::mesh::Part> {
        let nodes: std::collections::HashSet<usize> = zones.iter().flat_map(|z| z.mesh.node_list()).collect();
        let mut out = Vec::new();
        for p in &self.ties {
            let conn: Vec<usize> =
                p.elems().filter(|e| e.iter().all(|n| nodes.contains(n))).flatten().copied().collect();
            if !conn.is_empty() {
                out.push(crate::fem::mesh::Part::with(p.ty, conn));
            }
        }
        out
    }

    /// The zones whose formulation or element is one of `words`. Names
    /// compare on their first four letters, as Cast3M's keywords do
    /// (`'MECA'` and `'MECANIQUE'` are one formulation).
    pub fn zones_with(&self, key: ZoneKey, words: &[String]) -> Model {
        let four = |s: &str| s.trim().to_uppercase().chars().take(4).collect::<String>();
        let wanted: Vec<String> = words.iter().map(|w| four(w)).collect();
        let zones = self
            .zones
            .iter()
            .filter(|z| match key {
                ZoneKey::Formulation => wanted.contains(&four(&z.formulation)),
                ZoneKey::Element => wanted.contains(&four(&z.element)),
                ZoneKey::Behaviour => z.behaviour.iter().any(|b| wanted.contains(&four(b))),
            })
            .cloned()
            .collect();
        Model { zones, ties: self.ties.clone() }
    }
}
