//! BSIG of a pressure model on 3D shells (`MODE surface 'CHARGEMENT'
//! 'PRESSION' COQ3|DKT|COQ4`): each node takes p ∫N_i dA along the
//! element normal, as PRES 'COQU' (see `fem::shell::pressure_load`). The
//! pressure must be uniform over each element: the shells' load is
//! computed for a constant pressure, so a varying one is refused rather
//! than averaged.

use super::Args;
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::element::Formulation;
use crate::fem::shell;
use crate::value::model::MchamlZone;
use crate::value::Chpoint;

/// Adds to `out` the nodal forces (FX FY FZ) of component `c` of `z`.
pub(crate) fn forces(it: &Interp, a: &Args, f: Formulation, z: &MchamlZone, c: usize, out: &mut Chpoint) -> Result<()> {
    let mut e = 0;
    for part in &z.mesh.parts {
        for nodes in part.elems() {
            let v = z.values.get(e).ok_or_else(|| a.err(format!("the field has no values on element {}", e + 1)))?;
            let ps: Vec<f64> = v.iter().map(|r| r.get(c).copied().unwrap_or(0.0)).collect();
            let p = ps.first().copied().unwrap_or(0.0);
            if ps.iter().any(|q| (q - p).abs() > 1e-12 * p.abs().max(1e-300)) {
                return Err(a.err(format!(
                    "element {}: the pressure varies over a shell element; gibi loads shells with a uniform pressure only",
                    e + 1
                )));
            }
            let x: Vec<[f64; 3]> = nodes.iter().map(|n| it.nodes.get(*n)).collect();
            let fs = shell::pressure_load(f, &x, p).map_err(|err| a.err(format!("element {}: {}", e + 1, err)))?;
            for (k, n) in nodes.iter().enumerate() {
                for (d, name) in ["FX", "FY", "FZ"].iter().enumerate() {
                    out.add(*n, name, fs[k][d], true);
                }
            }
            e += 1;
        }
    }
    Ok(())
}
