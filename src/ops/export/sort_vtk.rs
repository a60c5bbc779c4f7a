//! SORT 'VTK': a mesh and its fields as a ParaView `.vtu`, one per call or,
//! with 'TEMPS', a numbered `.vtu` per step and the `.pvd` collection of
//! them all; 'CONTACT' adds the status, gap and pressure of the unilateral
//! conditions as point data.

use super::{io_err, out_path, sort_base, write_err, wrote};
use crate::error::Result;
use crate::eval::args::Args;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::io::vtk;
use crate::value::{Chpoint, Mchaml, Table, Value};
use std::cell::RefCell;
use std::path::Path;
use std::rc::Rc;

/// 'CONTACT': the conditions, the RESO solution, and optionally the limits.
type ContactArgs = (Rc<crate::value::Rigidite>, Rc<Chpoint>, Option<Rc<Chpoint>>);

pub(super) fn sort_vtk(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if let Some(t) = a.opt::<Rc<RefCell<Table>>>() {
        return super::sort_pasapas::sort_table(it, a, &t);
    }
    let mut mesh: Option<Rc<Mesh>> = None;
    let mut fields: Vec<(Value, String)> = Vec::new();
    let mut pending: Option<(Value, String)> = None;
    let mut time = None;
    let mut contact: Option<ContactArgs> = None;
    loop {
        if a.keyword(&["TEMPS"]).is_some() {
            time = Some(a.req_num()?);
            continue;
        }
        if a.keyword(&["CONTACT"]).is_some() {
            // 'CONTACT' RIGIDITE SOLUTION (LIMITS): status, gap and pressure
            // of the unilateral conditions, as point fields.
            let r = a.req::<Rc<crate::value::Rigidite>>()?;
            let u = a.req::<Rc<Chpoint>>()?;
            let d = a.opt_right::<Rc<Chpoint>>();
            contact = Some((r, u, d));
            continue;
        }
        let source_name = a.next_name_span().map(|sp| it.source.slice(sp).to_uppercase());
        let Some(v) = a.right_any() else { break };
        match v {
            Value::Mesh(m) if mesh.is_none() => mesh = Some(m),
            Value::Chpo(_) | Value::Mchaml(_) => {
                fields.extend(pending.take());
                let name = source_name.unwrap_or_else(|| format!("FIELD{}", fields.len() + 1));
                pending = Some((v, name));
            }
            Value::Mot(s) => match pending.take() {
                Some((f, _)) => fields.push((f, s.trim().to_string())),
                None => return Err(a.err(format!("the name '{}' follows no CHPOINT or MCHAML", s))),
            },
            other => return Err(a.err(format!("cannot export a {} (expected CHPOINT or MCHAML)", other.type_name()))),
        }
    }
    fields.extend(pending.take());
    let mesh = mesh.ok_or_else(|| a.missing("MAILLAGE"))?;
    let mut grid = vtk::Grid::new(&mesh, &it.nodes).map_err(io_err)?;
    for (f, name) in &fields {
        match f {
            Value::Chpo(c) => {
                // Multipliers (LX, FLX) live on multiplier nodes, not on the
                // mesh: they are not point data.
                let comps: Vec<String> = c.components().into_iter().filter(|x| x != "LX" && x != "FLX").collect();
                grid.add_point_field(name, &comps, |n, comp| c.get(n, comp))
            }
            Value::Mchaml(m) => grid.add_cell_array(cell_field(&grid, m, name)).map_err(io_err)?,
            _ => {}
        }
    }
    if let Some((r, u, d)) = &contact {
        let (mut nodes, mut closed, mut gap, mut pressure) = (vec![], vec![], vec![], vec![]);
        for c in r.conds.iter().filter(|c| c.kind.is_unilateral()) {
            let Some((node, _, _)) = c.terms.first() else { continue };
            let cu: f64 = c.terms.iter().map(|(n, comp, k)| k * u.get(*n, comp).unwrap_or(0.0)).sum();
            let limit = d.as_ref().and_then(|d| d.get(c.mult_node, "FLX")).unwrap_or(0.0);
            let lx = u.get(c.mult_node, "LX");
            nodes.push(*node);
            closed.push(lx.is_some());
            // Gap measured in the allowed direction: >= 0 when feasible.
            gap.push(c.kind.sense() * (cu - limit));
            // Support pressure: the magnitude of the reaction.
            pressure.push(lx.map_or(0.0, f64::abs));
        }
        grid.add_contact(&nodes, &closed, &gap, &pressure).map_err(io_err)?;
    }
    let base = sort_base(it).unwrap_or_else(|| "gibi".into());
    match time {
        None => {
            let p = out_path(it, &format!("{}.vtu", base))?;
            grid.write(&p).map_err(write_err)?;
            wrote(it, &p);
        }
        Some(t) => {
            // Steps of the collection being written (a new base starts anew).
            let mut steps = match &it.exports.pvd {
                Some((b, steps)) if *b == base => steps.clone(),
                _ => Vec::new(),
            };
            let local = write_step(it, &grid, &format!("{}_{:04}.vtu", base, steps.len()))?;
            steps.push((t, local));
            write_collection(it, &base, &steps)?;
            it.exports.pvd = Some((base, steps));
        }
    }
    Ok(vec![])
}

