//! VORO (VORONOI, voro.notice): the Voronoi partition of seed points
//! limited by a closed boundary, as a TABLE of cells, faces and edges.
//! The geometry is `fem::meshing::{voronoi, voronoi_3d}`; this file reads
//! the Gibiane arguments and builds the table.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::{ElemType, Mesh, Part};
use crate::fem::meshing::voronoi::{partition_2d, Lines, Partition};
use crate::fem::meshing::voronoi_3d::{partition_3d, Surface};
use crate::value::{Chpoint, Key, Nature, Table, Value};
use std::cell::RefCell;
use std::collections::HashMap;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "VORO",
    signature: "VORO POINTS BOUNDARY (CHPOINT)",
    doc: "Voronoi partition of a POI1 point set inside a closed boundary (SEG2 lines in 2D, a convex closed TRI3 surface in 3D); with a CHPOINT of weights r, the power diagram (|x-p|²-r² least). A TABLE: 'VISU' every edge (SEG2), 'POND' the weights, 'ARTS' . m the edge m, 'FACS' . n (3D) the face n ('VISU', 'ARTS' its edge numbers), 'CELL' . P the cell of seed P ('VISU' its edges, 'ARTS' (2D) or 'FACS' (3D) their numbers, 'VOIS' the seeds of the neighbouring cells).",
    example: "opti dime 2 ; t = voro ((0.25 0.5) et (0.75 0.5)) (cont ((d 1 (0. 0.) (1. 0.)) tran 1 (0. 1.))) ;",
    f: voro,
}];

fn table(t: Table) -> Value {
    Value::Table(Rc::new(RefCell::new(t)))
}

fn mot(s: &str) -> Key {
    Key::Mot(s.into())
}

fn seg2(conn: Vec<usize>) -> Value {
    Value::Mesh(Rc::new(Mesh::single(Part::with(ElemType::Seg2, conn))))
}

fn numbers(ids: &[usize]) -> Value {
    Value::ListEnti(Rc::new(ids.iter().map(|&i| i as i64 + 1).collect()))
}

fn voro(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let seeds = a.req::<Rc<Mesh>>()?;
    let bound = a.req::<Rc<Mesh>>()?;
    let weights = a.opt::<Rc<Chpoint>>();
    let dim = it.opts.dime;
    if let Some(p) = seeds.parts.iter().find(|p| !p.is_empty() && p.ty != ElemType::Poi1) {
        return Err(a.err(format!("the seeds are a mesh of POI1, not {}", p.ty.name())));
    }
    let seed_nodes = seeds.node_list();
    let w: Option<Vec<f64>> = match &weights {
        None => None,
        Some(c) => {
            let comps = c.components();
            if comps.len() != 1 {
                return Err(a.err(format!("the weights are a field of one component (it has {})", comps.len())));
            }
            let mut w = Vec::with_capacity(seed_nodes.len());
            for &n in &seed_nodes {
                match c.get(n, &comps[0]) {
                    Some(x) => w.push(x),
                    None => return Err(a.err(format!("the weights have no value at seed node {n}"))),
                }
            }
            Some(w)
        }
    };
    let want = if dim == 3 { ElemType::Tri3 } else { ElemType::Seg2 };
    if dim != 2 && dim != 3 {
        return Err(a.err("VORO works in 2D or 3D (OPTI DIME 2 or 3)"));
    }
    if let Some(p) = bound.parts.iter().find(|p| !p.is_empty() && p.ty != want) {
        return Err(a.err(format!("the boundary is made of {} in {dim}D, not {}", want.name(), p.ty.name())));
    }
    let bnodes = bound.node_list();
    let local: HashMap<usize, usize> = bnodes.iter().enumerate().map(|(k, &n)| (n, k)).collect();
    let coords: Vec<[f64; 3]> = bnodes.iter().map(|&n| it.nodes.get(n)).collect();
    let elems: Vec<Vec<usize>> = bound
        .parts
        .iter()
        .flat_map(|p| p.elems().map(|e| e.iter().map(|n| local[n]).collect::<Vec<_>>()).collect::<Vec<_>>())
        .collect();
    let part = if dim == 2 {
        let pts: Vec<[f64; 2]> = coords.iter().map(|c| [c[0], c[1]]).collect();
        let segs: Vec<[usize; 2]> = elems.iter().map(|e| [e[0], e[1]]).collect();
        let s: Vec<[f64; 2]> = seed_nodes.iter().map(|&n| it.nodes.get(n)).map(|c| [c[0], c[1]]).collect();
        partition_2d("VORO", &s, w.as_deref(), &Lines { pts: &pts, nodes: &bnodes, segs: &segs })
    } else {
        let tris: Vec<[usize; 3]> = elems.iter().map(|e| [e[0], e[1], e[2]]).collect();
        let s: Vec<[f64; 3]> = seed_nodes.iter().map(|&n| it.nodes.get(n)).collect();
        partition_3d("VORO", &s, w.as_deref(), &Surface { pts: &coords, nodes: &bnodes, tris: &tris })
    }
    .map_err(|e| a.err(e.message))?;
    let comp = weights.as_ref().map_or("SCAL".to_string(), |c| c.components()[0].clone());
    Ok(vec![build(it, &part, &seed_nodes, w.as_deref(), &comp, dim)])
}

