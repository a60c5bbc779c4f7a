//! `CHE1 ELEM test ('ABS') ('LARG'|'STRI') ('AVEC'|'SANS' LMOTS)`: the
//! elements of an MCHAML whose values meet a comparison test, as a mesh.

use super::mesh::mesh_val;
use super::poin_field::{predicate, read_test};
use super::Args;
use crate::error::Result;
use crate::fem::mesh::{Mesh, Part};
use crate::value::{Mchaml, Value};

/// An element is kept when one of its points meets the test ('LARG', the
/// default) or when all of them do ('STRI'); a point meets it when one of
/// its considered components does. The test sees every considered value
/// at once (MAXI/MINI look for the extreme over the whole field).
pub(crate) fn elem_of_mchaml(a: &mut Args, m: &Mchaml) -> Result<Vec<Value>> {
    let mut strict = a.keyword_next(&["STRI", "LARG"]).map(|k| k == "STRI");
    let (test, abs, filter) = read_test(a)?;
    if let Some(k) = a.keyword_next(&["STRI", "LARG"]) {
        strict = Some(k == "STRI");
    }
    let strict = strict.unwrap_or(false);
    let value = |v: f64| if abs { v.abs() } else { v };
    let mut all = vec![];
    for z in &m.zones {
        let cols: Vec<usize> = (0..z.comps.len()).filter(|&c| filter.takes(&z.comps[c])).collect();
        for pts in &z.values {
            for row in pts {
                all.extend(cols.iter().filter_map(|&c| row.get(c)).map(|&v| value(v)));
            }
        }
    }
    if all.is_empty() {
        return Err(a.err("the field has no point value to test"));
    }
    let test = predicate(test, &all);
    let mut out = Mesh::default();
    for z in &m.zones {
        let cols: Vec<usize> = (0..z.comps.len()).filter(|&c| filter.takes(&z.comps[c])).collect();
        let point_ok = |row: &Vec<f64>| cols.iter().filter_map(|&c| row.get(c)).any(|&v| test(value(v)));
        let mut e = 0;
        let mut kept = Mesh::default();
        for part in &z.mesh.parts {
            let mut p = Part { ty: part.ty, conn: vec![], colour: part.colour };
            for nodes in part.elems() {
                let Some(pts) = z.values.get(e) else { break };
                e += 1;
                let ok = if strict { !pts.is_empty() && pts.iter().all(point_ok) } else { pts.iter().any(point_ok) };
                if ok {
                    p.conn.extend_from_slice(nodes);
                }
            }
            if !p.conn.is_empty() {
                kept.parts.push(p);
            }
        }
        out = out.union(&kept);
    }
    Ok(mesh_val(out))
}
