//! SIMPLEX: linear programming over coefficients held in tables (the
//! numerics in `solve::simplex`). The objective table holds F0 at index 0
//! and Fi at index i; each inequality or equality is a sub-table with its
//! right-hand side at 0 and its coefficients at 1…n. Absent indices are
//! zeros, in the input and in the output.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::solve::simplex::{self, Outcome, Program};
use crate::value::{Key, Table, Value};
use std::cell::RefCell;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "SIMPLEX",
    signature: "SIMPLEX F_TABLE INEQ_TABLE EQ_TABLE [TOL] -> ENTIER TABLE TABLE",
    doc: "Maximises F0 + Σ Fi Xi over Xi ≥ 0 with Σ Iji Xi ≤ Ij and Σ Eji Xi = Ej (coefficients in tables, right-hand sides at index 0); gives 0 and the solution (F at 0, Xi at i) and the slacks of the inequalities, 1 if unbounded, −1 if infeasible (then the tables are empty).",
    example: "f = tabl ; f . 1 = 1. ; i = tabl ; i . 1 = tabl ; i . 1 . 0 = 2. ; i . 1 . 1 = 1. ; k x d = simplex f i (tabl) ;",
    f: simplex_op,
}];

type Tab = Rc<RefCell<Table>>;

fn simplex_op(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let f = a.req::<Tab>()?;
    let ineq = a.req::<Tab>()?;
    let eq = a.req::<Tab>()?;
    let tol = a.opt_num().unwrap_or(1e-10);
    if !(tol.is_finite() && tol > 0.0) {
        return Err(a.err(format!("the tolerance must be positive, found {}", tol)));
    }
    let fc = coefficients(a, &f.borrow(), "the objective")?;
    let ic = rows(a, &ineq.borrow(), "inequality")?;
    let ec = rows(a, &eq.borrow(), "equality")?;
    let n = fc.keys().chain(ic.iter().chain(&ec).flat_map(|(_, r)| r.keys())).max().unwrap_or(0);
    let dense = |c: &Coeffs| -> (Vec<f64>, f64) {
        let mut v = vec![0.0; n];
        for (&i, &x) in &c.0 {
            if i > 0 {
                v[i - 1] = x;
            }
        }
        (v, c.get(0))
    };
    let (c, c0) = dense(&fc);
    let p = Program {
        c0,
        c,
        le: ic.iter().map(|(_, r)| dense(r)).collect(),
        eq: ec.iter().map(|(_, r)| dense(r)).collect(),
    };
    let (code, xs, ds) = match simplex::solve(&p, tol) {
        Outcome::Optimum { value, x, slack } => {
            let mut xs = Table::new();
            xs.set(Key::Int(0), Value::Float(value));
            for (i, v) in x.iter().enumerate() {
                if *v != 0.0 {
                    xs.set(Key::Int(i as i64 + 1), Value::Float(*v));
                }
            }
            let mut ds = Table::new();
            for ((j, _), v) in ic.iter().zip(&slack) {
                if *v != 0.0 {
                    ds.set(Key::Int(*j), Value::Float(*v));
                }
            }
            (0, xs, ds)
        }
        Outcome::Unbounded => (1, Table::new(), Table::new()),
        Outcome::Infeasible => (-1, Table::new(), Table::new()),
    };
    Ok(vec![Value::Int(code), Value::Table(Rc::new(RefCell::new(xs))), Value::Table(Rc::new(RefCell::new(ds)))])
}

/// Coefficients by index (0 the constant or right-hand side).
struct Coeffs(std::collections::BTreeMap<usize, f64>);

impl Coeffs {
    fn keys(&self) -> impl Iterator<Item = usize> + '_ {
        self.0.keys().copied()
    }
    fn get(&self, i: usize) -> f64 {
        self.0.get(&i).copied().unwrap_or(0.0)
    }
}

fn coefficients(a: &Args, t: &Table, what: &str) -> Result<Coeffs> {
    let mut c = std::collections::BTreeMap::new();
    for (k, v) in t.iter() {
        let Key::Int(i) = k else { continue };
        let i = usize::try_from(*i).map_err(|_| a.err(format!("{} has a negative index {}", what, i)))?;
        let x = match v {
            Value::Float(x) => *x,
            Value::Int(x) => *x as f64,
            other => {
                return Err(a.err(format!("{} holds a {} at index {}, not a FLOTTANT", what, other.type_name(), i)))
            }
        };
        if !x.is_finite() {
            return Err(a.err(format!("{} holds a non-finite value at index {}", what, i)));
        }
        c.insert(i, x);
    }
    Ok(Coeffs(c))
}

/// The constraint sub-tables, in the order of their indices.
fn rows(a: &Args, t: &Table, what: &str) -> Result<Vec<(i64, Coeffs)>> {
    let mut out = Vec::new();
    for (k, v) in t.iter() {
        let Key::Int(j) = k else { continue };
        let Value::Table(r) = v else {
            return Err(a.err(format!("the {} table holds a {} at index {}, not a TABLE", what, v.type_name(), j)));
        };
        out.push((*j, coefficients(a, &r.borrow(), &format!("{} {}", what, j))?));
    }
    out.sort_by_key(|(j, _)| *j);
    Ok(out)
}
