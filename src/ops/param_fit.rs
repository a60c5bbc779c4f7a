//! MOCA and LEVM: fitting a model's parameters to measured values
//! (moca.notice, levm.notice). MOCA is one least-squares step for a model
//! given with its derivatives; LEVM runs Levenberg-Marquardt, calling a
//! Gibiane procedure for the model. Numerics in `value::signal::levmar`.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::machine::GroupState;
use crate::eval::Interp;
use crate::syntax::ast::ProcDef;
use crate::value::signal::levmar;
use crate::value::Value;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "MOCA",
        signature: "MOCA PARAMS MEASURED VALUES DERIV_1 … DERIV_P ('POIDS' WEIGHTS) -> LISTREEL",
        doc: "One least-squares step: the parameters p + δ, δ minimising Σ (w (m − f − Σ δ_i d_i))², for a model of values f at parameters p with derivatives d_i (one LISTREEL per parameter), measured values m and weights w (1 by default).",
        example: "p = moca (prog 0. 0.) (prog 1. 3. 5.) (prog 0. 0. 0.) (prog 1. 1. 1.) (prog 0. 1. 2.) ;",
        f: moca,
    },
    OpDef {
        name: "LEVM",
        signature: "LEVM 'ABSC' X 'ORDO' Y ('SIGM' SIGMA) 'PARA' P0 'PROC' PROCEDURE -> LISTREEL FLOTTANT",
        doc: "Levenberg-Marquardt fit of parameters to the points (X, Y): the procedure, called with X and the parameters, returns the model's values at X and their derivatives (a LISTREEL, for each point the derivatives in every parameter). Gives the parameters minimising χ² = Σ ((Y − f)/SIGMA)² (SIGMA 1 by default) and that χ².",
        example: "debp f x*listreel p*listreel ; finp (x * (extr p 1)) x ; p c = levm 'ABSC' (prog 1. 2.) 'ORDO' (prog 2. 4.) 'PARA' (prog 1.) 'PROC' f ;",
        f: levm,
    },
];

type List = Rc<Vec<f64>>;

fn moca(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let p = a.req::<List>()?;
    let m = a.req::<List>()?;
    let f = a.req::<List>()?;
    let n = m.len();
    same_len(a, "the model's values", f.len(), n)?;
    let mut d = Vec::with_capacity(p.len());
    for i in 0..p.len() {
        let di = a.opt::<List>().ok_or_else(|| {
            a.err(format!("{} parameters need {} LISTREEL of derivatives; only {} given", p.len(), p.len(), i))
        })?;
        same_len(a, "each list of derivatives", di.len(), n)?;
        d.push(di.to_vec());
    }
    let w = match a.keyword(&["POIDS"]) {
        Some(_) => {
            let w = a.req::<List>()?;
            same_len(a, "the weights", w.len(), n)?;
            w.to_vec()
        }
        None => vec![1.0; n],
    };
    finite(a, [&p[..], &m, &f, &w].into_iter().chain(d.iter().map(|v| &v[..])))?;
    let q = levmar::gauss_newton_step(&p, &m, &f, &d, &w).map_err(|e| a.err(e))?;
    Ok(vec![Value::ListReel(Rc::new(q))])
}

fn levm(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let (mut x, mut y, mut s, mut p0, mut proc_) = (None, None, None, None, None::<Rc<ProcDef>>);
    while let Some(k) = a.keyword(&["ABSC", "ORDO", "SIGM", "PARA", "PROC"]) {
        match k {
            "ABSC" => x = Some(a.req::<List>()?),
            "ORDO" => y = Some(a.req::<List>()?),
            "SIGM" => s = Some(a.req::<List>()?),
            "PARA" => p0 = Some(a.req::<List>()?),
            _ => proc_ = Some(a.right_proc().ok_or_else(|| a.missing("PROCEDURE"))?),
        }
    }
    let x = x.ok_or_else(|| a.missing("'ABSC' LISTREEL"))?;
    let y = y.ok_or_else(|| a.missing("'ORDO' LISTREEL"))?;
    let p0 = p0.ok_or_else(|| a.missing("'PARA' LISTREEL"))?;
    let proc_ = proc_.ok_or_else(|| a.missing("'PROC' PROCEDURE"))?;
    let n = x.len();
    same_len(a, "'ORDO'", y.len(), n)?;
    let s = match s {
        Some(s) => {
            same_len(a, "'SIGM'", s.len(), n)?;
            if s.contains(&0.0) {
                return Err(a.err("'SIGM' holds a zero: every point needs a non-zero weight σ"));
            }
            s.to_vec()
        }
        None => vec![1.0; n],
    };
    finite(a, [&x[..], &y, &s, &p0])?;
    let m = p0.len();
    let span = a.span;
    let name = proc_.name.clone();
    let r = levmar::levenberg_marquardt(&p0, &y, &s, 500, |p| {
        let mut st = GroupState {
            left: vec![Value::ListReel(x.clone()), Value::ListReel(Rc::new(p.to_vec()))],
            right: Default::default(),
        };
        let out = it.call_proc(proc_.clone(), &mut st, span)?;
        let list = |v: Option<&Value>, what: &str, len: usize| match v {
            Some(Value::ListReel(l)) if l.len() == len && l.iter().all(|v| v.is_finite()) => Ok(l.clone()),
            Some(Value::ListReel(l)) if l.len() == len => {
                Err(a.err(format!("{name} returned a non-finite number in {what}")))
            }
            Some(Value::ListReel(l)) => {
                Err(a.err(format!("{name} returned {} numbers for {what}, {len} expected", l.len())))
            }
            _ => {
                Err(a
                    .err(format!("{name} must return two LISTREEL: the values at the abscissas, then the derivatives")))
            }
        };
        let f = list(out.first(), "the values", n)?;
        let d = list(out.get(1), "the derivatives (for each point, one per parameter)", n * m)?;
        Ok::<_, crate::error::Error>((f.to_vec(), d.chunks(m.max(1)).map(|c| c.to_vec()).collect()))
    })?;
    let (p, c) = r.map_err(|e| a.err(e))?;
    Ok(vec![Value::ListReel(Rc::new(p)), Value::Float(c)])
}

fn same_len(a: &Args, what: &str, got: usize, n: usize) -> Result<()> {
    if got != n {
        return Err(a.err(format!("{what} hold {got} values, the measured values {n}")));
    }
    Ok(())
}

fn finite<'v>(a: &Args, lists: impl IntoIterator<Item = &'v [f64]>) -> Result<()> {
    if lists.into_iter().flatten().any(|v| !v.is_finite()) {
        return Err(a.err("the lists hold a non-finite number"));
    }
    Ok(())
}
