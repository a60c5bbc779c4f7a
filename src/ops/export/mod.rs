//! Files for other tools: SORT (ParaView `.vtu`/`.pvd`, MatrixMarket),
//! LIRE 'GMSH', TRAC and DESS (SVG/PNG pictures). These files read Gibiane
//! arguments and convert objects; the formats live in `crate::io`.
//!
//! Every path goes through the host's file policy. Output names come from
//! `OPTI SORT 'name'` (kept in `opts.kept`, like every OPTI key gibi does
//! not interpret itself); what must survive between calls (the steps of a
//! `.pvd` collection, the picture counter) is the interpreter's typed
//! `exports` state.
//!
//! One file per kind: [`sort_vtk`] (ParaView) with [`sort_pasapas`] (a
//! PASAPAS table as a collection), [`sort_matrix`]
//! (MatrixMarket), [`read_gmsh`], [`pictures`] (TRAC, DESS, VECT) with
//! [`trac_fields`] (the scalar a picture is coloured by).

mod avs;
mod nastran;
mod pictures;
pub(crate) use pictures::Vecteur;
mod read_csv;
mod read_gmsh;
mod read_proc;
mod sort_matrix;
mod sort_mesh;
mod sort_pasapas;
mod sort_text;
mod sort_vtk;
mod stl;
mod trac_fields;

