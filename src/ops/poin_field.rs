//! `CHE1 POIN test`: the points of a field (CHPOINT or MCHAML) whose
//! values meet a test, as a POI1 mesh.

use super::mesh::mesh_val;
use super::Args;
use crate::error::Result;
use crate::eval::Interp;
use crate::fem::element::{gauss_points, Formulation};
use crate::fem::mesh::{ElemType, Mesh};
use crate::value::{Chpoint, Mchaml, Value};
use std::collections::HashSet;
use std::rc::Rc;

const TESTS: &[&str] = &["MAXI", "MINI", "SUPE", "INFE", "EGSU", "EGIN", "EGAL", "DIFF", "COMP"];

/// Which components take part ('AVEC' list / 'SANS' list / all).
pub(crate) struct Filter {
    keep: Option<(bool, Rc<Vec<String>>)>,
}

impl Filter {
    fn read(a: &mut Args) -> Result<Filter> {
        let keep = match a.keyword(&["AVEC", "SANS"]) {
            Some(k) => Some((k == "AVEC", a.req::<Rc<Vec<String>>>()?)),
            None => None,
        };
        Ok(Filter { keep })
    }

    pub(crate) fn takes(&self, comp: &str) -> bool {
        match &self.keep {
            None => true,
            Some((avec, names)) => names.iter().any(|n| n == comp) == *avec,
        }
    }
}

