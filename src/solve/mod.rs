//! Language-free numerics for linear statics with conditions.
//!
//! This layer knows matrices, unknown numbers and condition rows, never the
//! Gibiane language: `scripts/check-layering.sh` fails if anything here
//! imports `syntax`, `eval`, `ops` or `value`.
//!
//! * [`problem`]: the data RESO hands over (stiffness, condition rows, loads)
//!   and what comes back (displacements, multipliers, statuses).
//! * [`error`]: what can go wrong, in terms of unknown and condition numbers
//!   (the caller turns them into node and component names).
//! * [`lagrange`], [`ordering`] (AMD, or METIS nested dissection in `nd`),
//!   [`linear`], [`direct`]: the doubled-multiplier system of Verpeaux &
//!   Charras and its pivot-free LDLᵀ on faer.
//! * [`condense`]: the interrupted factorisation onto the second multipliers
//!   of the unilateral conditions, normally with the border kept out of the
//!   sparse factor (`bordered`), and onto chosen unknowns (SUPER).
//! * [`status`]: the status (active-set) iteration on the condensed operator.
//! * [`unilateral`]: the UNIL driver choosing among the methods: CONDENSE
//!   (above), ANCIEN (`uni_ancien`: Guyan condensation onto the contact
//!   unknowns and [`ancien`]), CREUX (`creux`: the status iteration on the
//!   sparse system, for conditions on most unknowns) and ITER (`iter`: G by
//!   preconditioned CG, no factorisation).

pub mod ancien;
mod bordered;
pub mod condense;
pub mod condensed_op;
mod creux;
pub mod dense_ldlt;
pub mod direct;
mod eliminate;
pub mod error;
pub mod groups;
mod iter;
pub mod lagrange;
pub mod linear;
mod nd;
pub mod nonsym;
pub mod ordering;
pub mod problem;
pub mod status;
mod uni_ancien;
#[doc(hidden)]
pub mod unilateral;

#[cfg(test)]
mod methods_props;
#[cfg(test)]
mod methods_tests;
#[cfg(test)]
mod status_loop_tests;
#[cfg(test)]
mod status_props;
#[cfg(test)]
mod status_testkit;
#[cfg(test)]
mod status_tests;

pub use error::SolveError;
pub use problem::{Condensed, Condition, Kind, Load, Matrix, Problem, Solution};
