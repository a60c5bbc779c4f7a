//! PASAPAS with 'DYNAMIQUE' VRAI, the table side: the mass (MASS of the
//! mechanical zones, plus 'MASSE_CONSTANTE') and the damping
//! ('AMORTISSEMENT') on the run's numbering, the initial state
//! ('VITESSES'.0, 'ACCELERATIONS'.0, or the CONTINUATION of a previous
//! run) and the state as fields. The scheme is `analysis::dynamics`.

use super::dofs::dual_of;
use super::pasapas_model::{self as pmodel, Loads, Structure};
use super::Args;
use crate::analysis::dynamics::{matvec, Newmark};
use crate::error::Result;
use crate::eval::Interp;
use crate::solve::Matrix;
use crate::value::{Chpoint, Key, Mchaml, Model, Nature, Rigidite, Table, Value};
use rustc_hash::FxHashMap as HashMap;
use std::cell::RefCell;
use std::rc::Rc;

type Tab = Rc<RefCell<Table>>;

fn get(t: &Tab, k: &str) -> Option<Value> {
    t.borrow().get(&Key::Mot(k.to_string())).cloned()
}

/// A RIGIDITE (mass, damping) as a matrix on the unknowns of `s`; its
/// unknowns must all be unknowns of the structure.
fn on_numbering(a: &Args, s: &Structure, r: &Rigidite, what: &str) -> Result<Matrix> {
    let index: HashMap<(usize, &str), usize> =
        s.asm.dofs.iter().enumerate().map(|(i, (n, c))| ((*n, c.as_str()), i)).collect();
    let mut entries = Vec::new();
    let mut symmetric = true;
    for b in &r.blocks {
        symmetric &= b.symmetry == crate::value::rigidity::Symmetry::Symmetric;
        let nd = b.ndof();
        let mut idx = vec![0usize; nd];
        for e in 0..b.n_elem() {
            let conn = &b.conn[e * b.nodes_per_elem..(e + 1) * b.nodes_per_elem];
            for (i, (l, c)) in b.dofs.iter().enumerate() {
                idx[i] = *index.get(&(conn[*l], c.as_str())).ok_or_else(|| {
                    a.err(format!(
                        "{} acts on {} of node {}, which the model's stiffness does not hold",
                        what, c, conn[*l]
                    ))
                })?;
            }
            let m = b.mat(e);
            for i in 0..nd {
                for j in 0..nd {
                    if m[i * nd + j] != 0.0 {
                        entries.push((idx[i], idx[j], m[i * nd + j]));
                    }
                }
            }
        }
    }
    if !r.conds.is_empty() {
        return Err(a.err(format!("{} holds conditions: give them in 'BLOCAGES_MECANIQUES'", what)));
    }
    Ok(Matrix { n: s.asm.problem.k.n, entries, symmetric })
}

/// The mass and damping of a dynamic run, its state still at rest.
pub(crate) fn newmark(
    it: &Interp,
    a: &Args,
    tab: &Tab,
    s: &Structure,
    model: &Model,
    cara: &[Rc<Mchaml>],
) -> Result<Newmark> {
    let (mech, _) = pmodel::split(model);
    let mech = Model { zones: mech.into_iter().cloned().collect(), ties: model.ties.clone() };
    let mass = match super::post::model_mass(it, Rc::new(mech), cara.to_vec(), false)
        .map_err(|e| a.err(format!("'DYNAMIQUE': the mass of the model: {}", e.message)))?
        .pop()
    {
        Some(Value::Rigi(r)) => r,
        _ => return Err(a.err("'DYNAMIQUE': the model gives no mass")),
    };
    let mut m = on_numbering(a, s, &mass, "the mass")?;
    let rigi = |k: &str| -> Result<Option<Rc<Rigidite>>> {
        match get(tab, k) {
            Some(Value::Rigi(r)) => Ok(Some(r)),
            None => Ok(None),
            Some(v) => Err(a.err(format!("'{}' must be a RIGIDITE, not a {}", k, v.type_name()))),
        }
    };
    if let Some(r) = rigi("MASSE_CONSTANTE")? {
        let extra = on_numbering(a, s, &r, "'MASSE_CONSTANTE'")?;
        m.entries.extend(extra.entries);
        m.symmetric &= extra.symmetric;
    }
    let c = rigi("AMORTISSEMENT")?.map(|r| on_numbering(a, s, &r, "'AMORTISSEMENT'")).transpose()?;
    let n = m.n;
    Ok(Newmark::new(m, c, vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]))
}

