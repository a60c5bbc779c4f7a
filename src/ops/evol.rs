//! EVOLUTIO objects: curves y(x) built by hand (`EVOL 'MANU'`) or read
//! along an ordered line from a node field (`EVOL 'CHPO'`); what EXTR
//! gives back from them is in `evol_extr`.
//! Cast3M mostly draws these; gibi has no graphics, so the colour word is
//! accepted and dropped.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::fem::meshing as mg;
use crate::value::model::Curve;
use crate::value::{Chpoint, Evolution, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "EVOL",
    signature: "EVOL (colour) 'MANU' ('TYPE' kind) ('LEGE' text) (nameX) LISTREEL|LISTENTI|LISTMOTS (nameY) LISTREEL|LISTENTI|LISTMOTS | EVOL (colour) 'CHPO' CHPOINT (comp) LINE | EVOL (colour) 'TEMP' TABLE|LISTCHPO LISTREEL ('MOT') (LISTENTI) COMP|LISTMOTS POINT|MAILLAGE|(N1 N2 N3)",
    doc: "A curve: given point by point, or a node field along an ordered line against its curvilinear abscissa, or a result against time at points ('TEMP': the tables of a PASAPAS run, DEPLACEMENTS by default, or a LISTCHPO and its times; N1 N2 N3 for an MCHAML: point N3 of element N2 of zone N1).",
    example: "ev = evol 'CHPO' u 'UY' l ;",
    f: evol,
}];

/// Cast3M's colour words (only meaningful for drawing), the extended
/// palette of coul.notice included (TFR and BRUI read them too). OR is
/// left out: as a short choice it would take any word beginning OR.
pub(crate) const COLOURS: &[&str] = &[
    "DEFA", "NOIR", "BLEU", "ROUG", "ROSE", "VERT", "TURQ", "JAUN", "BLAN", "AZUR", "ORAN", "VIOL", "OCEA", "CYAN",
    "OLIV", "GRIS", "POUR", "BRUN", "BRIQ", "CORA", "BEIG", "MARI", "BOUT", "LIME", "LAVA", "BRON", "KAKI", "PEAU",
    "CARA", "INDI",
];

fn evol(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    // OR (gold) is a colour too, read only as the whole word (see COLOURS).
    if a.keyword(COLOURS).is_none()
        && matches!(a.peek_right(), Some(Value::Mot(w)) if w.trim().eq_ignore_ascii_case("OR"))
    {
        a.word();
    }
    let curve = match a.req_keyword(&["MANU", "CHPO", "TEMP", "COMP"])? {
        "MANU" => manu(a)?,
        "COMP" => return Ok(vec![Value::Evol(Rc::new(complex(a)?))]),
        "TEMP" => return super::evol_temps::evol_temp(it, a),
        _ => along_line(it, a)?,
    };
    Ok(vec![Value::Evol(Rc::new(Evolution { curves: vec![curve] }))])
}

/// `'MANU' ('TYPE' kind) ('LEGE' text) (nameX) LX (nameY) LY`.
fn manu(a: &mut Args) -> Result<Curve> {
    // The kind (REEL, HIST, MOTS...) only tells Cast3M's drawing how to
    // show the points; gibi's curves are numbers, so it is read and dropped.
    if a.keyword(&["TYPE"]).is_some() {
        a.word().ok_or_else(|| a.missing("the kind of curve after 'TYPE'"))?;
    }
    let mut legend = String::new();
    if a.keyword(&["LEGE", "TITR"]).is_some() {
        legend = a.word().ok_or_else(|| a.missing("the legend text"))?;
    }
    let mut x_name = label(a).unwrap_or_default();
    let x = numbers(a).ok_or_else(|| a.missing("LISTREEL (the abscissae)"))?;
    let mut y_name = label(a).unwrap_or_default();
    // Cast3M reads the optional names wherever they stand: with two names
    // between the lists (`lx 'ABS' 'TEMPS' ly`) the first names the abscissae.
    if x_name.is_empty() && !y_name.is_empty() {
        if let Some(second) = label(a) {
            x_name = std::mem::replace(&mut y_name, second);
        }
    }
    let y = numbers(a).ok_or_else(|| a.missing("LISTREEL (the ordinates)"))?;
    if x.len() != y.len() {
        return Err(a.err(format!("the abscissae have {} values but the ordinates {}", x.len(), y.len())));
    }
    if x.is_empty() {
        return Err(a.err("a curve needs at least one point"));
    }
    Ok(Curve { legend, x_name, y_name, x, y })
}

