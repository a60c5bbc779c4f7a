//! Files for other tools: SORT (ParaView `.vtu`/`.pvd`, MatrixMarket),
//! LIRE 'GMSH', TRAC and DESS (SVG/PNG pictures). This file reads Gibiane
//! arguments and converts objects; the formats live in `crate::io`.
//!
//! Every path goes through the host's file policy. Output names come from
//! `OPTI SORT 'name'` (kept in `opts.other`, like every OPTI key gibi does
//! not interpret itself); state that must survive between calls (the steps
//! of a `.pvd` collection, the picture counter) is kept there too, under
//! keys no OPTI word can produce.

use super::{Args, OpDef};
use crate::error::{Error, Result};
use crate::eval::{FilePolicy, Interp};
use crate::fem::mesh::Mesh;
use crate::io::{self, gmsh, mtx, plot, vtk};
use crate::value::{Chpoint, Evolution, Key, Mchaml, Rigidite, Table, Value};
use std::cell::RefCell;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "SORT",
        signature: "SORT 'VTK' MAILLAGE (CHPOINT|MCHAML ('NAME'))… ('CONTACT' RIGIDITE SOLUTION (LIMITS)) ('TEMPS' t) | SORT 'VTK' TABLE_PASAPAS (MAILLAGE) | SORT 'MAT' RIGIDITE 'file.mtx'",
        doc: "Write files for other tools. 'VTK': a ParaView .vtu named by OPTI SORT (default gibi.vtu) with \
              nodal fields (UX UY UZ → one 3-component vector, also in 2D) and element fields (MCHAML, averaged \
              per element); with 'TEMPS' t each call writes name_NNNN.vtu and rewrites name.pvd with every time \
              so far. A field is named by the word after it, else by its variable name. A PASAPAS table gives \
              name.pvd with every saved step (DEPL, SIGMA, EPSI, contact_status, contact_pressure) on the mesh of \
              its model (or the mesh given). 'MAT': the assembled \
              matrix in MatrixMarket format plus file.mtx.dofs (row node component); conditions are extra LX \
              rows with a single multiplier each.",
        example: "opti sort 'beam' ; sort 'VTK' s u 'DEPL' sig 'SIGMA' 'TEMPS' 1. ;",
        f: sort,
    },
    OpDef {
        name: "LIRE",
        signature: "LIRE 'GMSH' 'file.msh'",
        doc: "Read a Gmsh mesh (formats 2.2 and 4.1, ASCII; SEG2/3, TRI3/6, QUA4/8, TET4, PRI6, CUB8, POI1). \
              Returns a TABLE of MAILLAGE keyed by physical group name (by tag when unnamed), plus 'TOUT' for \
              every element. New nodes get coordinates in the current dimension (a non-zero z in DIME 2 is \
              an error).",
        example: "t = lire 'GMSH' 'plate.msh' ; s = t . 'PLATE' ; bas = t . 'BOTTOM' ;",
        f: lire,
    },
    OpDef {
        name: "TRAC",
        signature: "TRAC (CHPOINT) MAILLAGE… ('TITR' text) (device words)",
        doc: "Draw meshes (one colour each; a deformed mesh is `m PLUS (u * scale)`) or a nodal field on its \
              mesh as an SVG or PNG file (OPTI TRAC 'SVG'|'PNG'; other devices such as PSC or X mean SVG). \
              File: the OPTI SORT name, else gibi_trac_N. Unknown option words are ignored; with no file \
              access allowed by the host, nothing is drawn.",
        example: "opti trac 'PNG' ; trac (exco u 'UY') s ; trac (s et (s plus (u * 100.))) ;",
        f: trac,
    },
    OpDef {
        name: "DESS",
        signature: "DESS EVOLUTIO… ('TITR' text) (options)",
        doc: "Draw curves as an SVG or PNG file, named like TRAC's. Unknown options are ignored.",
        example: "dess ev 'TITR' 'load-displacement' ;",
        f: dess,
    },
    OpDef {
        name: "VECT",
        signature: "VECT CHPOINT (SCALE) (comp…) (COLOUR) | VECT MCHAML MMODEL (SCALE) (comp…) (COLOUR)",
        doc: "An arrows object (type VECTEUR) for TRAC: the field, its scale, the components taken as the \
              vector's coordinates (default: the displacements or forces of the field) and a colour. gibi's \
              pictures do not draw arrows: TRAC draws the meshes given with it and passes over the VECTEUR, so \
              that decks which draw vectors still run.",
        example: "v = vect u 1.e3 'UX' 'UY' 'ROUG' ; trac v s ;",
        f: vect,
    },
];