/// The table of the partition, its vertices made nodes.
fn build(it: &mut Interp, p: &Partition, seeds: &[usize], w: Option<&[f64]>, comp: &str, dim: usize) -> Value {
    let dens = it.opts.dens;
    let node: Vec<usize> =
        p.verts.iter().zip(&p.vert_node).map(|(x, n)| n.unwrap_or_else(|| it.nodes.push(*x, dens))).collect();
    let edge_conn = |e: usize| vec![node[p.edges[e][0]], node[p.edges[e][1]]];
    let edges_mesh = |ids: &[usize]| seg2(ids.iter().flat_map(|&e| edge_conn(e)).collect());
    let mut arts = Table::new();
    for e in 0..p.edges.len() {
        arts.set(Key::Int(e as i64 + 1), seg2(edge_conn(e)));
    }
    let mut out = Table::new();
    let all: Vec<usize> = (0..p.edges.len()).collect();
    out.set(mot("VISU"), edges_mesh(&all));
    let pond = Chpoint::from_entries(
        Nature::Discret,
        seeds.iter().enumerate().map(|(k, &n)| (n, comp, w.map_or(0.0, |w| w[k]))),
    );
    out.set(mot("POND"), Value::Chpo(Rc::new(pond)));
    let mut cells = Table::new();
    for c in &p.cells {
        let mut t = Table::new();
        t.set(mot("VISU"), edges_mesh(&c.edges));
        if dim == 3 {
            t.set(mot("FACS"), numbers(&c.faces));
        } else {
            t.set(mot("ARTS"), numbers(&c.edges));
        }
        let vois: Vec<usize> = c.neighbours.iter().map(|&j| seeds[j]).collect();
        t.set(mot("VOIS"), Value::Mesh(Rc::new(Mesh::single(Part::with(ElemType::Poi1, vois)))));
        cells.set(Key::Point(seeds[c.seed]), table(t));
    }
    out.set(mot("CELL"), table(cells));
    if dim == 3 {
        let mut facs = Table::new();
        for (f, edges) in p.faces.iter().enumerate() {
            let mut t = Table::new();
            t.set(mot("VISU"), edges_mesh(edges));
            t.set(mot("ARTS"), numbers(edges));
            facs.set(Key::Int(f as i64 + 1), table(t));
        }
        out.set(mot("FACS"), table(facs));
    }
    out.set(mot("ARTS"), table(arts));
    Value::Table(Rc::new(RefCell::new(out)))
}
