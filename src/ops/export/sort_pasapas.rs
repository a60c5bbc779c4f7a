//! `SORT 'VTK'` of a PASAPAS table: one ParaView collection (.pvd) with a
//! .vtu per saved step, at its time: displacements (DEPL), stresses
//! (SIGMA) and strains (EPSI) averaged per element, and with a contact
//! model the status and pressure at the contact nodes (contact_status,
//! contact_pressure; NaN elsewhere).

use super::sort_vtk::{cell_field, write_collection, write_step};
use super::{io_err, sort_base};
use crate::error::Result;
use crate::eval::args::Args;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::io::vtk;
use crate::value::{Key, Table, Value};
use std::cell::RefCell;
use std::rc::Rc;

pub(super) fn sort_table(it: &mut Interp, a: &mut Args, t: &Rc<RefCell<Table>>) -> Result<Vec<Value>> {
    let t = t.borrow();
    let get = |k: &str| t.get(&Key::Mot(k.into())).cloned();
    let times = match get("TEMPS") {
        Some(Value::Table(x)) => x,
        _ => return Err(a.err("the TABLE is not a PASAPAS result (no 'TEMPS'): run PASAPAS on it first")),
    };
    let mesh = match a.opt::<Rc<Mesh>>() {
        Some(m) => (*m).clone(),
        None => match get("MODELE") {
            // The mechanical zones: contact elements are not cells.
            Some(Value::Model(m)) => {
                m.zones.iter().filter(|z| z.formulation != "CONTACT").fold(Mesh::default(), |acc, z| acc.union(&z.mesh))
            }
            _ => return Err(a.missing("MAILLAGE (the table has no 'MODELE')")),
        },
    };
    let series = |k: &str| match get(k) {
        Some(Value::Table(x)) => Some(x),
        _ => None,
    };
    let (depl, sig, eps) = (series("DEPLACEMENTS"), series("CONTRAINTES"), series("DEFORMATIONS"));
    let (stat, pres) = (series("STATUTS_CONTACT"), series("PRESSIONS_CONTACT"));
    let mut indices: Vec<i64> =
        times.borrow().iter().filter_map(|(k, _)| if let Key::Int(i) = k { Some(*i) } else { None }).collect();
    indices.sort_unstable();
    let base = sort_base(it).unwrap_or_else(|| "gibi".into());
    let mut steps: Vec<(f64, String)> = Vec::new();
    for i in indices {
        let at = |s: &Option<Rc<RefCell<Table>>>| s.as_ref().and_then(|s| s.borrow().get(&Key::Int(i)).cloned());
        let time = times.borrow().get(&Key::Int(i)).and_then(Value::as_f64).unwrap_or(i as f64);
        let mut grid = vtk::Grid::new(&mesh, &it.nodes).map_err(io_err)?;
        if let Some(Value::Chpo(u)) = at(&depl) {
            let comps: Vec<String> = u.components().into_iter().filter(|c| c != "LX" && c != "FLX").collect();
            grid.add_point_field("DEPL", &comps, |n, c| u.get(n, c));
        }
        for (name, s) in [("SIGMA", &sig), ("EPSI", &eps)] {
            if let Some(Value::Mchaml(m)) = at(s) {
                grid.add_cell_array(cell_field(&grid, &m, name)).map_err(io_err)?;
            }
        }
        for (name, comp, s) in [("contact_status", "STAT", &stat), ("contact_pressure", "PRES", &pres)] {
            if let Some(Value::Chpo(c)) = at(s) {
                grid.add_point_field(name, &[comp.to_string()], |n, k| c.get(n, k));
            }
        }
        steps.push((time, write_step(it, &grid, &format!("{}_{:04}.vtu", base, i))?));
    }
    write_collection(it, &base, &steps)?;
    Ok(vec![])
}
