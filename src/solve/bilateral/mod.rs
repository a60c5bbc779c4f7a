//! The bilateral half of the solver: equality conditions as doubled
//! Lagrange multipliers (Verpeaux & Charras 2011), factorised by a
//! pivot-free LDLᵀ on faer.
//!
//! * [`lagrange`]: the doubled system (u, λ1, λ2), its scaling and values;
//! * [`ordering`] (AMD, or METIS nested dissection in `nd`): the
//!   elimination order;
//! * [`linear`]: the sparse factorisations (supernodal LDLᵀ, LU for a
//!   non-symmetric operator) behind one interface;
//! * [`direct`]: RESO's direct solve, with the diagnosis of a singular
//!   system in unknown and condition numbers;
//! * [`pool`]: the last factorisations kept by the interpreter, and the
//!   policy that reuses them; [`rigid_modes`]: 'ENSE', a singular system
//!   solved with each free rigid mode held; [`redundant`]: conditions
//!   implied by others, dropped when their values agree;
//! * [`schur`]: the interrupted factorisation onto a trailing block (SUPER,
//!   and the unilateral condensations);
//! * [`eliminate`]: conditions eliminated by substitution instead (the
//!   iterative unilateral method needs a definite operator).

pub mod direct;
pub mod eliminate;
pub mod lagrange;
pub mod linear;
pub mod mult_masters;
mod nd;
pub mod ordering;
pub mod pool;
mod redundant;
mod refine;
pub mod rigid_modes;
pub mod schur;

#[cfg(test)]
pub(crate) mod tests;