/// The test named after POIN, with its reference values.
pub(crate) enum Test {
    Maxi,
    Mini,
    Compare(&'static str, f64),
    Between(f64, f64),
}

/// The test and its options ('ABS', a component filter), which may stand
/// before the test, after its keyword or after its values.
pub(crate) fn read_test(a: &mut Args) -> Result<(Test, bool, Filter)> {
    let mut abs = false;
    let mut filter = Filter { keep: None };
    let mut options = |a: &mut Args| -> Result<()> {
        abs |= a.keyword_next(&["ABS"]).is_some();
        if filter.keep.is_none() {
            filter = Filter::read(a)?;
        }
        abs |= a.keyword_next(&["ABS"]).is_some();
        Ok(())
    };
    options(a)?;
    let k = a.req_keyword(TESTS)?;
    options(a)?;
    let test = match k {
        "MAXI" => Test::Maxi,
        "MINI" => Test::Mini,
        "COMP" => Test::Between(a.req_num()?, a.req_num()?),
        _ => Test::Compare(k, a.req_num()?),
    };
    options(a)?;
    Ok((test, abs, filter))
}

/// The test as a predicate on one value, given every value it looks at
/// (MAXI/MINI need their extreme; EGAL/DIFF a round-off tolerance).
pub(crate) fn predicate(test: Test, vals: &[f64]) -> Box<dyn Fn(f64) -> bool> {
    let scale = vals.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    match test {
        Test::Maxi => {
            let top = vals.iter().fold(f64::NEG_INFINITY, |m, &v| m.max(v));
            let tol = 1e-10 * scale;
            Box::new(move |v| v >= top - tol)
        }
        Test::Mini => {
            let low = vals.iter().fold(f64::INFINITY, |m, &v| m.min(v));
            let tol = 1e-10 * scale;
            Box::new(move |v| v <= low + tol)
        }
        Test::Between(lo, hi) => Box::new(move |v| lo <= v && v <= hi),
        Test::Compare(k, t) => {
            let tol = 1e-10 * scale.max(t.abs());
            match k {
                "SUPE" => Box::new(move |v| v > t),
                "INFE" => Box::new(move |v| v < t),
                "EGSU" => Box::new(move |v| v >= t),
                "EGIN" => Box::new(move |v| v <= t),
                "EGAL" => Box::new(move |v| (v - t).abs() <= tol),
                _ => Box::new(move |v| (v - t).abs() > tol),
            }
        }
    }
}

/// `CHPOINT POIN test`: the nodes where one considered value meets it.
pub(crate) fn poin_of_chpo(a: &mut Args, ch: &Chpoint) -> Result<Vec<Value>> {
    let (test, abs, filter) = read_test(a)?;
    let value = |v: f64| if abs { v.abs() } else { v };
    let vals: Vec<(usize, f64)> =
        ch.entries().filter(|(_, c, _)| filter.takes(c)).map(|(n, _, v)| (n, value(v))).collect();
    if vals.is_empty() {
        return Err(a.err("the field has no value to test"));
    }
    let all: Vec<f64> = vals.iter().map(|e| e.1).collect();
    let test = predicate(test, &all);
    let mut seen = HashSet::new();
    let nodes: Vec<usize> = vals.into_iter().filter(|&(n, v)| test(v) && seen.insert(n)).map(|e| e.0).collect();
    Ok(mesh_val(Mesh::points(&nodes)))
}

/// Where one value of an MCHAML lies: a node of the mesh, or a position
/// inside an element (a centre or a Gauss point) that becomes a new point.
#[derive(Clone, Copy)]
enum Site {
    Node(usize),
    At([f64; 3]),
}

/// `MCHAML POIN test`: the points supporting a value that meets it, in
/// element order (so that a field built element by element from the
/// result lines up with the MCHAML). Fields at the nodes give the nodes;
/// fields at centres or Gauss points give new points there.
pub(crate) fn poin_of_mchaml(it: &mut Interp, a: &mut Args, m: &Mchaml) -> Result<Vec<Value>> {
    let (test, abs, filter) = read_test(a)?;
    let value = |v: f64| if abs { v.abs() } else { v };
    let mut sites: Vec<(Site, Vec<f64>)> = vec![];
    for z in &m.zones {
        let cols: Vec<usize> = (0..z.comps.len()).filter(|&c| filter.takes(&z.comps[c])).collect();
        let mut e = 0;
        for part in &z.mesh.parts {
            for nodes in part.elems() {
                let Some(pts) = z.values.get(e) else { break };
                e += 1;
                let at = positions(it, a, part.ty, nodes, pts.len(), z.at_nodes)?;
                for (site, row) in at.into_iter().zip(pts) {
                    sites.push((site, cols.iter().filter_map(|&c| row.get(c)).map(|&v| value(v)).collect()));
                }
            }
        }
    }
    let all: Vec<f64> = sites.iter().flat_map(|s| s.1.iter().copied()).collect();
    if all.is_empty() {
        return Err(a.err("the field has no point value to test"));
    }
    let test = predicate(test, &all);
    let d = it.opts.dens;
    let mut seen = HashSet::new();
    let mut out = vec![];
    for (site, vals) in sites {
        if !vals.iter().any(|&v| test(v)) {
            continue;
        }
        let n = match site {
            Site::Node(n) => n,
            Site::At(x) => it.nodes.push(x, d),
        };
        if seen.insert(n) {
            out.push(n);
        }
    }
    Ok(mesh_val(Mesh::points(&out)))
}

/// The sites of the `count` values of one element.
fn positions(it: &Interp, a: &Args, ty: ElemType, nodes: &[usize], count: usize, at_nodes: bool) -> Result<Vec<Site>> {
    if at_nodes && count == nodes.len() {
        return Ok(nodes.iter().map(|&n| Site::Node(n)).collect());
    }
    let x: Vec<[f64; 3]> = nodes.iter().map(|&n| it.nodes.get(n)).collect();
    let map = |p: [f64; 3]| {
        let s = crate::fem::shape::eval(ty, p);
        let mut y = [0.0; 3];
        for (w, xi) in s.n.iter().zip(&x) {
            for c in 0..3 {
                y[c] += w * xi[c];
            }
        }
        Site::At(y)
    };
    if count == 1 {
        // One value per element: at its centre (the image of the mean of
        // the reference nodes, as CHAN 'GRAVITE' places it).
        let refs = crate::fem::shape::ref_nodes(ty);
        let k = refs.len() as f64;
        let centre = refs.iter().fold([0.0; 3], |acc, p| [0, 1, 2].map(|i| acc[i] + p[i] / k));
        return Ok(vec![map(centre)]);
    }
    let gauss = gauss_points(Formulation::Solid, ty);
    if gauss.len() == count {
        return Ok(gauss.into_iter().map(|(p, _)| map(p)).collect());
    }
    Err(a.err(format!(
        "cannot place the {count} values of a {} element: change the field to its nodes or centres first (CHAN 'NOEUD' or 'GRAVITE')",
        ty.name()
    )))
}
