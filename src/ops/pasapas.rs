//! PASAPAS: Cast3M's incremental procedure, natively, for elastic
//! structures with contact (pasapas.notice). This file follows the table
//! protocol; the numbers are computed by `analysis` (the step driver) from
//! the structure `pasapas_model` builds, and turned back into objects by
//! `pasapas_fields`.
//!
//! The protocol, as Cast3M's procedure keeps it:
//! * inputs: 'MODELE', 'CARACTERISTIQUES', 'BLOCAGES_MECANIQUES',
//!   'RIGIDITE_CONSTANTE', 'CHARGEMENT', 'TEMPS_CALCULES', 'TEMPS_SAUVES'
//!   (default: every time computed), 'TEMPERATURES' (its index 0 is the
//!   reference temperature, as is 'TEMPERATURE_REFERENCE');
//! * results in tables indexed 0 1 2 …, one index per saved time, 0 being
//!   the initial state: 'TEMPS', 'DEPLACEMENTS' (without multipliers),
//!   'CONTRAINTES', 'DEFORMATIONS', 'REACTIONS', with a contact model
//!   'STATUTS_CONTACT' and 'PRESSIONS_CONTACT' (gibi's), with 'T' loads
//!   'TEMPERATURES';
//! * the working tables user procedures read and change: 'WTABLE' (its
//!   'CHARGEMENT' is re-read at every step), 'ESTIMATION' (the step just
//!   computed) and 'CONTINUATION' (the last state);
//! * user procedures, when the table asks for them: PERSO1 (before the
//!   first step with 'PERSO1_APPEL' = 1, after every step with 2; it may
//!   set 'ARRET' to stop and 'A_CALCULER' to change the times left),
//!   CHARMECA (`t2 = CHARMECA tab time`, its 'ADDI_SECOND' added to the
//!   loads of the step), REEV_MEC (`REEV_MEC tab 0` first, then
//!   `REEV_MEC tab 1` after each step) and REEV_THE (`REEV_THE tab 0`);
//! * continuation: a second call on the same table goes on after the last
//!   saved time, numbering on from the last index.
//!
//! Pressure loads are fields of a pressure model (MODE … 'CHARGEMENT'
//! 'PRESSION') in the model, given as CHAR 'PRES'; properties that are
//! curves of a parameter are evaluated at each step from the CHARGEMENT's
//! field of that name (`pasapas_vary`); 'AUTOMATIQUE' computes the times
//! asked: an elastic step is exact whatever the steps before it.
//!
//! 'DYNAMIQUE' VRAI runs linear dynamics (`pasapas_dyn`, the scheme in
//! `analysis::dynamics`): 'VITESSES' and 'ACCELERATIONS' join the results.
//!
//! What is not elastic mechanics (a plastic model, friction, large
//! displacements, thermal analysis) is refused before anything is
//! written: the table is left untouched.

use super::pasapas_fields as fields;
use super::pasapas_model::{self as pmodel, Loads, Structure};
use super::{Args, OpDef};
use crate::analysis::dynamics::Newmark;
use crate::analysis::stepper::{StepOutcome, Stepper};
use crate::error::Result;
use crate::eval::machine::GroupState;
use crate::eval::Interp;
use crate::solve::Load;
use crate::value::{fmt_float, Chargement, Chpoint, Key, Mchaml, Model, Rigidite, Table, Value};
use std::cell::RefCell;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "PASAPAS",
    signature: "PASAPAS TABLE",
    doc: "Incremental analysis of an elastic structure, with contact models and unilateral conditions, following \
          Cast3M's table: MODELE, CARACTERISTIQUES, BLOCAGES_MECANIQUES, CHARGEMENT ('MECA', 'DIMP', 'T'), \
          TEMPS_CALCULES, TEMPS_SAUVES in; TEMPS, DEPLACEMENTS, CONTRAINTES, DEFORMATIONS, REACTIONS \
          (STATUTS_CONTACT, PRESSIONS_CONTACT; VITESSES, ACCELERATIONS with DYNAMIQUE) out, indexed 0 (the initial state) 1 2 …; PERSO1, CHARMECA, REEV_MEC \
          hooks; a second call continues. One factorisation for the whole run.",
    example: "t = tabl ; t.'MODELE' = mo ; t.'CARACTERISTIQUES' = ma ; t.'BLOCAGES_MECANIQUES' = cl ; \
              t.'CHARGEMENT' = ch ; t.'TEMPS_CALCULES' = prog 0.5 1. ; pasapas t ;",
    f: pasapas,
}];

