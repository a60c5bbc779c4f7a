//! The scalar TRAC colours a picture with: of a CHPOINT, on the nodes of
//! its support mesh; of an MCHAML (VMIS, SIGM, …), one value per element,
//! the mean of its points.

use crate::fem::mesh::Mesh;
use crate::io::plot;
use crate::value::{Chpoint, Mchaml};

/// The only component, else the displacement magnitude, else the first
/// component.
pub(super) fn nodal_field(c: &Chpoint, mesh: Mesh) -> plot::Field {
    let comps = c.components();
    let disp: Vec<&str> = ["UX", "UY", "UZ"].into_iter().filter(|u| comps.iter().any(|c| c == u)).collect();
    let (name, values) = if comps.len() != 1 && !disp.is_empty() {
        let mag = |n: usize| disp.iter().map(|u| c.get(n, u).unwrap_or(0.0).powi(2)).sum::<f64>().sqrt();
        ("|U|".to_string(), c.nodes.iter().map(|&n| (n, mag(n))).collect())
    } else {
        let first = comps.first().cloned().unwrap_or_default();
        let values = c.nodes.iter().filter_map(|&n| Some((n, c.get(n, &first)?))).collect();
        (first, values)
    };
    plot::Field::Nodal(plot::NodalField { mesh, values, name })
}

/// Every element of every zone with the mean of its point values for one
/// component (the only one, else VMIS/SCAL when present, else the first),
/// or the zone's constant. Err when the field has no component to show.
pub(super) fn element_field(m: &Mchaml) -> Result<plot::Field, String> {
    let mut comps: Vec<&str> = Vec::new();
    for z in &m.zones {
        let names: Vec<&str> = match z.values.is_empty() {
            true => z.constants.keys().map(String::as_str).collect(),
            false => z.comps.iter().map(String::as_str).collect(),
        };
        for c in names {
            if !comps.contains(&c) {
                comps.push(c);
            }
        }
    }
    let name = match comps.as_slice() {
        [] => return Err(format!("the {} field has no value to draw", m.subtype)),
        [one] => one.to_string(),
        many => many.iter().find(|c| ["VMIS", "SCAL"].contains(c)).unwrap_or(&many[0]).to_string(),
    };
    let mut cells = Vec::new();
    for z in &m.zones {
        let ci = z.comps.iter().position(|c| *c == name);
        let elems = z.mesh.parts.iter().flat_map(|p| p.elems().map(move |e| (p.ty, e)));
        for (e, (ty, conn)) in elems.enumerate() {
            let v = match (ci, z.values.get(e)) {
                (Some(ci), Some(pts)) if !pts.is_empty() => {
                    pts.iter().map(|p| p.get(ci).copied().unwrap_or(f64::NAN)).sum::<f64>() / pts.len() as f64
                }
                _ => z.constants.get(&name).copied().unwrap_or(f64::NAN),
            };
            cells.push((ty, conn.to_vec(), v));
        }
    }
    if comps.len() > 1 {
        let others = comps.iter().filter(|c| **c != name).count();
        return Ok(plot::Field::Element(plot::ElementField { cells, name: format!("{} (+{} more)", name, others) }));
    }
    Ok(plot::Field::Element(plot::ElementField { cells, name }))
}
