//! Incremental analysis below the language: the step driver PASAPAS runs.
//!
//! Like `fem` and `solve`, this layer never sees Gibiane objects
//! (`scripts/check-layering.sh`): it works on numbered unknowns, condition
//! rows, element sets and load vectors. The operator side translates the
//! PASAPAS table into these and the results back into fields.
//!
//! * [`history`]: time functions and loads as functions of time.
//! * [`body`]: element sets on numbered unknowns; strains, stresses and
//!   thermal forces through the [`material`] seam (elasticity today).
//! * [`dynamics`]: Newmark's average acceleration over the stepper.
//! * [`stepper`]: the operator factorised once, one load per step, the
//!   contact statuses carried from step to step.
pub mod body;
pub mod dynamics;
pub mod history;
pub mod material;
pub mod stepper;
