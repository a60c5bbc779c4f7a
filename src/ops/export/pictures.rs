//! Pictures: TRAC (meshes, a nodal field on its mesh, or an element
//! field by element: see [`super::trac_fields`]), DESS (curves)
//! as SVG or PNG files, and VECT, the arrows object decks hand to TRAC.

use super::trac_fields::{element_field, nodal_field};
use super::{base_of, out_path, sort_base, write_err, wrote};
use crate::error::Result;
use crate::eval::args::Args;
use crate::eval::{FilePolicy, Interp};
use crate::fem::mesh::Mesh;
use crate::io::plot;
use crate::value::{Chpoint, Evolution, Mchaml, Value};
use std::path::PathBuf;
use std::rc::Rc;

/// Picture format and file for the next TRAC/DESS; None when the host
/// allows no file at all (pictures are for people: an embedded run that
/// cannot write files must still get through decks that draw).
fn picture_path(it: &mut Interp) -> Result<Option<(plot::Format, PathBuf)>> {
    if matches!(it.files, FilePolicy::Nothing) {
        return Ok(None);
    }
    let dev = it.opts.text("TRAC").unwrap_or_default();
    let format = if dev == "PNG" { plot::Format::Png } else { plot::Format::Svg };
    // OPTI FTRA names Cast3M's picture file; else OPTI SORT's name.
    let base = it.opts.text("FTRA").and_then(base_of).or_else(|| sort_base(it));
    let name = match base {
        Some(b) => format!("{}.{}", b, format.ext()),
        None => {
            it.exports.pictures += 1;
            format!("gibi_trac_{}.{}", it.exports.pictures, format.ext())
        }
    };
    Ok(Some((format, out_path(it, &name)?)))
}

/// The line width set by OPTI EPTR (pixels, at least 1; at most 20).
fn eptr(it: &Interp) -> Option<u32> {
    it.opts.int("EPTR").map(|n| n.clamp(1, 20) as u32)
}

/// Title from `'TITR' text` (`title` starts as the deck's TITR); other
/// words, numbers and lists are options of Cast3M's graphics and are
/// skipped. Called between arguments: a 'TITR' found ahead of them sets
/// the title once, later calls keep it.
fn skip_options(a: &mut Args, title: &mut String) {
    loop {
        if a.keyword(&["TITR"]).is_some() {
            if let Some(w) = a.word_not_operator() {
                *title = w;
            }
            continue;
        }
        // TRAC's drawing options are words even where they name an
        // operator (`TRAC FACE MAIL`): TRAC reads them, nothing runs them.
        if a.keyword_next(DRAWING_OPTIONS).is_none() {
            break;
        }
    }
}

/// trac.notice's option words that gibi passes over when it draws.
const DRAWING_OPTIONS: &[&str] = &[
    "ANIME", "ARET", "BOITE", "CACH", "CHAMP", "COUL", "COUPE", "DATE", "DIRE", "ECLA", "ELEM", "FACB", "FACE", "FSDB",
    "LEGE", "LIGNE", "MOINS", "NCLK", "NOEUD", "NOLE", "OSCIL", "QUAL", "SECT", "SULI", "SURF",
];

pub(super) fn trac(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mut title = it.title.clone();
    let mut meshes = Vec::new();
    let mut models = Vec::new();
    let mut field: Option<(Rc<Chpoint>, Option<Mesh>)> = None;
    let mut elem_field: Option<Rc<Mchaml>> = None;
    loop {
        skip_options(a, &mut title);
        let Some(v) = a.right_any() else { break };
        let mesh = match v {
            Value::Mesh(m) => (*m).clone(),
            Value::Point(p) => Mesh::points(&[p]),
            Value::Model(m) => {
                let mesh = m.zones.iter().fold(Mesh::default(), |acc, z| acc.union(&z.mesh));
                models.push(meshes.len());
                mesh
            }
            Value::Chpo(_) | Value::Mchaml(_) if field.is_some() || elem_field.is_some() => {
                return Err(a.err("TRAC draws one field at a time (a CHPOINT or an MCHAML)"));
            }
            Value::Chpo(c) => {
                field = Some((c, None));
                continue;
            }
            Value::Mchaml(m) => {
                elem_field = Some(m);
                continue;
            }
            // Cast3M's options (words, numbers, lists of iso-values) and
            // VECT's arrows, which gibi does not draw, are passed over.
            Value::Mot(_)
            | Value::Int(_)
            | Value::Float(_)
            | Value::Bool(_)
            | Value::ListReel(_)
            | Value::ListEnti(_)
            | Value::ListMots(_)
            | Value::Host(_) => continue,
            Value::Evol(_) => return Err(a.err("TRAC draws meshes and fields; an EVOLUTIO is drawn by DESS")),
            other => return Err(a.err(format!("TRAC cannot draw a {}", other.type_name()))),
        };
        match &mut field {
            Some((_, support @ None)) => *support = Some(mesh),
            _ => meshes.push(mesh),
        }
    }
    let field = match (field, elem_field) {
        (Some((c, Some(m))), _) => Some(nodal_field(&c, m)),
        // A field with no mesh after it is drawn on the mesh given just
        // before it (`TRAC mail chpo`), else on its own nodes.
        (Some((c, None)), _) => {
            let support = meshes.pop().unwrap_or_else(|| Mesh::points(&c.nodes));
            Some(nodal_field(&c, support))
        }
        (None, Some(m)) => {
            // The element field carries its mesh: a model given with it
            // is its support, not one more mesh to draw.
            for k in models.into_iter().rev() {
                meshes.remove(k);
            }
            Some(element_field(&m).map_err(|e| a.err(e))?)
        }
        (None, None) => None,
    };
    if meshes.is_empty() && field.is_none() {
        return Err(a.missing("MAILLAGE, CHPOINT or MCHAML"));
    }
    let Some((format, path)) = picture_path(it)? else { return Ok(vec![]) };
    let line_width = eptr(it);
    let pic = plot::MeshPicture { nodes: &it.nodes, meshes, field, title, line_width };
    plot::draw_mesh(&pic, format, &path).map_err(write_err)?;
    wrote(it, &path);
    Ok(vec![])
}

