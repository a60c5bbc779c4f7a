//! RESO, REAC and UNIL: the bridge between RIGIDITE objects and `solve`.

use super::assemble::{self, explain, solution_field, Assembled};
use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::solve::bilateral::pool::Phase;
use crate::solve::bilateral::rigid_modes::hold_rigid_modes;
use crate::solve::direct::DirectOptions;
use crate::solve::unilateral::{solve_unilateral, Method, UnilOptions, UnilReport};
use crate::solve::{Load, SolveError};
use crate::value::{fmt_float, Chpoint, Key, Rigidite, Table, Value};
use std::cell::RefCell;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef { name: "RESO", signature: "RESO RIGIDITE CHPOINT|LISTCHPO (CHPOINT|LISTCHPO …) ('NOID') ('NOUNIL') ('STAB') ('ENSE') ('SOUC') ('INIB' RIGIDITE LISTENTI)", doc: "Solve K u = F with bilateral and unilateral conditions; the result holds the unknowns and the LX of active conditions. Several right-hand sides share one factorisation; a LISTCHPO gives a LISTCHPO of solutions in the same order.", example: "u = reso (k et cl) f ;", f: reso },
    OpDef { name: "REAC", signature: "REAC RIGIDITE CHPOINT|LISTCHPO", doc: "Reactions -Cᵀλ of the conditions of RIGIDITE, from the multipliers LX of a RESO result (DISCRET field); a LISTCHPO of results gives a LISTCHPO of reactions.", example: "r = reac cl u ;", f: reac },
    OpDef { name: "UNIL", signature: "UNIL RIGIDITE CHPOINT ('CONDENSE'|'ANCIEN'|'ITER'|'CREUX') ('RAPIDE'|'PDAS'|'MIXTE'|'UNITAIRE') ('INIB' LISTENTI) ('MAXI' n) ('SOUC') ('VERBEUX')", doc: "The unilateral solver (Cast3M's UNILATER): returns the solution and a TABLE of diagnostics (METHODE, NCONDITIONS, NITER, NACTIFS, CONVERGE, per-iteration records, phase times). 'SOUC' returns the last iterate with a warning when the status iteration does not converge.", example: "u diag = unil (k et c) f 'CONDENSE' ;", f: unil },
];

struct Opts {
    ense: bool,
    noid: bool,
    nounil: bool,
    stab: bool,
    soft: bool,
    initial: Option<Vec<bool>>,
    method: Method,
    rule: crate::solve::unilateral::Rule,
    max_iter: Option<usize>,
    verbose: bool,
}

fn read_options(it: &Interp, a: &mut Args, r: &Rigidite) -> Result<Opts> {
    let mut o = Opts {
        ense: false,
        noid: false,
        nounil: false,
        stab: false,
        soft: false,
        initial: None,
        method: if it.opts.reso.starts_with("ITER") { Method::Iter } else { Method::Auto },
        rule: crate::solve::unilateral::Rule::Auto,
        max_iter: None,
        verbose: it.opts.echo >= 1,
    };
    const KW: &[&str] = &[
        "NOID", "NOUNIL", "STAB", "NOSTAB", "ENSE", "SOUC", "ELIM", "INIB", "CONDENSE", "ANCIEN", "ITER", "CREUX",
        "PDAS", "MIXTE", "RAPIDE", "UNITAIRE", "MAXI", "VERBEUX", "GRAD", "CHOL",
    ];
    while let Some(k) = a.keyword(KW) {
        match k {
            "NOID" => o.noid = true,
            "ENSE" => o.ense = true,
            "NOUNIL" => o.nounil = true,
            "STAB" => o.stab = true,
            "SOUC" => o.soft = true,
            "ELIM" => {
                a.opt_right::<i64>();
            }
            "INIB" => {
                let _ = a.opt::<Rc<Rigidite>>();
                let l = a.req::<Rc<Vec<i64>>>()?;
                let m = r.n_unilateral();
                if l.len() != m {
                    return Err(a.err(format!("'INIB': {} statuses for {} unilateral conditions", l.len(), m)));
                }
                o.initial = Some(l.iter().map(|&s| s != 0).collect());
            }
            "CONDENSE" => o.method = Method::Condense,
            "ANCIEN" => o.method = Method::Ancien,
            "ITER" => o.method = Method::Iter,
            "CREUX" => o.method = Method::Creux,
            "PDAS" => o.rule = crate::solve::unilateral::Rule::Pdas,
            "MIXTE" => o.rule = crate::solve::unilateral::Rule::Mixed,
            "RAPIDE" => o.rule = crate::solve::unilateral::Rule::Damped,
            "UNITAIRE" => o.rule = crate::solve::unilateral::Rule::SingleChange,
            "MAXI" => o.max_iter = Some(a.req::<i64>()?.max(1) as usize),
            "VERBEUX" => o.verbose = true,
            _ => {}
        }
    }
    Ok(o)
}

