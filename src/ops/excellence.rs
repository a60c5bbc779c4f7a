//! EXCELLENCE: one step of the method of moving asymptotes (exce.notice).
//! The deck computes the objective, the constraints and their gradients;
//! EXCE reads them from the table and writes the next point in
//! TAB1.'VX0'. Numerics in `solve::mma`. The moving method needs the two
//! previous points and asymptotes: they are kept in the table itself
//! (entries 'EXCE_X1', 'EXCE_X2', 'EXCE_LOW', 'EXCE_UPP').

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::solve::mma::{self, Asymptotes, History};
use crate::value::{Key, Table, Value};
use std::cell::RefCell;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "EXCE",
    signature: "EXCELLENCE TABLE -> TABLE",
    doc: "One step of the method of moving asymptotes (MMA): from TAB.'VX0' (x), TAB.'VF' (f at .0, its gradient at .1…N), TAB.'MC' . j (each constraint likewise), TAB.'VCMAX' . j (their bounds), TAB.'VXMIN' and TAB.'VXMAX', the minimum of the convex approximation; written in TAB.'VX0'. 'METHODE' 'STA' (fixed asymptotes, 'T0', default 1/3), 'MOV' (moving, 'S0', default 0.7) or 'LIN'.",
    example: "t = tabl ; v = tabl ; v . 1 = 2. ; t . 'VX0' = v ; f = tabl ; f . 0 = 4. ; f . 1 = 4. ; t . 'VF' = f ; t . 'MC' = tabl ; t . 'VCMAX' = tabl ; a = tabl ; a . 1 = 0.5 ; t . 'VXMIN' = a ; b = tabl ; b . 1 = 10. ; t . 'VXMAX' = b ; t = exce t ;",
    f: exce,
}];

type Tab = Rc<RefCell<Table>>;

fn exce(_: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let tab = a.req::<Tab>()?;
    let t = tab.borrow();
    let sub = |name: &str| match t.get(&Key::Mot(name.into())) {
        Some(Value::Table(s)) => Ok(s.clone()),
        _ => Err(a.err(format!("the table has no table '{name}'"))),
    };
    let vx0 = sub("VX0")?;
    let n = (1..).take_while(|i| vx0.borrow().get(&Key::Int(*i)).is_some()).count();
    if n == 0 {
        return Err(a.err("TAB.'VX0' holds no variable (expected at indices 1, 2, …)"));
    }
    let list = |s: &Tab, what: &str, from: i64, count: usize| -> Result<Vec<f64>> {
        (from..from + count as i64)
            .map(|i| match s.borrow().get(&Key::Int(i)) {
                Some(Value::Float(v)) if v.is_finite() => Ok(*v),
                Some(Value::Int(v)) => Ok(*v as f64),
                _ => Err(a.err(format!("{what} . {i} is not a finite number"))),
            })
            .collect()
    };
    let x = list(&vx0, "TAB.'VX0'", 1, n)?;
    let grad_f = list(&sub("VF")?, "TAB.'VF'", 1, n)?;
    let xmin = list(&sub("VXMIN")?, "TAB.'VXMIN'", 1, n)?;
    let xmax = list(&sub("VXMAX")?, "TAB.'VXMAX'", 1, n)?;
    for i in 0..n {
        if xmin[i] >= xmax[i] || x[i] < xmin[i] || x[i] > xmax[i] {
            return Err(a.err(format!(
                "variable {}: it must lie within its bounds, min < max (x = {}, min = {}, max = {})",
                i + 1,
                x[i],
                xmin[i],
                xmax[i]
            )));
        }
    }
    let mc = sub("MC")?;
    let m = (1..).take_while(|j| mc.borrow().get(&Key::Int(*j)).is_some()).count();
    let bounds = if m > 0 { list(&sub("VCMAX")?, "TAB.'VCMAX'", 1, m)? } else { vec![] };
    let mut cons = Vec::with_capacity(m);
    for (j, b) in bounds.into_iter().enumerate() {
        let cj = match mc.borrow().get(&Key::Int(j as i64 + 1)) {
            Some(Value::Table(c)) => c.clone(),
            _ => return Err(a.err(format!("TAB.'MC' . {} is not a table", j + 1))),
        };
        let v = list(&cj, &format!("TAB.'MC' . {}", j + 1), 0, n + 1)?;
        cons.push((v[0], v[1..].to_vec(), b));
    }
    let num = |name: &str| match t.get(&Key::Mot(name.into())) {
        Some(Value::Float(v)) => Some(*v),
        Some(Value::Int(v)) => Some(*v as f64),
        _ => None,
    };
    let method = match t.get(&Key::Mot("METHODE".into())) {
        Some(Value::Mot(w)) => w.trim().to_uppercase(),
        None => "STA".into(),
        Some(_) => return Err(a.err("TAB.'METHODE' must be a word: 'STA', 'MOV' or 'LIN'")),
    };
    let how = match method.as_str() {
        "STA" => Asymptotes::Fixed(num("T0").unwrap_or(1.0 / 3.0)),
        "MOV" => Asymptotes::Moving(num("S0").unwrap_or(0.7)),
        "LIN" => Asymptotes::Linear,
        w => return Err(a.err(format!("TAB.'METHODE' is {w}: expected 'STA', 'MOV' or 'LIN'"))),
    };
    if let Asymptotes::Fixed(c) | Asymptotes::Moving(c) = how {
        if !(c > 0.0 && c < 1.0) {
            return Err(a.err(format!("'T0' and 'S0' lie strictly between 0 and 1 (got {c})")));
        }
    }
    let hist_list = |name: &str| match t.get(&Key::Mot(name.into())) {
        Some(Value::ListReel(l)) if l.len() == n => Some(l.to_vec()),
        _ => None,
    };
    let h = History {
        x1: hist_list("EXCE_X1"),
        x2: hist_list("EXCE_X2"),
        low: hist_list("EXCE_LOW"),
        upp: hist_list("EXCE_UPP"),
    };
    let s = mma::Step { x: &x, grad_f: &grad_f, cons: &cons, xmin: &xmin, xmax: &xmax };
    let (low, upp) = mma::asymptotes(&s, how, &h);
    let next = mma::step(&s, &low, &upp);
    if next.iter().any(|v| !v.is_finite()) {
        return Err(a.err("the step gives a non-finite point"));
    }
    let mut out = vx0.borrow().clone();
    for (i, v) in next.iter().enumerate() {
        out.set(Key::Int(i as i64 + 1), Value::Float(*v));
    }
    let x1 = h.x1.clone();
    drop(t);
    let mut t = tab.borrow_mut();
    t.set(Key::Mot("VX0".into()), Value::Table(Rc::new(RefCell::new(out))));
    let l = |v: Vec<f64>| Value::ListReel(Rc::new(v));
    if let Some(x1) = x1 {
        t.set(Key::Mot("EXCE_X2".into()), l(x1));
    }
    t.set(Key::Mot("EXCE_X1".into()), l(x));
    t.set(Key::Mot("EXCE_LOW".into()), l(low));
    t.set(Key::Mot("EXCE_UPP".into()), l(upp));
    drop(t);
    Ok(vec![Value::Table(tab)])
}