pub(super) fn io_err(e: io::IoError) -> Error {
    Error::io(e.0)
}

/// The base name set by OPTI SORT, without a known extension.
pub(super) fn sort_base(it: &Interp) -> Option<String> {
    let s = it.opts.other.get("SORT")?.trim();
    if s.is_empty() {
        return None;
    }
    let lower = s.to_lowercase();
    let cut = [".vtu", ".pvd", ".svg", ".png"].iter().find(|e| lower.ends_with(*e)).map_or(0, |e| e.len());
    Some(s[..s.len() - cut].to_string())
}

/// A path the script may write, with its directory created.
pub(super) fn out_path(it: &Interp, name: &str) -> Result<PathBuf> {
    let p = it.files.check(name)?;
    if let Some(dir) = p.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(|e| Error::io(format!("cannot create {}: {}", dir.display(), e)))?;
    }
    Ok(p)
}

// ---- SORT -------------------------------------------------------------

fn sort(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    match a.req_keyword(&["VTK", "MAT"])? {
        "VTK" => sort_vtk(it, a),
        _ => sort_mat(it, a),
    }
}

/// 'CONTACT': the conditions, the RESO solution, and optionally the limits.
type ContactArgs = (Rc<crate::value::Rigidite>, Rc<Chpoint>, Option<Rc<Chpoint>>);

fn sort_vtk(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    if let Some(t) = a.opt::<Rc<RefCell<Table>>>() {
        return super::export_pasapas::sort_table(it, a, &t);
    }
    let mut mesh: Option<Rc<Mesh>> = None;
    let mut fields: Vec<(Value, String)> = Vec::new();
    let mut pending: Option<(Value, String)> = None;
    let mut time = None;
    let mut contact: Option<ContactArgs> = None;
    loop {
        if a.keyword(&["TEMPS"]).is_some() {
            time = Some(a.req_num()?);
            continue;
        }
        if a.keyword(&["CONTACT"]).is_some() {
            // 'CONTACT' RIGIDITE SOLUTION (LIMITS): status, gap and pressure
            // of the unilateral conditions, as point fields.
            let r = a.req::<Rc<crate::value::Rigidite>>()?;
            let u = a.req::<Rc<Chpoint>>()?;
            let d = a.opt_right::<Rc<Chpoint>>();
            contact = Some((r, u, d));
            continue;
        }
        let source_name = a.next_name_span().map(|sp| it.source.slice(sp).to_uppercase());
        let Some(v) = a.right_any() else { break };
        match v {
            Value::Mesh(m) if mesh.is_none() => mesh = Some(m),
            Value::Chpo(_) | Value::Mchaml(_) => {
                fields.extend(pending.take());
                let name = source_name.unwrap_or_else(|| format!("FIELD{}", fields.len() + 1));
                pending = Some((v, name));
            }
            Value::Mot(s) => match pending.take() {
                Some((f, _)) => fields.push((f, s.trim().to_string())),
                None => return Err(a.err(format!("the name '{}' follows no CHPOINT or MCHAML", s))),
            },
            other => return Err(a.err(format!("cannot export a {} (expected CHPOINT or MCHAML)", other.type_name()))),
        }
    }
    fields.extend(pending.take());
    let mesh = mesh.ok_or_else(|| a.missing("MAILLAGE"))?;
    let mut grid = vtk::Grid::new(&mesh, &it.nodes).map_err(io_err)?;
    for (f, name) in &fields {
        match f {
            Value::Chpo(c) => {
                // Multipliers (LX, FLX) live on multiplier nodes, not on the
                // mesh: they are not point data.
                let comps: Vec<String> = c.components().into_iter().filter(|x| x != "LX" && x != "FLX").collect();
                grid.add_point_field(name, &comps, |n, comp| c.get(n, comp))
            }
            Value::Mchaml(m) => grid.add_cell_array(cell_field(&grid, m, name)).map_err(io_err)?,
            _ => {}
        }
    }
    if let Some((r, u, d)) = &contact {
        let (mut nodes, mut closed, mut gap, mut pressure) = (vec![], vec![], vec![], vec![]);
        for c in r.conds.iter().filter(|c| c.kind.is_unilateral()) {
            let Some((node, _, _)) = c.terms.first() else { continue };
            let cu: f64 = c.terms.iter().map(|(n, comp, k)| k * u.get(*n, comp).unwrap_or(0.0)).sum();
            let limit = d.as_ref().and_then(|d| d.get(c.mult_node, "FLX")).unwrap_or(0.0);
            let lx = u.get(c.mult_node, "LX");
            nodes.push(*node);
            closed.push(lx.is_some());
            // Gap measured in the allowed direction: >= 0 when feasible.
            gap.push(c.kind.sense() * (cu - limit));
            // Support pressure: the magnitude of the reaction.
            pressure.push(lx.map_or(0.0, f64::abs));
        }
        grid.add_contact(&nodes, &closed, &gap, &pressure).map_err(io_err)?;
    }
    let base = sort_base(it).unwrap_or_else(|| "gibi".into());
    match time {
        None => grid.write(&out_path(it, &format!("{}.vtu", base))?).map_err(io_err)?,
        Some(t) => {
            // Steps of the collection being written: "base\nt|file\n…".
            let key = "SORT PVD";
            let mut steps: Vec<(f64, String)> = match it.opts.other.get(key) {
                Some(s) if s.lines().next() == Some(base.as_str()) => s
                    .lines()
                    .skip(1)
                    .filter_map(|l| l.split_once('|'))
                    .filter_map(|(t, f)| Some((t.parse().ok()?, f.to_string())))
                    .collect(),
                _ => Vec::new(),
            };
            let file = format!("{}_{:04}.vtu", base, steps.len());
            grid.write(&out_path(it, &file)?).map_err(io_err)?;
            let local = Path::new(&file).file_name().map_or(file.clone(), |f| f.to_string_lossy().into_owned());
            steps.push((t, local));
            vtk::write_pvd(&out_path(it, &format!("{}.pvd", base))?, &steps).map_err(io_err)?;
            let state: Vec<String> = steps.iter().map(|(t, f)| format!("{:e}|{}", t, f)).collect();
            it.opts.other.insert(key.into(), format!("{}\n{}", base, state.join("\n")));
        }
    }
    Ok(vec![])
}