type Tab = Rc<RefCell<Table>>;

fn key(s: &str) -> Key {
    Key::Mot(s.to_string())
}

fn get(t: &Tab, k: &str) -> Option<Value> {
    t.borrow().get(&key(k)).cloned()
}

fn set(t: &Tab, k: &str, v: Value) {
    t.borrow_mut().set(key(k), v);
}

fn flag(t: &Tab, k: &str) -> bool {
    matches!(get(t, k), Some(Value::Bool(true)))
}

/// A sub-table of `t`, created if absent.
fn sub(t: &Tab, k: &str) -> Tab {
    if let Some(Value::Table(s)) = get(t, k) {
        return s;
    }
    let s = Rc::new(RefCell::new(Table::new()));
    set(t, k, Value::Table(s.clone()));
    s
}

fn table(v: Table) -> Value {
    Value::Table(Rc::new(RefCell::new(v)))
}

/// The inputs, read and checked before anything is written.
struct Input {
    model: Rc<Model>,
    cara: Vec<Rc<Mchaml>>,
    blocks: Option<Rigidite>,
    charge: Option<Rc<Chargement>>,
    times: Vec<f64>,
    saved: Vec<f64>,
    tref: Option<Rc<Chpoint>>,
    /// 'DYNAMIQUE': Newmark's average acceleration (`pasapas_dyn`).
    dynamic: bool,
}

/// Options of Cast3M's PASAPAS that change the physics gibi solves.
const REFUSED: &[(&str, &str)] = &[
    ("GRANDS_DEPLACEMENTS", "large displacements"),
    ("CONSOLIDATION", "consolidation"),
    ("K_SIGMA", "the geometric stiffness"),
    ("FEFP_FORMULATION", "finite strains"),
];

