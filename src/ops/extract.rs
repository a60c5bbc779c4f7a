//! EXTR and ENLE: a part of an object, or the object without it. One
//! entry each: the object found decides, and the family that owns its type
//! does the work (lists and words here in `lists`, fields in `fields`,
//! curves in `evol`, super-elements in `superele`, tables in `tables`).

use super::lists::{self, AnyList};
use super::{evol_extr, fields, superele, tables, Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::{Chpoint, Evolution, Mchaml, Model, Rigidite, Table, Value};
use std::cell::RefCell;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "EXTR",
        signature: "EXTR LISTREEL|LISTENTI|LISTMOTS|LISTCHPO I | LIST LISTENTI | MOT I J | CHPOINT COMP POINT | EVOLUTIO 'ABSC'|'ORDO' (N) | …",
        doc: "Extract a part of an object (list element, I from 1; sub-list at the places of a LISTENTI; substring; field value; \
              curve N's lists; …). Of an EVOLUTIO: 'ABSC'|'ORDO'|'LEGE'|'LEGX'|'LEGY' (N), a list by its name, 'COUR' \
              N|LISTENTI|name (curves), 'PAS' N, 'AVAN'|'APRE' ('ENTI' I)|X ('ZERO'), 'COMP' ('ENTI' I J)|X1 X2 ('ZERO') (couples).",
        example: "x = extr l 2 ;",
        f: extr,
    },
    OpDef {
        name: "ENLE",
        signature: "ENLE CHPOINT COMP|LISTMOTS | ENLE LISTREEL|LISTENTI|LISTMOTS|LISTCHPO I|LISTENTI | ENLE TABLE KEY",
        doc:
            "Remove components of a field, the items of a list at the given places, or a key (in a copy of the table).",
        example: "u2 = enle u 'LX' ;",
        f: enle,
    },
];

/// The objects are looked for in this order: an EVOLUTIO, a CHPOINT
/// written anywhere (`EXTR 'UX' u p` as well as `EXTR u 'UX' p`), a host
/// object next on the right, a RIGIDITE, an MCHAML, an MMODEL, then the
/// first list written (`EXTR (MOTS 'A' 'B') (LECT 2)` must not take the
/// LISTENTI of places for the list), a LISTCHPO, a word.
fn extr(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if let Some(ev) = a.opt::<Rc<Evolution>>() {
        return evol_extr::extr(a, &ev);
    }
    if let Some(ch) = a.find::<Rc<Chpoint>>() {
        return fields::extr_chpo(it, a, &ch);
    }
    if let Some(h) = a.peek_right().filter(|v| matches!(v, Value::Host(_))) {
        a.right_any();
        return superele::extr(a, &h);
    }
    if let Some(r) = a.opt::<Rc<Rigidite>>() {
        return fields::extr_rigi(a, &r);
    }
    if let Some(m) = a.opt::<Rc<Mchaml>>() {
        return fields::extr_mchaml(it, a, &m);
    }
    if let Some(m) = a.opt::<Rc<Model>>() {
        return fields::extr_model(a, &m);
    }
    if let Some(c) = a.opt_with(|v| if let Value::Charge(c) = v { Some(c.clone()) } else { None }) {
        return super::chargement_extr::extr(a, &c);
    }
    if let Some(AnyList(l)) = a.opt::<AnyList>() {
        return lists::extr_list(a, l);
    }
    if let Some(l) = a.opt::<Rc<Vec<Rc<Chpoint>>>>() {
        let i = a.req_index(l.len())?;
        return Ok(vec![Value::Chpo(l[i].clone())]);
    }
    if let Some(nu) = a.opt_with(|v| if let Value::Nuage(n) = v { Some(n.clone()) } else { None }) {
        return super::nuage::extr(a, &nu);
    }
    if let Some(m) = a.opt::<String>() {
        return lists::extr_word(a, &m);
    }
    Err(a.missing("an object to extract from"))
}

/// A CHPOINT found anywhere (`ENLE 'LX' u`), else a list, else a table.
fn enle(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if let Some(ch) = a.find::<Rc<Chpoint>>() {
        return fields::enle_components(a, &ch);
    }
    // Before the other lists: the places are a LISTENTI too.
    if let Some(l) = a.opt::<Rc<Vec<Rc<Chpoint>>>>() {
        return lists::enle(a, Value::ListChpo(l));
    }
    if let Some(AnyList(l)) = a.opt::<AnyList>() {
        return lists::enle(a, l);
    }
    if let Some(t) = a.opt::<Rc<RefCell<Table>>>() {
        return tables::enle(a, &t);
    }
    Err(a.missing("CHPOINT, a list or a TABLE"))
}
