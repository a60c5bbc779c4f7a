//! VERM: checks of a mesh of massive elements, reported as warnings
//! (the numerics are `fem::meshing::verify`).

use super::mesh::req_geo;
use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::meshing::verify::verify;
use crate::value::Value;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "VERM",
    signature: "VERM GEO",
    doc: "Check a mesh of massive elements and print a warning for each element repeated in its part, each linear element joined along an edge to a quadratic one, and each volume whose triangular face lies on a quadrangular face of another. Elements are numbered as ELEM numbers them (parts in order).",
    example: "verm (surf ((0. 0.) (1. 0.) (1. 1.) (0. 1.))) ;",
    f: verm,
}];

fn verm(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let geo = req_geo(a)?;
    let found = verify(&geo);
    // Element numbers of the whole mesh, as ELEM n counts them.
    let start: Vec<usize> = geo.parts.iter().scan(0, |s, p| Some(std::mem::replace(s, *s + p.len()))).collect();
    let num = |p: usize, e: usize| start[p] + e + 1;
    for &(p, e, first) in &found.repeated {
        let ty = geo.parts[p].ty.name();
        it.println(&format!("VERM: {} element {} repeats element {} of its part", ty, num(p, e), num(p, first)));
    }
    for &(p, e) in &found.mixed_degree {
        let ty = geo.parts[p].ty.name();
        it.println(&format!("VERM: linear {} element {} is joined to a quadratic element", ty, num(p, e)));
    }
    for &(p, e) in &found.face_mismatch {
        let ty = geo.parts[p].ty.name();
        it.println(&format!(
            "VERM: {} element {} has a triangular face on a quadrangular face of another element",
            ty,
            num(p, e)
        ));
    }
    Ok(vec![])
}