fn read_input(a: &Args, t: &Tab) -> Result<Input> {
    let model = match get(t, "MODELE") {
        Some(Value::Model(m)) => m,
        Some(v) => return Err(a.err(format!("'MODELE' must be an MMODEL, not a {}", v.type_name()))),
        None => return Err(a.err("the table has no 'MODELE'")),
    };
    for (k, what) in REFUSED {
        if flag(t, k) {
            return Err(
                a.err(format!("'{}' asks for {}: gibi's PASAPAS solves small-displacement statics only", k, what))
            );
        }
    }
    let (mech, cont) = pmodel::split(&model);
    for z in &model.zones {
        if z.formulation != "CONTACT"
            && z.formulation != super::pres_model::FORMULATION
            && !z.formulation.starts_with("MECA")
        {
            return Err(a.err(format!("the model has a {} zone: gibi's PASAPAS solves mechanics only", z.formulation)));
        }
    }
    for z in &mech {
        if let Some(w) = z.behaviour.iter().find(|b| super::model::inelastic(b)) {
            return Err(a
                .err(format!(
                    "the model is {} ({} elements): gibi's PASAPAS integrates elastic materials only, with no law for {} yet",
                    z.behaviour.join(" "),
                    z.element,
                    w
                ))
                .note("model the material as 'ELASTIQUE' (MODE … 'MECANIQUE' 'ELASTIQUE')"));
        }
    }
    for z in &cont {
        if let Some(w) = z.behaviour.iter().find(|b| !b.starts_with("UNIL")) {
            return Err(a
                .err(format!(
                    "the contact model is {}: gibi's PASAPAS solves frictionless contact only ({} is not available)",
                    z.behaviour.join(" "),
                    w
                ))
                .note("use MODE contact_mesh 'CONTACT' 'UNILATERAL'"));
        }
    }
    if mech.is_empty() {
        return Err(a.err("the model has no mechanical zone"));
    }
    let cara = match get(t, "CARACTERISTIQUES") {
        Some(Value::Mchaml(m)) => vec![m],
        Some(v) => return Err(a.err(format!("'CARACTERISTIQUES' must be an MCHAML, not a {}", v.type_name()))),
        None => return Err(a.err("the table has no 'CARACTERISTIQUES' (MATE of the model)")),
    };
    let rigi = |k: &str| -> Result<Option<Rc<Rigidite>>> {
        match get(t, k) {
            Some(Value::Rigi(r)) => Ok(Some(r)),
            None => Ok(None),
            Some(v) => Err(a.err(format!("'{}' must be a RIGIDITE, not a {}", k, v.type_name()))),
        }
    };
    let blocks = match (rigi("BLOCAGES_MECANIQUES")?, rigi("RIGIDITE_CONSTANTE")?) {
        (None, None) => None,
        (b, k) => {
            let mut r = Rigidite::new(crate::value::rigidity::Subtype::Rigidite);
            for x in [b, k].into_iter().flatten() {
                r.blocks.extend(x.blocks.iter().cloned());
                r.conds.extend(x.conds.iter().cloned());
            }
            Some(r)
        }
    };
    let charge = match get(t, "CHARGEMENT") {
        Some(Value::Charge(c)) => {
            pmodel::check_loads(a, &c)?;
            Some(c)
        }
        None => None,
        Some(v) => return Err(a.err(format!("'CHARGEMENT' must be a CHARGEMENT (CHAR), not a {}", v.type_name()))),
    };
    let list = |k: &str| -> Result<Option<Vec<f64>>> {
        match get(t, k) {
            Some(Value::ListReel(l)) => Ok(Some(l.to_vec())),
            None => Ok(None),
            Some(v) => Err(a.err(format!("'{}' must be a LISTREEL, not a {}", k, v.type_name()))),
        }
    };
    let (times, saved) = match (list("TEMPS_CALCULES")?, list("TEMPS_SAUVES")?) {
        (Some(c), Some(s)) => (c, s),
        (Some(c), None) => (c.clone(), c),
        (None, Some(s)) => (s.clone(), s),
        (None, None) => return Err(a.err("the table has no 'TEMPS_CALCULES' (the times to compute)")),
    };
    if let Some(x) = saved.iter().find(|x| !times.iter().any(|c| close(*c, **x))) {
        return Err(a.err(format!("'TEMPS_SAUVES' holds {}, which is not in 'TEMPS_CALCULES'", fmt_float(*x))));
    }
    let tref = match get(t, "TEMPERATURE_REFERENCE") {
        Some(Value::Chpo(c)) => Some(c),
        _ => match get(t, "TEMPERATURES") {
            Some(Value::Table(tt)) => match tt.borrow().get(&Key::Int(0)) {
                Some(Value::Chpo(c)) => Some(c.clone()),
                _ => None,
            },
            _ => None,
        },
    };
    let dynamic = flag(t, "DYNAMIQUE");
    Ok(Input { model, cara, blocks, charge, times, saved, tref, dynamic })
}

/// Times are equal within a relative 1e-10 (Cast3M's 'DANS' precision),
/// so a list built by PROG … 'PAS' … matches one written by hand.
pub(crate) fn close(x: f64, y: f64) -> bool {
    (x - y).abs() <= 1e-10 * x.abs().max(y.abs()).max(1e-300)
}

/// The run's state between steps.
struct Run {
    tab: Tab,
    s: Structure,
    stepper: Stepper,
    loads: Loads,
    /// The CHARGEMENT `loads` was built from (WTABLE may change it).
    charge: Option<Rc<Chargement>>,
    has_t: bool,
    contact: bool,
    /// The material is evaluated at each step (`pasapas_vary`).
    varying: bool,
    /// A dynamic run's mass, damping and state.
    dynm: Option<Newmark>,
}

