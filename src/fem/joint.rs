//! Linear elastic joint elements (JOI2 on RAC2, JOI3 on RAC3, JOI4 on
//! LIA4 and LIA3): a zero-thickness layer between two facing lines (2D)
//! or surfaces (3D) made by RACC or LIAI. Nodes: side 1, then the facing
//! nodes of side 2 in the same order.
//!
//! The "strain" is the jump of displacement across the joint, side 1
//! minus side 2, in the local frame of the face: tangential component(s)
//! first, then the normal one (positive when the joint opens). The
//! "stress" is the traction KS·jump (tangential), KN·jump (normal), so the
//! stiffness is ∫ Nᵀ Rᵀ diag(KS, KN) R N over the mid-face: a joint of
//! area A under a normal load F opens by F / (KN·A).
//!
//! Local frame. 2D: t along side 1 (node 1 to node 2); the joint lies to
//! the right of an observer walking along t, so side 1 opens towards the
//! left normal n = (-t_y, t_x). 3D: axes 1 = dx/dξ, 2 = dx/dη of side 1,
//! N = 1 × 2 (the opening direction), and the in-plane frame (e1, N × e1).

use super::element::{ElemMatrix, FemError, GaussField, Mode};
use super::material::Material;
use super::mesh::ElemType;
use super::quadrature::{quad, seg, tri, QPoint};
use super::shape;

pub fn dofs(mode: Mode) -> Result<&'static [&'static str], FemError> {
    match mode {
        Mode::PlanCont | Mode::PlanDefo => Ok(&["UX", "UY"]),
        Mode::Trid => Ok(&["UX", "UY", "UZ"]),
        Mode::Axis | Mode::Fourier(_) => Err(FemError::Unsupported { form: "JOI2", elem: "RAC2", mode: mode.name() }),
    }
}

/// Whether the geometry and the mode agree: lines of double points in 2D,
/// surfaces in 3D.
pub fn accepts(ty: ElemType, mode: Mode) -> bool {
    match ty.joint_face() {
        Some(face) => (face.dim() == 2) == (mode == Mode::Trid),
        None => false,
    }
}

/// Gauss rule on the face (exact for the face's own interpolation).
pub fn rule(ty: ElemType) -> Vec<QPoint> {
    match ty.joint_face() {
        Some(ElemType::Seg2) => seg(2),
        Some(ElemType::Seg3) => seg(3),
        Some(ElemType::Tri3) => tri(3),
        Some(ElemType::Qua4) => quad(2),
        _ => vec![],
    }
}

pub(crate) fn comp_names(mode: Mode, stress: bool) -> Vec<&'static str> {
    match (mode == Mode::Trid, stress) {
        (false, false) => vec!["EPSS", "EPSN"],
        (false, true) => vec!["SIGS", "SIGN"],
        (true, false) => vec!["EPS1", "EPS2", "EPSN"],
        (true, true) => vec!["SIG1", "SIG2", "SIGN"],
    }
}

/// At one Gauss point: the face shape values, the rows of the local frame
/// (tangential first, normal last) and the weight w·|J|·thickness.
struct Point {
    n: Vec<f64>,
    frame: Vec<[f64; 3]>,
    w: f64,
}

fn points(ty: ElemType, mode: Mode, x: &[[f64; 3]], m: &Material) -> Result<Vec<Point>, FemError> {
    let face = ty.joint_face().ok_or(FemError::Unsupported { form: "JOI2", elem: ty.name(), mode: mode.name() })?;
    let nf = face.nodes();
    if x.len() != 2 * nf {
        return Err(FemError::WrongNodeCount { elem: ty.name(), expected: 2 * nf, got: x.len() });
    }
    // The frame follows the mid-face, which is side 1 when the sides meet.
    let mid: Vec<[f64; 3]> = (0..nf).map(|i| std::array::from_fn(|c| 0.5 * (x[i][c] + x[nf + i][c]))).collect();
    let thick = if mode == Mode::PlanCont { m.dim3.unwrap_or(1.0) } else { 1.0 };
    let degenerate = || FemError::Degenerate { elem: ty.name(), why: "the joint's face has no length or area".into() };
    let mut out = Vec::new();
    for (p, w) in rule(ty) {
        let s = shape::eval(face, p);
        let mut d = [[0.0; 3]; 2];
        for (dn, xi) in s.dn.iter().zip(&mid) {
            for (a, da) in d.iter_mut().enumerate() {
                for c in 0..3 {
                    da[c] += dn[a] * xi[c];
                }
            }
        }
        let (frame, jac) = if face.dim() == 1 {
            let l = norm(d[0]);
            if l.is_nan() || l <= 0.0 || !l.is_finite() {
                return Err(degenerate());
            }
            let t = scale(d[0], 1.0 / l);
            (vec![t, [-t[1], t[0], 0.0]], l)
        } else {
            let nrm = cross(d[0], d[1]);
            let a = norm(nrm);
            let l1 = norm(d[0]);
            if a.is_nan() || a <= 0.0 || !a.is_finite() || l1.is_nan() || l1 <= 0.0 {
                return Err(degenerate());
            }
            let e3 = scale(nrm, 1.0 / a);
            let e1 = scale(d[0], 1.0 / l1);
            (vec![e1, cross(e3, e1), e3], a)
        };
        out.push(Point { n: s.n, frame, w: w * jac * thick });
    }
    Ok(out)
}

