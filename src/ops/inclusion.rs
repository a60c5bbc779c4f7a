//! INCL (INCLUSION, incl.notice): the elements of a mesh inside a region:
//! closed lines or a surface in the plane (a plane surface in 3D), or with
//! 'VOLU' a volume of TET4. The geometry is `fem::meshing::inclusion`.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::{ElemType, Mesh, Part};
use crate::fem::meshing::inclusion::{in_lines, in_tetrahedra, in_triangles, Where};
use crate::value::Value;
use std::collections::HashMap;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "INCL",
    signature: "INCL GEO2 GEO3 ('VOLU') ('STRI'|'LARG'|'BARY') ('NOID') (FLOT1)",
    doc: "The elements of GEO2 inside GEO3: closed lines or a surface in the plane (nodes on the boundary are inside with 'LARG', the default, outside with 'STRI'; 'BARY' tests the barycentre), or with 'VOLU' a volume of TET4 (all nodes inside with 'STRI', the default, one with 'LARG'; FLOT1 > 0 also takes nodes up to FLOT1 outside, in barycentric coordinates, and the boundary; FLOT1 <= 0 leaves the boundary out). An empty result is an error unless 'NOID'.",
    example: "opti dime 2 ; m = incl (manu poi1 (0.5 0.5)) ((0. 0.) d 1 (1. 0.) d 1 (1. 1.) d 1 (0. 0.)) 'NOID' ;",
    f: incl,
}];

#[derive(PartialEq, Clone, Copy)]
enum Mode {
    Stri,
    Larg,
    Bary,
}

/// A surface element split in triangles. A quadratic element is cut
/// through its mid-side nodes: its curved sides bulge out of the chords
/// between corners, and a mid-side node shared with GEO2 must be on the
/// region's boundary, not outside it.
fn triangles(ty: ElemType, e: &[usize]) -> Vec<[usize; 3]> {
    match ty {
        ElemType::Tri3 => vec![[e[0], e[1], e[2]]],
        ElemType::Tri6 => vec![[e[0], e[1], e[5]], [e[1], e[2], e[3]], [e[3], e[4], e[5]], [e[1], e[3], e[5]]],
        ElemType::Qua4 => vec![[e[0], e[1], e[2]], [e[0], e[2], e[3]]],
        ElemType::Qua8 => vec![
            [e[7], e[0], e[1]],
            [e[1], e[2], e[3]],
            [e[3], e[4], e[5]],
            [e[5], e[6], e[7]],
            [e[1], e[3], e[5]],
            [e[1], e[5], e[7]],
        ],
        _ => vec![],
    }
}

