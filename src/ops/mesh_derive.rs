//! Meshes derived from others: GENERATRICE (a line moved along a second
//! line) and DEDU 'TRAN' (objects carried from one mesh onto another of
//! the same topology). The geometry is `fem::meshing::{generatrix, deduce}`.

use super::mesh::mesh_val;
use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::args::keyword_matches;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::fem::meshing::deduce::{moved_masters, node_map};
use crate::fem::meshing::generatrix::generatrix;
use crate::fem::meshing::motion::Motion;
use crate::value::{Chpoint, Key, Table, Value};
use std::cell::RefCell;
use std::collections::HashMap;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "GENE",
        signature: "LINE1 GENE LINE2",
        doc: "The surface of QUA4 swept by LINE1 (SEG2) moved parallel to itself along LINE2 (SEG2): one strip of elements per element of LINE2, row j being LINE1 shifted by the vector from the first node of LINE2 to its node j.",
        example: "s = ((0. 0.) droi 3 (3. 0.)) gene ((0. 0.) droi 2 (0. 1.)) ;",
        f: gene,
    },
    OpDef {
        name: "DEDU",
        signature: "DEDU MAI2 MAI_ANC MAI_NOU | OBJ1 .. OBJN DEDU 'TRAN' GEO1 GEO2 | DEDU 'TRAN' OBJ1 .. OBJN GEO1 GEO2 | OBJ1 .. OBJN DEDU angle P1 (P2) 'ROTA' GEO1 GEO2",
        doc: "DEDU MAI2 MAI_ANC MAI_NOU: MAI2 moved by the affine map that sends the master points MAI_ANC (3 in 2D, 4 in 3D) to MAI_NOU, on new nodes. Otherwise each object (POINT, MAILLAGE, CHPOINT, MCHAML, MMODEL, or a TABLE of them) carried from GEO1 onto GEO2, a mesh of the same topology: node k of element e of GEO1 becomes node k of element e of GEO2. Every node of the objects must be a node of GEO1. With 'ROTA' (GEO2 being GEO1 turned by angle degrees about P1, about the axis P1 P2 in 3D; 'ROTA' may also come first) the vector components of nodal fields (UX UY UZ, FX…, RX…, MX…) and the stress and strain tensors of element fields are turned too.",
        example: "u2 = dedu 'TRAN' (coor 1 bas) bas (bas plus (0. 1.)) ;",
        f: dedu,
    },
];

fn gene(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let l1 = a.req::<Rc<Mesh>>()?;
    let l2 = a.req::<Rc<Mesh>>()?;
    Ok(mesh_val(generatrix(&mut it.nodes, &l1, &l2)?))
}

