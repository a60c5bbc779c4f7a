//! COUL: the colour of a mesh's elements, kept by ET and used by TRAC.

use super::export::Vecteur;
use super::{Args, OpDef, PointId};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::{Colour, Mesh};
use crate::value::{Evolution, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "COUL",
    signature: "MAILLAGE|POINT|EVOLUTIO|VECTEUR COUL (colour) (DEFA BLEU ROUG ROSE VERT TURQ JAUN BLAN NOIR ORAN VIOL OCEA CYAN OLIV GRIS AZUR)",
    doc: "The mesh with every element in the colour (kept by ET, drawn by TRAC). A POINT gives a one-point mesh; an EVOLUTIO is returned as it is (DESS picks its own colours); the arrows of a VECTEUR take the colour, or one each from a LISTMOTS.",
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
    let vecteur = a.opt_with(|v| match v {
        Value::Host(h) if h.as_any().is::<Vecteur>() => Some(h.clone()),
        _ => None,
    });
    if let Some(h) = vecteur {
        let Some(v) = h.as_any().downcast_ref::<Vecteur>() else { unreachable!("checked above") };
        // One colour for every set of arrows, or one each (LISTMOTS: as
        // many as the sets), or OPTI COUL's.
        let colours: Vec<Colour> = match a.peek_right() {
            Some(Value::Mot(_)) => vec![colour_word(a)?],
            Some(Value::ListMots(l)) => {
                a.right_any();
                if l.len() != v.len() {
                    return Err(a.err(format!("{} colours for {} sets of arrows", l.len(), v.len())));
                }
                let named =
                    l.iter().map(|w| Colour::from_name(w).ok_or_else(|| a.err(format!("{} is not a colour", w))));
                named.collect::<Result<_>>()?
            }
            _ => vec![current(it)],
        };
        let pick = |k: usize| colours[k.min(colours.len() - 1)].name().to_string();
        return Ok(vec![Value::Host(Rc::new(v.recoloured(pick)))]);
    }
    Err(a.missing("MAILLAGE, POINT, EVOLUTIO or VECTEUR"))
}
