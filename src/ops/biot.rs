//! BIOT: Biot–Savart fields of inductors (biot.notice). The numerics are
//! in `fem::biot_savart`; this file reads the inductor and makes fields.

use super::{Args, OpDef, PointId};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::biot_savart::{axial_loops, field, Conductor, Quantity, Section};
use crate::fem::mesh::Mesh;
use crate::value::field::{Chpoint, Nature};
use crate::value::Value;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "BIOT",
    signature: "BIOT ('POTE'|'INDU') MAILLAGE ('CERC' C P1 P2 RI RE H | 'ARC' C P1 P2 RI RE H | 'BARR' P1 P2 P3 DY DZ \
                | 'FIL' P1 P2) ('TRAP' PENTE1 PENTE2) DENS MU0 | BIOT CHPOINT MAILLAGE",
    doc: "The vector potential (AX AY AZ, 'POTE') or the induction (BX BY BZ, 'INDU', the default) on the nodes of \
          the mesh, of a current density DENS in a circular coil, an arc of coil, a straight bar or a wire, of \
          rectangular or trapezoidal ('TRAP') section, MU0 the permeability of vacuum (3D). With a CHPOINT of \
          loops about the z axis (components I, current, default 1, and E, wire section, default 1e-5): the \
          induction and FLUX, the flux through the circle about z of each node.",
    example: "opti dime 3 ; p = 0. 0. 0.5 ; b = biot 'INDU' (manu 'POI1' p) 'CERC' (0. 0. 0.) (1. 0. 0.) (0. 1. 0.) \
              1. 1. 0. 1. (4. * pi * 1.e-7) ;",
    f: biot,
}];

fn biot(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if it.opts.dime != 3 {
        return Err(a.err(format!("works in dimension 3 only (OPTI DIME is {})", it.opts.dime)));
    }
    if let Some(loops) = a.opt::<Rc<Chpoint>>() {
        let mesh = a.req::<Rc<Mesh>>()?;
        return Ok(vec![axial(it, &loops, &mesh)]);
    }
    let q = match a.keyword(&["POTE", "INDU"]) {
        Some("POTE") => Quantity::Potential,
        _ => Quantity::Induction,
    };
    let mesh = a.req::<Rc<Mesh>>()?;
    let kind = a.req_keyword(&["CERC", "ARC", "BARR", "FIL"])?;
    let pt = |a: &mut Args| -> Result<[f64; 3]> { Ok(it.nodes.get(a.req::<PointId>()?.0)) };
    let conductor = match kind {
        "CERC" | "ARC" => {
            let (c, p1, p2) = (pt(a)?, pt(a)?, pt(a)?);
            let (ri, re, h) = (a.req_num()?, a.req_num()?, a.req_num()?);
            let slopes = trap(a)?;
            let (u, v) = (sub(p1, c), sub(p2, c));
            let n = cross(u, v);
            let nn = norm(n);
            if nn <= 1e-12 * norm(u) * norm(v) || nn == 0.0 {
                return Err(a.err("the centre and the two points must define a plane (they are aligned)"));
            }
            if ri < 0.0 || re < ri {
                return Err(a.err(format!("the radii must satisfy 0 <= RI <= RE, found RI = {} and RE = {}", ri, re)));
            }
            let axis = scale(n, 1.0 / nn);
            let start = scale(u, 1.0 / norm(u));
            let angle =
                if kind == "CERC" { 2.0 * std::f64::consts::PI } else { dot(cross(u, v), axis).atan2(dot(u, v)) };
            Conductor::Coil {
                centre: c,
                axis,
                start,
                r_in: ri,
                angle,
                section: Section { width: re - ri, height: h, slopes },
            }
        }
        "BARR" => {
            let (p1, p2, p3) = (pt(a)?, pt(a)?, pt(a)?);
            let (dy, dz) = (a.req_num()?, a.req_num()?);
            let slopes = trap(a)?;
            let u = sub(p2, p1);
            if norm(u) == 0.0 {
                return Err(a.err("the two ends of the bar are the same point"));
            }
            let u = scale(u, 1.0 / norm(u));
            let w = sub(p3, p1);
            let y = sub(w, scale(u, dot(w, u)));
            if norm(y) <= 1e-12 * norm(w) || norm(y) == 0.0 {
                return Err(a.err("the third point must not lie on the axis of the bar"));
            }
            if dy < 0.0 || dz < 0.0 {
                return Err(a.err(format!("the section's sides must be 0 or more, found {} and {}", dy, dz)));
            }
            Conductor::Bar {
                from: p1,
                to: p2,
                y: scale(y, 1.0 / norm(y)),
                section: Section { width: dy, height: dz, slopes },
            }
        }
        _ => {
            let (p1, p2) = (pt(a)?, pt(a)?);
            let u = sub(p2, p1);
            if norm(u) == 0.0 {
                return Err(a.err("the two ends of the wire are the same point"));
            }
            // Any direction across the wire: its section is a point.
            let t =
                if u[0].abs() <= u[1].abs() && u[0].abs() <= u[2].abs() { [1.0, 0.0, 0.0] } else { [0.0, 0.0, 1.0] };
            let y = cross(u, t);
            let section = Section { width: 0.0, height: 0.0, slopes: (0.0, 0.0) };
            Conductor::Bar { from: p1, to: p2, y: scale(y, 1.0 / norm(y)), section }
        }
    };
    let dens = a.req_num()?;
    let mu0 = a.req_num()?;
    let names: [&str; 3] = match q {
        Quantity::Potential => ["AX", "AY", "AZ"],
        Quantity::Induction => ["BX", "BY", "BZ"],
    };
    let mut out = Chpoint::new(Nature::Diffus);
    for n in mesh.node_list() {
        let f = field(&conductor, q, dens, mu0, it.nodes.get(n));
        for (c, v) in names.iter().zip(f) {
            out.add(n, c, v, false);
        }
    }
    Ok(vec![Value::Chpo(Rc::new(out))])
}

/// `'TRAP' P1 P2`: the slopes of a trapezoidal section (0 and 0 else).
fn trap(a: &mut Args) -> Result<(f64, f64)> {
    if a.keyword(&["TRAP"]).is_some() {
        return Ok((a.req_num()?, a.req_num()?));
    }
    Ok((0.0, 0.0))
}

/// Case 2: loops about the z axis, one per node of `loops`.
fn axial(it: &Interp, loops: &Chpoint, mesh: &Mesh) -> Value {
    const MU0: f64 = 4.0e-7 * std::f64::consts::PI;
    let list: Vec<(f64, f64, f64, f64)> = loops
        .nodes
        .iter()
        .map(|&n| {
            let x = it.nodes.get(n);
            let i = loops.get(n, "I").unwrap_or(1.0);
            let e = loops.get(n, "E").unwrap_or(1.0e-5);
            ((x[0] * x[0] + x[1] * x[1]).sqrt(), x[2], i, e)
        })
        .collect();
    let mut out = Chpoint::new(Nature::Diffus);
    for n in mesh.node_list() {
        let (b, flux) = axial_loops(&list, MU0, it.nodes.get(n));
        for (c, v) in ["BX", "BY", "BZ"].iter().zip(b) {
            out.add(n, c, v, false);
        }
        out.add(n, "FLUX", flux, false);
    }
    Value::Chpo(Rc::new(out))
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn scale(a: [f64; 3], s: f64) -> [f64; 3] {
    [a[0] * s, a[1] * s, a[2] * s]
}
fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}
fn norm(a: [f64; 3]) -> f64 {
    dot(a, a).sqrt()
}
