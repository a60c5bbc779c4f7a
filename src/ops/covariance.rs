//! DCOV: the lower Cholesky factor M (M Mt = C) of the covariance matrix
//! C of a stationary random field between the points of a mesh, as a
//! RIGIDITE on unknown SCAL (numerics in `value::signal::covariance`).
//! `M * (BRUI ...)` is then a Gaussian field of that covariance.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::args::PointId;
use crate::eval::Interp;
use crate::fem::mesh::Mesh;
use crate::fem::tensor_frame;
use crate::value::rigidity::{Block, Rigidite, Subtype, Symmetry};
use crate::value::signal::covariance::{self, Law, Metric};
use crate::value::Value;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "DCOV",
    signature: "DCOV MAILLAGE 'EXPO'|'GAUS' 'SIGMA' S ('LAMBDA' L | 'LAMBDA1' L1 'LAMBDA2' L2 ('LAMBDA3' L3) ('DIRECTION' V1 (V2)))",
    doc: "Lower triangular M with M Mt = C, C the covariance between the nodes of the mesh: C_ij = S² exp(-r/L) ('EXPO') or S² exp(-r²/L) ('GAUS') for the distance r (isotropic), or S² exp(-√Σ(r_k/L_k)²) ('EXPO') and S² exp(-Σ(r_k/L_k)²) ('GAUS') with r_k the components of the distance along the axes V1, V1 turned by +90° (2D) or the frame of V1 and V2 (3D) (default: the global axes). A RIGIDITE on the unknown SCAL.",
    example: "m = dcov (droi 4 (0. 0.) (1. 0.)) 'EXPO' 'SIGMA' 1. 'LAMBDA' 0.5 ;",
    f: dcov,
}];

fn dcov(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let mesh = a.req::<Rc<Mesh>>()?;
    let law = match a.req_keyword(&["EXPO", "GAUS"])? {
        "EXPO" => Law::Exponential,
        _ => Law::Gaussian,
    };
    let (mut sigma, mut iso, mut lengths, mut dirs) = (None, None, [None; 3], Vec::new());
    // LAMBDA, LAMBDA1 … share their first four letters: whole words here.
    while let Some(w) = a.word() {
        match w.to_uppercase().as_str() {
            "SIGMA" => sigma = Some(a.req_num()?),
            "LAMBDA" => iso = Some(a.req_num()?),
            "LAMBDA1" => lengths[0] = Some(a.req_num()?),
            "LAMBDA2" => lengths[1] = Some(a.req_num()?),
            "LAMBDA3" => lengths[2] = Some(a.req_num()?),
            "DIRECTION" | "DIRE" => {
                dirs.push(a.req::<PointId>()?);
                if let Some(p) = a.opt::<PointId>() {
                    dirs.push(p);
                }
            }
            other => {
                return Err(
                    a.err(format!("expected SIGMA, LAMBDA, LAMBDA1, LAMBDA2, LAMBDA3 or DIRECTION, found {}", other))
                )
            }
        }
    }
    let sigma = sigma.ok_or_else(|| a.missing("'SIGMA' and the standard deviation"))?;
    let positive = |what: &str, x: f64| {
        if x > 0.0 && x.is_finite() {
            Ok(x)
        } else {
            Err(a.err(format!("the {} must be positive, found {}", what, x)))
        }
    };
    positive("standard deviation", sigma)?;
    let dim = it.opts.dime.clamp(1, 3);
    let metric = match (iso, lengths) {
        (Some(l), [None, None, None]) => Metric::Isotropic(positive("correlation length", l)?),
        (None, [Some(l1), Some(l2), l3]) => {
            if dim == 1 {
                return Err(a.err("in dimension 1 only an isotropic covariance ('LAMBDA') is allowed"));
            }
            let mut ls = vec![positive("correlation length", l1)?, positive("correlation length", l2)?];
            if dim == 3 {
                ls.push(positive("correlation length", l3.ok_or_else(|| a.missing("'LAMBDA3' (in 3D)"))?)?);
            }
            let xyz = |p: &PointId| it.nodes.coords[p.0];
            let frame = match dirs.as_slice() {
                [] => vec![[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
                [v] if dim == 2 => tensor_frame::frame(xyz(v), None).map_err(|m| a.err(m))?.to_vec(),
                [v1, v2, ..] => tensor_frame::frame(xyz(v1), Some(xyz(v2))).map_err(|m| a.err(m))?.to_vec(),
                _ => return Err(a.missing("the second direction VEC2 (in 3D)")),
            };
            Metric::Axes { frame: frame[..dim].to_vec(), lengths: ls }
        }
        _ => return Err(a.err("give either 'LAMBDA' (isotropic) or 'LAMBDA1' and 'LAMBDA2' ('LAMBDA3' in 3D)")),
    };
    let nodes = mesh.node_list();
    let points: Vec<[f64; 3]> = nodes.iter().map(|&n| it.nodes.coords[n]).collect();
    let n = nodes.len();
    let c = covariance::matrix(&points, law, sigma, &metric);
    let l = covariance::cholesky(&c, n).map_err(|m| a.err(m))?;
    let mut r = Rigidite::new(Subtype::Rigidite);
    r.blocks.push(Block {
        nodes_per_elem: n,
        conn: nodes,
        dofs: (0..n).map(|i| (i, "SCAL".to_string())).collect(),
        duals: vec!["SCAL".to_string(); n],
        mats: l,
        symmetry: Symmetry::General,
    });
    Ok(vec![Value::Rigi(Rc::new(r))])
}