use super::{Args, OpDef};
use crate::error::{Error, ErrorKind, Result};
use crate::eval::Interp;
use crate::io;
use crate::value::Value;
use std::path::{Path, PathBuf};

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "SORT",
        signature: "SORT MAILLAGE ('NOOP') | SORT 'VTK' MAILLAGE (CHPOINT|MCHAML ('NAME'))… ('CONTACT' RIGIDITE SOLUTION (LIMITS)) ('TEMPS' t) | SORT 'VTK' TABLE_PASAPAS (MAILLAGE) | SORT 'MAT' RIGIDITE 'file.mtx' | SORT 'STL' MAILLAGE | SORT 'AVS' (MAILLAGE) (CHPOINT) (MCHAML) ('SUIT') ('TEMP' t) | SORT 'NAS' MAILLAGE | SORT 'CHAI' OBJ…",
        doc: "Write files for other tools. 'VTK': a ParaView .vtu named by OPTI SORT (default gibi.vtu) with \
              nodal fields (UX UY UZ → one 3-component vector, also in 2D) and element fields (MCHAML, averaged \
              per element); with 'TEMPS' t each call writes name_NNNN.vtu and rewrites name.pvd with every time \
              so far. A field is named by the word after it, else by its variable name. A PASAPAS table gives \
              name.pvd with every saved step (DEPL, SIGMA, EPSI, contact_status, contact_pressure) on the mesh of \
              its model (or the mesh given). 'MAT': the assembled \
              matrix in MatrixMarket format plus file.mtx.dofs (row node component); conditions are extra LX \
              rows with a single multiplier each. 'STL': the surface elements of a mesh as a binary STL named \
              by OPTI SORT (default gibi.stl), a QUA4 as two triangles. 'AVS': an AVS UCD ASCII file (OPTI SORT \
              name, .inp added) with the mesh (else the MCHAML's support, else the CHPOINT's nodes), the nodal \
              field (zero where it has no value), the element field (one value per element: CHAN 'GRAVITE') \
              and the time; 'SUIT' appends a structure to the file this run wrote. 'NAS': Nastran bulk data \
              (OPTI SORT name, .nas added): GRID (large fields) and element cards, one property id per sub-mesh. 'CHAI': the objects (words, numbers, texts) as one line \
              of text, written as MESS shows them, to the OPTI SORT file (kept as named); later calls append \
              while OPTI SORT names the same file. With a MAILLAGE and no keyword: the mesh under its variable name, with every \
              named mesh made of its elements, in gibi's own text format (OPTI SORT name, else fort.7), for LIRE.",
        example: "opti sort 'beam' ; sort 'VTK' s u 'DEPL' sig 'SIGMA' 'TEMPS' 1. ;",
        f: sort,
    },
    OpDef {
        name: "LIRE",
        signature: "LIRE (GEO1) | LIRE 'GMSH' 'file.msh' | LIRE 'STL' 'file.stl' | LIRE 'CSV' 'file' ('DEBU' line) ('SEPA' char) | LIRE 'AVS' | LIRE 'NAS' 'file' | LIRE 'PROC' 'file' ('NAME')",
        doc: "Read a Gmsh mesh (formats 2.2 and 4.1, ASCII; SEG2/3, TRI3/6, QUA4/8, TET4, PRI6, CUB8, POI1). \
              Returns a TABLE of MAILLAGE keyed by physical group name (by tag when unnamed), plus 'TOUT' for \
              every element. New nodes get coordinates in the current dimension (a non-zero z in DIME 2 is \
              an error). 'STL' (ASCII or binary): a MAILLAGE of TRI3, vertices with equal coordinates being one \
              node (STL keeps single precision). 'CSV': a TABLE of LISTREEL indexed 1..N, one per column, read \
              from line 'DEBU' on (default 1), fields separated by 'SEPA' (default ';'). 'AVS': the next AVS UCD \
              structure of the OPTI LECT file as a TABLE: MAILSUPP (every node, POI1), LEMAILLA (sub-meshes by \
              type and material), SOUMAILA (them, indexed 1..N), LECHPOIN (nodal data), LEMCHAML (element data) \
              and each global value under its label cut to 4 characters ('time' for the 'TEMP' of SORT 'AVS'). 'NAS': Nastran bulk data (small, large or free fields) \
              as a TABLE: MAILLAGES (a MAILLAGE per property id), BLOCAGES (POI1 per SPC/SPC1 set), FORCES, \
              MOMENTS, TEMPERATURES (a CHPOINT per set), RBE2 (per element a TABLE whose MAILLAGE has the \
              independent point first), SYSTEMES (empty: coordinate systems are not read). 'PROC' (a directive): \
              defines the procedures of a file in the `$$$$ NAME` format (all, or only NAME), the DEBPROCs of a \
              plain file, or, with none, the file's instructions as the procedure NAME. With no keyword (a directive): the meshes \
              SORT MAILLAGE wrote to the OPTI LECT file, each under its name (GEO1: the file must hold it).",
        example: "t = lire 'GMSH' 'plate.msh' ; s = t . 'PLATE' ; c = lire 'CSV' 'data.csv' 'DEBU' 2 'SEPA' ',' ;",
        f: lire,
    },
    OpDef {
        name: "TRAC",
        signature: "TRAC (CHPOINT) MAILLAGE… | TRAC MAILLAGE CHPOINT | TRAC CHPOINT | TRAC MMODEL MCHAML (MAILLAGE…) ('TITR' text) (device words)",
        doc: "Draw meshes (one colour each; a deformed mesh is `m PLUS (u * scale)`), a nodal field on its \
              mesh (the mesh just before it, else its own nodes when none follows), or an element field (VMIS, SIGM…: each element coloured by the mean of its points, the \
              model as its support) with a colour bar, as an SVG or PNG file (OPTI TRAC 'SVG'|'PNG'; other \
              devices such as PSC or X mean SVG). File: the OPTI SORT name, else gibi_trac_N. Option words, \
              numbers and VECT arrows are passed over; an object that cannot be drawn is an error; with no \
              file access allowed by the host, nothing is drawn.",
        example: "opti trac 'PNG' ; trac (exco u 'UY') s ; trac mo (vmis mo sig) ;",
        f: pictures::trac,
    },
    OpDef {
        name: "DESS",
        signature: "DESS EVOLUTIO… ('TITR' text) (options)",
        doc: "Draw curves as an SVG or PNG file, named like TRAC's. Unknown options are ignored.",
        example: "dess ev 'TITR' 'load-displacement' ;",
        f: pictures::dess,
    },
    OpDef {
        name: "VECT",
        signature: "VECT CHPOINT (SCALE) (comp…) (COLOUR) | VECT MCHAML MMODEL (SCALE) (comp…) (COLOUR)",
        doc: "An arrows object (type VECTEUR) for TRAC: the field, its scale, the components taken as the \
              vector's coordinates (default: the displacements or forces of the field) and a colour. gibi's \
              pictures do not draw arrows: TRAC draws the meshes given with it and passes over the VECTEUR, so \
              that decks which draw vectors still run.",
        example: "v = vect u 1.e3 'UX' 'UY' 'ROUG' ; trac v s ;",
        f: pictures::vect,
    },
];

fn io_err(e: io::IoError) -> Error {
    Error::io(e.0)
}

fn write_err(e: io::IoError) -> Error {
    Error::new(ErrorKind::Write, e.0)
}

/// One line per file written (unless the host turned them off), relative
/// to the directory the run may use: users see where their output went.
fn wrote(it: &mut Interp, path: &Path) {
    if it.report_files {
        let shown = it.files.display(path);
        it.println(&format!("wrote {}", shown));
    }
}