/// A right-hand side as written: a CHPOINT gives one solution CHPOINT, a
/// LISTCHPO a LISTCHPO of solutions in the same order. All of them are
/// solved together, on one factorisation.
enum Rhs {
    One(Rc<Chpoint>),
    List(Rc<Vec<Rc<Chpoint>>>),
}

impl super::FromArg for Rhs {
    const EXPECT: &'static str = "CHPOINT or LISTCHPO";
    fn from_value(v: &Value) -> Option<Self> {
        match v {
            Value::Chpo(c) => Some(Rhs::One(c.clone())),
            Value::ListChpo(l) => Some(Rhs::List(l.clone())),
            _ => None,
        }
    }
}

impl Rhs {
    fn fields(&self) -> &[Rc<Chpoint>] {
        match self {
            Rhs::One(c) => std::slice::from_ref(c),
            Rhs::List(l) => l,
        }
    }
}

/// Put the solutions back in the shape the right-hand sides were given.
fn regroup(given: &[Rhs], sols: Vec<Rc<Chpoint>>) -> Vec<Value> {
    let mut sols = sols.into_iter();
    given
        .iter()
        .map(|g| match g {
            Rhs::One(_) => Value::Chpo(sols.next().expect("one solution per right-hand side")),
            Rhs::List(l) => Value::ListChpo(Rc::new(sols.by_ref().take(l.len()).collect())),
        })
        .collect()
}

fn reso(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let r = a.req::<Rc<Rigidite>>()?;
    let mut given: Vec<Rhs> = Vec::new();
    let mut o = read_options(it, a, &r)?;
    while let Some(c) = a.opt::<Rhs>() {
        given.push(c);
        let more = read_options(it, a, &r)?;
        merge(&mut o, more);
    }
    if given.is_empty() {
        return Err(a.missing("CHPOINT or LISTCHPO (the right-hand side)"));
    }
    let rhs: Vec<&Rc<Chpoint>> = given.iter().flat_map(|g| g.fields()).collect();
    if rhs.is_empty() {
        // Only empty LISTCHPOs: nothing to solve, nothing to factorise.
        return Ok(regroup(&given, Vec::new()));
    }
    let asm = r.numbered();
    let loads: Vec<Load> = rhs
        .iter()
        .map(|c| assemble::load_of(it, &r, &asm, &[c]))
        .collect::<Result<_>>()
        .map_err(|e| a.err(e.message))?;
    finite_data(&asm, &loads).map_err(|e| a.err(e))?;
    let unilateral = r.n_unilateral() > 0 && !o.nounil;
    if o.ense && !unilateral {
        let (sols, extra) = reso_ense(it, &r, &asm, &loads, &o)?;
        finite_solutions(&sols).map_err(|e| a.err(e))?;
        let mut out = regroup(&given, sols);
        out.extend(extra);
        return Ok(out);
    }
    let sols = if unilateral {
        // Each load has its own contact statuses: solved in turn.
        let mut sols = Vec::new();
        for load in &loads {
            let (sol, report) = solve_unil(it, &r, &asm, load, &o)?;
            sols.push(Rc::new(solution_field(&asm, &sol)));
            record(it, &report);
        }
        sols
    } else {
        solve_direct(it, &r, &asm, &loads, &o)?
    };
    finite_solutions(&sols).map_err(|e| a.err(e))?;
    Ok(regroup(&given, sols))
}

