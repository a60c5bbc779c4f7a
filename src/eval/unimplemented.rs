//! Cast3M names that gibi does not implement: how they are refused.
//!
//! Every name of Cast3M's catalogue ([`super::catalogue`]) that gibi lacks
//! stops the deck where the deck *calls* it, by its full name and with
//! what gibi offers instead. Without this a name would be an unknown word,
//! hence a MOT (language.md §2.2): `SAUV l ;` would run silently and
//! `y = DYNE k m 3 ;` would fail far away with "3 results for 1 name(s)".
//!
//! A refused name is refused only where it would run: as the operator of
//! an instruction or a group. Where an operator reads its arguments it
//! stays a plain word, so the many Cast3M names that decks write unquoted
//! as keywords (`BLOQ DEPL p`, `OPTI SAUV 'f'`, `MODE l MECANIQUE …`)
//! keep working, and it never hides an object or a procedure of that name.

use super::catalogue::{self, Entry, Kind};
use super::registry::Registry;
use crate::error::Error;

const STATICS: &str =
    "gibi solves linear statics: RIGI, BLOQ/RELA, RESO (UNIL for unilateral conditions), and PASAPAS on elastic structures with contact";
const FILES: &str = "gibi writes with SORT 'VTK' (ParaView), 'AVS', 'NAS', 'STL', 'MAT' and reads with LIRE 'GMSH', 'AVS', 'NAS', 'STL', 'CSV', 'PROC'";
const MESHING: &str = "gibi meshes with DROI, CERC, DALL, SURF, REGL, COUT, TRAN, ROTA, VOLU, SYME, PLUS, ELIM and ET";
const POST: &str = "gibi post-processes with SIGM, EPSI, VMIS, PRIN, EXTR, EVOL, INTG, and draws with TRAC and DESS";
const OTHER: &str = "`gibi --list-operators` lists what gibi implements";

/// Pointers for particular names, by key (what the name's section says is
/// often too vague for them).
pub(crate) const HINTS: &[(&str, &str)] = &[
    ("DYNAMIC", STATICS),
    ("DYNE", STATICS),
    ("ECOU", STATICS),
    ("EXCI", "UNIL runs the unilateral status iteration natively"),
    ("FLUX", STATICS),
    ("MREM", "RESO and UNIL re-insert eliminated unknowns themselves"),
    ("OBTE", FILES),
    ("PJBA", STATICS),
    ("RECO", STATICS),
    ("REST", FILES),
    ("SAUV", FILES),
];

/// What gibi offers instead of a name, from the section of the manual it
/// belongs to.
fn hint(e: &Entry) -> &'static str {
    if let Some((_, h)) = HINTS.iter().find(|(k, _)| *k == e.key) {
        return h;
    }
    match e.section {
        "Maillage" => MESHING,
        "Mecanique" | "Mechanics" => STATICS,
        "Post-traitement" => POST,
        "Entree-Sortie" => FILES,
        "Thermique" => "gibi's thermal side is steady conduction (MODE 'THERMIQUE', COND, CAPA, RESO) and thermal loading (EPTH turns a temperature field into strains)",
        _ => OTHER,
    }
}

/// Why a name of the catalogue cannot run. `library` says whether a
/// procedure library was given (a procedure is then refused only because
/// the library lacks it).
pub fn message(e: &Entry, library: bool) -> Error {
    match e.kind {
        Kind::Operator => {
            Error::runtime(format!("{} is a Cast3M operator that gibi does not implement", e.name)).note(hint(e))
        }
        Kind::Procedure if library => Error::runtime(format!(
            "{} is a Cast3M procedure that gibi does not implement, and the procedure library does not hold it",
            e.name
        ))
        .note(hint(e)),
        Kind::Procedure => {
            let e0 = Error::runtime(format!("{} is a Cast3M procedure that gibi does not implement", e.name));
            match HINTS.iter().find(|(k, _)| *k == e.key) {
                Some((_, h)) => e0.note(*h),
                None => e0,
            }
            .note(
                "gibi ships none of Cast3M's procedures: give a procedure library with GIBI_PROCEDURES or \
                 --procedures (Cast3M's procedur/ folder, or a file of $$$$ NAME procedures) to load them",
            )
        }
    }
}

/// The refusal for a word standing where it would run, if the word is a
/// Cast3M name that the registry does not implement.
pub fn refusal(word: &str, registry: &Registry, library: bool) -> Option<Error> {
    if registry.find(word).is_some() {
        return None;
    }
    catalogue::lookup(word).map(|e| message(e, library))
}