/// An element field averaged per element, on the cells of `grid`.
/// Elements of the field that the exported mesh lacks are dropped; cells
/// the field does not cover get NaN.
pub(super) fn cell_field(grid: &vtk::Grid, m: &Mchaml, name: &str) -> vtk::DataArray {
    let mut comps: Vec<String> = Vec::new();
    for z in &m.zones {
        let names = if z.values.is_empty() { z.constants.keys().cloned().collect() } else { z.comps.clone() };
        for c in names {
            if !comps.contains(&c) {
                comps.push(c);
            }
        }
    }
    let nc = comps.len().max(1);
    let mut values = vec![f64::NAN; grid.n_cells() * nc];
    let lookup = grid.cell_lookup();
    for z in &m.zones {
        let elems = z.mesh.parts.iter().flat_map(|p| p.elems().map(move |e| (p.ty, e)));
        for (e, (ty, conn)) in elems.enumerate() {
            let Some(&cell) = lookup.get(&(ty, conn)) else { continue };
            for (k, c) in comps.iter().enumerate() {
                let v = match (z.comps.iter().position(|x| x == c), z.values.get(e)) {
                    (Some(ci), Some(pts)) if !pts.is_empty() => {
                        pts.iter().map(|p| p.get(ci).copied().unwrap_or(f64::NAN)).sum::<f64>() / pts.len() as f64
                    }
                    _ => z.constants.get(c).copied().unwrap_or(f64::NAN),
                };
                values[cell * nc + k] = v;
            }
        }
    }
    let comps = if comps.len() > 1 { comps } else { vec![] };
    vtk::DataArray { name: name.to_string(), comps, values }
}

fn sort_mat(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let rig = a.req::<Rc<Rigidite>>()?;
    let file = a.req::<String>()?;
    let (triplets, unknowns, comments) = assemble(&rig);
    mtx::write(&out_path(it, &file)?, triplets, &unknowns, &comments).map_err(io_err)?;
    Ok(vec![])
}

/// Triplets, the unknown of each row, header comments.
type Assembled = (Vec<(usize, usize, f64)>, Vec<mtx::Unknown>, Vec<String>);