/// Writes one step's `.vtu` as `file`; its name as the `.pvd` that lists
/// it names it (the same folder).
pub(super) fn write_step(it: &mut Interp, grid: &vtk::Grid, file: &str) -> Result<String> {
    let p = out_path(it, file)?;
    grid.write(&p).map_err(write_err)?;
    wrote(it, &p);
    Ok(Path::new(file).file_name().map_or(file.to_string(), |f| f.to_string_lossy().into_owned()))
}

/// Writes `base.pvd`, the collection of `steps` (time, `.vtu` file).
pub(super) fn write_collection(it: &mut Interp, base: &str, steps: &[(f64, String)]) -> Result<()> {
    let p = out_path(it, &format!("{}.pvd", base))?;
    vtk::write_pvd(&p, steps).map_err(write_err)?;
    wrote(it, &p);
    Ok(())
}

/// An element field averaged per element, on the cells of `grid`.
/// Elements of the field that the exported mesh lacks are dropped; cells
/// the field does not cover get NaN.
pub(super) fn cell_field(grid: &vtk::Grid, m: &Mchaml, name: &str) -> vtk::DataArray {
    let mut comps: Vec<String> = Vec::new();
    for z in &m.zones {
        let names = if z.values.is_empty() { z.constants.keys().cloned().collect() } else { z.comps.clone() };
        for c in names {
            if !comps.contains(&c) {
                comps.push(c);
            }
        }
    }
    let nc = comps.len().max(1);
    let mut values = vec![f64::NAN; grid.n_cells() * nc];
    let lookup = grid.cell_lookup();
    for z in &m.zones {
        let elems = z.mesh.parts.iter().flat_map(|p| p.elems().map(move |e| (p.ty, e)));
        for (e, (ty, conn)) in elems.enumerate() {
            let Some(&cell) = lookup.get(&(ty, conn)) else { continue };
            for (k, c) in comps.iter().enumerate() {
                let v = match (z.comps.iter().position(|x| x == c), z.values.get(e)) {
                    (Some(ci), Some(pts)) if !pts.is_empty() => {
                        pts.iter().map(|p| p.get(ci).copied().unwrap_or(f64::NAN)).sum::<f64>() / pts.len() as f64
                    }
                    _ => z.constants.get(c).copied().unwrap_or(f64::NAN),
                };
                values[cell * nc + k] = v;
            }
        }
    }
    let comps = if comps.len() > 1 { comps } else { vec![] };
    vtk::DataArray { name: name.to_string(), comps, values }
}
