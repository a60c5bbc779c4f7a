//! MATE … 'MODS' section_model 'MATS' section_material: a beam section
//! given by a mesh of section elements (QUAS, TRIS). The fibres' rigidities
//! become the beam's section properties (see `fem::fibre_section`).

use super::Args;
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::fibre_section::{equivalent, Fibre};
use crate::value::{Mchaml, Model};
use std::rc::Rc;

/// The section model and material read among MATE's properties.
#[derive(Default)]
pub(crate) struct Given {
    model: Option<Rc<Model>>,
    material: Option<Rc<Mchaml>>,
}

impl Given {
    /// Read the value after `MODS` or `MATS`; false for another keyword.
    pub(crate) fn read(&mut self, k: &str, a: &mut Args) -> Result<bool> {
        match k {
            "MODS" => self.model = Some(a.req::<Rc<Model>>()?),
            "MATS" => self.material = Some(a.req::<Rc<Mchaml>>()?),
            _ => return Ok(false),
        }
        Ok(true)
    }

    /// The section model and material as the field's object components.
    pub(crate) fn objects(&self) -> Vec<(&'static str, crate::value::Value)> {
        use crate::value::Value;
        let mut out = Vec::new();
        if let Some(m) = &self.model {
            out.push(("MODS", Value::Model(m.clone())));
        }
        if let Some(f) = &self.material {
            out.push(("MATS", Value::Mchaml(f.clone())));
        }
        out
    }

    /// The equivalent section properties (none when no section was given).
    pub(crate) fn properties(&self, it: &Interp, a: &Args) -> Result<Vec<(&'static str, f64)>> {
        let (model, mats) = match (&self.model, &self.material) {
            (None, None) => return Ok(vec![]),
            (Some(m), Some(f)) => (m, f),
            (None, _) => return Err(a.missing("the section model ('MODS' MMODEL) with 'MATS'")),
            (_, None) => return Err(a.missing("the section's material ('MATS' MCHAML) with 'MODS'")),
        };
        let fields = [mats.clone()];
        let mut zone_mats = Vec::new();
        for zone in &model.zones {
            if !matches!(zone.element.as_str(), "QUAS" | "TRIS") {
                return Err(a.err(format!(
                    "the section model is made of {} elements; a section is meshed with QUAS (QUA4) or TRIS (TRI3) elements",
                    zone.element
                )));
            }
            let constant = |name: &str| {
                mats.zones.iter().filter(|z| z.mesh == zone.mesh).find_map(|z| z.constants.get(name).copied())
            };
            let m = super::model::material_for(zone, &fields);
            zone_mats.push((m, constant("ALPY").unwrap_or(1.0), constant("ALPZ").unwrap_or(1.0)));
        }
        let mut fibres = Vec::new();
        for (zone, (m, alpy, alpz)) in model.zones.iter().zip(&zone_mats) {
            for part in &zone.mesh.parts {
                for nodes in part.elems() {
                    let x = nodes.iter().map(|n| it.nodes.get(*n)).collect();
                    fibres.push(Fibre { ty: part.ty, x, mat: m, alpy: *alpy, alpz: *alpz });
                }
            }
        }
        equivalent(&fibres).map_err(|e| a.err(e))
    }
}