fn dedu(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mut objects = Vec::new();
    while let Some(v) = a.left_value() {
        objects.push(v);
    }
    objects.reverse();
    // Objects may also follow DEDU, before the word or the angle that
    // says how they move (`DEDU OBJ1 'TRAN' GEO1 GEO2`).
    let mut after = Vec::new();
    while a.peek_right().is_some_and(|v| !matches!(v, Value::Mot(_) | Value::Int(_) | Value::Float(_))) {
        after.extend(a.right_any());
    }
    // `DEDU MAI2 MAI_ANC MAI_NOU`: a mesh moved by master nodes.
    let moves = a.peek_word().is_some_and(|w| ["TRAN", "ROTA"].iter().any(|k| keyword_matches(&w, k)))
        || a.peek_right().is_some_and(|v| matches!(v, Value::Int(_) | Value::Float(_)));
    if let (true, [Value::Mesh(mesh), Value::Mesh(old), Value::Mesh(new)]) =
        (objects.is_empty() && !moves, after.as_slice())
    {
        if a.keyword(&["REGU"]).is_some() {
            return Err(a.err("DEDU … 'REGU' (smoothing the moved mesh) is not implemented"));
        }
        let dim = it.opts.dime;
        return Ok(mesh_val(moved_masters(&mut it.nodes, mesh, old, new, dim)?));
    }
    // 'TRAN', or a rotation: `angle P1 (P2) 'ROTA'` or `'ROTA' angle P1 (P2)`
    // (P2, the axis, in 3D).
    let turn = if a.keyword(&["TRAN"]).is_some() {
        None
    } else {
        let rota_first = a.keyword(&["ROTA"]).is_some();
        let angle_deg = a.opt_num().ok_or_else(|| {
            a.err("gibi implements DEDU 'TRAN', 'ROTA' and a mesh moved by master nodes fixing an affine map ('ADAP' is not implemented)")
        })?;
        let centre = super::mesh::vector(it, a).ok_or_else(|| a.missing("POINT (the centre)"))?;
        let axis_end = match it.opts.dime >= 3 {
            true => Some(super::mesh::vector(it, a).ok_or_else(|| a.missing("POINT (the axis)"))?),
            false => None,
        };
        if !rota_first {
            a.req_keyword(&["ROTA"])?;
        }
        Some(Motion::Rotate { angle_deg, centre, axis_end })
    };
    objects.extend(after);
    objects.extend(a.rest());
    if objects.len() < 3 {
        return Err(a.missing("the objects to carry, then the meshes GEO1 and GEO2"));
    }
    let geo2 = objects.pop();
    let geo1 = objects.pop();
    let (Some(Value::Mesh(geo1)), Some(Value::Mesh(geo2))) = (geo1, geo2) else {
        return Err(a.err("the last two operands of DEDU 'TRAN' must be the meshes GEO1 and GEO2"));
    };
    let map = node_map(&it.nodes, &geo1, &geo2)?;
    if let [Value::Table(t)] = objects.as_slice() {
        let mut out = Table::new();
        for (k, v) in t.borrow().iter() {
            let w = match (k, v) {
                (Key::Mot(s), _) if s == "SOUSTYPE" => v.clone(),
                _ => carry(a, &map, v, turn.as_ref())?,
            };
            out.set(k.clone(), w);
        }
        return Ok(vec![Value::Table(Rc::new(RefCell::new(out)))]);
    }
    objects.iter().map(|v| carry(a, &map, v, turn.as_ref())).collect()
}

/// One object on GEO1 as the same object on GEO2; with a rotation, the
/// vector and tensor components of fields turned by it (dedu.notice).
fn carry(a: &Args, map: &HashMap<usize, usize>, v: &Value, turn: Option<&Motion>) -> Result<Value> {
    let image = |n: usize| {
        map.get(&n)
            .copied()
            .ok_or_else(|| a.err(format!("node {} of the {} is not a node of GEO1", n + 1, v.ty().name())))
    };
    Ok(match v {
        Value::Point(p) => Value::Point(image(*p)?),
        Value::Mesh(m) => {
            let mut out = (**m).clone();
            for p in &mut out.parts {
                for n in &mut p.conn {
                    *n = image(*n)?;
                }
            }
            Value::Mesh(Rc::new(out))
        }
        Value::Chpo(c) => {
            let turned = match turn {
                Some(t) => Rc::new(super::mesh_move::turn_components(c, t).map_err(|e| a.err(e))?),
                None => c.clone(),
            };
            let c = &turned;
            let mut entries = Vec::new();
            for (n, comp, x) in c.entries() {
                entries.push((image(n)?, comp, x));
            }
            Value::Chpo(Rc::new(Chpoint::from_entries(c.nature, entries)))
        }
        Value::Model(_) | Value::Mchaml(_) => {
            let zones = super::move_models::zone_meshes(v).unwrap_or_default();
            let mut moved = Vec::with_capacity(zones.len());
            for mut m in zones {
                for p in &mut m.parts {
                    for n in &mut p.conn {
                        *n = image(*n)?;
                    }
                }
                moved.push(m);
            }
            super::move_models::moved(v, moved, turn).map_err(|e| a.err(e))?
        }
        _ => {
            return Err(a.err(format!(
                "DEDU carries POINT, MAILLAGE, CHPOINT, MCHAML, MMODEL or a TABLE of them, not a {}",
                v.ty().name()
            )))
        }
    })
}