/// Element matrices and condition rows of a RIGIDITE as global
/// (row, col, value) triplets. Unknowns are numbered node by node
/// (components in order of first appearance), then one LX row per
/// condition: a single Lagrange multiplier, not Cast3M's doubled pair,
/// which is the matrix most external tools expect.
fn assemble(r: &Rigidite) -> Assembled {
    let mut comp_rank: HashMap<&str, usize> = HashMap::new();
    let mut keys: Vec<(usize, &str)> = Vec::new();
    for b in &r.blocks {
        for e in 0..b.n_elem() {
            for (local, comp) in &b.dofs {
                let n = comp_rank.len();
                comp_rank.entry(comp).or_insert(n);
                keys.push((b.conn[e * b.nodes_per_elem + local], comp));
            }
        }
    }
    for c in &r.conds {
        for (node, comp, _) in &c.terms {
            let n = comp_rank.len();
            comp_rank.entry(comp).or_insert(n);
            keys.push((*node, comp));
        }
    }
    keys.sort_by_key(|&(n, c)| (n, comp_rank[c]));
    keys.dedup();
    let index: HashMap<(usize, &str), usize> = keys.iter().enumerate().map(|(i, &k)| (k, i)).collect();
    let mut t = Vec::new();
    for b in &r.blocks {
        let nd = b.ndof();
        for e in 0..b.n_elem() {
            let g: Vec<usize> =
                b.dofs.iter().map(|(l, c)| index[&(b.conn[e * b.nodes_per_elem + l], c.as_str())]).collect();
            let m = b.mat(e);
            for i in 0..nd {
                for j in 0..nd {
                    t.push((g[i], g[j], m[i * nd + j]));
                }
            }
        }
    }
    let n = keys.len();
    let mut unknowns: Vec<mtx::Unknown> = keys
        .iter()
        .map(|&(node, c)| mtx::Unknown { node: node + 1, comp: c.to_string(), note: String::new() })
        .collect();
    for (k, c) in r.conds.iter().enumerate() {
        for (node, comp, coef) in &c.terms {
            let j = index[&(*node, comp.as_str())];
            t.push((n + k, j, *coef));
            t.push((j, n + k, *coef));
        }
        let kind = format!("{:?}", c.kind).to_uppercase();
        unknowns.push(mtx::Unknown { node: c.mult_node + 1, comp: "LX".into(), note: kind });
    }
    let comments = vec![
        format!("gibi {}: {} primal unknowns, {} condition rows", r.subtype.name(), n, r.conds.len()),
        "conditions are single Lagrange multipliers (one LX row and column each), not Cast3M's doubled pair".into(),
        "unilateral conditions (MINI/MAXI) appear like equalities; their kind is in the .dofs file".into(),
    ];
    (t, unknowns, comments)
}

// ---- LIRE 'GMSH' ------------------------------------------------------

fn lire(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    a.req_keyword(&["GMSH"])?;
    let file = a.req::<String>()?;
    let path = it.files.check(&file)?;
    let g = gmsh::read(&path).map_err(io_err)?;
    let dime = it.opts.dime;
    for (i, x) in g.coords.iter().enumerate() {
        if let Some(k) = (dime.max(1)..3).find(|&k| dime > 0 && x[k].abs() > 1e-9 * (1.0 + x[0].abs() + x[1].abs())) {
            return Err(a.err(format!(
                "{}: node {} has {} = {} but OPTI DIME is {}",
                file,
                g.node_tags[i],
                ["x", "y", "z"][k],
                x[k],
                dime
            )));
        }
    }
    let base = it.nodes.len();
    for x in &g.coords {
        let mut p = *x;
        if dime > 0 {
            p[dime..].iter_mut().for_each(|c| *c = 0.0);
        }
        it.nodes.push(p, it.opts.dens);
    }
    let shift = |mut m: Mesh| {
        m.parts.iter_mut().for_each(|p| p.conn.iter_mut().for_each(|n| *n += base));
        Value::Mesh(Rc::new(m))
    };
    let mut t = Table::new();
    for grp in &g.groups {
        let key = match &grp.name {
            Some(n) => Key::Mot(n.clone()),
            None => Key::Int(grp.tag),
        };
        t.set(key, shift(g.group_mesh(grp.dim, grp.tag)));
    }
    t.set(Key::Mot("TOUT".into()), shift(g.all_mesh()));
    Ok(vec![Value::Table(Rc::new(RefCell::new(t)))])
}

// ---- TRAC, DESS -------------------------------------------------------

/// Picture format and file for the next TRAC/DESS; None when the host
/// allows no file at all (pictures are for people: an embedded run that
/// cannot write files must still get through decks that draw).
fn picture_path(it: &mut Interp) -> Result<Option<(plot::Format, PathBuf)>> {
    if matches!(it.files, FilePolicy::Nothing) {
        return Ok(None);
    }
    let dev = it.opts.other.get("TRAC").map(|s| s.trim().to_uppercase()).unwrap_or_default();
    let format = if dev.starts_with("PNG") { plot::Format::Png } else { plot::Format::Svg };
    let name = match sort_base(it) {
        Some(b) => format!("{}.{}", b, format.ext()),
        None => {
            let n: u64 = it.opts.other.get("TRAC COUNT").and_then(|s| s.parse().ok()).unwrap_or(0) + 1;
            it.opts.other.insert("TRAC COUNT".into(), n.to_string());
            format!("gibi_trac_{}.{}", n, format.ext())
        }
    };
    Ok(Some((format, out_path(it, &name)?)))
}

