//! Language-free numerics for linear statics with conditions.
//!
//! This layer knows matrices, unknown numbers and condition rows, never the
//! Gibiane language: `scripts/check-layering.sh` fails if anything here
//! imports `syntax`, `value`, `eval` or `ops` (or `fem` and `io`).
//!
//! Two halves, over shared types:
//!
//! * [`problem`] and [`error`], shared: the data RESO hands over
//!   (stiffness, condition rows, loads), what comes back (displacements,
//!   multipliers, statuses), and what can go wrong, in unknown and
//!   condition numbers (the caller turns them into node and component
//!   names);
//! * [`bilateral`]: equality conditions, doubled multipliers, ordering,
//!   factorisation, elimination, static condensation;
//! * [`unilateral`]: MINI/MAXI conditions: the driver, the one status
//!   loop, and its backends (condensed, old method, sparse, iterative,
//!   non-symmetric), built on the bilateral half;
//! * [`numbering`] and [`cache`], shared: the numbering of a system over
//!   named unknowns, and what one object keeps between solves.
//!
//! `unilateral` uses `bilateral`, never the other way round.

pub mod assignment;
pub mod bilateral;
pub mod cache;
pub mod complex_modes;
pub mod eigen;
pub mod error;
pub mod mma;
pub mod numbering;
pub mod poly_roots;
pub mod problem;
pub mod simplex;
pub mod twins;
pub mod unilateral;

pub use bilateral::direct;
pub use bilateral::pool::FactorPool;
pub use bilateral::schur::{schur_onto, SchurOnto};
pub use cache::SolverCache;
pub use error::SolveError;
pub use numbering::{Assembled, LoadError};
pub use problem::{Condition, Kind, Load, Matrix, Problem, Solution};