/// RESO's data hold finite numbers only: an infinity or a NaN in the
/// matrix, the loads or the imposed values would come out as a NaN
/// solution (and a NaN passes every `SI (err > tol)` check).
fn finite_data(asm: &Assembled, loads: &[Load]) -> std::result::Result<(), String> {
    use crate::value::finite::describe;
    let bad = |x: &f64| !x.is_finite();
    let p = &asm.problem;
    let in_matrix = p.k.entries.iter().map(|e| &e.2);
    let in_conditions = p.conditions.iter().flat_map(|c| c.terms.iter().chain(c.dual.iter().flatten())).map(|t| &t.1);
    if let Some(x) = in_matrix.chain(in_conditions).find(|x| bad(x)) {
        return Err(format!("the matrix holds {}", describe(*x)));
    }
    if let Some(x) = loads.iter().flat_map(|l| &l.f).find(|x| bad(x)) {
        return Err(format!("the loads hold {}", describe(*x)));
    }
    if let Some(x) = loads.iter().flat_map(|l| &l.d).find(|x| bad(x)) {
        return Err(format!("the imposed values hold {}", describe(*x)));
    }
    Ok(())
}

/// Finite data can still give an overflowing solution (a load of 1.E308
/// on a soft structure): an error, whatever 'NOID' says.
fn finite_solutions(sols: &[Rc<Chpoint>]) -> std::result::Result<(), String> {
    let value = sols.iter().find_map(|c| crate::value::finite::first_non_finite(&Value::Chpo(c.clone())));
    match value {
        Some(x) => Err(format!(
            "the solution holds {}: the loads or imposed values are too large for this matrix",
            crate::value::finite::describe(x)
        )),
        None => Ok(()),
    }
}

/// Every load on one factorisation, reused from the pool when the
/// RIGIDITE (or one of the same pattern) was factorised before.
fn solve_direct(it: &mut Interp, r: &Rigidite, asm: &Assembled, loads: &[Load], o: &Opts) -> Result<Vec<Rc<Chpoint>>> {
    let t = std::time::Instant::now();
    let opts = DirectOptions { check_residual: !o.noid, stab: o.stab };
    let factored = {
        let mut cache = r.cache.borrow_mut();
        let cache = &mut *cache;
        it.factors.factor(cache.id, &mut cache.key, &asm.problem, &opts)
    };
    let (fact, phase) = match factored {
        Ok(f) => f,
        Err(e) => return soft_singular(it, r, asm, loads, o, e),
    };
    let fact_s = t.elapsed().as_secs_f64();
    let t = std::time::Instant::now();
    let mut warnings: Vec<String> = Vec::new();
    let sols = match fact.solve_checked(loads, !o.noid) {
        // 'SOUC': an inaccurate solution is a warning, not a failure.
        Err(SolveError::Inaccurate { residual, .. }) if o.soft => {
            warnings.push(format!(
                "RESO 'SOUC': warning: inaccurate solution (relative residual {}) returned anyway",
                fmt_float(residual)
            ));
            fact.solve_checked(loads, false)
        }
        other => other,
    };
    let sols = sols.map_err(|e| explain(it, r, asm, e, loads)).map(|mut v| {
        for (s, l) in v.iter_mut().zip(loads) {
            s.snap_blocked(&asm.problem, l);
        }
        v
    });
    let solve_s = t.elapsed().as_secs_f64();
    if phase != Phase::Reused {
        it.timers.phase(&format!("RESO {}", phase.name()), fact_s);
    }
    it.timers.phase("RESO solve", solve_s);
    if it.opts.echo >= 1 {
        it.println(&format!(
            "RESO: {} unknowns, {} conditions, {} right-hand side(s); matrix {} ({:.3} s), solve {:.3} s",
            asm.problem.k.n,
            asm.problem.conditions.len(),
            loads.len(),
            phase.name(),
            fact_s,
            solve_s
        ));
    }
    for w in warnings {
        it.println(&w);
    }
    Ok(sols?.iter().map(|s| Rc::new(solution_field(asm, s))).collect())
}

