//! FRON: arrival times of a front spreading at a given speed
//! (fron.notice). Numerics in `fem::front`.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::{Chpoint, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "FRON",
    signature: "FRON CHPO_TPS CHPO_VIT_TCMB T1 DT -> CHPOINT",
    doc: "Advance a front: CHPO_TPS holds at each point the time 'TPS' the front reaches it (points with TPS <= T1 have burnt at T1); the front spreads from them at the speed 'VIT', each point burning for 'TCMB' after it is reached. Gives the field with the times of the points reached by T1 + DT; the other points keep their value.",
    example: "p1 = 0. 0. ; p2 = 1. 0. ; t = (manu chpo p1 1 'TPS' 0.) et (manu chpo p2 1 'TPS' 9.) ; c = manu chpo (p1 et p2) 2 'VIT' 2. 'TCMB' 5. ; t = fron t c 0. 1. ;",
    f: fron,
}];

fn fron(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let times = a.req::<Rc<Chpoint>>()?;
    let cara = a.req::<Rc<Chpoint>>()?;
    let t1 = a.req_num()?;
    let dt = a.req_num()?;
    if !t1.is_finite() || !dt.is_finite() || dt < 0.0 {
        return Err(a.err(format!("T1 and DT must be finite numbers, DT >= 0 (T1 = {t1}, DT = {dt})")));
    }
    let (mut nodes, mut t, mut v, mut burn) = (vec![], vec![], vec![], vec![]);
    for (n, c, ti) in times.entries() {
        if c != "TPS" {
            continue;
        }
        let name = |comp: &str| {
            cara.get(n, comp).ok_or_else(|| {
                a.err(format!("the second field has no component '{comp}' at node {n}, where the times have 'TPS'"))
            })
        };
        let (vi, bi) = (name("VIT")?, name("TCMB")?);
        if !(ti.is_finite() && vi.is_finite() && bi.is_finite()) || vi < 0.0 {
            return Err(a.err(format!(
                "node {n}: 'TPS' {ti}, 'VIT' {vi}, 'TCMB' {bi}: the values must be finite and the speed >= 0"
            )));
        }
        nodes.push(n);
        t.push(ti);
        v.push(vi);
        burn.push(bi);
    }
    if nodes.is_empty() {
        return Err(a.err("the first field has no component 'TPS'"));
    }
    let x: Vec<[f64; 3]> = nodes.iter().map(|&n| it.nodes.get(n)).collect();
    let new = crate::fem::front::arrival_times(&x, &t, &v, &burn, t1, t1 + dt);
    let mut out = (*times).clone();
    for (n, ti) in nodes.iter().zip(new) {
        if let Some(ti) = ti {
            out.add(*n, "TPS", ti, false);
        }
    }
    Ok(vec![Value::Chpo(Rc::new(out))])
}
