//! Cast3M's catalogue: every name of its reference manual, as data.
//!
//! `catalogue.tsv` lists the operators, directives and procedures that
//! Cast3M's notices describe, one per line: kind, key, full name and the
//! section of the manual. It holds names only (facts), read from the
//! notices' headers by `scripts/dev/gen-catalogue.py`.
//!
//! A word is found in the catalogue the way Cast3M finds it: an operator
//! (or directive) by its first 4 letters, a procedure by its full name
//! (procedures are objects in Cast3M, so their names are not shortened).
//! What gibi does with a name it lacks is in [`super::unimplemented`].
//! The machine consults both (eval never names ops); their tests against
//! the standard registry are in `ops/catalogue_tests.rs`.

use super::registry::{op_key, Registry};
use rustc_hash::FxHashMap as HashMap;
use std::sync::OnceLock;

/// What a name is in Cast3M.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// An operator or a directive, matched on its first 4 letters.
    Operator,
    /// A procedure written in Gibiane (Cast3M's library), matched on its
    /// full name.
    Procedure,
}

/// One name of the catalogue.
#[derive(Debug)]
pub struct Entry {
    pub kind: Kind,
    /// What a word is matched on: the 4-letter key of an operator, the
    /// full name of a procedure.
    pub key: &'static str,
    /// The name the manual gives (`SAUVER` for the key `SAUV`).
    pub name: &'static str,
    /// The first word of the manual's section (Maillage, Mecanique, …).
    pub section: &'static str,
}

/// How gibi stands with a name of the catalogue (`gibi --list-operators`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Status {
    /// An operator of the registry, or a directive of the language.
    Implemented,
    /// A Cast3M operator gibi lacks: calling it stops the deck, named.
    Refused,
    /// A Cast3M procedure: loaded from a procedure library when one is
    /// given (gibi ships none), refused otherwise.
    Procedure,
}

impl Status {
    pub fn as_str(self) -> &'static str {
        match self {
            Status::Implemented => "implemented",
            Status::Refused => "refused",
            Status::Procedure => "procedure",
        }
    }
}

struct Catalogue {
    entries: Vec<Entry>,
    operators: HashMap<&'static str, usize>,
    procedures: HashMap<&'static str, usize>,
}

fn catalogue() -> &'static Catalogue {
    static CATALOGUE: OnceLock<Catalogue> = OnceLock::new();
    CATALOGUE.get_or_init(|| {
        let mut c = Catalogue { entries: Vec::new(), operators: HashMap::default(), procedures: HashMap::default() };
        for line in include_str!("catalogue.tsv").lines() {
            let mut f = line.split('\t');
            let (Some(kind), Some(key), Some(name)) = (f.next(), f.next(), f.next()) else { continue };
            let kind = match kind {
                "procedure" => Kind::Procedure,
                _ => Kind::Operator,
            };
            let map = match kind {
                Kind::Operator => &mut c.operators,
                Kind::Procedure => &mut c.procedures,
            };
            map.insert(key, c.entries.len());
            c.entries.push(Entry { kind, key, name, section: f.next().unwrap_or("") });
        }
        c
    })
}

/// Every name, sorted by key.
pub fn entries() -> &'static [Entry] {
    &catalogue().entries
}

/// The Cast3M operator a word names (by its first 4 letters).
pub fn operator(word: &str) -> Option<&'static Entry> {
    let c = catalogue();
    c.operators.get(op_key(word)).map(|&i| &c.entries[i])
}

/// The Cast3M procedure a word names (by its full name).
pub fn procedure(word: &str) -> Option<&'static Entry> {
    let c = catalogue();
    c.procedures.get(word).map(|&i| &c.entries[i])
}

/// The catalogue entry of a word that gibi cannot run: a procedure of that
/// full name first (as Cast3M finds procedures before operators), else an
/// operator of that key. `None` when the word is not a Cast3M name.
pub fn lookup(word: &str) -> Option<&'static Entry> {
    procedure(word).or_else(|| operator(word))
}

/// The directives the parser handles itself (blocks, procedures), which
/// the registry does not hold.
const LANGUAGE: &[&str] = &["SI", "SINO", "FINS", "REPE", "FIN", "ITER", "QUIT", "DEBP", "FINP", "ARGU", "RESP"];

/// Whether gibi implements a name of the catalogue.
pub fn status(e: &Entry, registry: &Registry) -> Status {
    match e.kind {
        Kind::Operator if LANGUAGE.contains(&e.key) || registry.find(e.key).is_some() => Status::Implemented,
        Kind::Operator => Status::Refused,
        Kind::Procedure if registry.find(e.key).is_some_and(|op| op.name == e.key) => Status::Implemented,
        Kind::Procedure => Status::Procedure,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn operators_by_four_letters_procedures_by_full_name() {
        assert_eq!(operator("SAUVER").map(|e| e.name), Some("SAUVER"));
        assert_eq!(operator("SAUV").map(|e| e.name), Some("SAUVER"));
        assert_eq!(procedure("PASAPAS").map(|e| e.kind), Some(Kind::Procedure));
        // A procedure is not found by a shortened name.
        assert!(procedure("PASA").is_none());
        assert!(lookup("PASA").is_none());
        assert!(lookup("TOTO").is_none());
    }

    #[test]
    fn keys_are_unique_and_operators_four_letters_at_most() {
        let mut seen = std::collections::HashSet::new();
        for e in entries() {
            assert!(seen.insert((e.kind == Kind::Operator, e.key)), "{} twice", e.key);
            if e.kind == Kind::Operator {
                assert!(e.key.chars().count() <= 4, "{}", e.key);
                assert!(e.name.starts_with(e.key), "{} / {}", e.key, e.name);
            }
        }
        assert!(entries().len() > 900);
    }
}
