//! RESO, REAC and UNIL: the bridge between RIGIDITE objects and `solve`.

use super::assemble::Assembled;
use super::{Args, OpDef};
use crate::error::{Error, Result};
use crate::eval::Interp;
use crate::solve::direct::{DirectOptions, Factorization};
use crate::solve::unilateral::{solve_unilateral, Method, UnilOptions, UnilReport};
use crate::solve::Load;
use crate::value::{fmt_float, Chpoint, Key, Nature, Rigidite, Table, Value};
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

/// The numbering of a RIGIDITE, computed once per object.
fn assembled(r: &Rigidite) -> Rc<Assembled> {
    let mut cache = r.cache.borrow_mut();
    cache.assembled.get_or_insert_with(|| Rc::new(Assembled::new(r))).clone()
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
    let asm = assembled(&r);
    let loads: Vec<Load> =
        rhs.iter().map(|c| asm.load(it, &[c])).collect::<Result<_>>().map_err(|e| a.err(e.message))?;
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
            sols.push(Rc::new(asm.field(&r, &sol)));
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
    let mut warnings: Vec<String> = Vec::new();
    let sols = {
        let key = {
            let mut cache = r.cache.borrow_mut();
            let id = cache.id;
            let k = *cache.key.get_or_insert_with(|| crate::solve::lagrange::structure_hash(&asm.problem));
            // STAB changes the values factorised: keep it in the key.
            (k ^ (o.stab as u64).wrapping_mul(0x9e37_79b9_7f4a_7c15), id)
        };
        let (key, id) = key;
        let opts = DirectOptions { check_residual: !o.noid, stab: o.stab };
        let mut phase = "reused";
        let entry = match it.factors.get(key) {
            Some(e) if e.owner == id => e,
            Some(e) if e.fact.same_pattern(&asm.problem) => {
                // Same pattern, new values: numeric factorisation only.
                let res = e.fact.refactor(&asm.problem);
                e.owner = id;
                phase = "numeric refactorisation";
                if let Err(err) = res {
                    return soft_singular(it, r, asm, loads, o, err);
                }
                it.factors.get(key).expect("present")
            }
            _ => {
                let f = match Factorization::new(&asm.problem, &opts) {
                    Ok(f) => f,
                    Err(e) => return soft_singular(it, r, asm, loads, o, e),
                };
                phase = "factorisation";
                it.factors.insert(crate::ops::solver_cache::PoolEntry { key, owner: id, fact: f })
            }
        };
        let fact_s = t.elapsed().as_secs_f64();
        let t = std::time::Instant::now();
        let s = match entry.fact.solve_checked(loads, !o.noid) {
            // 'SOUC': an inaccurate solution is a warning, not a failure.
            Err(crate::solve::SolveError::Inaccurate { residual, .. }) if o.soft => {
                let s = entry.fact.solve_checked(loads, false);
                warnings.push(format!(
                    "RESO 'SOUC': warning: inaccurate solution (relative residual {}) returned anyway",
                    crate::value::fmt_float(residual)
                ));
                s.map_err(|e| asm.explain(it, r, e, loads))
            }
            other => other.map_err(|e| asm.explain(it, r, e, loads)),
        };
        let solve_s = t.elapsed().as_secs_f64();
        if phase != "reused" {
            it.timers.phase(&format!("RESO {}", phase), fact_s);
        }
        it.timers.phase("RESO solve", solve_s);
        if it.opts.echo >= 1 {
            it.println(&format!(
                "RESO: {} unknowns, {} conditions, {} right-hand side(s); matrix {} ({:.3} s), solve {:.3} s",
                asm.problem.k.n,
                asm.problem.conditions.len(),
                loads.len(),
                phase,
                fact_s,
                solve_s
            ));
        }
        s
    };
    for w in warnings {
        it.println(&w);
    }
    Ok(sols?.iter().map(|s| Rc::new(asm.field(r, s))).collect())
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
    e: crate::solve::SolveError,
) -> Result<Vec<Rc<Chpoint>>> {
    if !(o.soft && matches!(e, crate::solve::SolveError::Singular { .. })) {
        return Err(asm.explain(it, r, e, loads));
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
    use crate::solve::{Condition, Kind, SolveError};
    let opts = DirectOptions { check_residual: !o.noid, stab: o.stab };
    let mut p = asm.problem.clone();
    let mut held: Vec<usize> = Vec::new();
    let fact = loop {
        match Factorization::new(&p, &opts) {
            Ok(f) => break f,
            Err(SolveError::Singular { dofs }) if !dofs.is_empty() && !held.contains(&dofs[0]) && held.len() < 64 => {
                held.push(dofs[0]);
                p.conditions.push(Condition { terms: vec![(dofs[0], 1.0)], kind: Kind::Equal, dual: None });
            }
            Err(e) => return Err(asm.explain(it, r, e, loads)),
        }
    };
    let extended: Vec<Load> = loads
        .iter()
        .map(|l| {
            let mut d = l.d.clone();
            d.resize(p.conditions.len(), 0.0);
            Load { f: l.f.clone(), d }
        })
        .collect();
    let sols = fact.solve(&extended).map_err(|e| asm.explain(it, r, e, loads))?;
    let fields: Vec<Rc<Chpoint>> = sols.iter().map(|s| Rc::new(asm.field(r, s))).collect();
    let mut nodes: Vec<usize> = Vec::new();
    for &j in &held {
        let n = asm.dofs[j].0;
        if !nodes.contains(&n) {
            nodes.push(n);
        }
    }
    let extra = vec![Value::Int(held.len() as i64), Value::Mesh(Rc::new(crate::fem::mesh::Mesh::points(&nodes)))];
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
        cancel: Some(crate::solve::status::Cancel(it.interrupt.shared())),
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
        crate::solve::SolveError::Interrupted => {
            it.interrupt.clear();
            crate::eval::interrupted()
        }
        e => asm.explain(it, r, e, std::slice::from_ref(load)),
    })?;
    if !report.converged {
        // 'SOUC': Cast3M's UNILATER returns its last iterate with a warning.
        let last = report.records.last().expect("an unconverged iteration has records");
        let changing: Vec<String> = last
            .activated
            .iter()
            .chain(&last.released)
            .take(8)
            .map(|&k| super::assemble::describe_condition(it, r, k, load.d.get(k).copied().unwrap_or(0.0)))
            .collect();
        it.println(&format!(
            "RESO 'SOUC': warning: the status iteration did not converge after {} solves; the last iterate is returned ({} condition(s) still changing: {})",
            report.iterations,
            last.activated.len() + last.released.len(),
            changing.join("; ")
        ));
    }
    r.cache.borrow_mut().last_unil = Some(diagnostics(r, &sol, &report));
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
        Rhs::One(u) => Value::Chpo(Rc::new(reaction(&r, &u))),
        Rhs::List(l) => Value::ListChpo(Rc::new(l.iter().map(|u| Rc::new(reaction(&r, u))).collect())),
    }])
}

