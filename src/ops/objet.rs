//! OBJET: make an object of the class a method names, and run that
//! method (its constructor) on it (obje.notice). Methods, `%` and
//! inheritance are language, in eval/objet.rs.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::Value;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "OBJE",
    signature: "OBJET METHODE -> OBJET",
    doc: "Make an OBJET of the class named by a method (made by DEBMETH) and run that method on it as its constructor; inside a method %ELE reads or writes an entry, and o%NAME args calls a method.",
    example: "DEBMETH CPT ; %N = 0 ; FINMETH ; c = OBJET CPT ;",
    f: objet,
}];

fn objet(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let ctor = match a.right_proc() {
        Some(p) => p,
        None => {
            let name = a.word().ok_or_else(|| a.missing("the constructor (a method made by DEBMETH)"))?;
            it.method_named(&name.to_uppercase(), a.span)?
                .ok_or_else(|| a.err(format!("{} is not a method (made by DEBMETH)", name)))?
        }
    };
    Ok(vec![it.new_objet(ctor, a.span)?])
}
