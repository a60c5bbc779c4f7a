//! Tests of the unilateral half. Each module's own tests sit here, named
//! after it and attached to it (`#[path]`, so they see its private items);
//! the suites that cross modules are declared below: the status loop on
//! dense problems ([`kit`]), the driver, and every method against CONDENSE
//! and against brute force.

pub(crate) mod kit;

mod driver;
mod methods;
mod methods_props;
mod status;
mod status_loop;
mod status_props;
