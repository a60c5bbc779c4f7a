//! ZERO (zero.notice): an element field of zeros on a model, of the
//! subtype named: the node unknowns ('DEPLACEM'), their forces ('FORCES')
//! or one scalar ('NOEUD') at the element nodes; the displacement gradient
//! at the stress points ('GRADIENT'); the internal variables ('VARINTER'),
//! which gibi's elastic models have none of (a field without components).

use super::model::{formulation, zone_mode};
use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::element::{self, node_dofs, node_duals};
use crate::fem::material::Material;
use crate::value::model::{MchamlZone, ModelZone};
use crate::value::{Mchaml, Model, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "ZERO",
    signature: "ZERO MMODEL 'DEPLACEM'|'FORCES'|'NOEUD'|'GRADIENT'|'VARINTER'",
    doc: "An element field of zeros on the model, at the element nodes: its displacement components ('DEPLACEM'), \
          force components ('FORCES') or one scalar SCAL ('NOEUD'); the displacement gradient at the stress points \
          ('GRADIENT'); no internal variables ('VARINTER': the elastic models have none).",
    example: "z = zero mo 'FORCES' ;",
    f: zero,
}];

fn zero(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let model = a.req::<Rc<Model>>()?;
    let kind = a.word().ok_or_else(|| a.missing("the subtype (DEPLACEM, FORCES or NOEUD)"))?;
    let kind = kind.trim().to_uppercase();
    let (subtype, what) = match kind.as_str() {
        "DEPLACEM" | "DEPL" => ("DEPLACEMENTS", 0),
        "FORCES" | "FORC" => ("FORCES", 1),
        "NOEUD" | "NOEU" => ("SCALAIRE", 2),
        "GRADIENT" | "GRAD" => ("GRADIENT", 3),
        "VARINTER" | "VARI" => ("VARIABLES INTERNES", 4),
        _ => {
            return Err(a.err(format!("ZERO makes DEPLACEM, FORCES, NOEUD, GRADIENT or VARINTER fields, not {}", kind)))
        }
    };
    let mut out = Mchaml { subtype: subtype.into(), zones: vec![] };
    for z in &model.zones {
        if what >= 3 {
            out.zones.push(at_points(it, a, z, what == 3)?);
            continue;
        }
        let comps: Vec<String> = if what == 2 {
            vec!["SCAL".into()]
        } else {
            let (f, mode) = (formulation(z), zone_mode(z)?);
            let names = if what == 1 { node_duals(f, mode) } else { node_dofs(f, mode) };
            names.map_err(|e| a.err(e))?.iter().map(|s| s.to_string()).collect()
        };
        let mut mz = MchamlZone { mesh: z.mesh.clone(), element: z.element.clone(), ..Default::default() };
        mz.at_nodes = true;
        for part in &z.mesh.parts {
            for nodes in part.elems() {
                mz.values.push(vec![vec![0.0; comps.len()]; nodes.len()]);
            }
        }
        mz.comps = comps;
        out.zones.push(mz);
    }
    Ok(vec![Value::Mchaml(Rc::new(out))])
}

/// The zone's zero gradient at its stress points (the gradient of a zero
/// displacement), or an empty internal-variable field.
fn at_points(it: &Interp, a: &Args, z: &ModelZone, gradient: bool) -> Result<MchamlZone> {
    let mut mz = MchamlZone { mesh: z.mesh.clone(), element: z.element.clone(), ..Default::default() };
    let (f, mode) = (formulation(z), zone_mode(z)?);
    let dofs = node_dofs(f, mode).map_err(|e| a.err(e))?.len();
    for part in &z.mesh.parts {
        for nodes in part.elems() {
            if !gradient {
                mz.values.push(vec![]);
                continue;
            }
            let x: Vec<[f64; 3]> = nodes.iter().map(|n| it.nodes.get(*n)).collect();
            let g = element::gradient(f, part.ty, mode, &x, &Material::default(), &vec![0.0; dofs * nodes.len()])
                .map_err(|e| a.err(e))?;
            if mz.comps.is_empty() {
                mz.comps = g.comps.iter().map(|c| c.to_string()).collect();
            }
            mz.values.push(g.values);
        }
    }
    Ok(mz)
}