/// `'COMP' ('REIM'|'MOPH') ('LEGE' T1 T2) (nameX) LX (name1) L1 (name2) L2`:
/// a complex curve as TFR gives one, two curves on the same abscissae. The
/// form fixes the ordinates' names (PREE/PIMA or MODU/PHAS, which `* /`,
/// RIMP and TFRI read, as Cast3M's subtypes): names the deck gives are
/// labels, kept as the curves' legends unless 'LEGE' gives them.
fn complex(a: &mut Args) -> Result<Evolution> {
    let moph = a.keyword(&["REIM", "MOPH"]) == Some("MOPH");
    let (mut t1, mut t2) = if moph { ("Amp", "Phase") } else { ("Re", "Im") };
    let (l1, l2);
    let lege = a.keyword(&["LEGE"]).is_some();
    if lege {
        l1 = a.word().ok_or_else(|| a.missing("the title of the first curve"))?;
        l2 = a.word().ok_or_else(|| a.missing("the title of the second curve"))?;
        (t1, t2) = (&l1, &l2);
    }
    let x_name = label(a).unwrap_or_default();
    let x = numbers(a).ok_or_else(|| a.missing("LISTREEL (the abscissae)"))?;
    let (d1, d2) = if moph { ("MODU", "PHAS") } else { ("PREE", "PIMA") };
    let named = |l: Option<String>, t: &mut String| {
        if let (Some(l), false) = (l, lege) {
            *t = l;
        }
    };
    let (mut t1, mut t2) = (t1.to_string(), t2.to_string());
    named(label(a), &mut t1);
    let (n1, n2) = (d1.to_string(), d2.to_string());
    let y1 = numbers(a).ok_or_else(|| a.missing("LISTREEL (the real parts or moduli)"))?;
    named(label(a), &mut t2);
    let y2 = numbers(a).ok_or_else(|| a.missing("LISTREEL (the imaginary parts or phases)"))?;
    if x.len() != y1.len() || x.len() != y2.len() {
        return Err(a.err(format!(
            "the abscissae have {} values but the ordinates {} and {}",
            x.len(),
            y1.len(),
            y2.len()
        )));
    }
    if x.is_empty() {
        return Err(a.err("a curve needs at least one point"));
    }
    let curve = |legend: &str, y_name: String, y: Vec<f64>| Curve {
        legend: legend.into(),
        x_name: x_name.clone(),
        y_name,
        x: x.clone(),
        y,
    };
    Ok(Evolution { curves: vec![curve(&t1, n1, y1), curve(&t2, n2, y2)] })
}

/// A list's name: a word before the list, even one that names an
/// operator (`EVOL 'MANU' temp lt ampl la`: a title, not the TEMP operator).
fn label(a: &mut Args) -> Option<String> {
    if let Some((w, g)) = a.word_with_glued_group() {
        return Some(format!("{}({})", w, g));
    }
    a.word_before_value().or_else(|| a.word_not_operator())
}

/// A LISTREEL, or a LISTENTI read as reals. A LISTMOTS (words along an
/// axis, as the bars of a chart) stands at its ranks 1, 2, …: the words
/// only label the ticks of a drawing, the ranks keep the curve numeric.
fn numbers(a: &mut Args) -> Option<Vec<f64>> {
    a.opt_with(|v| match v {
        Value::ListReel(l) => Some(l.to_vec()),
        Value::ListEnti(l) => Some(l.iter().map(|&i| i as f64).collect()),
        Value::ListMots(l) => Some((1..=l.len()).map(|i| i as f64).collect()),
        _ => None,
    })
}

/// `'CHPO' CHPO (comp) LINE`: values at the line's nodes in order, against
/// the distance travelled from its first node.
fn along_line(it: &Interp, a: &mut Args) -> Result<Curve> {
    let ch = a.req::<Rc<Chpoint>>()?;
    let comp = a.word_not_operator();
    let line = a.req::<Rc<Mesh>>()?;
    let comp = match comp.or_else(|| a.word_not_operator()) {
        Some(c) => c,
        None => {
            let cs = ch.components();
            if cs.len() != 1 {
                return Err(a.err(format!("say which component to follow (the field has {})", cs.join(" "))));
            }
            cs[0].clone()
        }
    };
    if !ch.components().contains(&comp) {
        return Err(a.err(format!("the field has no component {} (it has {})", comp, ch.components().join(" "))));
    }
    let nodes = mg::line_chain("EVOL", &line).map_err(|e| a.err(e.message))?;
    let mut x = Vec::with_capacity(nodes.len());
    let mut y = Vec::with_capacity(nodes.len());
    let mut s = 0.0;
    for (k, n) in nodes.iter().enumerate() {
        if k > 0 {
            let (p, q) = (it.nodes.get(nodes[k - 1]), it.nodes.get(*n));
            s += ((q[0] - p[0]).powi(2) + (q[1] - p[1]).powi(2) + (q[2] - p[2]).powi(2)).sqrt();
        }
        let v = ch.get(*n, &comp).ok_or_else(|| {
            a.err(format!("the field has no {} value at node {} (point {} of the line)", comp, n + 1, k + 1))
        })?;
        x.push(s);
        y.push(v);
    }
    // Cast3M titles this abscissa ABS: decks read it back with `EXTR ev 'ABS'`.
    Ok(Curve { legend: String::new(), x_name: "ABS".into(), y_name: comp, x, y })
}
