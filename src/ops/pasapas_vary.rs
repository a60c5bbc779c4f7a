//! PASAPAS with material properties that depend on a parameter (MATE …
//! 'YOUN' EVOLUTIO, the abscissa naming 'T' or any other variable): at
//! each step the properties are evaluated at the element points from the
//! CHARGEMENT's part of that name at the step's time, and the stiffness is
//! reassembled with them and refactorised on the same structure. The law stays elastic and total (σ = D(p(t)) ε), so a
//! step's result depends on its time only, not on the steps before.

use super::pasapas_model::{self as pmodel, Loads, Structure};
use super::Args;
use crate::analysis::stepper::Stepper;
use crate::error::Result;
use crate::eval::Interp;
use crate::value::{fmt_float, Chargement, Chpoint, Mchaml, Model, Rigidite};
use std::rc::Rc;

/// Whether some property of the material fields is a curve of a parameter.
pub(crate) fn is_varying(cara: &[Rc<Mchaml>]) -> bool {
    cara.iter().any(|m| m.zones.iter().any(|z| !z.laws.is_empty()))
}

/// The material fields with their curves evaluated at time `t`, the
/// parameters read from `charge`.
pub(crate) fn evaluated(
    it: &mut Interp,
    a: &Args,
    model: &Model,
    cara: &[Rc<Mchaml>],
    charge: Option<&Chargement>,
    t: f64,
) -> Result<Vec<Rc<Mchaml>>> {
    if !is_varying(cara) {
        return Ok(cara.to_vec());
    }
    let mut out = Vec::with_capacity(cara.len());
    for m in cara {
        let mut param = |name: &str| {
            let Some(ch) = charge.filter(|c| c.has(name)) else {
                return Err(a.err(format!(
                    "the material depends on {} (an EVOLUTIO): give its field in 'CHARGEMENT' (CHAR '{}' field evolution)",
                    name, name
                )));
            };
            super::chargement::at(it, a, ch, Some(name), t)
                .map_err(|e| a.err(format!("{} at time {}: {}", name, fmt_float(t), e.message)))
        };
        out.push(Rc::new(super::variable_fields::material_with(a, model, m, &mut param)?));
    }
    Ok(out)
}

/// The structure and its loads for the material at time `t`, `stepper`
/// refactorised for it (its contact statuses kept as the start).
#[allow(clippy::too_many_arguments)]
pub(crate) fn rebuild(
    it: &mut Interp,
    a: &Args,
    model: &Model,
    cara: &[Rc<Mchaml>],
    blocks: Option<&Rigidite>,
    charge: Option<&Chargement>,
    tref: &[f64],
    stepper: &mut Stepper,
    t: f64,
) -> Result<(Structure, Loads)> {
    let cara_t = evaluated(it, a, model, cara, charge, t)?;
    let s = pmodel::build(it, a, model, &cara_t, blocks)?;
    // Same mesh, same conditions: the factorisation keeps its structure
    // and only refactorises the numbers (Stepper::renew).
    stepper
        .renew(s.asm.problem.clone())
        .map_err(|e| a.err(format!("time {}: the stiffness cannot be factorised: {:?}", fmt_float(t), e)))?;
    stepper.set_adhesion(&s.adhesion).map_err(|e| a.err(format!("'ADHE': {}", e)))?;
    let tref_field = Chpoint::from_entries(
        crate::value::Nature::Diffus,
        tref.iter().enumerate().filter(|(_, v)| **v != 0.0).map(|(n, v)| (n, "T", *v)),
    );
    let loads = pmodel::loads(it, a, &s, charge, Some(&tref_field))?;
    Ok((s, loads))
}
