//! ITER (placeholder).
use super::error::SolveError;
use super::problem::{Load, Problem, Solution};
use super::status::{IterRecord, StatusOptions};
use super::unilateral::StatusError;

pub(super) fn solve(
    _p: &Problem,
    _load: &Load,
    _uni: &[usize],
    _sopts: &StatusOptions,
    _on_iter: &mut dyn FnMut(&IterRecord),
    _phases: &mut Vec<(&'static str, f64)>,
) -> Result<(Solution, Vec<bool>), StatusError> {
    Err(StatusError::Global(SolveError::Other("ITER not available yet".into())))
}