/// The file OPTI SORT names, else Cast3M's logical unit 7 ('fort.7').
fn sort_file(it: &Interp) -> String {
    it.opts.text("SORT").map(str::trim).filter(|s| !s.is_empty()).unwrap_or("fort.7").to_string()
}

/// The file OPTI LECT names; `what` (the operation) words the error when
/// none is named.
fn lect_file(it: &Interp, a: &Args, what: &str) -> Result<String> {
    it.opts
        .text("LECT")
        .map(|s| s.trim().to_string())
        .filter(|s| !s.is_empty())
        .ok_or_else(|| a.err(format!("{} reads the file named by OPTI LECT 'name', and none is named", what)))
}

/// The base name set by OPTI SORT, without a known extension.
fn sort_base(it: &Interp) -> Option<String> {
    base_of(it.opts.text("SORT")?)
}

/// A file name without a known extension (None when blank).
fn base_of(s: &str) -> Option<String> {
    let s = s.trim();
    if s.is_empty() {
        return None;
    }
    let lower = s.to_lowercase();
    let cut = [".vtu", ".pvd", ".svg", ".png", ".ps", ".eps", ".mif"]
        .iter()
        .find(|e| lower.ends_with(*e))
        .map_or(0, |e| e.len());
    Some(s[..s.len() - cut].to_string())
}

/// A path the script may write (its real path: see eval::FilePolicy),
/// with its directory created.
fn out_path(it: &Interp, name: &str) -> Result<PathBuf> {
    let p = it.files.check_write(name)?;
    if let Some(dir) = p.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir)
            .map_err(|e| Error::new(ErrorKind::Write, format!("cannot create {}: {}", dir.display(), e)))?;
    }
    Ok(p)
}

fn sort(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    const KINDS: [&str; 6] = ["VTK", "MAT", "STL", "AVS", "NAS", "CHAI"];
    if matches!(a.peek_right(), Some(Value::Mesh(_))) {
        return sort_mesh::sort(it, a);
    }
    match a.req_keyword(&KINDS)? {
        "VTK" => sort_vtk::sort_vtk(it, a),
        "CHAI" => sort_text::sort(it, a),
        "NAS" => nastran::sort(it, a),
        "AVS" => avs::sort(it, a),
        "STL" => stl::sort(it, a),
        _ => sort_matrix::sort_mat(it, a),
    }
}

fn lire(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    const KINDS: [&str; 6] = ["GMSH", "STL", "CSV", "AVS", "NAS", "PROC"];
    let Some(kind) = a.keyword(&KINDS) else {
        // Cast3M's other formats ('MED', 'FEM', 'UNV') are refused as
        // formats; any other word is the directive's mesh name.
        const OTHER_FORMATS: [&str; 3] = ["MED", "FEM", "UNV"];
        if let Some(Value::Mot(w)) = a.peek_right() {
            if OTHER_FORMATS.contains(&w.to_uppercase().as_str()) {
                a.req_keyword(&KINDS)?;
            }
        }
        return sort_mesh::lire(it, a);
    };
    match kind {
        "GMSH" => read_gmsh::lire(it, a),
        "PROC" => read_proc::lire(it, a),
        "NAS" => nastran::lire(it, a),
        "AVS" => avs::lire(it, a),
        "STL" => stl::lire(it, a),
        _ => read_csv::lire(it, a),
    }
}

/// New nodes for coordinates read from `file`, in the current dimension:
/// a coordinate the dimension drops must be zero. Returns the number of
/// the first. `label` names a node as the file numbers it.
fn add_nodes(
    it: &mut Interp,
    a: &Args,
    file: &str,
    coords: &[[f64; 3]],
    label: impl Fn(usize) -> String,
) -> Result<usize> {
    let dime = it.opts.dime;
    for (i, x) in coords.iter().enumerate() {
        if let Some(k) = (dime.max(1)..3).find(|&k| dime > 0 && x[k].abs() > 1e-9 * (1.0 + x[0].abs() + x[1].abs())) {
            return Err(a.err(format!(
                "{}: {} has {} = {} but OPTI DIME is {}",
                file,
                label(i),
                ["x", "y", "z"][k],
                x[k],
                dime
            )));
        }
    }
    let base = it.nodes.len();
    for x in coords {
        let mut p = *x;
        if dime > 0 {
            p[dime..].iter_mut().for_each(|c| *c = 0.0);
        }
        it.nodes.push(p, it.opts.dens);
    }
    Ok(base)
}
