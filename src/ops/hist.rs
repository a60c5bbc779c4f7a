//! HIST on lists: the class of each event (a tuple of reals given as one
//! LISTREEL per coordinate, each followed by its class bounds) and the
//! number of events per class (numerics in `value::signal::histogram`).

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::colour::Colour;
use crate::value::signal::histogram;
use crate::value::{Model, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "HIST",
    signature: "LENT1 (LENT2) = HIST LVAL1 LCLAS1 (LVAL2 LCLAS2 …) ('CLAS') ('OCCU')   (LVAL, LCLAS: LISTREEL) | EVOL = HIST (colour) MMODEL MCHAML ('ABS') LRE (MOT | LISTMOTS)",
    doc: "Sorts N events (coordinate i of each in LVALi) into classes: LCLASi holds the strictly increasing bounds of the Ni intervals of coordinate i (closed below, open above; the last keeps its top). 'CLAS' gives the global class of each event, k = k1 + N1 (k2 - 1) + N1 N2 (k3 - 1) + …, 0 when outside the bounds; 'OCCU' the number of events in each class. Without either, both, classes first. With a model and an element field: one curve per component (all, or those named) of the density of its values (absolute with 'ABS') over the classes of LRE, each value counting once: share of the values in a class / its width, at each bound (the last repeats).",
    example: "lc lo = hist (prog 0.2 0.7) (prog 0. 0.5 1.) ;",
    f: hist,
}];

fn hist(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    // Curves carry no colour in gibi: a colour word is read and dropped.
    if a.peek_word().is_some_and(|w| Colour::from_name(&w).is_some()) {
        a.word();
    }
    if a.opt::<Rc<Model>>().is_some() {
        return super::hist_field::hist_field(a);
    }
    let mut values = Vec::new();
    let mut bounds = Vec::new();
    while let Some(v) = a.opt::<Rc<Vec<f64>>>() {
        let b = a.opt::<Rc<Vec<f64>>>().ok_or_else(|| a.missing("LISTREEL (class bounds)"))?;
        values.push(v);
        bounds.push(b);
    }
    if values.is_empty() {
        return Err(a.missing("LISTREEL (values)"));
    }
    let n = values[0].len();
    if let Some(v) = values.iter().find(|v| v.len() != n) {
        return Err(a.err(format!("the lists of values differ in length ({} and {})", n, v.len())));
    }
    for b in &bounds {
        if b.len() < 2 {
            return Err(a.err(format!("a list of class bounds needs at least 2 values, not {}", b.len())));
        }
        if b.windows(2).any(|w| w[0] >= w[1]) {
            return Err(a.err("class bounds must be strictly increasing"));
        }
    }
    let mut wanted = Vec::new();
    while let Some(k) = a.keyword(&["CLAS", "OCCU"]) {
        wanted.push(k);
    }
    if wanted.is_empty() {
        wanted = vec!["CLAS", "OCCU"];
    }
    let vs: Vec<&[f64]> = values.iter().map(|v| v.as_slice()).collect();
    let bs: Vec<&[f64]> = bounds.iter().map(|b| b.as_slice()).collect();
    let (classes, occurrences) = histogram::classify(&vs, &bs);
    Ok(wanted
        .into_iter()
        .map(|k| Value::ListEnti(Rc::new(if k == "CLAS" { classes.clone() } else { occurrences.clone() })))
        .collect())
}