/// A factorisation error: with 'SOUC' a singular system is solved as
/// 'ENSE' does (each free rigid mode held at its largest unknown) with a
/// warning naming where; anything else, or no 'SOUC', is the error.
fn soft_singular(
    it: &mut Interp,
    r: &Rigidite,
    asm: &Assembled,
    loads: &[Load],
    o: &Opts,
    e: SolveError,
) -> Result<Vec<Rc<Chpoint>>> {
    if !matches!(e, SolveError::Singular { .. }) {
        return Err(explain(it, r, asm, e, loads));
    }
    if !o.soft {
        // Cast3M's RESO goes through a free mode that nothing loads (a
        // plane truss in 3D and its out-of-plane motion): holding it gives
        // the solution whose free-mode part is zero. A load with work along
        // the mode has no equilibrium: that stays the error.
        let opts = DirectOptions { check_residual: !o.noid, stab: o.stab };
        let held = hold_rigid_modes(&asm.problem, &opts).map_err(|_| explain(it, r, asm, e.clone(), loads))?;
        let sols = held.solve(loads).map_err(|_| explain(it, r, asm, e.clone(), loads))?;
        if !unloaded_modes(asm.problem.conditions.len(), loads, &sols) {
            return Err(explain(it, r, asm, e, loads));
        }
        return Ok(sols.iter().map(|s| Rc::new(solution_field(asm, s))).collect());
    }
    let (sols, extra) = reso_ense(it, r, asm, loads, o)?;
    let held = match &extra[..] {
        [Value::Int(k), Value::Mesh(m)] => {
            let nodes: Vec<String> = m.node_list().iter().take(8).map(|&n| super::assemble::node_name(it, n)).collect();
            format!("{} rigid mode(s) held at {}", k, nodes.join(", "))
        }
        _ => "rigid modes held".to_string(),
    };
    it.println(&format!("RESO 'SOUC': warning: singular system; {held}; that solution is returned"));
    Ok(sols)
}

/// Whether the conditions added to hold the free modes (after the `m`
/// given ones) carry no force: each one's multiplier is the work of the
/// load along its mode, negligible against the loads and reactions.
fn unloaded_modes(m: usize, loads: &[Load], sols: &[crate::solve::Solution]) -> bool {
    loads.iter().zip(sols).all(|(l, s)| {
        let big = |v: &[f64]| v.iter().fold(0.0f64, |a, x| a.max(x.abs()));
        let scale = big(&l.f).max(big(&s.lambda[..m]));
        let held = big(&s.lambda[m..]);
        held <= 1e-9 * scale || (scale == 0.0 && held == 0.0)
    })
}

/// 'ENSE': on a singular system, hold each free rigid mode by blocking its
/// largest unknown, as Cast3M's RESO does for UNILATER. Results: the
/// solution, the number of kernel vectors removed, and the mesh of the
/// nodes constrained to remove them (the last two, returned apart).
fn reso_ense(
    it: &mut Interp,
    r: &Rigidite,
    asm: &Assembled,
    loads: &[Load],
    o: &Opts,
) -> Result<(Vec<Rc<Chpoint>>, Vec<Value>)> {
    let opts = DirectOptions { check_residual: !o.noid, stab: o.stab };
    let held = hold_rigid_modes(&asm.problem, &opts).map_err(|e| explain(it, r, asm, e, loads))?;
    let sols = held.solve(loads).map_err(|e| explain(it, r, asm, e, loads))?;
    let fields: Vec<Rc<Chpoint>> = sols.iter().map(|s| Rc::new(solution_field(asm, s))).collect();
    let mut nodes: Vec<usize> = Vec::new();
    for &j in &held.held {
        let n = asm.dofs[j].0;
        if !nodes.contains(&n) {
            nodes.push(n);
        }
    }
    let extra = vec![Value::Int(held.held.len() as i64), Value::Mesh(Rc::new(crate::fem::mesh::Mesh::points(&nodes)))];
    Ok((fields, extra))
}

