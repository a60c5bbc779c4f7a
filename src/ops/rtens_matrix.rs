//! RTENS's fifth form (rten.notice): a stress or strain field turned by a
//! field of rotation matrices given point by point (a GRADIENT field,
//! component `Ui,j` the entry of row i, column j): Rt A R ('RTAR', the
//! default) or R A Rt ('RART'). G_THETA brings the crack front's local
//! auxiliary stresses back to the global axes this way.

use super::rtens::{Job, Turn};
use super::Args;
use crate::error::Result;
use crate::value::model::MchamlZone;
use crate::value::{Mchaml, Value};
use std::rc::Rc;

const NAMES: [[&str; 3]; 3] = [["UX,X", "UX,Y", "UX,Z"], ["UY,X", "UY,Y", "UY,Z"], ["UZ,X", "UZ,Y", "UZ,Z"]];

/// Whether `m` holds 3 × 3 matrices (every zone has the nine entries).
pub(super) fn is_rotation(m: &Mchaml) -> bool {
    !m.zones.is_empty() && m.zones.iter().all(|z| NAMES.iter().flatten().all(|n| has(z, n)))
}

fn has(z: &MchamlZone, n: &str) -> bool {
    z.comps.iter().any(|c| c == n) || z.constants.contains_key(n)
}

/// The matrix of zone `z` at point `p` of element `e`.
fn matrix(z: &MchamlZone, e: usize, p: usize) -> Option<[[f64; 3]; 3]> {
    let mut r = [[0.0; 3]; 3];
    for (i, row) in NAMES.iter().enumerate() {
        for (j, n) in row.iter().enumerate() {
            r[i][j] = match z.comps.iter().position(|c| c == n) {
                Some(k) => {
                    let pts = z.values.get(e)?;
                    // A value per element (one point) holds for all its points.
                    let v = if pts.len() == 1 { &pts[0] } else { pts.get(p)? };
                    *v.get(k)?
                }
                None => *z.constants.get(*n)?,
            };
        }
    }
    Some(r)
}

fn transpose(r: [[f64; 3]; 3]) -> [[f64; 3]; 3] {
    let mut t = [[0.0; 3]; 3];
    for (i, row) in r.iter().enumerate() {
        for (j, x) in row.iter().enumerate() {
            t[j][i] = *x;
        }
    }
    t
}

/// `RTENS CHAM1 MODL1 GRAD1 ('RTAR'|'RART')`, the model and the matrices
/// already read.
pub(super) fn by_matrices(a: &mut Args, field: &Mchaml, rot: &Mchaml) -> Result<Vec<Value>> {
    let rart = a.keyword(&["RTAR", "RART"]) == Some("RART");
    let mut out = field.clone();
    for (iz, z) in out.zones.iter_mut().enumerate() {
        let job = Job::of(z)
            .ok_or_else(|| a.err("expected a stress or strain field of massive elements (SMXX …, EPXX …)"))?;
        if !matches!(job, Job::Massive(..)) {
            return Err(a.err("a field of rotation matrices turns the stresses or strains of massive elements only"));
        }
        // The matrices on the same elements: the zone of the same mesh, else
        // the zone of the same rank.
        let rz = rot.zones.iter().find(|r| r.mesh == z.mesh).or_else(|| rot.zones.get(iz));
        let rz = rz.ok_or_else(|| a.err("the field of rotation matrices has no zone on the elements of the field"))?;
        // s'_ij = e_i . s . e_j: R A Rt takes the rows of R as e, Rt A R
        // its columns.
        let frame = |e: usize, p: usize| -> Option<[[f64; 3]; 3]> {
            let r = matrix(rz, e, p)?;
            Some(if rart { r } else { transpose(r) })
        };
        if z.values.is_empty() {
            let e = frame(0, 0).ok_or_else(|| a.err("the rotation matrices do not cover the field"))?;
            if rz.values.len() > 1 {
                return Err(a.err("a constant field cannot be turned by matrices that vary from element to element"));
            }
            let keys: Vec<String> = z.constants.keys().cloned().collect();
            let mut v: Vec<f64> = keys.iter().map(|k| z.constants[k]).collect();
            job.turn(&mut v, Turn::Frame(&e));
            for (k, x) in keys.iter().zip(v) {
                z.constants.insert(k.clone(), x);
            }
            continue;
        }
        for (e, el) in z.values.iter_mut().enumerate() {
            for (p, v) in el.iter_mut().enumerate() {
                let f = frame(e, p).ok_or_else(|| {
                    a.err(format!("no rotation matrix at point {} of element {} of the field", p + 1, e + 1))
                })?;
                job.turn(v, Turn::Frame(&f));
            }
        }
    }
    Ok(vec![Value::Mchaml(Rc::new(out))])
}
