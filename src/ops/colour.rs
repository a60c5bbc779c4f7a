//! COUL: the colour of a mesh's elements, kept by ET and used by TRAC.

use super::{Args, OpDef, PointId};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::{Colour, Mesh};
use crate::value::{Evolution, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "COUL",
    signature: "MAILLAGE|POINT|EVOLUTIO COUL (colour) (DEFA BLEU ROUG ROSE VERT TURQ JAUN BLAN NOIR ORAN VIOL OCEA CYAN OLIV GRIS AZUR)",
    doc: "The mesh with every element in the colour (kept by ET, drawn by TRAC). A POINT gives a one-point mesh; an EVOLUTIO is returned as it is (DESS picks its own colours).",
    example: "s = s coul roug ;",
    f: coul,
}];

/// The colour OPTI COUL set, DEFA by default.
fn current(it: &Interp) -> Colour {
    match it.opts.kept.get("COUL") {
        Some(Value::Mot(w)) => Colour::from_name(w).unwrap_or_default(),
        _ => Colour::default(),
    }
}

/// The colour word on the right (`ROUGE` = `ROUG`).
pub(crate) fn colour_word(a: &mut Args) -> Result<Colour> {
    let Some(w) = a.word() else {
        return Err(a.missing("a colour"));
    };
    Colour::from_name(&w).ok_or_else(|| {
        a.err(format!("{} is not a colour (the colours are {})", w, Colour::names().collect::<Vec<_>>().join(" ")))
    })
}

fn coul(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if let Some(m) = a.opt::<Rc<Mesh>>() {
        // Without a colour (coul.notice: MOT1 is optional), the current
        // one of OPTI COUL.
        let c = match a.peek_right() {
            Some(Value::Mot(_)) => colour_word(a)?,
            // A deformed shape (kept as a mesh) may be given one colour
            // per shape: the mesh takes the first.
            Some(Value::ListMots(l)) => {
                a.right_any();
                match l.first() {
                    Some(w) => Colour::from_name(w).ok_or_else(|| a.err(format!("{} is not a colour", w)))?,
                    None => current(it),
                }
            }
            _ => current(it),
        };
        return Ok(vec![Value::Mesh(Rc::new(m.coloured(c)))]);
    }
    if let Some(p) = a.opt::<PointId>() {
        let c = colour_word(a)?;
        return Ok(vec![Value::Mesh(Rc::new(Mesh::points(&[p.0]).coloured(c)))]);
    }
    if let Some(e) = a.opt::<Rc<Evolution>>() {
        // One colour, one per curve (LISTMOTS), or none: DESS picks its own.
        if a.opt_right::<Rc<Vec<String>>>().is_none() && matches!(a.peek_right(), Some(Value::Mot(_))) {
            colour_word(a)?;
        }
        return Ok(vec![Value::Evol(e)]);
    }
    Err(a.missing("MAILLAGE, POINT or EVOLUTIO"))
}