fn merge(o: &mut Opts, m: Opts) {
    o.ense |= m.ense;
    o.noid |= m.noid;
    o.nounil |= m.nounil;
    o.stab |= m.stab;
    o.soft |= m.soft;
    o.verbose |= m.verbose;
    if m.initial.is_some() {
        o.initial = m.initial;
    }
    if m.method != Method::Auto {
        o.method = m.method;
    }
    if m.max_iter.is_some() {
        o.max_iter = m.max_iter;
    }
    if m.rule != crate::solve::unilateral::Rule::Auto {
        o.rule = m.rule;
    }
}

fn solve_unil(
    it: &mut Interp,
    r: &Rigidite,
    asm: &Assembled,
    load: &Load,
    o: &Opts,
) -> Result<(crate::solve::Solution, UnilReport)> {
    let opts = UnilOptions {
        method: o.method,
        max_iter: o.max_iter,
        initial: o.initial.clone(),
        rule: o.rule,
        keep_last: o.soft,
        cancel: Some(crate::solve::unilateral::status::Cancel(it.interrupt.shared())),
    };
    let mut lines = Vec::new();
    let verbose = o.verbose;
    let res = {
        let mut cache = r.cache.borrow_mut();
        let mut on_iter = |rec: &crate::solve::unilateral::IterRecord| {
            if verbose {
                lines.push(format!(
                    "UNIL iteration {:>3} ({}): active {:>5}, activated {:>4}, released {:>4}, worst violation {}, worst wrong sign {}",
                    rec.iteration,
                    rec.mode,
                    rec.active_count,
                    rec.activated.len(),
                    rec.released.len(),
                    fmt_float(rec.worst_violation),
                    fmt_float(rec.worst_wrong_sign)
                ));
            }
        };
        solve_unilateral(&asm.problem, load, &opts, &mut cache.unil, &mut on_iter)
    };
    for l in lines {
        it.println(&l);
    }
    let (sol, report) = res.map_err(|e| match e {
        // Ctrl-C between two status solves: the flag is used up here.
        SolveError::Interrupted => {
            it.interrupt.clear();
            crate::eval::interrupted()
        }
        e => explain(it, r, asm, e, std::slice::from_ref(load)),
    })?;
    if !report.converged {
        // 'SOUC': Cast3M's UNILATER returns its last iterate with a warning.
        let last = report.records.last().expect("an unconverged iteration has records");
        let changing: Vec<String> = last
            .activated
            .iter()
            .chain(&last.released)
            .take(8)
            .map(|&k| super::assemble::describe_condition(it, r, asm.origin(k), load.d.get(k).copied().unwrap_or(0.0)))
            .collect();
        it.println(&format!(
            "RESO 'SOUC': warning: the status iteration did not converge after {} solves; the last iterate is returned ({} condition(s) still changing: {})",
            report.iterations,
            last.activated.len() + last.released.len(),
            changing.join("; ")
        ));
    }
    // Only equality rows are merged: the unilateral ones keep their order.
    let statuses =
        asm.problem.conditions.iter().enumerate().filter(|(_, c)| c.kind.is_unilateral()).map(|(k, _)| sol.active[k]);
    r.cache.borrow_mut().last_unil = Some((report.clone(), statuses.collect()));
    Ok((sol, report))
}

fn record(it: &mut Interp, report: &UnilReport) {
    for (name, s) in &report.phase_seconds {
        it.timers.phase(&format!("UNIL {}", name), *s);
    }
    if it.opts.echo >= 1 {
        it.println(&format!(
            "UNIL {}: {} condition(s), {} solve(s), {} active",
            report.method, report.m, report.iterations, report.active_count
        ));
    }
}

