//! PRIN (PRINCIPALE): principal stresses and directions of a stress
//! MCHAML of massive elements, point by point. The algebra lives in
//! `fem::principal`.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::principal::{self, Principal};
use crate::value::model::MchamlZone;
use crate::value::{Mchaml, Model, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "PRIN",
    signature: "PRIN MCHAML_STRESS (MMODEL)",
    doc: "Principal stresses SI11 ≥ SI22 (≥ SI33 in 3D; in 2D SI33 is the out-of-plane stress) and their unit directions COX1 COY1 (COZ1) … at every point of a stress field of massive elements.",
    example: "sp = prin sig mo ;",
    f: prin,
}];

/// Where each stress component sits in the field, by analysis kind.
enum Layout {
    /// In-plane xx, yy, xy and out-of-plane zz (PLAN) or tt (AXIS).
    Plane([usize; 3], Option<usize>),
    /// xx yy zz xy xz yz.
    Space([usize; 6]),
}

fn layout(z: &MchamlZone) -> Option<Layout> {
    let at = |n: &str| z.comps.iter().position(|c| c == n);
    if let (Some(xx), Some(yy), Some(zz), Some(xy), Some(xz), Some(yz)) =
        (at("SMXX"), at("SMYY"), at("SMZZ"), at("SMXY"), at("SMXZ"), at("SMYZ"))
    {
        return Some(Layout::Space([xx, yy, zz, xy, xz, yz]));
    }
    if let (Some(rr), Some(zz), Some(rz)) = (at("SMRR"), at("SMZZ"), at("SMRZ")) {
        return Some(Layout::Plane([rr, zz, rz], at("SMTT")));
    }
    if let (Some(xx), Some(yy), Some(xy)) = (at("SMXX"), at("SMYY"), at("SMXY")) {
        return Some(Layout::Plane([xx, yy, xy], at("SMZZ")));
    }
    None
}

fn prin(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let sig = a.req::<Rc<Mchaml>>()?;
    // The model adds nothing: the components tell the kind of analysis.
    let _ = a.opt::<Rc<Model>>();
    let mut out = Mchaml { subtype: "CONTRAINTES PRINCIPALES".into(), zones: vec![] };
    for z in &sig.zones {
        let Some(lay) = layout(z) else {
            return Err(a.err(format!(
                "expected the stresses of massive elements (SMXX SMYY SMXY …), found {}",
                if z.comps.is_empty() { "no point values".to_string() } else { z.comps.join(" ") }
            )));
        };
        let mut nz = MchamlZone { mesh: z.mesh.clone(), element: z.element.clone(), ..Default::default() };
        nz.at_nodes = z.at_nodes;
        let space = matches!(lay, Layout::Space(_));
        nz.comps = if space {
            ["SI11", "SI22", "SI33", "COX1", "COY1", "COZ1", "COX2", "COY2", "COZ2", "COX3", "COY3", "COZ3"]
                .map(String::from)
                .to_vec()
        } else {
            ["SI11", "SI22", "SI33", "COX1", "COY1", "COX2", "COY2"].map(String::from).to_vec()
        };
        for pts in &z.values {
            let row = pts
                .iter()
                .map(|v| {
                    let p: Principal = match &lay {
                        Layout::Space(i) => principal::space(i.map(|k| v[k])),
                        Layout::Plane([xx, yy, xy], zz) => {
                            principal::plane(v[*xx], v[*yy], v[*xy], zz.map_or(0.0, |k| v[k]))
                        }
                    };
                    let mut r = p.values.to_vec();
                    if space {
                        r.extend(p.dirs.iter().flatten());
                    } else {
                        r.extend([p.dirs[0][0], p.dirs[0][1], p.dirs[1][0], p.dirs[1][1]]);
                    }
                    r
                })
                .collect();
            nz.values.push(row);
        }
        out.zones.push(nz);
    }
    Ok(vec![Value::Mchaml(Rc::new(out))])
}
