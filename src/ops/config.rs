//! FORME: the CONFIGURATION of the geometry (the coordinates of every
//! node). `FORM` alone records the current one; `FORM CHPO` moves the
//! nodes by a displacement field; `FORM CONF (CHPO)` puts a recorded one
//! back (then moves it). Every object holding the nodes sees them moved,
//! as with DEPL. The result is always the configuration now active, so
//! `C0 = FORM ;` and the directive `FORM U ;` are one form.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::meshing::motion::{displace, restore};
use crate::value::{Chpoint, HostObject, Value};
use std::any::Any;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "FORM",
    signature: "FORME (CONFIGURATION) (CHPOINT) -> CONFIGURATION",
    doc: "Record the coordinates of every node (a CONFIGURATION), move the nodes by a displacement field (UX UY UZ, or UR UZ in axisymmetry), or put a recorded configuration back; returns the configuration now active.",
    example: "p = 1. 2. ; c0 = form ; u = manu 'CHPO' p 2 'UX' 0.5 'UY' 0. ; form u ; form c0 ;",
    f: forme,
}];

/// The coordinates of the nodes that existed when it was recorded.
pub struct Configuration(Rc<Vec<[f64; 3]>>);

impl std::fmt::Debug for Configuration {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "CONFIGURATION of {} node(s)", self.0.len())
    }
}

impl HostObject for Configuration {
    fn type_name(&self) -> &str {
        "CONFIGUR"
    }
    fn as_any(&self) -> &dyn Any {
        self
    }
}

fn as_config(v: &Value) -> Option<Rc<Vec<[f64; 3]>>> {
    match v {
        Value::Host(h) => h.as_any().downcast_ref::<Configuration>().map(|c| c.0.clone()),
        _ => None,
    }
}

/// Which coordinate a displacement component moves, in the current mode:
/// in axisymmetry (and Fourier) UR is the radius and UZ the second axis.
fn axis_of(comp: &str, dim: usize, axisym: bool) -> Option<usize> {
    match comp {
        "UX" => Some(0),
        "UY" => Some(1),
        "UR" if axisym => Some(0),
        "UZ" if dim == 2 && axisym => Some(1),
        "UZ" if dim == 3 => Some(2),
        _ => None,
    }
}

fn forme(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let conf = a.opt_with(as_config);
    let u = a.opt::<Rc<Chpoint>>();
    if a.opt::<Rc<crate::value::Model>>().is_some() {
        return Err(a.err("updating the local frames of a model's characteristics (MMODEL MCHAML) is not supported"));
    }
    if let Some(c) = &conf {
        restore(&mut it.nodes, c);
    }
    if let Some(u) = &u {
        let dim = it.opts.dime.max(2);
        let axisym = it.opts.mode.starts_with("AXIS") || it.opts.mode.starts_with("FOUR");
        let moves: Vec<(usize, usize, f64)> =
            u.entries().filter_map(|(n, c, v)| axis_of(c, dim, axisym).map(|k| (n, k, v))).collect();
        displace(&mut it.nodes, &moves)?;
    }
    Ok(vec![Value::Host(Rc::new(Configuration(Rc::new(it.nodes.coords.clone()))))])
}