fn incl(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let geo2 = a.req::<Rc<Mesh>>()?;
    let geo3 = a.req::<Rc<Mesh>>()?;
    let (mut volu, mut mode, mut noid, mut flot) = (false, None, false, None);
    loop {
        match a.keyword(&["VOLU", "STRI", "LARG", "BARY", "NOID"]) {
            Some("VOLU") => volu = true,
            Some("STRI") => mode = Some(Mode::Stri),
            Some("LARG") => mode = Some(Mode::Larg),
            Some("BARY") => mode = Some(Mode::Bary),
            Some(_) => noid = true,
            None => match a.opt_num() {
                Some(x) if flot.is_none() => flot = Some(x),
                Some(_) => return Err(a.err("one precision only")),
                None => break,
            },
        }
    }
    let mode = mode.unwrap_or(if volu { Mode::Stri } else { Mode::Larg });
    let flot = flot.unwrap_or(1e-2);
    if let Some(x) = Some(flot).filter(|x| !x.is_finite()) {
        return Err(a.err(format!("the precision is not a finite number ({x})")));
    }
    // Every element of GEO2 to test: its nodes, or its barycentre.
    let elems: Vec<(usize, Vec<usize>)> =
        geo2.parts.iter().enumerate().flat_map(|(k, p)| p.elems().map(move |e| (k, e.to_vec()))).collect();
    let pts: Vec<[f64; 3]> = elems
        .iter()
        .flat_map(|(_, e)| {
            let x: Vec<[f64; 3]> = e.iter().map(|&n| it.nodes.get(n)).collect();
            if mode == Mode::Bary {
                let k = x.len() as f64;
                vec![x.iter().fold([0.0; 3], |s, p| [s[0] + p[0] / k, s[1] + p[1] / k, s[2] + p[2] / k])]
            } else {
                x
            }
        })
        .collect();
    let ids = geo3.node_list();
    let local: HashMap<usize, usize> = ids.iter().enumerate().map(|(k, &n)| (n, k)).collect();
    let verts: Vec<[f64; 3]> = ids.iter().map(|&n| it.nodes.get(n)).collect();
    let places: Vec<Where> = if volu {
        let mut tets = vec![];
        for p in geo3.parts.iter().filter(|p| !p.is_empty()) {
            if p.ty != ElemType::Tet4 {
                return Err(a.err(format!("'VOLU' needs a volume of TET4, not {} (CHAN TET4 it)", p.ty.name())));
            }
            tets.extend(p.elems().map(|e| [e[0], e[1], e[2], e[3]].map(|n| local[&n])));
        }
        in_tetrahedra(&pts, &verts, &tets)
    } else {
        let dime = it.opts.dime;
        let mut tris = vec![];
        let mut segs = vec![];
        for p in &geo3.parts {
            for e in p.elems() {
                if p.ty.dim() == 1 {
                    // A SEG3 through its middle node (e[1]), as its curve.
                    let chain: Vec<usize> =
                        if e.len() == 3 { vec![e[0], e[1], e[2]] } else { vec![e[0], e[e.len() - 1]] };
                    segs.extend(chain.windows(2).map(|w| [local[&w[0]], local[&w[1]]]));
                } else {
                    tris.extend(triangles(p.ty, e).into_iter().map(|t| t.map(|n| local[&n])));
                }
            }
        }
        // In 3D, coordinates in the region's plane.
        let flat = |x: [f64; 3], u: [f64; 3], v: [f64; 3], o: [f64; 3]| {
            let d = [x[0] - o[0], x[1] - o[1], x[2] - o[2]];
            [d[0] * u[0] + d[1] * u[1] + d[2] * u[2], d[0] * v[0] + d[1] * v[1] + d[2] * v[2]]
        };
        let (u, v, o) =
            if dime == 3 { plane_axes(&verts, &tris, &segs) } else { ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0; 3]) };
        let p2: Vec<[f64; 2]> = pts.iter().map(|x| flat(*x, u, v, o)).collect();
        let v2: Vec<[f64; 2]> = verts.iter().map(|x| flat(*x, u, v, o)).collect();
        if !tris.is_empty() {
            in_triangles(&p2, &v2, &tris)
        } else if !segs.is_empty() {
            in_lines(&p2, &segs.iter().map(|s| [v2[s[0]], v2[s[1]]]).collect::<Vec<_>>())
        } else {
            return Err(a.err("the region is made of lines or surfaces (or a volume with 'VOLU')"));
        }
    };
    let inside = |w: Where| match w {
        Where::Inside => true,
        Where::Boundary => (volu && flot > 0.0) || (!volu && mode != Mode::Stri),
        Where::Outside(l) => volu && flot > 0.0 && l >= -flot,
    };
    let mut out: Vec<Part> = geo2.parts.iter().map(|p| Part { conn: vec![], ..p.clone() }).collect();
    let mut at = 0;
    for (k, e) in &elems {
        let n = if mode == Mode::Bary { 1 } else { e.len() };
        let w = &places[at..at + n];
        at += n;
        let keep = if volu && mode == Mode::Larg { w.iter().any(|&x| inside(x)) } else { w.iter().all(|&x| inside(x)) };
        if keep {
            out[*k].conn.extend_from_slice(e);
        }
    }
    out.retain(|p| !p.is_empty());
    if out.is_empty() && !noid {
        return Err(a.err("no element of the mesh is inside the region"));
    }
    let mesh = if out.is_empty() {
        Mesh::single(Part::new(geo2.parts.first().map_or(ElemType::Poi1, |p| p.ty)))
    } else {
        Mesh { parts: out }
    };
    Ok(vec![Value::Mesh(Rc::new(mesh))])
}

/// Axes of the plane of a region in space: two unit vectors in it and a
/// point of it.
fn plane_axes(x: &[[f64; 3]], tris: &[[usize; 3]], segs: &[[usize; 2]]) -> ([f64; 3], [f64; 3], [f64; 3]) {
    let sub = |a: [f64; 3], b: [f64; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    let cross =
        |a: [f64; 3], b: [f64; 3]| [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    let o = x.first().copied().unwrap_or([0.0; 3]);
    // Newell's normal of the triangles, or of the lines' polygon.
    let mut n = [0.0; 3];
    let mut acc = |a: [f64; 3], b: [f64; 3], c: [f64; 3]| {
        let m = cross(sub(b, a), sub(c, a));
        n = [n[0] + m[0], n[1] + m[1], n[2] + m[2]];
    };
    for t in tris {
        acc(x[t[0]], x[t[1]], x[t[2]]);
    }
    for s in segs {
        acc(o, x[s[0]], x[s[1]]);
    }
    let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    if len == 0.0 {
        return ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], o);
    }
    let n = n.map(|c| c / len);
    let h = if n[0].abs() < 0.9 { [1.0, 0.0, 0.0] } else { [0.0, 1.0, 0.0] };
    let u = cross(n, h);
    let lu = (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]).sqrt();
    let u = u.map(|c| c / lu);
    (u, cross(n, u), o)
}