fn pasapas(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let tab = a.req::<Tab>()?;
    let input = read_input(a, &tab)?;
    let temp0 = start_time(&tab);
    // Properties that are curves of a parameter: evaluated at each step.
    let varying = super::pasapas_vary::is_varying(&input.cara);
    let cara0 = super::pasapas_vary::evaluated(it, a, &input.model, &input.cara, input.charge.as_deref(), temp0)?;
    let s = pmodel::build(it, a, &input.model, &cara0, input.blocks.as_ref())?;
    // The reference temperature: given, or the 'T' load at the start.
    let tref = match (&input.tref, &input.charge) {
        (Some(c), _) => Some(c.clone()),
        (None, Some(ch)) if ch.has("T") => match super::chargement::at(it, a, ch, Some("T"), temp0)? {
            Value::Chpo(c) => Some(c),
            _ => None,
        },
        _ => None,
    };
    let loads = pmodel::loads(it, a, &s, input.charge.as_deref(), tref.as_deref())?;
    if input.dynamic && varying {
        return Err(a.err(
            "'DYNAMIQUE' with material properties that vary along the run is not supported: gibi's dynamics keeps one \
             effective operator per step length",
        ));
    }
    let mut dynm =
        if input.dynamic { Some(super::pasapas_dyn::newmark(it, a, &tab, &s, &input.model, &cara0)?) } else { None };
    let t = std::time::Instant::now();
    // Dynamics solves with the effective operator K + 4/h² M (+ 2/h C).
    let problem = match dynm.as_mut() {
        Some(nm) => nm.effective(&s.asm.problem, super::pasapas_dyn::first_step(&input.times, temp0)),
        None => s.asm.problem.clone(),
    };
    let mut stepper = Stepper::new(problem).map_err(|e| a.err(explain(it, &s, e, None)))?;
    stepper.set_adhesion(&s.adhesion).map_err(|e| a.err(format!("'ADHE': {}", e)))?;
    // Ctrl-C stops a long status iteration between two solves.
    stepper.set_cancel(crate::solve::unilateral::status::Cancel(it.interrupt.shared()));
    it.timers.phase("PASAPAS factorisation", t.elapsed().as_secs_f64());
    let has_t = input.charge.as_ref().is_some_and(|c| c.has("T"));
    let contact = !s.contact.is_empty();
    let mut run =
        Run { tab: tab.clone(), s, stepper, loads, charge: input.charge.clone(), has_t, contact, varying, dynm };
    initial_state(it, a, &mut run, &input, temp0)?;
    if let Some(nm) = run.dynm.as_mut() {
        super::pasapas_dyn::initial(a, &tab, &run.s, &run.loads, temp0, nm)?;
    }
    // A continued run starts its statuses where the last one ended.
    let w = sub(&tab, "WTABLE");
    if let Some(Value::ListEnti(l)) = w.borrow().get(&key("STATUTS_UNILATERAUX")) {
        run.stepper.set_statuses(l.iter().map(|&x| x != 0).collect());
    }
    steps(it, a, &mut run, &input, temp0)?;
    if let Some(st) = run.stepper.statuses() {
        let l: Vec<i64> = st.iter().map(|&x| x as i64).collect();
        w.borrow_mut().set(key("STATUTS_UNILATERAUX"), Value::ListEnti(Rc::new(l)));
    }
    if let Some(nm) = &run.dynm {
        // The inertial force at the end: a continued run starts from it.
        w.borrow_mut().set(key("FREA1"), Value::Chpo(Rc::new(super::pasapas_dyn::field(&run.s, &nm.r, true))));
    }
    // pasapas.notice's outputs: the run converged, without error.
    set(&tab, "CONV", Value::Bool(true));
    set(&tab, "ERREUR", Value::Bool(false));
    set(&tab, "SOUSTYPE", Value::mot("PASAPAS"));
    Ok(vec![Value::Table(tab)])
}