/// The values of a field on the unknowns of `s` (0 where it has none);
/// `dual` reads the force names (FX for UX).
fn vector(s: &Structure, c: &Chpoint, dual: bool) -> Vec<f64> {
    s.asm
        .dofs
        .iter()
        .map(|(n, comp)| {
            let name = if dual { dual_of(comp) } else { comp.clone() };
            c.get(*n, &name).unwrap_or(0.0)
        })
        .collect()
}

/// The state at the start, from CONTINUATION (a fresh run put the table's
/// index 0 there): displacements, velocities, accelerations; the
/// inertial force kept by a previous run ('FREA1' of WTABLE), else the
/// equilibrium residual F(t₀) − K u₀.
pub(crate) fn initial(a: &Args, tab: &Tab, s: &Structure, loads: &Loads, t0: f64, nm: &mut Newmark) -> Result<()> {
    let conti = match get(tab, "CONTINUATION") {
        Some(Value::Table(c)) => c,
        _ => return Ok(()),
    };
    let read = |k: &str| match get(&conti, k) {
        Some(Value::Chpo(c)) => Some(vector(s, &c, false)),
        _ => None,
    };
    let n = nm.u.len();
    nm.u = read("DEPLACEMENTS").unwrap_or_else(|| vec![0.0; n]);
    nm.v = read("VITESSES").unwrap_or_else(|| vec![0.0; n]);
    nm.a = read("ACCELERATIONS").unwrap_or_else(|| vec![0.0; n]);
    let kept = match get(tab, "WTABLE") {
        Some(Value::Table(w)) => match w.borrow().get(&Key::Mot("FREA1".into())) {
            Some(Value::Chpo(c)) => Some(vector(s, c, true)),
            _ => None,
        },
        _ => None,
    };
    nm.r = match kept {
        Some(r) => r,
        None => {
            let f = loads.history.at(t0).map_err(|e| a.err(format!("CHARGEMENT at the start: {}", e)))?.f;
            let ku = matvec(&s.asm.problem.k, &nm.u);
            let residual = f.iter().zip(ku).map(|(f, k)| f - k).collect();
            nm.start_from(&s.asm.problem.conditions, residual);
            nm.r.clone()
        }
    };
    Ok(())
}

/// A vector on the unknowns as a field of the primal names (velocities,
/// accelerations) or of their duals (forces).
pub(crate) fn field(s: &Structure, x: &[f64], dual: bool) -> Chpoint {
    let mut out = Chpoint::new(if dual { Nature::Discret } else { Nature::Diffus });
    for ((n, c), v) in s.asm.dofs.iter().zip(x) {
        let name = if dual { dual_of(c) } else { c.clone() };
        out.add(*n, &name, *v, false);
    }
    out
}

/// The first step's length: from `t0` to the first time after it (1 when
/// there is none: no step will use it).
pub(crate) fn first_step(times: &[f64], t0: f64) -> f64 {
    let next = times.iter().copied().filter(|t| *t > t0 && !super::pasapas::close(*t, t0)).fold(f64::NAN, f64::min);
    if next.is_nan() {
        1.0
    } else {
        next - t0
    }
}

/// Velocities and accelerations at index 0: the table's, else zero.
pub(crate) fn given_or_zero(tab: &Tab, s: &Structure, k: &str) -> Value {
    if let Some(Value::Table(t)) = get(tab, k) {
        if let Some(v @ Value::Chpo(_)) = t.borrow().get(&Key::Int(0)) {
            return v.clone();
        }
    }
    Value::Chpo(Rc::new(field(s, &vec![0.0; s.asm.dofs.len()], false)))
}
