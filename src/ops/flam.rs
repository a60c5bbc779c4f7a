//! FLAM (flam.notice): hydrogen combustion over one time step, point by
//! point, for the forms whose rate the notice states in full: 'ARRHENIU'
//! (ω = A T^−b ρH2^c ρO2 exp(−Ta/T) above a threshold) and 'HEAVYSID'
//! (infinitely fast above it). The numerics are in `fem::combustion`; this
//! file reads the fields and walks the points of the threshold field.
//! 'LAMINAIR' (its constants are "predefined" but not given), 'EBU' (the
//! energy update is not stated) and 'CREBCOM' (the criterion is not given)
//! are refused.

use super::{Args, Num, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::combustion::{self, Arrhenius, Formation, Mixture};
use crate::value::{Chpoint, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "FLAM",
    signature: "FLAM 'ARRHENIU' TS A B C TA H0H2 H0O2 H0H2O DT RH2 RO2 RH2O T | FLAM 'HEAVYSID' TS H0H2 H0O2 H0H2O RH2 RO2 RH2O T",
    doc: "Burns hydrogen by 2 H2 + O2 -> 2 H2O at each point of the threshold temperature field TS ('SCAL'), where the temperature T ('SCAL') exceeds it. RH2, RO2, RH2O are the partial densities (components 'H2', 'O2', 'H2O'); H0H2 H0O2 H0H2O the energies of formation at 0 K (J/kg). 'HEAVYSID' burns the species in defect completely; 'ARRHENIU' integrates the molar rate A T^-B RH2^C RO2 exp(-TA/T) over the step DT (linearly implicit on the species in defect). Gives the new partial densities and the heat released per volume ('SCAL').",
    example: "p = 0. 0. ; m = manu poi1 p ; ts = manu chpo m 1 'SCAL' 1000. ; t = manu chpo m 1 'SCAL' 1500. ; rh = manu chpo m 1 'H2' 0.01 ; ro = manu chpo m 1 'O2' 0.2 ; rw = manu chpo m 1 'H2O' 0. ; a b c q = flam 'HEAVYSID' ts 0. 0. -1.4e7 rh ro rw t ;",
    f: flam,
}];

const FORMS: &[&str] = &["ARRHENIU", "HEAVYSID", "LAMINAIR", "EBU", "CREBCOM", "CREBCOM2"];

fn flam(_it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let form = a.word().map(|w| w.trim().to_uppercase()).ok_or_else(|| a.missing("one of 'ARRHENIU' 'HEAVYSID'"))?;
    // 'CREBCOM' and 'CREBCOM2' share their first four letters: whole words.
    let form = match FORMS.iter().find(|f| **f == form || (form.len() == 4 && f.starts_with(&form))) {
        Some(f) => *f,
        None => return Err(a.err(format!("unknown form '{}' (expected 'ARRHENIU' or 'HEAVYSID')", form))),
    };
    let ts: Rc<Chpoint> = a.req()?;
    let law = if form == "ARRHENIU" {
        Some(Arrhenius { a: num(a)?, b: num(a)?, c: num(a)?, ta: num(a)? })
    } else if form == "HEAVYSID" {
        None
    } else {
        return Err(a.err(format!(
            "the form '{}' of FLAM is not implemented in gibi (its notice does not give the whole law)",
            form
        )));
    };
    let h0 = Formation { h2: num(a)?, o2: num(a)?, h2o: num(a)? };
    let dt = if law.is_some() { num(a)? } else { 0.0 };
    if !dt.is_finite() || dt < 0.0 {
        return Err(a.err(format!("the time step must be finite and not negative, found {}", dt)));
    }
    let (rh2, ro2, rh2o, t): (Rc<Chpoint>, Rc<Chpoint>, Rc<Chpoint>, Rc<Chpoint>) =
        (a.req()?, a.req()?, a.req()?, a.req()?);
    let mut out: Vec<Chpoint> = (0..4).map(|_| Chpoint::new(ts.nature)).collect();
    for &n in &ts.nodes {
        let m = Mixture {
            h2: value_at(a, &rh2, "H2 density", n, "H2")?,
            o2: value_at(a, &ro2, "O2 density", n, "O2")?,
            h2o: value_at(a, &rh2o, "H2O density", n, "H2O")?,
        };
        let threshold = value_at(a, &ts, "threshold temperature", n, "SCAL")?;
        let temp = value_at(a, &t, "temperature", n, "SCAL")?;
        let res = match &law {
            Some(law) => combustion::arrhenius(&m, temp, threshold, law, &h0, dt),
            None => combustion::heaviside(&m, temp, threshold, &h0),
        };
        let (r, q) = res.map_err(|e| a.err(format!("at node {}: {}", n + 1, e)))?;
        for (c, (comp, v)) in out.iter_mut().zip([("H2", r.h2), ("O2", r.o2), ("H2O", r.h2o), ("SCAL", q)]) {
            c.add(n, comp, v, false);
        }
    }
    Ok(out.into_iter().map(|c| Value::Chpo(Rc::new(c))).collect())
}

fn num(a: &mut Args) -> Result<f64> {
    let x = a.opt_with(Num::accept).map(|n| n.0).ok_or_else(|| a.missing("FLOTTANT"))?;
    if !x.is_finite() {
        return Err(a.err(format!("the constants must be finite, found {}", x)));
    }
    Ok(x)
}

/// The value of a one-component field at a node; its component is taken
/// whatever its name when it is the only one.
fn value_at(a: &Args, c: &Chpoint, what: &str, node: usize, comp: &str) -> Result<f64> {
    let name = if c.comps.len() == 1 { c.comps[0].as_str() } else { comp };
    c.get(node, name).ok_or_else(|| {
        a.err(format!(
            "the {} has no component '{}' at node {}: the fields must share the support of the threshold field",
            what,
            comp,
            node + 1
        ))
    })
}