/// The time the run starts from: the last state of a previous run, else 0.
fn start_time(t: &Tab) -> f64 {
    if let Some(Value::Table(c)) = get(t, "CONTINUATION") {
        if let Some(x) = c.borrow().get(&key("TEMPS")).and_then(Value::as_f64) {
            return x;
        }
    }
    if let Some(Value::Table(tt)) = get(t, "TEMPS") {
        let last = last_index(&tt.borrow());
        if let Some(x) = tt.borrow().get(&Key::Int(last)).and_then(Value::as_f64) {
            return x;
        }
    }
    0.0
}

/// The largest integer index of a result table (0 when empty).
fn last_index(t: &Table) -> i64 {
    t.iter().filter_map(|(k, _)| if let Key::Int(i) = k { Some(*i) } else { None }).max().unwrap_or(0)
}

/// Index 0 of the result tables (when absent), WTABLE, CONTINUATION and
/// ESTIMATION, and the first calls of the user procedures.
fn initial_state(it: &mut Interp, a: &Args, run: &mut Run, input: &Input, temp0: f64) -> Result<()> {
    let tab = &run.tab;
    let s = &run.s;
    let n = s.asm.problem.k.n;
    let zero = vec![0.0; n];
    let mut f0 = s.body.fields(&zero, None).map_err(|e| a.err(pmodel::body_error(s, &e)))?;
    let mut first = Table::new();
    first.set(key("TEMPS"), Value::Float(temp0));
    first.set(key("DEPLACEMENTS"), Value::Chpo(Rc::new(fields::displacements(s, &zero))));
    first.set(key("CONTRAINTES"), Value::Mchaml(Rc::new(fields::element_field(s, &mut f0, true))));
    first.set(key("DEFORMATIONS"), Value::Mchaml(Rc::new(fields::element_field(s, &mut f0, false))));
    let m = s.asm.problem.conditions.len();
    first.set(key("REACTIONS"), Value::Chpo(Rc::new(fields::reactions(s, &vec![0.0; m]))));
    if run.contact {
        let none = crate::solve::Solution { u: zero.clone(), lambda: vec![0.0; m], active: vec![false; m] };
        let (st, pr) = fields::contact(s, &none);
        first.set(key("STATUTS_CONTACT"), Value::Chpo(Rc::new(st)));
        first.set(key("PRESSIONS_CONTACT"), Value::Chpo(Rc::new(pr)));
    }
    if run.dynm.is_some() {
        for k in ["VITESSES", "ACCELERATIONS"] {
            first.set(key(k), super::pasapas_dyn::given_or_zero(tab, s, k));
        }
    }
    if run.has_t {
        if let Some(Value::Chpo(c)) =
            run.charge.as_ref().map(|ch| super::chargement::at(it, a, ch, Some("T"), temp0)).transpose()?
        {
            first.set(key("TEMPERATURES"), Value::Chpo(c));
        }
    }
    // Result tables: index 0 where they do not exist yet.
    for (k, v) in first.iter() {
        let Key::Mot(name) = k else { continue };
        let r = sub(tab, name);
        if r.borrow().get(&Key::Int(0)).is_none() {
            r.borrow_mut().set(Key::Int(0), v.clone());
        }
    }
    let conti = sub(tab, "CONTINUATION");
    if conti.borrow().get(&key("DEPLACEMENTS")).is_none() {
        for (k, v) in first.iter() {
            conti.borrow_mut().set(k.clone(), v.clone());
        }
    }
    set(tab, "ESTIMATION", table(conti.borrow().clone()));
    let w = sub(tab, "WTABLE");
    {
        let mut w = w.borrow_mut();
        w.set(key("TEMPS0"), Value::Float(temp0));
        w.set(key("MO_TOT"), Value::Model(input.model.clone()));
        // What post-processing procedures (G_THETA) read of a run: the
        // mechanical model and its material, the kind of run, and the
        // temperature the expansion coefficients refer to.
        let (mech, _) = pmodel::split(&input.model);
        let mod_mec = Model { zones: mech.into_iter().cloned().collect(), ties: input.model.ties.clone() };
        w.set(key("MOD_MEC"), Value::Model(Rc::new(mod_mec)));
        if let Some(m) = input.cara.first() {
            w.set(key("MAT_MEC"), Value::Mchaml(m.clone()));
        }
        w.set(key("DYNAMIQUE"), Value::Bool(input.dynamic));
        w.set(key("GRANDS_DEPLACEMENTS"), Value::Bool(false));
        let talpha = get(tab, "TALPHA_REFERENCE").unwrap_or(Value::Float(0.0));
        w.set(key("TALPHA_REFERENCE"), talpha);
        w.set(key("CONV"), Value::Bool(true));
        if let Some(c) = &input.charge {
            w.set(key("CHARGEMENT"), Value::Charge(c.clone()));
            w.set(key("CHARGEMENT_I"), Value::Charge(c.clone()));
        }
    }
    if flag(tab, "PROCEDURE_PERSO1") {
        set(tab, "PERSO1_APPEL", Value::Int(1));
        hook(it, a, "PERSO1", &[Value::Table(tab.clone())])?;
    }
    if flag(tab, "PROCEDURE_REEV_MEC") {
        hook(it, a, "REEV_MEC", &[Value::Table(tab.clone()), Value::Int(0)])?;
    }
    if flag(tab, "PROCEDURE_REEV_THE") {
        hook(it, a, "REEV_THE", &[Value::Table(tab.clone()), Value::Int(0)])?;
    }
    Ok(())
}

