//! MAXI and MINI of an EVOLUTIO (maxi.notice, second form): the index,
//! abscissa and ordinate of the extreme ordinate of each curve, the first
//! one when it is reached several times.

use super::Args;
use crate::error::Result;
use crate::value::{Evolution, Value};
use std::rc::Rc;

/// `None` when the next operand is not an EVOLUTIO. `use_abs` compares the
/// ordinates' absolute values ('ABS' may also follow the curve); the
/// ordinate returned keeps its sign. One curve gives ENTIER FLOTTANT
/// FLOTTANT, several give LISTENTI LISTREEL LISTREEL.
pub(crate) fn extremum(a: &mut Args, max: bool, use_abs: bool) -> Result<Option<Vec<Value>>> {
    let Some(ev) = a.opt::<Rc<Evolution>>() else { return Ok(None) };
    let use_abs = use_abs || a.keyword(&["ABS"]).is_some();
    let key = |y: f64| if use_abs { y.abs() } else { y };
    let (mut idx, mut xs, mut ys) = (Vec::new(), Vec::new(), Vec::new());
    for c in &ev.curves {
        let mut best: Option<usize> = None;
        for (i, &y) in c.y.iter().enumerate() {
            let better = match best {
                None => true,
                Some(b) if max => key(y) > key(c.y[b]),
                Some(b) => key(y) < key(c.y[b]),
            };
            if better {
                best = Some(i);
            }
        }
        let Some(b) = best else { return Err(a.err("the EVOLUTIO has an empty curve")) };
        idx.push(b as i64 + 1);
        xs.push(c.x[b]);
        ys.push(c.y[b]);
    }
    Ok(Some(if let ([i], [x], [y]) = (idx.as_slice(), xs.as_slice(), ys.as_slice()) {
        vec![Value::Int(*i), Value::Float(*x), Value::Float(*y)]
    } else {
        vec![Value::ListEnti(Rc::new(idx)), Value::ListReel(Rc::new(xs)), Value::ListReel(Rc::new(ys))]
    }))
}
