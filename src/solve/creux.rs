//! CREUX (placeholder).
use super::error::SolveError;
use super::problem::{Load, Problem, Solution};
use super::status::{IterRecord, StatusOptions};
use super::unilateral::{StatusError, UnilCache};

#[derive(Debug)]
pub(super) struct Creux;

pub(super) fn solve(
    _p: &Problem,
    _load: &Load,
    _uni: &[usize],
    _sopts: &StatusOptions,
    _cache: &mut UnilCache,
    _on_iter: &mut dyn FnMut(&IterRecord),
    _phases: &mut Vec<(&'static str, f64)>,
) -> Result<(Solution, Vec<bool>), StatusError> {
    Err(StatusError::Global(SolveError::Other("CREUX not available yet".into())))
}
