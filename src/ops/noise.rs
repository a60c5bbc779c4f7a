//! BRUI: white noise, as a LISTREEL, an EVOLUTIO against given times, a
//! CHPOINT on the nodes of a mesh, or Poisson counts in a LISTENTI. The
//! generator is the interpreter's (`value::signal::noise`): the same seed
//! at every start, so a deck's values are reproducible.

use super::{limits, Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::value::model::Curve;
use crate::value::signal::noise::Law;
use crate::value::{Chpoint, Evolution, Nature, Value};
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "BRUI",
    signature: "BRUI 'BLAN' 'GAUS'|'UNIF'|'EXPO' MEAN SPREAD N|LISTREEL (colour)|MAILLAGE (SKIP) | BRUI 'BLAN' 'POIS' MEAN N (SKIP)",
    doc: "Uncorrelated random values: N of them in a LISTREEL, a curve 'SIGNAL' against the times of a LISTREEL, or a CHPOINT 'SCAL' on the nodes of a mesh. 'GAUS': normal of that mean and standard deviation; 'UNIF': uniform on MEAN ± SPREAD; 'EXPO': exponential of mean SPREAD (MEAN is ignored). 'POIS': a LISTENTI of N Poisson counts of mean MEAN. SKIP passes over that many draws first. Every run starts the generator from the same seed; successive calls continue it.",
    example: "l = brui 'BLAN' 'UNIF' 0. 1. 10 ;",
    f: brui,
}];

/// Where the values go.
enum Support {
    Count(usize),
    Times(Rc<Vec<f64>>),
    Nodes(Vec<usize>),
}

fn brui(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    a.req_keyword(&["BLAN"])?;
    let kind = a.req_keyword(&["GAUS", "UNIF", "EXPO", "POIS"])?;
    if kind == "POIS" {
        let mean = a.req::<i64>()?;
        if mean < 0 {
            return Err(a.err(format!("the mean of a Poisson law must be positive or zero, found {}", mean)));
        }
        let n = a.req::<i64>()?;
        let n = limits::room(a, 0, n as f64)?;
        skip(it, a)?;
        let v = it.noise.poisson(mean as f64, n).map_err(|e| a.err(e))?;
        return Ok(vec![Value::ListEnti(Rc::new(v))]);
    }
    let mean = a.req_num()?;
    let spread = a.req_num()?;
    if !spread.is_finite() || !mean.is_finite() || spread <= 0.0 {
        return Err(a.err(format!(
            "the {} must be a positive number, found {}",
            if kind == "UNIF" { "amplitude" } else { "standard deviation" },
            spread
        )));
    }
    let support = a
        .opt_with(|v| match v {
            Value::Int(n) => Some(Err(*n)),
            Value::ListReel(l) => Some(Ok(Support::Times(l.clone()))),
            Value::Mesh(m) => Some(Ok(Support::Nodes(Mesh::node_list(m)))),
            _ => None,
        })
        .ok_or_else(|| a.missing("ENTIER, LISTREEL or MAILLAGE (where the values go)"))?;
    let support = match support {
        Ok(s) => s,
        Err(n) => Support::Count(limits::room(a, 0, n as f64)?),
    };
    // The colour of the curve may come before or after the skip count.
    a.keyword(super::evol::COLOURS);
    skip(it, a)?;
    a.keyword(super::evol::COLOURS);
    let law = match kind {
        "GAUS" => Law::Gauss { mean, sd: spread },
        "UNIF" => Law::Uniform { mean, half_width: spread },
        _ => Law::Exponential { mean: spread },
    };
    let n = match &support {
        Support::Count(n) => *n,
        Support::Times(t) => t.len(),
        Support::Nodes(v) => v.len(),
    };
    let values = it.noise.draw(law, n).map_err(|e| a.err(e))?;
    Ok(vec![match support {
        Support::Count(_) => Value::ListReel(Rc::new(values)),
        Support::Times(t) => Value::Evol(Rc::new(Evolution {
            curves: vec![Curve {
                legend: String::new(),
                x_name: "TEMPS".into(),
                y_name: "SIGNAL".into(),
                x: t.to_vec(),
                y: values,
            }],
        })),
        Support::Nodes(nodes) => Value::Chpo(Rc::new(Chpoint::from_entries(
            Nature::Discret,
            nodes.iter().zip(&values).map(|(&n, &v)| (n, "SCAL", v)),
        ))),
    }])
}

/// The optional count of draws to pass over first.
fn skip(it: &mut Interp, a: &mut Args) -> Result<()> {
    if let Some(k) = a.opt::<i64>() {
        if k < 0 {
            return Err(a.err(format!("the number of draws to skip must be positive or zero, found {}", k)));
        }
        it.noise.skip(k as u64);
    }
    Ok(())
}
