//! MANU 'CHML' with a field as a component's value (manu.notice, OBJi):
//! a one-component MCHAML on the same elements gives its values, element
//! by element and point by point (a strain field assembled from scalar
//! fields of its terms).

use crate::value::model::Mchaml;

/// Writes the values of `field` (one component, any name) into component
/// `comp` of `out`, whose zones are already made with the right points.
pub(crate) fn fill(out: &mut Mchaml, comp: &str, field: &Mchaml) -> Result<(), String> {
    let names: Vec<&String> = field.zones.iter().flat_map(|z| z.comps.iter().chain(z.constants.keys())).collect();
    if names.iter().any(|n| *n != names[0]) || names.is_empty() {
        return Err("a field given as a value must have one component".into());
    }
    // A field constant over its zones gives that constant.
    if field.zones.iter().all(|z| z.values.is_empty()) {
        let v = field.zones.iter().find_map(|z| z.constants.values().next().copied()).unwrap_or(0.0);
        return each_value(out, comp, |_, _, _, _| Ok(v));
    }
    let laid = field
        .realign(out)
        .ok_or_else(|| "the field given as a value is not defined on every element of the result".to_string())?;
    each_value(out, comp, |zi, e, k, m| {
        let pts = &laid.zones[zi].values[e];
        match pts.len() {
            1 => Ok(pts[0][0]),
            n if n == m => Ok(pts[k][0]),
            n => Err(format!("the field given as a value has {} points in an element where the result has {}", n, m)),
        }
    })
}

fn each_value(
    out: &mut Mchaml,
    comp: &str,
    mut v: impl FnMut(usize, usize, usize, usize) -> Result<f64, String>,
) -> Result<(), String> {
    for (zi, z) in out.zones.iter_mut().enumerate() {
        let Some(c) = z.comps.iter().position(|x| x == comp) else { continue };
        for (e, pts) in z.values.iter_mut().enumerate() {
            let m = pts.len();
            for (k, p) in pts.iter_mut().enumerate() {
                p[c] = v(zi, e, k, m)?;
            }
        }
    }
    Ok(())
}
