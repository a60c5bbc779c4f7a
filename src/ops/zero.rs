//! ZERO (zero.notice): a field by element of a model whose components are
//! all zero, of a given subtype. Its components and points are those the
//! model's elements give for that subtype (UX UY at the nodes for
//! displacements, SMXX … at the stress points for stresses, …), so it can
//! start a sum or stand for "nothing yet" in a procedure.

use super::model::{formulation, zone_mode};
use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::element::{self, Formulation, Mode};
use crate::fem::mesh::{Mesh, Part};
use crate::fem::solid;
use crate::value::model::{Mchaml, MchamlZone, Model, ModelZone};
use crate::value::Value;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "ZERO",
    signature: "CHAM1 = ZERO MMODEL MOT   (MOT: NOEUD GRAVITE RIGIDITE MASSE STRESSES DEPLACEM FORCES GRADIENT CONTRAIN DEFORMAT MATERIAU CARACTER TEMPERAT PRINCIPA VARINTER DEFINELA)",
    doc: "A field by element of the model with every component zero. NOEUD, GRAVITE, RIGIDITE, MASSE and STRESSES give the scalar SCAL at the nodes, the centre, or the integration points; DEPLACEM and FORCES the model's unknowns and their duals at the nodes; GRADIENT, CONTRAIN, DEFORMAT, DEFINELA, PRINCIPA, VARINTER, MATERIAU, CARACTER and TEMPERAT their components at the stress points.",
    example: "m = manu 'QUA4' (0 0) (1 0) (1 1) (0 1) ; mo = mode m 'MECANIQUE' ; s = zero mo 'CONTRAIN' ;",
    f: zero,
}];

/// Where a subtype lives in an element.
#[derive(Clone, Copy, PartialEq)]
enum Points {
    Nodes,
    Centre,
    Stress,
}

const KINDS: &[&str] = &[
    "NOEUD", "GRAVITE", "RIGIDITE", "MASSE", "STRESSES", "DEPLACEM", "FORCES", "GRADIENT", "CONTRAIN", "DEFORMAT",
    "MATERIAU", "CARACTER", "TEMPERAT", "PRINCIPA", "MAHOOKE", "HOTANGEN", "VARINTER", "DEFINELA",
];

fn zero(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let model = a.req::<Rc<Model>>()?;
    let kind = a.req_keyword(KINDS)?;
    if matches!(kind, "MAHOOKE" | "HOTANGEN") {
        return Err(a.err(format!("{}: gibi's fields by element hold numbers, not Hooke matrices", kind)));
    }
    let mut out = Mchaml { subtype: subtype(kind).into(), zones: vec![] };
    // A pressure model's zones have a geometry only: the scalar layouts
    // (a field to give PRES mop CHEL1) but no mechanical components.
    let scalar = matches!(kind, "NOEUD" | "GRAVITE" | "RIGIDITE" | "MASSE" | "STRESSES");
    for zone in model.zones.iter().filter(|z| scalar || z.formulation != super::pres_model::FORMULATION) {
        let (points, comps) = layout(kind, zone).map_err(|m| a.err(m))?;
        for part in &zone.mesh.parts {
            out.zones.push(zeros(zone, part, points, &comps));
        }
    }
    Ok(vec![Value::Mchaml(Rc::new(out))])
}

/// The title of the field, as the operators that compute it give it.
fn subtype(kind: &str) -> &'static str {
    match kind {
        "DEPLACEM" => "DEPLACEMENTS",
        "FORCES" => "FORCES",
        "GRADIENT" => "GRADIENT",
        "CONTRAIN" => "CONTRAINTES",
        "DEFORMAT" => "DEFORMATIONS",
        "DEFINELA" => "DEFORMATIONS INELASTIQUES",
        "MATERIAU" => "CARACTERISTIQUES",
        "CARACTER" => "CARACTERISTIQUES",
        "TEMPERAT" => "TEMPERATURES",
        "PRINCIPA" => "CONTRAINTES PRINCIPALES",
        "VARINTER" => "VARIABLES INTERNES",
        _ => "SCALAIRE",
    }
}

fn thermal(zone: &ModelZone) -> bool {
    zone.formulation.starts_with("THER")
}