/// Calls the user procedure `name` with `args`.
fn hook(it: &mut Interp, a: &Args, name: &str, args: &[Value]) -> Result<Vec<Value>> {
    let p = match it.store.get(name) {
        Some(Value::Proc(p)) => p.clone(),
        _ => {
            return Err(a.err(format!(
                "the table asks for the procedure {} ('PROCEDURE_{}' is VRAI), but no procedure {} is defined",
                name, name, name
            )))
        }
    };
    let mut st = GroupState { left: args.to_vec(), right: Default::default() };
    it.call_proc(p, &mut st, a.span)
}

fn steps(it: &mut Interp, a: &Args, run: &mut Run, input: &Input, temp0: f64) -> Result<()> {
    let tab = run.tab.clone();
    let mut nsor = match get(&tab, "TEMPS") {
        Some(Value::Table(t)) => last_index(&t.borrow()),
        _ => 0,
    };
    let mut time = temp0;
    let mut list = input.times.clone();
    let total = list.iter().filter(|t| **t > time && !close(**t, time)).count();
    let mut ipas = 0;
    let mut i = 0;
    while i < list.len() {
        let ti = list[i];
        i += 1;
        if ti < time || close(ti, time) {
            continue;
        }
        // Ctrl-C between two steps (the steps done stay in the table).
        if it.interrupt.is_pending() {
            it.interrupt.clear();
            return Err(crate::eval::interrupted());
        }
        ipas += 1;
        if run.varying {
            let current = current_charge(run);
            if let Some(c) = &current {
                pmodel::check_loads(a, c)?;
            }
            let (s, loads) = super::pasapas_vary::rebuild(
                it,
                a,
                &input.model,
                &input.cara,
                input.blocks.as_ref(),
                current.as_deref(),
                &run.loads.tref,
                &mut run.stepper,
                ti,
            )?;
            (run.s, run.loads, run.charge) = (s, loads, current);
        }
        let (coefs, mut extra, heat) = step_load(it, a, run, ti)?;
        if let Some(nm) = run.dynm.as_mut() {
            // A new step length needs a new effective operator.
            let h = ti - time;
            if !nm.same_step(h) {
                let p = nm.effective(&run.s.asm.problem, h);
                run.stepper.renew(p).map_err(|e| a.err(explain(it, &run.s, e, None)))?;
            }
            let mut load = nm.inertia_load(h, run.s.asm.problem.conditions.len());
            if let Some(e) = &extra {
                crate::analysis::history::axpy(&mut load.f, 1.0, &e.f);
                crate::analysis::history::axpy(&mut load.d, 1.0, &e.d);
            }
            extra = Some(load);
        }
        // Cast3M prints its step lines unless told OPTI ECHO 0.
        let verbose = it.opts.echo >= 1 || !it.opts.kept.contains_key("ECHO");
        let out = run.stepper.solve_history(&run.loads.history, &coefs, extra.as_ref(), &mut |_| {}).map_err(|e| {
            if e == crate::solve::SolveError::Interrupted {
                it.interrupt.clear();
                return crate::eval::interrupted();
            }
            let load = run.loads.history.combine(&coefs);
            a.err(format!("step {} (time {}): {}", ipas, fmt_float(ti), explain(it, &run.s, e, Some(&load))))
        })?;
        for (name, secs) in &out.phases {
            it.timers.phase(&format!("PASAPAS {}", name), *secs);
        }
        if verbose {
            it.println(&progress_line(ipas, ti, &out, run.contact || run.stepper.statuses().is_some()));
        }
        if let Some(p) = it.progress.as_mut() {
            p(ipas, total.max(ipas));
        }
        if let Some(nm) = run.dynm.as_mut() {
            nm.advance(ti - time, &out.solution.u);
        }
        let estim = results(it, a, run, ti, &out, heat.as_deref())?;
        set(&tab, "ESTIMATION", Value::Table(estim.clone()));
        if flag(&tab, "PROCEDURE_REEV_MEC") {
            hook(it, a, "REEV_MEC", &[Value::Table(tab.clone()), Value::Int(1)])?;
        }
        time = ti;
        if let Some(Value::Table(w)) = get(&tab, "WTABLE") {
            w.borrow_mut().set(key("TEMPS0"), Value::Float(ti));
            w.borrow_mut().set(key("PAS"), Value::Int(ipas as i64));
        }
        if flag(&tab, "PROCEDURE_PERSO1") {
            set(&tab, "PERSO1_APPEL", Value::Int(2));
            hook(it, a, "PERSO1", &[Value::Table(tab.clone())])?;
            // PERSO1 may change the times left to compute.
            if let Some(Value::ListReel(l)) = tab.borrow_mut().remove(&key("A_CALCULER")) {
                list = l.to_vec();
                i = 0;
            }
        }
        // The estimation becomes the continuation; saved times get an index.
        let conti = sub(&tab, "CONTINUATION");
        let saving = input.saved.iter().any(|x| close(*x, ti));
        if saving {
            nsor += 1;
        }
        for (k, v) in estim.borrow().iter() {
            conti.borrow_mut().set(k.clone(), v.clone());
            if let (true, Key::Mot(name)) = (saving, k) {
                sub(&tab, name).borrow_mut().set(Key::Int(nsor), v.clone());
            }
        }
        if flag(&tab, "ARRET") {
            break;
        }
    }
    Ok(())
}