/// REAC of a solution, or of each solution of a LISTCHPO.
fn reac(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let r = a.req::<Rc<Rigidite>>()?;
    Ok(vec![match a.req::<Rhs>()? {
        Rhs::One(u) => Value::Chpo(Rc::new(r.reactions(&u))),
        Rhs::List(l) => Value::ListChpo(Rc::new(l.iter().map(|u| Rc::new(r.reactions(u))).collect())),
    }])
}

/// The diagnostics TABLE of one unilateral solve: what UNIL returns, and
/// what `EXTR RIG 'CONT'` gives back afterwards.
/// `statuses`: the final status of each unilateral condition, in order.
pub(crate) fn diagnostics(rep: &UnilReport, statuses: &[bool]) -> Value {
    let mut t = Table::with_subtype("UNILATERAL");
    let set = |t: &mut Table, k: &str, v: Value| t.set(Key::Mot(k.into()), v);
    set(&mut t, "METHODE", Value::mot(rep.method));
    set(&mut t, "NCONDITIONS", Value::Int(rep.m as i64));
    set(&mut t, "NITER", Value::Int(rep.iterations as i64));
    set(&mut t, "NACTIFS", Value::Int(rep.active_count as i64));
    set(&mut t, "CONVERGE", Value::Bool(rep.converged));
    let mut iters = Table::new();
    for (i, rec) in rep.records.iter().enumerate() {
        let mut e = Table::new();
        set(&mut e, "ACTIVES", Value::Int(rec.active_count as i64));
        set(&mut e, "ACTIVEES", Value::Int(rec.activated.len() as i64));
        set(&mut e, "RELACHEES", Value::Int(rec.released.len() as i64));
        set(&mut e, "VIOLATION", Value::Float(rec.worst_violation));
        set(&mut e, "MAUVAIS_SIGNE", Value::Float(rec.worst_wrong_sign));
        set(&mut e, "MODE", Value::mot(rec.mode));
        iters.set(Key::Int(i as i64 + 1), Value::Table(Rc::new(RefCell::new(e))));
    }
    set(&mut t, "ITERATIONS", Value::Table(Rc::new(RefCell::new(iters))));
    let mut phases = Table::new();
    for (name, s) in &rep.phase_seconds {
        phases.set(Key::Mot(name.to_uppercase()), Value::Float(*s));
    }
    set(&mut t, "TEMPS", Value::Table(Rc::new(RefCell::new(phases))));
    let statuses: Vec<i64> = statuses.iter().map(|&s| s as i64).collect();
    set(&mut t, "STATUTS", Value::ListEnti(Rc::new(statuses)));
    Value::Table(Rc::new(RefCell::new(t)))
}

/// UNIL: the unilateral solver called directly, with its diagnostics.
fn unil(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let r = a.req::<Rc<Rigidite>>()?;
    let mut o = read_options(it, a, &r)?;
    let f = a.req::<Rc<Chpoint>>()?;
    merge(&mut o, read_options(it, a, &r)?);
    if r.n_unilateral() == 0 {
        return Err(a.err("the RIGIDITE holds no unilateral condition"));
    }
    let asm = r.numbered();
    let load = assemble::load_of(it, &r, &asm, &[&f]).map_err(|e| a.err(e.message))?;
    finite_data(&asm, std::slice::from_ref(&load)).map_err(|e| a.err(e))?;
    let (sol, rep) = solve_unil(it, &r, &asm, &load, &o)?;
    record(it, &rep);
    // solve_unil kept the report with the RIGIDITE (EXTR RIG 'CONT').
    let statuses: Vec<bool> = r.cache.borrow().last_unil.as_ref().map(|l| l.1.clone()).unwrap_or_default();
    let t = diagnostics(&rep, &statuses);
    let field = Rc::new(solution_field(&asm, &sol));
    finite_solutions(std::slice::from_ref(&field)).map_err(|e| a.err(e))?;
    Ok(vec![Value::Chpo(field), t])
}