fn reaction(r: &Rigidite, u: &Chpoint) -> Chpoint {
    let mut out = Chpoint::new(Nature::Discret);
    for c in &r.conds {
        // An inactive unilateral condition has no LX: its reaction is 0
        // (reac.notice), written explicitly so EXTR finds it.
        let l = u.get(c.mult_node, "LX").unwrap_or(0.0);
        for (n, comp, coef) in c.reaction_terms() {
            out.add(*n, &super::dofs::dual_of(comp), -coef * l, true);
        }
    }
    out
}

/// The diagnostics TABLE of one unilateral solve: what UNIL returns, and
/// what `EXTR RIG 'CONT'` gives back afterwards.
fn diagnostics(r: &Rigidite, sol: &crate::solve::Solution, rep: &UnilReport) -> Value {
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
    let statuses: Vec<i64> =
        r.conds.iter().enumerate().filter(|(_, c)| c.kind.is_unilateral()).map(|(k, _)| sol.active[k] as i64).collect();
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
    let asm = assembled(&r);
    let load = asm.load(it, &[&f]).map_err(|e| a.err(e.message))?;
    finite_data(&asm, std::slice::from_ref(&load)).map_err(|e| a.err(e))?;
    let (sol, rep) = solve_unil(it, &r, &asm, &load, &o)?;
    record(it, &rep);
    // solve_unil kept the diagnostics with the RIGIDITE (EXTR RIG 'CONT').
    let t = r.cache.borrow().last_unil.clone().unwrap_or_else(|| diagnostics(&r, &sol, &rep));
    let field = Rc::new(asm.field(&r, &sol));
    finite_solutions(std::slice::from_ref(&field)).map_err(|e| a.err(e))?;
    Ok(vec![Value::Chpo(field), t])
}

#[allow(dead_code)]
fn unused(_: Error) {}
