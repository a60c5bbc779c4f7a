//! CHARGEMENT: loads described in space and time (CHAR), evaluated by
//! TIRE and PASAPAS.

use super::Value;
use crate::analysis::history::TimeFunction;

/// Elementary loads, in the order they were joined with `ET`.
#[derive(Debug, Clone, Default)]
pub struct Chargement {
    pub parts: Vec<LoadPart>,
}

/// One elementary load: a name PASAPAS reads it by ('MECA' forces, 'DIMP'
/// imposed values, 'T' temperatures, any other word for variables the
/// material may depend on), and its description in space and time.
#[derive(Debug, Clone)]
pub struct LoadPart {
    /// Upper case, at most 4 letters as Cast3M keeps it; empty when CHAR
    /// was given no name.
    pub name: String,
    pub time: Timing,
}

#[derive(Debug, Clone)]
pub enum Timing {
    /// A field (CHPOINT or MCHAML) scaled by a time function.
    Scaled { field: Value, function: TimeFunction },
    /// Fields given at times (`CHAR TAB1 TAB2`), linear in between.
    Table(Vec<(f64, Value)>),
}

impl LoadPart {
    /// The fields and their weights at time `t`: one field, or the two
    /// around `t` for the table form. Err names the times covered.
    pub fn weights(&self, t: f64) -> Result<Vec<(f64, &Value)>, String> {
        match &self.time {
            Timing::Scaled { field, function } => Ok(vec![(function.at(t).map_err(|e| e.to_string())?, field)]),
            Timing::Table(steps) => {
                let (first, last) = (steps[0].0, steps[steps.len() - 1].0);
                let tol = 1e-12 * first.abs().max(last.abs()).max(1.0);
                if !(t >= first - tol && t <= last + tol) {
                    return Err(format!("time {t} is outside the times of the table, {first} to {last}"));
                }
                let k = steps.partition_point(|(x, _)| *x <= t).max(1) - 1;
                if k + 1 >= steps.len() || (steps[k].0 - t).abs() <= tol {
                    return Ok(vec![(1.0, &steps[k].1)]);
                }
                let (t0, t1) = (steps[k].0, steps[k + 1].0);
                let w = (t - t0) / (t1 - t0);
                Ok(vec![(1.0 - w, &steps[k].1), (w, &steps[k + 1].1)])
            }
        }
    }
}

impl Chargement {
    /// Whether an elementary load of this name exists (4-letter names,
    /// trailing blanks ignored).
    pub fn has(&self, name: &str) -> bool {
        self.parts.iter().any(|p| p.name == name)
    }
}