/// The points and component names of one subtype in one zone.
fn layout(kind: &str, zone: &ModelZone) -> std::result::Result<(Points, Vec<String>), String> {
    let names = |v: &[&str]| v.iter().map(|s| s.to_string()).collect::<Vec<_>>();
    let mech = || -> std::result::Result<(Formulation, Mode), String> {
        Ok((formulation(zone), zone_mode(zone).map_err(|e| e.message)?))
    };
    Ok(match kind {
        "NOEUD" => (Points::Nodes, names(&["SCAL"])),
        "GRAVITE" => (Points::Centre, names(&["SCAL"])),
        "RIGIDITE" | "MASSE" | "STRESSES" => (Points::Stress, names(&["SCAL"])),
        "TEMPERAT" if thermal(zone) => (Points::Nodes, names(&["T"])),
        "TEMPERAT" => (Points::Stress, names(&["T"])),
        "DEPLACEM" | "FORCES" if thermal(zone) => (Points::Nodes, names(&[if kind == "FORCES" { "Q" } else { "T" }])),
        "DEPLACEM" => {
            let (f, m) = mech()?;
            (Points::Nodes, names(element::node_dofs(f, m).map_err(|e| e.to_string())?))
        }
        "FORCES" => {
            let (f, m) = mech()?;
            (Points::Nodes, names(element::node_duals(f, m).map_err(|e| e.to_string())?))
        }
        _ if thermal(zone) => return Err(format!("{} is not a subtype of a thermal model", kind)),
        "VARINTER" => (Points::Stress, internal_variables(zone)),
        "MATERIAU" => (Points::Stress, names(&["YOUN", "NU", "RHO", "ALPH"])),
        "CARACTER" => (Points::Stress, Vec::new()),
        _ => {
            let (f, m) = mech()?;
            (Points::Stress, stress_point_comps(kind, f, m, zone)?)
        }
    })
}

/// Internal variables of the behaviour: the cumulated plastic strain EPSE.
/// A purely elastic material carries it too (always zero), so that a
/// procedure written for elasto-plasticity (G_THETA's plastic work term,
/// `EXCO VARF 'EPSE'`) runs unchanged on an elastic model.
fn internal_variables(zone: &ModelZone) -> Vec<String> {
    if zone.behaviour.iter().any(|b| b.starts_with("PLAS") || b.starts_with("ELAS")) {
        vec!["EPSE".into()]
    } else {
        Vec::new()
    }
}

/// GRADIENT, CONTRAIN, DEFORMAT, DEFINELA, PRINCIPA components.
fn stress_point_comps(
    kind: &str,
    f: Formulation,
    m: Mode,
    zone: &ModelZone,
) -> std::result::Result<Vec<String>, String> {
    let massive = matches!(f, Formulation::Solid | Formulation::Q4ri | Formulation::Q8ri);
    let v: Vec<&str> = match kind {
        "CONTRAIN" if massive => solid::stress_comps(m),
        "DEFORMAT" | "DEFINELA" if massive => solid::strain_comps(m),
        "GRADIENT" if massive => solid::gradient_comps(m),
        "PRINCIPA" if massive && m == Mode::Trid => {
            vec!["SI11", "SI22", "SI33", "COX1", "COY1", "COZ1", "COX2", "COY2", "COZ2", "COX3", "COY3", "COZ3"]
        }
        "PRINCIPA" if massive => vec!["SI11", "SI22", "SI33", "COX1", "COY1", "COX2", "COY2"],
        // Shells: their generalised stresses and strains (SIGM, EPSI).
        "CONTRAIN" if f == Formulation::Coq2 => crate::fem::coq2::STRESS.to_vec(),
        "DEFORMAT" | "DEFINELA" if f == Formulation::Coq2 => crate::fem::coq2::STRAIN.to_vec(),
        "CONTRAIN" if f.is_shell() => crate::fem::shell::STRESS.to_vec(),
        "DEFORMAT" | "DEFINELA" if f.is_shell() => crate::fem::shell::STRAIN.to_vec(),
        _ => return Err(format!("{} of {} elements is not available (massive elements only)", kind, zone.element)),
    };
    Ok(v.into_iter().map(String::from).collect())
}

fn zeros(zone: &ModelZone, part: &Part, points: Points, comps: &[String]) -> MchamlZone {
    let n = match points {
        Points::Nodes => part.ty.nodes(),
        Points::Centre => 1,
        Points::Stress => element::gauss_points(formulation(zone), part.ty).len(),
    };
    let values = part.elems().map(|_| vec![vec![0.0; comps.len()]; n]).collect();
    MchamlZone {
        mesh: Mesh::single(part.clone()),
        element: zone.element.clone(),
        comps: comps.to_vec(),
        values,
        at_nodes: points == Points::Nodes,
        ..Default::default()
    }
}
