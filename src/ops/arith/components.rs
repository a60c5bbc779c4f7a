//! `X op Y L1 L2 L3` for two CHPOINT or two MCHAML (aaa2.notice,
//! aaa_division.notice, aaa4/aaa5.notice): three LISTMOTS after the
//! operands name the operand components and the result's. The algebra is
//! `value::by_components`.

use crate::error::Result;
use crate::eval::args::Args;
use crate::value::arith::{float_op, Bin};
use crate::value::by_components::check_lists;
use crate::value::{Nature, Value};
use std::rc::Rc;

/// The component-wise result when three lists follow two fields, else
/// None (the lists are not read: the ordinary rules apply). `first`: the
/// first list, already read between the operands (the prefix form
/// `'*' X L1 Y L2 L3`).
pub(super) fn apply(
    a: &mut Args,
    op: Bin,
    x: &Value,
    y: &Value,
    first: Option<Rc<Vec<String>>>,
) -> Result<Option<Value>> {
    let fields = matches!((x, y), (Value::Chpo(_), Value::Chpo(_)) | (Value::Mchaml(_), Value::Mchaml(_)));
    if !fields || op == Bin::Pow {
        return Ok(None);
    }
    let Some(l1) = first.or_else(|| a.opt_right::<Rc<Vec<String>>>()) else { return Ok(None) };
    let l2 = a.opt_right::<Rc<Vec<String>>>().ok_or_else(|| a.missing("a second LISTMOTS (the components of OBJ2)"))?;
    let l3 = a.opt_right::<Rc<Vec<String>>>().ok_or_else(|| a.missing("a third LISTMOTS (the result's components)"))?;
    check_lists(&l1, &l2, &l3).map_err(|e| a.err(e))?;
    let names = (l1.as_slice(), l2.as_slice(), l3.as_slice());
    let f = |p: f64, q: f64| float_op(op, p, q);
    Ok(Some(match (x, y) {
        (Value::Chpo(c), Value::Chpo(d)) => {
            let nature = crate::ops::fields::nature_word(a)?.unwrap_or(match (c.nature, d.nature) {
                (Nature::Indeter, _) | (_, Nature::Indeter) => Nature::Indeter,
                (Nature::Discret, _) | (_, Nature::Discret) => Nature::Discret,
                _ => Nature::Diffus,
            });
            Value::Chpo(Rc::new(c.by_components(d, names, op == Bin::Div, nature, f)))
        }
        (Value::Mchaml(m), Value::Mchaml(n)) => {
            Value::Mchaml(Rc::new(m.by_components(n, names, f).map_err(|e| a.err(e))?))
        }
        _ => return Ok(None),
    }))
}