/// The load of a step: the weights of the CHARGEMENT's terms at `t` (its
/// history rebuilt if a user procedure replaced WTABLE's CHARGEMENT),
/// CHARMECA's 'ADDI_SECOND' as an extra load, and the temperature rise by
/// node for the stresses.
type StepLoad = (Vec<f64>, Option<Load>, Option<Vec<f64>>);

/// The CHARGEMENT of the step: WTABLE's (a user procedure may replace
/// it), else the one the run started with.
fn current_charge(run: &Run) -> Option<Rc<Chargement>> {
    match get(&run.tab, "WTABLE").and_then(|w| match w {
        Value::Table(w) => w.borrow().get(&key("CHARGEMENT")).cloned(),
        _ => None,
    }) {
        Some(Value::Charge(c)) => Some(c),
        _ => run.charge.clone(),
    }
}

fn step_load(it: &mut Interp, a: &Args, run: &mut Run, t: f64) -> Result<StepLoad> {
    let current = current_charge(run);
    let same = match (&current, &run.charge) {
        (Some(x), Some(y)) => Rc::ptr_eq(x, y),
        (None, None) => true,
        _ => false,
    };
    if !same {
        if let Some(c) = &current {
            pmodel::check_loads(a, c)?;
        }
        let tref = run.loads.tref.clone();
        let tref_field = Chpoint::from_entries(
            crate::value::Nature::Diffus,
            tref.iter().enumerate().filter(|(_, v)| **v != 0.0).map(|(n, v)| (n, "T", *v)),
        );
        run.loads = pmodel::loads(it, a, &run.s, current.as_deref(), Some(&tref_field))?;
        run.charge = current;
    }
    let coefs = run.loads.history.coefficients(t).map_err(|e| a.err(format!("CHARGEMENT: {}", e)))?;
    let mut extra = None;
    let heat = run.loads.heat_at(t).map_err(|e| a.err(format!("CHARGEMENT 'T': {}", e)))?;
    if flag(&run.tab, "PROCEDURE_CHARMECA") {
        let r = hook(it, a, "CHARMECA", &[Value::Table(run.tab.clone()), Value::Float(t)])?;
        if let Some(Value::Table(t2)) = r.first() {
            if t2.borrow().get(&key("ADDI_MATRICE")).is_some() {
                return Err(
                    a.err("CHARMECA's 'ADDI_MATRICE' (a stiffness that changes with the steps) is not supported")
                );
            }
            if let Some(Value::Chpo(f)) = t2.borrow().get(&key("ADDI_SECOND")) {
                let l = super::assemble::load(it, &run.s.asm, &[f])
                    .map_err(|e| a.err(format!("CHARMECA 'ADDI_SECOND': {}", e.message)))?;
                extra = Some(l);
            }
        }
    }
    Ok((coefs, extra, heat))
}

