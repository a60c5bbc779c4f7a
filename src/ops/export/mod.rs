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

mod pictures;
pub(crate) use pictures::Vecteur;
mod read_gmsh;
mod sort_matrix;
mod sort_pasapas;
mod sort_vtk;
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
        f: read_gmsh::lire,
    },
    OpDef {
        name: "TRAC",
        signature: "TRAC (CHPOINT) MAILLAGE… | TRAC MMODEL MCHAML (MAILLAGE…) ('TITR' text) (device words)",
        doc: "Draw meshes (one colour each; a deformed mesh is `m PLUS (u * scale)`), a nodal field on its \
              mesh, or an element field (VMIS, SIGM…: each element coloured by the mean of its points, the \
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
    match a.req_keyword(&["VTK", "MAT"])? {
        "VTK" => sort_vtk::sort_vtk(it, a),
        _ => sort_matrix::sort_mat(it, a),
    }
}
