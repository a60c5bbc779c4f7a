//! RTENS: stresses or strains of an element field in a new orthonormal
//! frame (massive elements: from the global axes; thin shells: from each
//! element's local frame, whose first axis is along its first side).
//! Component names are kept; their values are those in the new axes.
//! The algebra is in `fem::tensor_frame`.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::args::PointId;
use crate::eval::Interp;
use crate::fem::tensor_frame as tf;
use crate::value::model::MchamlZone;
use crate::value::{Mchaml, Model, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "RTENS",
    signature: "RTENS MCHAML MMODEL (MCHAML_CARA) POINT1 (POINT2) | RTENS MCHAML MMODEL GRADIENT ('RTAR'|'RART')",
    doc: "The stress or strain field in the direct orthonormal frame of POINT1 (2D: and POINT1 turned by +90°; 3D: the direction of POINT2 made normal to POINT1, and their vector product). Massive elements: SMXX SMYY SMZZ SMXY SMXZ SMYZ (EPXX … GAXY …, shear strains counted as engineering ones; SMRR SMZZ SMRZ in axisymmetry) from the global axes. Thin shells: N11 N22 N12, M11 M22 M12, V1 V2 (EP.., GA.., RT..) from each element's frame, the first axis along the projection of POINT1 on the element. The names are kept. With a field of rotation matrices R (UX,X … UZ,Z, row then column), each point's tensor A becomes Rt A R ('RTAR', the default) or R A Rt ('RART').",
    example: "s2 = rtens s mo (1. 1.) ;",
    f: rtens,
}];

fn rtens(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let field = a.req::<Rc<Mchaml>>()?;
    let _model = a.req::<Rc<Model>>()?;
    // Thick shells' thicknesses: the frame of thin ones does not need them.
    // A field of rotation matrices instead: the fifth form.
    if let Some(m) = a.opt::<Rc<Mchaml>>() {
        if super::rtens_matrix::is_rotation(&m) {
            return super::rtens_matrix::by_matrices(a, &field, &m);
        }
    }
    let p1 = a.req::<PointId>()?;
    let p2 = a.opt::<PointId>();
    let xyz = |p: PointId| it.nodes.coords.get(p.0).copied();
    let v1 = xyz(p1).ok_or_else(|| a.err("unknown point"))?;
    let v2 = match p2 {
        Some(p) => Some(xyz(p).ok_or_else(|| a.err("unknown point"))?),
        None => None,
    };
    let mut out = (*field).clone();
    for z in out.zones.iter_mut() {
        let job = Job::of(z)
            .ok_or_else(|| a.err(format!("expected stresses or strains (SMXX …, N11 …), found {}", names(z))))?;
        match job {
            Job::Massive(..) => {
                // Without a second direction: a turn about z.
                let e = tf::frame(v1, v2).map_err(|m| a.err(m))?;
                apply_all(z, |vals, _| job.turn(vals, Turn::Frame(&e)));
            }
            Job::Shell { .. } => {
                let elems: Vec<Vec<[f64; 3]>> = z
                    .mesh
                    .parts
                    .iter()
                    .flat_map(|p| p.elems())
                    .map(|el| el.iter().map(|&n| it.nodes.coords[n]).collect())
                    .collect();
                let mut angles = Vec::with_capacity(elems.len());
                for el in &elems {
                    angles.push(tf::shell_angle(el, v1).map_err(|m| a.err(m))?);
                }
                if z.values.is_empty() && !angles.is_empty() {
                    // Constants hold on every element: only a common frame keeps them constant.
                    let (c, s) = angles[0];
                    if angles.iter().any(|&(c2, s2)| (c2 - c).abs() > 1e-12 || (s2 - s).abs() > 1e-12) {
                        return Err(a.err(
                            "a constant shell field cannot be turned into frames that differ from element to element",
                        ));
                    }
                }
                apply_all(z, |vals, e| {
                    let (c, s) = angles.get(e).copied().unwrap_or((1.0, 0.0));
                    job.turn(vals, Turn::Angle(c, s))
                });
            }
        }
    }
    Ok(vec![Value::Mchaml(Rc::new(out))])
}

fn names(z: &MchamlZone) -> String {
    let mut n: Vec<String> = z.comps.clone();
    n.extend(z.constants.keys().cloned());
    if n.is_empty() {
        "no component".into()
    } else {
        n.join(" ")
    }
}