/// The ESTIMATION table of a step.
fn results(it: &mut Interp, a: &Args, run: &Run, t: f64, out: &StepOutcome, heat: Option<&[f64]>) -> Result<Tab> {
    let s = &run.s;
    let sol = &out.solution;
    let mut f = s.body.fields(&sol.u, heat).map_err(|e| a.err(pmodel::body_error(s, &e)))?;
    let mut e = Table::new();
    e.set(key("TEMPS"), Value::Float(t));
    e.set(key("DEPLACEMENTS"), Value::Chpo(Rc::new(fields::displacements(s, &sol.u))));
    e.set(key("CONTRAINTES"), Value::Mchaml(Rc::new(fields::element_field(s, &mut f, true))));
    e.set(key("DEFORMATIONS"), Value::Mchaml(Rc::new(fields::element_field(s, &mut f, false))));
    e.set(key("REACTIONS"), Value::Chpo(Rc::new(fields::reactions(s, &sol.lambda))));
    if let Some(nm) = &run.dynm {
        e.set(key("VITESSES"), Value::Chpo(Rc::new(super::pasapas_dyn::field(s, &nm.v, false))));
        e.set(key("ACCELERATIONS"), Value::Chpo(Rc::new(super::pasapas_dyn::field(s, &nm.a, false))));
    }
    if run.contact {
        let (st, pr) = fields::contact(s, sol);
        e.set(key("STATUTS_CONTACT"), Value::Chpo(Rc::new(st)));
        e.set(key("PRESSIONS_CONTACT"), Value::Chpo(Rc::new(pr)));
    }
    if run.has_t {
        if let Some(ch) = &run.charge {
            e.set(key("TEMPERATURES"), super::chargement::at(it, a, ch, Some("T"), t)?);
        }
    }
    Ok(Rc::new(RefCell::new(e)))
}

/// One line per step: number, time, and with unilateral conditions the
/// status solves, the changes since the previous step, the active count.
fn progress_line(ipas: usize, t: f64, out: &StepOutcome, unilateral: bool) -> String {
    let mut s = format!("PASAPAS step {:>4} time {}", ipas, fmt_float(t));
    if unilateral {
        s.push_str(&format!(": {} status solve(s), {} change(s), {} active", out.iterations, out.changed, out.active));
    }
    s
}

/// A solver error in the words RESO uses (nodes and components named).
fn explain(it: &Interp, s: &Structure, e: crate::solve::SolveError, load: Option<&Load>) -> String {
    let loads: Vec<Load> = load.cloned().into_iter().collect();
    let m = super::assemble::explain(it, &s.rig, &s.asm, e, &loads);
    m.message.trim_start_matches("RESO: ").to_string()
}