fn stiffnesses(m: &Material, ncomp: usize) -> Result<Vec<f64>, FemError> {
    let mode = if ncomp == 3 { Mode::Trid } else { Mode::PlanDefo };
    if let Some(d) = super::hooke_matrix::given(m, &comp_names(mode, true), &comp_names(mode, false)) {
        // The joint's law is diagonal in its local frame.
        return Ok(d?.iter().enumerate().map(|(i, r)| r[i]).collect());
    }
    let ks = m.positive(m.ks, "KS", "JOI2")?;
    let kn = m.positive(m.kn, "KN", "JOI2")?;
    Ok((0..ncomp).map(|i| if i + 1 == ncomp { kn } else { ks }).collect())
}

/// B at one point: rows = local components, columns = element dofs.
fn b_matrix(p: &Point, nc: usize) -> Vec<Vec<f64>> {
    let nf = p.n.len();
    p.frame
        .iter()
        .map(|e| {
            let mut row = vec![0.0; 2 * nf * nc];
            for (i, ni) in p.n.iter().enumerate() {
                for c in 0..nc {
                    row[i * nc + c] = ni * e[c];
                    row[(nf + i) * nc + c] = -ni * e[c];
                }
            }
            row
        })
        .collect()
}

pub fn stiffness(ty: ElemType, mode: Mode, x: &[[f64; 3]], m: &Material) -> Result<ElemMatrix, FemError> {
    let names = dofs(mode)?;
    let nc = names.len();
    let n = x.len() * nc;
    let mut k = vec![0.0; n * n];
    for p in points(ty, mode, x, m)? {
        let b = b_matrix(&p, nc);
        let d = stiffnesses(m, b.len())?;
        for (row, dk) in b.iter().zip(&d) {
            for i in 0..n {
                if row[i] == 0.0 {
                    continue;
                }
                for j in 0..n {
                    k[i * n + j] += p.w * dk * row[i] * row[j];
                }
            }
        }
    }
    Ok(ElemMatrix { dofs: dof_list(x.len(), names), k })
}

fn dof_list(nodes: usize, names: &'static [&'static str]) -> Vec<(usize, &'static str)> {
    (0..nodes).flat_map(|i| names.iter().map(move |&d| (i, d))).collect()
}

/// Displacement jumps at the Gauss points.
pub fn strain(ty: ElemType, mode: Mode, x: &[[f64; 3]], m: &Material, u: &[f64]) -> Result<GaussField, FemError> {
    let nc = dofs(mode)?.len();
    if u.len() != x.len() * nc {
        return Err(FemError::WrongDofCount { elem: ty.name(), expected: x.len() * nc, got: u.len() });
    }
    let values = points(ty, mode, x, m)?
        .iter()
        .map(|p| b_matrix(p, nc).iter().map(|row| row.iter().zip(u).map(|(b, v)| b * v).sum()).collect())
        .collect();
    Ok(GaussField { comps: comp_names(mode, false), values })
}

/// Tractions at the Gauss points.
pub fn stress(ty: ElemType, mode: Mode, x: &[[f64; 3]], m: &Material, u: &[f64]) -> Result<GaussField, FemError> {
    let mut g = strain(ty, mode, x, m, u)?;
    let d = stiffnesses(m, g.comps.len())?;
    for v in &mut g.values {
        v.iter_mut().zip(&d).for_each(|(s, k)| *s *= k);
    }
    g.comps = comp_names(mode, true);
    Ok(g)
}

/// Tractions of the strain field's components (ELAS).
pub fn hooke(mode: Mode, m: &Material, eps: &GaussField) -> Result<GaussField, FemError> {
    let comps = comp_names(mode, false);
    let d = stiffnesses(m, comps.len())?;
    let values = eps
        .values
        .iter()
        .map(|v| {
            comps.iter().zip(&d).map(|(c, k)| k * eps.comps.iter().position(|n| n == c).map_or(0.0, |i| v[i])).collect()
        })
        .collect();
    Ok(GaussField { comps: comp_names(mode, true), values })
}

/// Nodal forces Bᵀσ of a traction field (BSIG).
pub fn internal_forces(
    ty: ElemType,
    mode: Mode,
    x: &[[f64; 3]],
    m: &Material,
    sig: &GaussField,
) -> Result<Vec<f64>, FemError> {
    let nc = dofs(mode)?.len();
    let pts = points(ty, mode, x, m)?;
    if sig.values.len() != pts.len() {
        return Err(FemError::WrongPointCount { elem: ty.name(), expected: pts.len(), got: sig.values.len() });
    }
    let comps = comp_names(mode, true);
    let mut f = vec![0.0; x.len() * nc];
    for (k, p) in pts.iter().enumerate() {
        for (row, c) in b_matrix(p, nc).iter().zip(&comps) {
            let s = sig.get(c, k).ok_or(FemError::MissingComponent { comp: c, elem: ty.name() })?;
            f.iter_mut().zip(row).for_each(|(fi, b)| *fi += p.w * b * s);
        }
    }
    Ok(f)
}

/// Weights turning values at the Gauss points into an integral over the
/// joint's face (INTG).
pub fn point_weights(ty: ElemType, mode: Mode, x: &[[f64; 3]]) -> Result<Vec<f64>, FemError> {
    let m = Material { dim3: None, ..Material::default() };
    Ok(points(ty, mode, x, &m)?.iter().map(|p| p.w).collect())
}

fn norm(a: [f64; 3]) -> f64 {
    (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt()
}

fn scale(a: [f64; 3], s: f64) -> [f64; 3] {
    [a[0] * s, a[1] * s, a[2] * s]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}
