//! Cast3M operators and procedures that gibi does not implement.
//!
//! Without this table such a word would be an unknown word, hence a MOT
//! (language.md §2.2): `SAUV l ;` would run silently and
//! `y = VIBR k m 3 ;` would fail far away with "3 results for 1 name(s)".
//! Registered as operators that always fail, they stop the deck where the
//! deck calls them, naming the operator. A stub never shadows an operator
//! that exists (see [`super::Registry::standard`]), so implementing one of
//! these names only means adding it to its family table.
//!
//! Names that decks commonly write unquoted as *keywords* of other
//! operators (DEPL, COMP, FORM, PLAS, CONV, THERMIQUE …) are left out on
//! purpose: as operators they would stop `BLOQ DEPL p`-like calls that
//! read them as words. Harmless directives (MENAGE, INFO) are left out too:
//! a deck that calls them loses nothing when they are ignored.

use super::{Args, OpDef};
use crate::error::{Error, Result};
use crate::eval::Interp;
use crate::value::Value;

/// What a name is in Cast3M.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    Operator,
    Procedure,
}

/// One missing name: the 4-letter key a word is matched on (a procedure is
/// matched on its first 4 letters too, like every operator word), the full
/// Cast3M name, what it is, and an optional pointer to what gibi offers.
pub struct Missing {
    pub key: &'static str,
    pub name: &'static str,
    pub kind: Kind,
    pub hint: &'static str,
}

const fn op(key: &'static str, name: &'static str, hint: &'static str) -> Missing {
    Missing { key, name, kind: Kind::Operator, hint }
}

const fn proc(key: &'static str, name: &'static str, hint: &'static str) -> Missing {
    Missing { key, name, kind: Kind::Procedure, hint }
}

const STATICS: &str = "gibi solves linear statics: RIGI, BLOQ/RELA, RESO (UNIL for unilateral conditions)";
const FILES: &str = "gibi writes results with SORT 'VTK' (ParaView) and reads meshes with LIRE 'GMSH'";
const MESHING: &str = "gibi meshes with DROI, CERC, DALL, TRAN, ROTA, VOLU, SYME, PLUS, ELIM and ET";

/// The table, sorted by key.
pub const MISSING: &[Missing] = &[
    op("ACQU", "ACQUERIR", "read data with LIRE"),
    op("AMOR", "AMORTISSEMENT", STATICS),
    op("CALP", "CALP", "SIGM gives the beam resultants EFFX … MOMZ"),
    op("CAPA", "CAPACITE", STATICS),
    op("COND", "CONDUCTIVITE", STATICS),
    op("DOMA", "DOMAINE", ""),
    proc("DYNA", "DYNAMIC", STATICS),
    op("DYNE", "DYNE", STATICS),
    op("ECOU", "ECOULEMENT", STATICS),
    op("EQEX", "EQEX", ""),
    op("EQPR", "EQPR", ""),
    op("EXCI", "EXCITER", "UNIL runs the unilateral status iteration natively"),
    op("FLUX", "FLUX", STATICS),
    op("GRAD", "GRADIENT", "EPSI gives strains"),
    op("HOOK", "HOOKE", ""),
    proc("INCR", "INCREME", STATICS),
    op("ISOV", "ISOVALEUR", ""),
    op("KCHA", "KCHA", ""),
    op("KCHT", "KCHT", ""),
    op("KSIG", "KSIGMA", STATICS),
    op("MREM", "MREM", "RESO and UNIL re-insert eliminated unknowns themselves"),
    op("NUAG", "NUAGE", ""),
    op("OBTE", "OBTENIR", FILES),
    op("PAVE", "PAVER", MESHING),
    op("PJBA", "PJBA", STATICS),
    op("PROI", "PROI", ""),
    op("RACC", "RACCORDER", MESHING),
    op("RECO", "RECOMBINER", STATICS),
    op("REGL", "REGLER", MESHING),
    op("REST", "RESTITUER", FILES),
    op("SAUV", "SAUVER", FILES),
    op("VARI", "VARIABLE", ""),
    op("VIBR", "VIBRATION", STATICS),
];

/// The message for a missing name, as written in the deck.
pub fn message(m: &Missing) -> Error {
    let what = match m.kind {
        Kind::Operator => "operator",
        Kind::Procedure => "procedure",
    };
    let e = Error::runtime(format!("{} is a Cast3M {} that gibi does not implement", m.name, what));
    if m.hint.is_empty() {
        e
    } else {
        e.note(m.hint)
    }
}

/// The body every stub shares: find its row by the key it is registered
/// under, and fail.
fn stub(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    match MISSING.iter().find(|m| m.key == a.op.name) {
        Some(m) => Err(message(m)),
        None => Err(Error::runtime(format!("{} is a Cast3M name that gibi does not implement", a.op.name))),
    }
}

/// The stubs as operator rows (not part of the manual: `Registry::all`
/// lists only what gibi implements).
pub(crate) fn ops() -> impl Iterator<Item = OpDef> {
    MISSING.iter().map(|m| OpDef {
        name: m.key,
        // Not a bare name: an operator whose signature is its name alone
        // takes no argument and is evaluated wherever it is met (PI), which
        // would stop `OPTI SAUV 'f'` at the key SAUV.
        signature: "(no usage: a Cast3M name that gibi does not implement)",
        doc: "A Cast3M name that gibi does not implement.",
        example: "",
        f: stub,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_are_sorted_unique_and_four_letters_at_most() {
        for w in MISSING.windows(2) {
            assert!(w[0].key < w[1].key, "{} before {}", w[0].key, w[1].key);
        }
        for m in MISSING {
            assert!(m.key.len() <= 4 && m.name.starts_with(m.key), "{} / {}", m.key, m.name);
        }
    }

    #[test]
    fn no_stub_names_an_operator_gibi_has() {
        let r = super::super::Registry::standard();
        for m in MISSING {
            let op = r.find(m.key).unwrap();
            assert_eq!(op.doc, "A Cast3M name that gibi does not implement.", "{} is implemented", m.key);
        }
    }
}
