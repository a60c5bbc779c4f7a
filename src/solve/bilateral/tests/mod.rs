//! Tests of the bilateral half. Each module's own tests sit here, named
//! after it and attached to it (`#[path]`, so they see its private items);
//! [`kit`] holds the small problems they share with the unilateral tests.

pub(crate) mod kit;
