//! CHAN 'CHAM' CHPO (GEO | MODL (support)) (subtype): a field by point
//! turned into a field by element, interpolated with the element's shape
//! functions at the points of the support (the nodes by default).

use super::model::formulation;
use super::Args;
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::{Mesh, Part};
use crate::value::model::MchamlZone;
use crate::value::{Chpoint, Mchaml, Model, Value};
use std::rc::Rc;

/// The components of `ch` present at some node of `part`, in field order.
fn comps_on(ch: &Chpoint, part: &Part) -> Vec<String> {
    let nodes: std::collections::HashSet<usize> = part.conn.iter().copied().collect();
    ch.components().into_iter().filter(|c| nodes.iter().any(|n| ch.get(*n, c).is_some())).collect()
}

/// Values at reference points `refs` of every element (0 where the field
/// has no value at a node).
fn zone(ch: &Chpoint, part: &Part, refs: Option<&[[f64; 3]]>, element: String) -> Option<MchamlZone> {
    let comps = comps_on(ch, part);
    if comps.is_empty() {
        return None;
    }
    let shapes: Option<Vec<Vec<f64>>> =
        refs.map(|r| r.iter().map(|p| crate::fem::shape::eval(part.ty, *p).n).collect());
    let mut values = Vec::new();
    for e in part.elems() {
        let at_nodes: Vec<Vec<f64>> =
            e.iter().map(|n| comps.iter().map(|c| ch.get(*n, c).unwrap_or(0.0)).collect()).collect();
        values.push(match &shapes {
            None => at_nodes,
            Some(sh) => sh
                .iter()
                .map(|w| (0..comps.len()).map(|c| w.iter().zip(&at_nodes).map(|(wi, row)| wi * row[c]).sum()).collect())
                .collect(),
        });
    }
    Some(MchamlZone {
        mesh: Mesh::single(part.clone()),
        element,
        comps,
        values,
        at_nodes: refs.is_none(),
        ..Default::default()
    })
}

pub(super) fn from_chpoint(_it: &mut Interp, a: &mut Args, ch: &Chpoint) -> Result<Vec<Value>> {
    let mut zones = Vec::new();
    if let Some(model) = a.opt::<Rc<Model>>() {
        let support = a.keyword(&["NOEUD", "GRAVITE", "RIGIDITE", "MASSE", "STRESSES"]).unwrap_or("NOEUD");
        for z in &model.zones {
            let form = formulation(z);
            for part in &z.mesh.parts {
                let refs: Option<Vec<[f64; 3]>> = match support {
                    "NOEUD" => None,
                    "GRAVITE" => {
                        let r = crate::fem::shape::ref_nodes(part.ty);
                        let n = r.len() as f64;
                        Some(vec![r.iter().fold([0.0; 3], |s, p| [s[0] + p[0] / n, s[1] + p[1] / n, s[2] + p[2] / n])])
                    }
                    _ => Some(crate::fem::element::gauss_points(form, part.ty).into_iter().map(|(p, _)| p).collect()),
                };
                zones.extend(zone(ch, part, refs.as_deref(), z.element.clone()));
            }
        }
    } else {
        let geo = super::mesh::req_geo(a)?;
        for part in &geo.parts {
            zones.extend(zone(ch, part, None, part.ty.name().to_string()));
        }
    }
    let subtype = a.word_not_operator().map(|w| w.trim().to_uppercase()).unwrap_or_default();
    Ok(vec![Value::Mchaml(Rc::new(Mchaml { subtype, zones }))])
}

/// `CHAN (TYPE) GEO LISTENTI`: elements of TYPE (the OPTI ELEM type by
/// default) whose nodes are the listed points of the POI1 mesh GEO, taken
/// in groups of the element's node count. None when the arguments are not
/// this form (nothing is consumed then).
pub(super) fn connect(it: &mut Interp, a: &mut Args) -> Result<Option<Vec<Value>>> {
    use crate::fem::mesh::ElemType;
    // The types CHAN converts a whole mesh to keep that meaning.
    const CONVERTED: &[&str] = &["POI1", "QUA8", "TRI6", "SEG3", "QUA4", "TRI3", "SEG2"];
    let ty = match a.peek_right() {
        Some(Value::Mesh(_)) => None,
        Some(Value::Mot(w)) => match ElemType::from_name(w.trim().to_uppercase().as_str()) {
            Some(t) if !CONVERTED.contains(&t.name()) => {
                a.word();
                Some(t)
            }
            _ => return Ok(None),
        },
        _ => return Ok(None),
    };
    let given = ty.is_some();
    let ty = ty.unwrap_or_else(|| super::mesh::elem_type_opt(it));
    let geo = a.req::<Rc<Mesh>>()?;
    let Some(conn) = a.opt_right::<Rc<Vec<i64>>>() else {
        if !given {
            // `CHAN GEO 'TET4'`: the words are read from either side.
            if matches!(a.peek_right(), Some(Value::Mot(w)) if w.trim().eq_ignore_ascii_case("TET4")) {
                a.word();
                return Ok(Some(vec![Value::Mesh(Rc::new(crate::fem::meshing::tetra::to_tet4(&it.nodes, &geo)?))]));
            }
            // `CHAN GEO 'TRI3'`: a mesh first, then one of the other forms.
            a.unread(Value::Mesh(geo));
            return Ok(None);
        }
        if ty == ElemType::Tet4 {
            // `CHAN 'TET4' volume`: the elements cut into tetrahedra.
            return Ok(Some(vec![Value::Mesh(Rc::new(crate::fem::meshing::tetra::to_tet4(&it.nodes, &geo)?))]));
        }
        return Err(a.missing("LISTENTI (the connectivity)"));
    };
    let pts: Vec<usize> = geo.parts.iter().flat_map(|p| p.conn.iter().copied()).collect();
    if geo.parts.iter().any(|p| p.ty != ElemType::Poi1) {
        return Err(a.err("the mesh must be made of POI1 elements"));
    }
    let n = ty.nodes();
    if conn.len() % n != 0 {
        return Err(a.err(format!("{} numbers do not make {} elements of {} nodes", conn.len(), ty.name(), n)));
    }
    let mut nodes = Vec::with_capacity(conn.len());
    for &k in conn.iter() {
        let i = usize::try_from(k - 1)
            .ok()
            .filter(|&i| i < pts.len())
            .ok_or_else(|| a.err(format!("point number {} is out of range (the mesh has {} points)", k, pts.len())))?;
        nodes.push(pts[i]);
    }
    let elems: Vec<Mesh> =
        nodes.chunks(n).map(|e| crate::fem::meshing::manu(&it.nodes, ty, e)).collect::<std::result::Result<_, _>>()?;
    let mut out = Mesh::default();
    for m in elems {
        out = out.union(&m);
    }
    Ok(Some(vec![Value::Mesh(Rc::new(out))]))
}