/// Title from `'TITR' text` (`title` starts as the deck's TITR); other
/// words, numbers and lists are options of Cast3M's graphics and are
/// skipped. Called between arguments: a 'TITR' found ahead of them sets
/// the title once, later calls keep it.
fn skip_options(a: &mut Args, title: &mut String) {
    while a.keyword(&["TITR"]).is_some() {
        if let Some(w) = a.word_not_operator() {
            *title = w;
        }
    }
}

fn trac(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mut title = it.title.clone();
    let mut meshes = Vec::new();
    let mut field: Option<(Rc<Chpoint>, Option<Mesh>)> = None;
    loop {
        skip_options(a, &mut title);
        let Some(v) = a.right_any() else { break };
        let mesh = match v {
            Value::Mesh(m) => (*m).clone(),
            Value::Point(p) => Mesh::points(&[p]),
            Value::Model(m) => m.zones.iter().fold(Mesh::default(), |acc, z| acc.union(&z.mesh)),
            Value::Chpo(c) if field.is_none() => {
                field = Some((c, None));
                continue;
            }
            _ => continue,
        };
        match &mut field {
            Some((_, support @ None)) => *support = Some(mesh),
            _ => meshes.push(mesh),
        }
    }
    let field = match field {
        Some((c, Some(m))) => Some(nodal_field(&c, m)),
        Some((_, None)) => return Err(a.err("TRAC of a CHPOINT needs the mesh it lives on: TRAC chpo mesh")),
        None => None,
    };
    if meshes.is_empty() && field.is_none() {
        return Err(a.missing("MAILLAGE or CHPOINT"));
    }
    let Some((format, path)) = picture_path(it)? else { return Ok(vec![]) };
    let pic = plot::MeshPicture { nodes: &it.nodes, meshes, field, title };
    plot::draw_mesh(&pic, format, &path).map_err(io_err)?;
    Ok(vec![])
}

/// The scalar TRAC shows: the only component, else the displacement
/// magnitude, else the first component.
fn nodal_field(c: &Chpoint, mesh: Mesh) -> plot::NodalField {
    let comps = c.components();
    let disp: Vec<&str> = ["UX", "UY", "UZ"].into_iter().filter(|u| comps.iter().any(|c| c == u)).collect();
    let (name, values) = if comps.len() != 1 && !disp.is_empty() {
        let mag = |n: usize| disp.iter().map(|u| c.get(n, u).unwrap_or(0.0).powi(2)).sum::<f64>().sqrt();
        ("|U|".to_string(), c.nodes.iter().map(|&n| (n, mag(n))).collect())
    } else {
        let first = comps.first().cloned().unwrap_or_default();
        let values = c.nodes.iter().filter_map(|&n| Some((n, c.get(n, &first)?))).collect();
        (first, values)
    };
    plot::NodalField { mesh, values, name }
}

/// The VECTEUR object of VECT: what it would draw, kept for LIST and TYPE.
#[derive(Debug)]
pub struct Vecteur {
    comps: Vec<String>,
    scale: f64,
    colour: String,
}

impl crate::value::HostObject for Vecteur {
    fn type_name(&self) -> &str {
        "VECTEUR"
    }
    fn describe(&self) -> String {
        format!(
            "arrows of {} scaled by {}, colour {} (TRAC does not draw them)",
            self.comps.join(" "),
            crate::value::fmt_float(self.scale),
            self.colour
        )
    }
    fn as_any(&self) -> &dyn std::any::Any {
        self
    }
}

fn vect(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
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
        } else if comps.contains(&w) || ["DEPL", "FORC", "ROTA", "MOME"].contains(&w.as_str()) {
            chosen.push(w);
        } else {
            return Err(a.err(format!("the field has no component {} (it has {})", w, comps.join(" "))));
        }
    }
    if chosen.is_empty() {
        chosen = comps;
    }
    let v = Vecteur { comps: chosen, scale, colour: colour.name().to_string() };
    Ok(vec![Value::Host(Rc::new(v))])
}

fn dess(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
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
    };
    let Some((format, path)) = picture_path(it)? else { return Ok(vec![]) };
    plot::draw_curves(&pic, format, &path).map_err(io_err)?;
    Ok(vec![])
}