/// The VECTEUR object of VECT: what it would draw, kept for LIST and TYPE.
/// `ET` gathers several sets of arrows into one VECTEUR (et.notice).
#[derive(Debug)]
pub struct Vecteur {
    sets: Vec<Arrows>,
}

#[derive(Debug, Clone)]
struct Arrows {
    comps: Vec<String>,
    scale: f64,
    colour: String,
}

impl Vecteur {
    /// The same arrows in new colours: `colour(k)` for the k-th set
    /// (COUL: one colour for all, or one per set).
    pub(crate) fn recoloured(&self, colour: impl Fn(usize) -> String) -> Vecteur {
        let sets = self.sets.iter().enumerate().map(|(k, s)| Arrows { colour: colour(k), ..s.clone() }).collect();
        Vecteur { sets }
    }

    /// How many sets of arrows (one per VECT joined by ET).
    pub(crate) fn len(&self) -> usize {
        self.sets.len()
    }

    /// The union `v1 ET v2`: the arrows of both, in order.
    pub(crate) fn join(&self, other: &Vecteur) -> Vecteur {
        Vecteur { sets: self.sets.iter().chain(&other.sets).cloned().collect() }
    }
}

impl crate::value::HostObject for Vecteur {
    fn type_name(&self) -> &str {
        "VECTEUR"
    }
    fn describe(&self) -> String {
        let sets: Vec<String> = self
            .sets
            .iter()
            .map(|s| {
                format!(
                    "arrows of {} scaled by {}, colour {}",
                    s.comps.join(" "),
                    crate::value::fmt_float(s.scale),
                    s.colour
                )
            })
            .collect();
        format!("{} (TRAC does not draw them)", sets.join("; "))
    }
    fn as_any(&self) -> &dyn std::any::Any {
        self
    }
}

pub(super) fn vect(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    // The field's components, to check the names the deck gives; an MCHAML
    // comes with its model (vect.notice: stresses drawn as principal axes).
    let comps: Vec<String> = match a.opt::<Rc<Chpoint>>() {
        Some(c) => c.components(),
        None => {
            let m = a.req::<Rc<Mchaml>>()?;
            a.req::<Rc<crate::value::Model>>()?;
            m.zones.iter().flat_map(|z| z.comps.iter().cloned()).collect()
        }
    };
    let scale = a.opt_num().unwrap_or(1.0);
    let mut chosen = Vec::new();
    let mut colour = crate::fem::colour::Colour::default();
    while let Some(w) = a.word_not_operator() {
        let w = w.trim().to_uppercase();
        if let Some(c) = crate::fem::colour::Colour::from_name(&w) {
            colour = c;
        } else {
            chosen.push(w);
        }
    }
    // A direction the field lacks draws as zero (Cast3M decks name FX FY
    // for a field of FY only); a list naming none of the field's
    // components is a mistake.
    let known = |w: &String| comps.contains(w) || ["DEPL", "FORC", "ROTA", "MOME"].contains(&w.as_str());
    if !chosen.is_empty() && !chosen.iter().any(known) {
        return Err(a.err(format!(
            "the field has none of the components {} (it has {})",
            chosen.join(" "),
            comps.join(" ")
        )));
    }
    if chosen.is_empty() {
        chosen = comps;
    }
    let v = Vecteur { sets: vec![Arrows { comps: chosen, scale, colour: colour.name().to_string() }] };
    Ok(vec![Value::Host(Rc::new(v))])
}

pub(super) fn dess(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mut title = it.title.clone();
    let mut evols: Vec<Rc<Evolution>> = Vec::new();
    loop {
        skip_options(a, &mut title);
        match a.right_any() {
            Some(Value::Evol(e)) => evols.push(e),
            Some(_) => {}
            None => break,
        }
    }
    if evols.is_empty() {
        return Err(a.missing("EVOLUTIO"));
    }
    let curves: Vec<_> = evols.iter().flat_map(|e| e.curves.iter()).collect();
    let pic = plot::CurvePicture {
        title,
        x_label: curves.first().map(|c| c.x_name.clone()).unwrap_or_default(),
        y_label: curves.first().map(|c| c.y_name.clone()).unwrap_or_default(),
        curves: curves
            .iter()
            .map(|c| plot::Curve { label: c.legend.clone(), x: c.x.clone(), y: c.y.clone() })
            .collect(),
        line_width: eptr(it),
    };
    let Some((format, path)) = picture_path(it)? else { return Ok(vec![]) };
    plot::draw_curves(&pic, format, &path).map_err(write_err)?;
    wrote(it, &path);
    Ok(vec![])
}
