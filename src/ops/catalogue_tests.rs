//! The catalogue and the refusals (`eval::catalogue`, `eval::unimplemented`)
//! against the standard registry, which only ops can build.

use super::Registry;
use crate::eval::catalogue::{lookup, status, Status};
use crate::eval::unimplemented::{refusal, HINTS};

#[test]
fn statuses() {
    let r = Registry::standard();
    let st = |w: &str| status(lookup(w).unwrap(), &r);
    assert_eq!(st("RESO"), Status::Implemented);
    assert_eq!(st("SI"), Status::Implemented);
    assert_eq!(st("DYNE"), Status::Refused);
    assert_eq!(st("MAILSTRU"), Status::Procedure);
    // PASAPAS is a procedure in Cast3M and an operator in gibi.
    assert_eq!(st("PASAPAS"), Status::Implemented);
    // JEU is a procedure in Cast3M and an operator in gibi.
    assert_eq!(st("JEU"), Status::Implemented);
}

#[test]
fn hints_name_catalogue_operators_gibi_lacks() {
    let r = Registry::standard();
    for (k, _) in HINTS {
        let e = lookup(k).unwrap_or_else(|| panic!("{} is not in the catalogue", k));
        assert!(r.find(k).is_none(), "{} is implemented", k);
        assert_eq!(e.key, *k);
    }
}

#[test]
fn refusals_use_the_full_name() {
    let r = Registry::standard();
    let e = refusal("DYNE", &r, false).unwrap();
    assert_eq!(e.message, "DYNE is a Cast3M operator that gibi does not implement");
    assert!(refusal("RESO", &r, false).is_none());
    assert!(refusal("TOTO", &r, false).is_none());
    assert!(refusal("PASAPAS", &r, false).is_none());
    let p = refusal("MAILSTRU", &r, false).unwrap();
    assert!(p.notes.iter().any(|n| n.contains("GIBI_PROCEDURES")));
}
