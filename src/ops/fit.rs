//! AJU1 and AJU2: the least-squares steps of the AJUSTE procedure
//! (numerics in `value::signal::fit`). The function values come in a
//! TABLE: `.'F'` a table of LISTREEL indexed 1…L (one per linear
//! coefficient), `.'G'` an optional LISTREEL added to the fit; AJU2's
//! second table holds the derivatives in the nonlinear parameters,
//! `.'F' . j . i` and `.'G' . j`.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::signal::fit;
use crate::value::{Key, Table, Value};
use std::cell::RefCell;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[
    OpDef {
        name: "AJU1",
        signature: "AJU1 L TABLE Y WEIGHTS -> FLOTTANT LISTREEL",
        doc: "Weighted linear least squares (a step of AJUSTE): the L coefficients q minimising Σ (w (g + Σ q_i f_i − y))², the functions f_i and g read in TABLE (.'F'.i, .'G'); gives the minimum, then q.",
        example: "t = tabl ; t . 'F' = tabl ; t . 'F' . 1 = prog 1. 1. ; phi q = aju1 1 t (prog 2. 4.) (prog 1. 1.) ;",
        f: aju1,
    },
    OpDef {
        name: "AJU2",
        signature: "AJU2 K Q TABLE DTABLE Y WEIGHTS -> FLOTTANT LISTREEL",
        doc: "Gradient of the weighted residual in K nonlinear parameters (a step of AJUSTE): d_j = Σ w² (y − g − Σ q_i f_i)(∂g/∂p_j + Σ q_i ∂f_i/∂p_j), the derivatives read in DTABLE (.'F'.j.i, .'G'.j); gives Σ d_j², then d.",
        example: "t = tabl ; t . 'G' = prog 1. 1. ; d = tabl ; d . 'G' = tabl ; d . 'G' . 1 = prog 1. 1. ; a g = aju2 1 (prog) t d (prog 2. 4.) (prog 1. 1.) ;",
        f: aju2,
    },
];

type Tab = Rc<RefCell<Table>>;

fn aju1(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let l = count(a)?;
    let t = a.req::<Tab>()?;
    let y = a.req::<Rc<Vec<f64>>>()?;
    let w = a.req::<Rc<Vec<f64>>>()?;
    let n = y.len();
    check_len(a, "the weights", w.len(), n)?;
    let (f, g) = functions(a, &t, l, n)?;
    let (q, phi) = fit::linear(&f, &g, &y, &w).map_err(|e| a.err(e))?;
    Ok(vec![Value::Float(phi), Value::ListReel(Rc::new(q))])
}

fn aju2(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let k = count(a)?;
    let q = a.req::<Rc<Vec<f64>>>()?;
    let t = a.req::<Tab>()?;
    let dt = a.req::<Tab>()?;
    let y = a.req::<Rc<Vec<f64>>>()?;
    let w = a.req::<Rc<Vec<f64>>>()?;
    let (l, n) = (q.len(), y.len());
    check_len(a, "the weights", w.len(), n)?;
    let (f, g) = functions(a, &t, l, n)?;
    let has_g = t.borrow().get(&Key::Mot("G".into())).is_some();
    let mut dg = vec![vec![0.0; n]; k];
    let mut df = vec![vec![vec![0.0; n]; l]; k];
    if l > 0 {
        let tf = sub_table(a, &dt, "F")?;
        for (j, dfj) in df.iter_mut().enumerate() {
            let tj = indexed_table(a, &tf, j + 1, "F")?;
            for (i, dfji) in dfj.iter_mut().enumerate() {
                *dfji = indexed_list(a, &tj, i + 1, n, &format!("F . {}", j + 1))?;
            }
        }
    }
    if has_g {
        let tg = sub_table(a, &dt, "G")?;
        for (j, dgj) in dg.iter_mut().enumerate() {
            *dgj = indexed_list(a, &tg, j + 1, n, "G")?;
        }
    }
    let (d, s) = fit::gradient(&f, &g, &q, &dg, &df, &y, &w);
    Ok(vec![Value::Float(s), Value::ListReel(Rc::new(d))])
}

fn count(a: &mut Args) -> Result<usize> {
    let l = a.req::<i64>()?;
    usize::try_from(l).map_err(|_| a.err(format!("the number of coefficients must be positive or zero, found {}", l)))
}

fn check_len(a: &Args, what: &str, have: usize, n: usize) -> Result<()> {
    if have != n {
        return Err(a.err(format!("{} have {} values, the data {}", what, have, n)));
    }
    Ok(())
}

/// `.'F' . 1…l` and `.'G'` (zero when absent) of the function table.
fn functions(a: &Args, t: &Tab, l: usize, n: usize) -> Result<(Vec<Vec<f64>>, Vec<f64>)> {
    let mut f = Vec::with_capacity(l);
    if l > 0 {
        let tf = sub_table(a, t, "F")?;
        for i in 1..=l {
            f.push(indexed_list(a, &tf, i, n, "F")?);
        }
    }
    let g = match t.borrow().get(&Key::Mot("G".into())) {
        None => vec![0.0; n],
        Some(Value::ListReel(g)) if g.len() == n => g.to_vec(),
        Some(Value::ListReel(g)) => return Err(a.err(format!("the list G has {} values, the data {}", g.len(), n))),
        Some(v) => return Err(a.err(format!("the index G must hold a LISTREEL, found a {}", v.type_name()))),
    };
    Ok((f, g))
}

fn sub_table(a: &Args, t: &Tab, key: &str) -> Result<Tab> {
    match t.borrow().get(&Key::Mot(key.into())) {
        Some(Value::Table(s)) => Ok(s.clone()),
        _ => Err(a.err(format!("the table has no TABLE at index {}", key))),
    }
}

fn indexed_table(a: &Args, t: &Tab, i: usize, what: &str) -> Result<Tab> {
    match t.borrow().get(&Key::Int(i as i64)) {
        Some(Value::Table(s)) => Ok(s.clone()),
        _ => Err(a.err(format!("the table {} has no TABLE at index {}", what, i))),
    }
}

fn indexed_list(a: &Args, t: &Tab, i: usize, n: usize, what: &str) -> Result<Vec<f64>> {
    match t.borrow().get(&Key::Int(i as i64)) {
        Some(Value::ListReel(l)) if l.len() == n => Ok(l.to_vec()),
        Some(Value::ListReel(l)) => Err(a.err(format!("{} . {} has {} values, the data {}", what, i, l.len(), n))),
        _ => Err(a.err(format!("the table {} has no LISTREEL at index {}", what, i))),
    }
}
