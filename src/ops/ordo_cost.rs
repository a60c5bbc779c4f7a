//! `ORDO 'COUT' ('HONG'|'COMP') LISCOU LIS1 (… LISN)`: the permutation of
//! least total cost (ordo.notice), applied to the lists.

use super::lists::AnyList;
use super::{Args, FromArg};
use crate::error::Result;
use crate::solve::assignment;
use crate::value::Value;
use std::rc::Rc;

/// Called once ORDO has read the word 'COUT'. Returns the least total
/// cost (ENTIER for integer costs), then each list permuted: item i of a
/// result is item perm(i) of the list, perm minimising sum_i C(i, perm(i))
/// with C(i, j) at place (i-1)*n + j of LISCOU.
pub(super) fn ordo_cost(a: &mut Args) -> Result<Vec<Value>> {
    let exhaustive = a.keyword(&["HONG", "COMP"]) == Some("COMP");
    let costs = match a.opt_right::<AnyList>().or_else(|| a.opt::<AnyList>()) {
        Some(AnyList(Value::ListEnti(l))) => Cost::Int(l),
        Some(AnyList(Value::ListReel(l))) => Cost::Real(l),
        _ => return Err(a.missing("the costs after 'COUT' (LISTENTI or LISTREEL)")),
    };
    let mut lists = Vec::new();
    while let Some(AnyList(l)) = a.opt::<AnyList>() {
        lists.push(l);
    }
    let Some(first) = lists.first() else { return Err(a.missing(AnyList::EXPECT)) };
    let n = super::lists::list_len(first).unwrap_or(0);
    if let Some(l) = lists.iter().find(|l| super::lists::list_len(l) != Some(n)) {
        return Err(a.err(format!(
            "the lists have different lengths ({} and {})",
            n,
            super::lists::list_len(l).unwrap_or(0)
        )));
    }
    let c = costs.as_f64();
    if c.len() != n * n {
        return Err(a.err(format!("'COUT' needs n*n = {} costs for lists of {} items, found {}", n * n, n, c.len())));
    }
    if exhaustive && n > 10 {
        return Err(a.err(format!("'COMP' tries all {}! permutations: too many, use 'HONG'", n)));
    }
    let perm = if exhaustive { assignment::exhaustive(&c, n) } else { assignment::hungarian(&c, n) };
    let total = match &costs {
        Cost::Int(l) => Value::Int(perm.iter().enumerate().map(|(i, &j)| l[i * n + j]).sum()),
        Cost::Real(l) => Value::Float(perm.iter().enumerate().map(|(i, &j)| l[i * n + j]).sum()),
    };
    let mut out = vec![total];
    out.extend(lists.iter().map(|l| match l {
        Value::ListReel(l) => Value::ListReel(Rc::new(perm.iter().map(|&i| l[i]).collect())),
        Value::ListEnti(l) => Value::ListEnti(Rc::new(perm.iter().map(|&i| l[i]).collect())),
        Value::ListMots(l) => Value::ListMots(Rc::new(perm.iter().map(|&i| l[i].clone()).collect())),
        other => other.clone(),
    }));
    Ok(out)
}

enum Cost {
    Int(Rc<Vec<i64>>),
    Real(Rc<Vec<f64>>),
}

impl Cost {
    fn as_f64(&self) -> Vec<f64> {
        match self {
            Cost::Int(l) => l.iter().map(|&x| x as f64).collect(),
            Cost::Real(l) => l.to_vec(),
        }
    }
}