pub(super) enum Turn<'a> {
    Frame(&'a [[f64; 3]; 3]),
    Angle(f64, f64),
}

/// Where the components sit in a vector of named values.
#[derive(Clone)]
pub(super) enum Job {
    /// Indices of xx yy zz xy xz yz (zz and the out-of-plane ones may be
    /// absent in 2D), and the factor of the shear ones (1/2 for
    /// engineering shear strains).
    Massive([Option<usize>; 6], f64),
    /// Plane tensors (11 22 12) with their shear factors, and vectors (1 2).
    Shell { tensors: Vec<([usize; 3], f64)>, vectors: Vec<[usize; 2]> },
}

impl Job {
    pub(super) fn of(z: &MchamlZone) -> Option<Job> {
        let list: Vec<String> =
            if z.comps.is_empty() { z.constants.keys().cloned().collect() } else { z.comps.clone() };
        let at = |n: &str| list.iter().position(|c| c == n);
        for (pre, sh, f) in [("SM", "SM", 1.0), ("EP", "GA", 0.5)] {
            let n = |s: &str| at(&format!("{}{}", pre, s));
            let m = |s: &str| at(&format!("{}{}", sh, s));
            if let (Some(xx), Some(yy), Some(xy)) = (n("XX"), n("YY"), m("XY")) {
                return Some(Job::Massive([Some(xx), Some(yy), n("ZZ"), Some(xy), m("XZ"), m("YZ")], f));
            }
            if let (Some(rr), Some(zz), Some(rz)) = (n("RR"), n("ZZ"), m("RZ")) {
                return Some(Job::Massive([Some(rr), Some(zz), None, Some(rz), None, None], f));
            }
        }
        let mut tensors = Vec::new();
        for (a, b, c, f) in [
            ("N11", "N22", "N12", 1.0),
            ("M11", "M22", "M12", 1.0),
            ("EP11", "EP22", "GA12", 0.5),
            ("RT11", "RT22", "RT12", 0.5),
        ] {
            if let (Some(i), Some(j), Some(k)) = (at(a), at(b), at(c)) {
                tensors.push(([i, j, k], f));
            }
        }
        let mut vectors = Vec::new();
        for (a, b) in [("V1", "V2"), ("GA13", "GA23")] {
            if let (Some(i), Some(j)) = (at(a), at(b)) {
                vectors.push([i, j]);
            }
        }
        (!tensors.is_empty() || !vectors.is_empty()).then_some(Job::Shell { tensors, vectors })
    }

    pub(super) fn turn(&self, v: &mut [f64], how: Turn) {
        match (self, how) {
            (Job::Massive(ix, f), Turn::Frame(e)) => {
                let get = |k: usize| ix[k].map_or(0.0, |i| v[i]) * if k >= 3 { *f } else { 1.0 };
                let s = [get(0), get(1), get(2), get(3), get(4), get(5)];
                let r = tf::rotate_sym(s, e);
                for k in 0..6 {
                    if let Some(i) = ix[k] {
                        v[i] = r[k] / if k >= 3 { *f } else { 1.0 };
                    }
                }
            }
            (Job::Shell { tensors, vectors }, Turn::Angle(c, s)) => {
                for (ix, f) in tensors {
                    let r = tf::rotate_plane([v[ix[0]], v[ix[1]], v[ix[2]] * f], c, s);
                    v[ix[0]] = r[0];
                    v[ix[1]] = r[1];
                    v[ix[2]] = r[2] / f;
                }
                for ix in vectors {
                    let (p, q) = (v[ix[0]], v[ix[1]]);
                    v[ix[0]] = c * p + s * q;
                    v[ix[1]] = -s * p + c * q;
                }
            }
            _ => {}
        }
    }
}

/// `g` applied to every point's vector of values (element index given),
/// or to the constants taken as one vector.
fn apply_all(z: &mut MchamlZone, g: impl Fn(&mut [f64], usize)) {
    if z.values.is_empty() {
        let keys: Vec<String> = z.constants.keys().cloned().collect();
        let mut v: Vec<f64> = keys.iter().map(|k| z.constants[k]).collect();
        g(&mut v, 0);
        for (k, x) in keys.iter().zip(v) {
            z.constants.insert(k.clone(), x);
        }
        return;
    }
    for (e, el) in z.values.iter_mut().enumerate() {
        for p in el.iter_mut() {
            g(p, e);
        }
    }
}
