//! PLUS, MOIN and TOUR of models and element fields (plus.notice,
//! tour.notice): the meshes of their zones move with the other operands
//! (each node once), and a rotation turns the stress and strain tensors
//! of a field (SMXX … SMYZ, EPXX … EPYZ); other components are kept.

use crate::fem::mesh::Mesh;
use crate::fem::meshing::motion::Motion;
use crate::value::Value;
use std::rc::Rc;

/// The meshes a model or a field moves, one per zone (None for others).
pub(crate) fn zone_meshes(o: &Value) -> Option<Vec<Mesh>> {
    match o {
        Value::Model(m) => Some(m.zones.iter().map(|z| z.mesh.clone()).collect()),
        Value::Mchaml(c) => Some(c.zones.iter().map(|z| z.mesh.clone()).collect()),
        _ => None,
    }
}

/// The model or field `o` on the moved meshes of its zones; a field's
/// tensors turned by `turn` when the motion is a rotation.
pub(crate) fn moved(o: &Value, meshes: Vec<Mesh>, turn: Option<&Motion>) -> Result<Value, String> {
    match o {
        Value::Model(m) => {
            let mut m = (**m).clone();
            for (z, mesh) in m.zones.iter_mut().zip(meshes) {
                z.mesh = mesh;
            }
            Ok(Value::Model(Rc::new(m)))
        }
        Value::Mchaml(c) => {
            let mut c = (**c).clone();
            let r = match turn {
                Some(t) => Some(linear_part(t)?),
                None => None,
            };
            for (z, mesh) in c.zones.iter_mut().zip(meshes) {
                z.mesh = mesh;
                if let Some(r) = &r {
                    for pre in ["SM", "EP"] {
                        turn_tensor(&mut z.comps, &mut z.values, pre, r);
                    }
                }
            }
            Ok(Value::Mchaml(Rc::new(c)))
        }
        other => Ok(other.clone()),
    }
}

/// The rotation's matrix: column k is the image of the k-th axis.
fn linear_part(t: &Motion) -> Result<[[f64; 3]; 3], String> {
    let o = t.image([0.0; 3]).map_err(|e| e.to_string())?;
    let mut r = [[0.0; 3]; 3];
    for k in 0..3 {
        let mut e = [0.0; 3];
        e[k] = 1.0;
        let p = t.image(e).map_err(|e| e.to_string())?;
        for (i, row) in r.iter_mut().enumerate() {
            row[k] = p[i] - o[i];
        }
    }
    Ok(r)
}

/// Symmetric tensor components, as (row, column).
const SLOTS: [(&str, usize, usize); 6] =
    [("XX", 0, 0), ("YY", 1, 1), ("ZZ", 2, 2), ("XY", 0, 1), ("XZ", 0, 2), ("YZ", 1, 2)];

/// R T Rᵀ.
fn rotated(r: &[[f64; 3]; 3], t: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
    let mut out = [[0.0; 3]; 3];
    for (i, row) in out.iter_mut().enumerate() {
        for (j, v) in row.iter_mut().enumerate() {
            *v = (0..3).map(|a| (0..3).map(|b| r[i][a] * t[a][b] * r[j][b]).sum::<f64>()).sum();
        }
    }
    out
}

/// Turn the tensor named `pre`XX … `pre`YZ at every point. A component
/// the field lacks is zero; it is added when the rotation gives it a
/// value (SMXX alone turned in the plane gives SMYY and SMXY).
fn turn_tensor(comps: &mut Vec<String>, values: &mut [Vec<Vec<f64>>], pre: &str, r: &[[f64; 3]; 3]) {
    let names: Vec<String> = SLOTS.iter().map(|(s, _, _)| format!("{pre}{s}")).collect();
    let present: Vec<Option<usize>> = names.iter().map(|n| comps.iter().position(|c| c == n)).collect();
    if present.iter().all(Option::is_none) {
        return;
    }
    // A missing component is added if some present one feeds it.
    let mut reached = [false; 6];
    for (j, &(_, a, b)) in SLOTS.iter().enumerate() {
        if present[j].is_none() {
            continue;
        }
        let mut unit = [[0.0; 3]; 3];
        unit[a][b] = 1.0;
        unit[b][a] = 1.0;
        let t = rotated(r, &unit);
        for (k, &(_, i, l)) in SLOTS.iter().enumerate() {
            reached[k] |= t[i][l].abs() > 1e-12;
        }
    }
    let mut slot: Vec<Option<usize>> = present.clone();
    for (k, name) in names.iter().enumerate() {
        if slot[k].is_none() && reached[k] {
            comps.push(name.clone());
            slot[k] = Some(comps.len() - 1);
            for elem in values.iter_mut() {
                for pt in elem.iter_mut() {
                    pt.push(0.0);
                }
            }
        }
    }
    for elem in values.iter_mut() {
        for pt in elem.iter_mut() {
            let mut t = [[0.0; 3]; 3];
            for (j, &(_, a, b)) in SLOTS.iter().enumerate() {
                if let Some(c) = present[j] {
                    t[a][b] = pt[c];
                    t[b][a] = pt[c];
                }
            }
            let t = rotated(r, &t);
            for (k, &(_, a, b)) in SLOTS.iter().enumerate() {
                if let Some(c) = slot[k] {
                    pt[c] = t[a][b];
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_uniaxial_stress_turned_a_quarter_lies_along_y() {
        let t = Motion::Rotate { angle_deg: 90.0, centre: [1.0, 2.0, 0.0], axis_end: None };
        let r = linear_part(&t).unwrap();
        let mut comps = vec!["SMXX".to_string(), "EQEQ".to_string()];
        let mut values = vec![vec![vec![3.0, 7.0]]];
        turn_tensor(&mut comps, &mut values, "SM", &r);
        // sin 90° cos 90° is rounding noise: SMXY is not added.
        assert_eq!(comps, ["SMXX", "EQEQ", "SMYY"]);
        let v = &values[0][0];
        assert!(v[0].abs() < 1e-12 && (v[1] - 7.0).abs() < 1e-12 && (v[2] - 3.0).abs() < 1e-12);
    }
}
