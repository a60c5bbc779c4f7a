//! Flat shells: COQ3 and DKT on TRI3, COQ4 on QUA4 (thin), DST on TRI3
//! (with transverse shear, see [`super::dst`]), in TRID only.
//!
//! Each element is flat: a membrane (constant-strain triangle, bilinear
//! quadrangle) plus a discrete Kirchhoff plate (DKT, DKQ; see
//! [`super::plate`]), uncoupled in the element's own frame. COQ3 and DKT
//! are the same element here. Dofs per node are UX UY UZ RX RY RZ; CARA
//! gives the thickness EPAI.
//!
//! Local frame of an element: x3 along the normal n = (x2 − x1) × (x3 − x1)
//! (TRI3) or (x3 − x1) × (x4 − x2) (QUA4), so it follows the node order; x1
//! is the first side x2 − x1 projected on the element plane (Cast3M's
//! convention for thin shells); x2 = x3 × x1. A warped QUA4 is projected
//! on its mean plane. Resultants and strains are given in this frame.
//!
//! Drilling: a flat element has no stiffness for the rotation θ3 about
//! its normal, so a plane mesh would be singular in RZ. As in Cast3M, a
//! small fictitious stiffness is added; ours ties each node's θ3 to the
//! element's in-plane rotation ω = (u2,1 − u1,2)/2 (at the centre): energy
//! ½ k Σ (θ3,i − ω)², with k = [`DRILL`] times the element's mean bending
//! stiffness of the in-plane rotations. Rigid motions then cost nothing
//! (a spring to ground would resist rigid rotations), a uniform in-plane
//! strain still passes the patch test exactly, and the relative effect on
//! other answers is of order DRILL·(t/h)².
//!
//! Output (SIGM), at the Gauss points (3 on TRI3, each nearest a corner;
//! 2×2 on QUA4): N11 N22 N12 (membrane forces per unit length), M11 M22
//! M12 (moments per unit length, M11 = ∫ σ11 x3 dx3, so positive M11
//! stretches the +n face) and V1 V2, the transverse shears that balance
//! the moments (V1 = M11,1 + M12,2, V2 = M12,1 + M22,2; the Kirchhoff
//! element has no shear strain, so BSIG ignores them). EPSI gives EPSS
//! EPTT GAST (membrane strains, engineering shear) and RTSS RTTT RTST
//! (curvatures, RTST = 2κ12, so M12 = D(1 − ν)/2 · RTST).

use super::dst::{self, Dst};
use super::element::{ElemMatrix, FemError, Formulation, GaussField, Mode};
use super::material::Material;
use super::mesh::ElemType;
use super::plate::{self, PlatePoint};
use super::quadrature::{quad, tri, QPoint};
use super::shell_offset;
use super::vec3::{cross, dot, sub, unit};

/// Fictitious drilling stiffness, relative to the bending rotations'.
pub const DRILL: f64 = 1e-4;

pub const STRESS: [&str; 8] = ["N11", "N22", "N12", "M11", "M22", "M12", "V1", "V2"];
pub const STRAIN: [&str; 6] = ["EPSS", "EPTT", "GAST", "RTSS", "RTTT", "RTST"];

pub fn dofs(f: Formulation, mode: Mode) -> Result<&'static [&'static str], FemError> {
    match mode {
        Mode::Trid => Ok(&["UX", "UY", "UZ", "RX", "RY", "RZ"]),
        _ => Err(FemError::Unsupported { form: f.name(), elem: geometry(f).name(), mode: mode.name() }),
    }
}

/// The one mesh geometry each shell element lives on.
pub fn geometry(f: Formulation) -> ElemType {
    if f == Formulation::Coq4 {
        ElemType::Qua4
    } else {
        ElemType::Tri3
    }
}

/// Integration and output points: 3 interior points on the triangle
/// (exact for the DKT's quadratic energy density), 2×2 on the quadrangle.
pub fn rule(ty: ElemType) -> Vec<QPoint> {
    if ty == ElemType::Tri3 {
        tri(3)
    } else {
        quad(2)
    }
}

/// Rotation (rows x1, x2, x3 in global) and corner coordinates in the
/// element plane.
struct Frame {
    r: [[f64; 3]; 3],
    xl: Vec<[f64; 2]>,
    /// DST's condensed shear, once the material is known (see [`shear`]).
    dst: Option<Dst>,
}

fn frame(f: Formulation, x: &[[f64; 3]]) -> Result<Frame, FemError> {
    let ty = geometry(f);
    if x.len() != ty.nodes() {
        return Err(FemError::WrongNodeCount { elem: ty.name(), expected: ty.nodes(), got: x.len() });
    }
    let n =
        if x.len() == 3 { cross(sub(x[1], x[0]), sub(x[2], x[0])) } else { cross(sub(x[2], x[0]), sub(x[3], x[1])) };
    let size = x.iter().map(|p| dot(sub(*p, x[0]), sub(*p, x[0]))).fold(0.0, f64::max);
    let nn = dot(n, n).sqrt();
    if nn <= 1e-12 * size || !nn.is_finite() {
        return Err(FemError::Degenerate { elem: f.name(), why: "zero area (aligned or coincident nodes)".into() });
    }
    let e3 = [n[0] / nn, n[1] / nn, n[2] / nn];
    // x1 along the first side, as Cast3M's thin shells (RTEN's notice):
    // resultants are read in this frame, so decks name them after it.
    let axis = sub(x[1], x[0]);
    let p = dot(axis, e3);
    let e1 = unit([axis[0] - p * e3[0], axis[1] - p * e3[1], axis[2] - p * e3[2]]);
    let e2 = cross(e3, e1);
    let c: [f64; 3] = std::array::from_fn(|k| x.iter().map(|p| p[k]).sum::<f64>() / x.len() as f64);
    let xl = x.iter().map(|p| [dot(e1, sub(*p, c)), dot(e2, sub(*p, c))]).collect();
    Ok(Frame { r: [e1, e2, e3], xl, dst: None })
}

/// What the element needs from the material, read once.
struct Section {
    /// Membrane and bending plane-stress matrices E t/(1 − ν²)·…, D·….
    dm: [[f64; 3]; 3],
    db: [[f64; 3]; 3],
}

fn section(f: Formulation, m: &Material) -> Result<Section, FemError> {
    let elem = f.name();
    let e = m.young(elem)?;
    let nu = m.poisson_plane_stress(elem)?;
    let t = m.positive(m.epai, "EPAI", elem)?;
    let c = e * t / (1.0 - nu * nu);
    Ok(Section { dm: plate::plane_stress(c, nu), db: plate::plane_stress(c * t * t / 12.0, nu) })
}

/// A frame with DST's shear condensed (other elements: unchanged).
fn shear(f: Formulation, mut fr: Frame, m: &Material, sec: &Section) -> Result<Frame, FemError> {
    if f == Formulation::Dst {
        let ds = dst::SHEAR_FACTOR * m.shear_modulus(f.name())? * m.positive(m.epai, "EPAI", f.name())?;
        fr.dst = Some(dst::condense(&fr.xl, &sec.db, ds)?);
    }
    Ok(fr)
}

/// The strain rows at reference point `p`.
fn point_at(fr: &Frame, p: [f64; 3]) -> PlatePoint {
    match &fr.dst {
        Some(d) => dst::at(&fr.xl, p, d),
        None => plate::at(&fr.xl, p),
    }
}

/// The element's points with their strain rows, in the local plane.
fn points(f: Formulation, fr: &Frame) -> Result<Vec<(PlatePoint, f64)>, FemError> {
    rule(geometry(f))
        .into_iter()
        .map(|(p, w)| {
            let pp = point_at(fr, p);
            if pp.det <= 0.0 || !pp.det.is_finite() {
                return Err(FemError::Degenerate {
                    elem: f.name(),
                    why: "the element is folded or not convex in its plane".into(),
                });
            }
            Ok((pp, w))
        })
        .collect()
}

/// Local dof index of membrane dof `k` (2 per corner) and bending dof `k`
/// (3 per corner) in the 6-per-node local vector (u1 u2 w θ1 θ2 θ3).
fn mem(k: usize) -> usize {
    6 * (k / 2) + k % 2
}
fn bend(k: usize) -> usize {
    6 * (k / 3) + 2 + k % 3
}

/// Add w·Bᵀ D B to the local matrix, B's columns mapped by `idx`.
fn add_btdb(k: &mut [f64], n: usize, b: &[Vec<f64>; 3], d: &[[f64; 3]; 3], w: f64, idx: impl Fn(usize) -> usize) {
    let nc = b[0].len();
    let db: Vec<[f64; 3]> = (0..nc).map(|c| std::array::from_fn(|r| (0..3).map(|s| d[r][s] * b[s][c]).sum())).collect();
    for i in 0..nc {
        for j in 0..nc {
            let v: f64 = (0..3).map(|r| b[r][i] * db[j][r]).sum();
            k[idx(i) * n + idx(j)] += w * v;
        }
    }
}

/// Global (UX UY UZ RX RY RZ per node) ↔ local: every triple turns by R.
fn to_local(r: &[[f64; 3]; 3], u: &[f64]) -> Vec<f64> {
    u.chunks(3).flat_map(|v| (0..3).map(move |i| r[i][0] * v[0] + r[i][1] * v[1] + r[i][2] * v[2])).collect()
}
fn to_global(r: &[[f64; 3]; 3], u: &[f64]) -> Vec<f64> {
    u.chunks(3).flat_map(|v| (0..3).map(move |j| r[0][j] * v[0] + r[1][j] * v[1] + r[2][j] * v[2])).collect()
}

fn dof_list(nodes: usize) -> Vec<(usize, &'static str)> {
    let names = ["UX", "UY", "UZ", "RX", "RY", "RZ"];
    (0..nodes).flat_map(|i| names.iter().map(move |&d| (i, d))).collect()
}

pub fn stiffness(f: Formulation, mode: Mode, x: &[[f64; 3]], m: &Material) -> Result<ElemMatrix, FemError> {
    dofs(f, mode)?;
    let sec = section(f, m)?;
    let fr = shear(f, frame(f, x)?, m, &sec)?;
    let nn = x.len();
    let n = 6 * nn;
    let mut kl = vec![0.0; n * n];
    let e = m.exce.unwrap_or(0.0);
    for (p, w) in points(f, &fr)? {
        add_btdb(&mut kl, n, &shell_offset::membrane_rows(&p, e, mem, bend), &sec.dm, w * p.det, |c| c);
        add_btdb(&mut kl, n, &p.bb, &sec.db, w * p.det, bend);
        if let Some(d) = &fr.dst {
            // Transverse shear energy: γ is constant, its stiffness k G t.
            for i in 0..9 {
                for j in 0..9 {
                    let v: f64 = (0..2).map(|r| d.gamma[r][i] * d.gamma[r][j]).sum();
                    kl[bend(i) * n + bend(j)] += w * p.det * d.ds * v;
                }
            }
        }
    }
    let rot: f64 = (0..nn).map(|i| kl[(6 * i + 3) * n + 6 * i + 3] + kl[(6 * i + 4) * n + 6 * i + 4]).sum();
    let drill = DRILL * rot / (2 * nn) as f64;
    let centre = plate::at(&fr.xl, if nn == 3 { [1.0 / 3.0, 1.0 / 3.0, 0.0] } else { [0.0; 3] });
    // ω over the membrane dofs: ½(γ-row with u1 terms negated) = ½(u2,1 − u1,2).
    let omega: Vec<f64> =
        (0..2 * nn).map(|c| if c % 2 == 0 { -0.5 * centre.bm[2][c] } else { 0.5 * centre.bm[2][c] }).collect();
    for i in 0..nn {
        let mut b = vec![0.0; n];
        b[6 * i + 5] = 1.0;
        for (c, o) in omega.iter().enumerate() {
            b[mem(c)] -= o;
        }
        for r in 0..n {
            for q in 0..n {
                kl[r * n + q] += drill * b[r] * b[q];
            }
        }
    }
    // K = Tᵀ K_l T, applied column by column then row by row.
    let mut tmp = vec![0.0; n * n];
    for i in 0..n {
        let row = to_global(&fr.r, &kl[i * n..(i + 1) * n]);
        tmp[i * n..(i + 1) * n].copy_from_slice(&row);
    }
    let mut k = vec![0.0; n * n];
    for j in 0..n {
        let col: Vec<f64> = (0..n).map(|i| tmp[i * n + j]).collect();
        for (i, v) in to_global(&fr.r, &col).into_iter().enumerate() {
            k[i * n + j] = v;
        }
    }
    Ok(ElemMatrix { dofs: dof_list(nn), k })
}

fn check_u(f: Formulation, x: &[[f64; 3]], u: &[f64]) -> Result<(), FemError> {
    if u.len() != 6 * x.len() {
        return Err(FemError::WrongDofCount { elem: f.name(), expected: 6 * x.len(), got: u.len() });
    }
    Ok(())
}

/// Membrane strains (of the mid-surface, at offset `e` from the nodes'
/// plane: ε + e κ) and curvatures (the 6 [`STRAIN`] values) at `p`.
fn strains(p: &PlatePoint, ul: &[f64], e: f64) -> [f64; 6] {
    let em = |r: usize| (0..p.bm[r].len()).map(|c| p.bm[r][c] * ul[mem(c)]).sum::<f64>();
    let eb = |r: usize| (0..p.bb[r].len()).map(|c| p.bb[r][c] * ul[bend(c)]).sum::<f64>();
    [em(0) + e * eb(0), em(1) + e * eb(1), em(2) + e * eb(2), eb(0), eb(1), eb(2)]
}

fn resultants(sec: &Section, e: &[f64; 6]) -> [f64; 6] {
    let mul =
        |d: &[[f64; 3]; 3], v: &[f64]| -> [f64; 3] { std::array::from_fn(|r| (0..3).map(|s| d[r][s] * v[s]).sum()) };
    let (n, m) = (mul(&sec.dm, &e[..3]), mul(&sec.db, &e[3..]));
    [n[0], n[1], n[2], m[0], m[1], m[2]]
}

pub fn strain(f: Formulation, mode: Mode, x: &[[f64; 3]], m: &Material, u: &[f64]) -> Result<GaussField, FemError> {
    dofs(f, mode)?;
    check_u(f, x, u)?;
    let fr = if f == Formulation::Dst { shear(f, frame(f, x)?, m, &section(f, m)?)? } else { frame(f, x)? };
    let ul = to_local(&fr.r, u);
    let e = m.exce.unwrap_or(0.0);
    let values = points(f, &fr)?.iter().map(|(p, _)| strains(p, &ul, e).to_vec()).collect();
    Ok(GaussField { comps: STRAIN.to_vec(), values })
}

pub fn stress(f: Formulation, mode: Mode, x: &[[f64; 3]], m: &Material, u: &[f64]) -> Result<GaussField, FemError> {
    dofs(f, mode)?;
    check_u(f, x, u)?;
    let sec = section(f, m)?;
    let fr = shear(f, frame(f, x)?, m, &sec)?;
    let ul = to_local(&fr.r, u);
    let e = m.exce.unwrap_or(0.0);
    let moments = |p: [f64; 3]| {
        let r = resultants(&sec, &strains(&point_at(&fr, p), &ul, e));
        [r[3], r[4], r[5]]
    };
    // Moment gradients by central differences in the reference plane:
    // exact, since the moments are at most quadratic along each direction.
    const H: f64 = 0.01;
    let mut values = Vec::new();
    for ((p, _), (xi, _)) in points(f, &fr)?.iter().zip(rule(geometry(f))) {
        let r = resultants(&sec, &strains(p, &ul, e));
        let d = |a: usize| -> [f64; 3] {
            let (mut lo, mut hi) = (xi, xi);
            lo[a] -= H;
            hi[a] += H;
            let (ml, mh) = (moments(lo), moments(hi));
            std::array::from_fn(|c| (mh[c] - ml[c]) / (2.0 * H))
        };
        let (dxi, deta) = (d(0), d(1));
        let g = |c: usize, k: usize| p.inv[k][0] * dxi[c] + p.inv[k][1] * deta[c];
        let v1 = g(0, 0) + g(2, 1);
        let v2 = g(2, 0) + g(1, 1);
        values.push(vec![r[0], r[1], r[2], r[3], r[4], r[5], v1, v2]);
    }
    Ok(GaussField { comps: STRESS.to_vec(), values })
}

/// BSIG: Σ w (B_mᵀ N + B_bᵀ M) in global axes. V1 V2 do no work in the
/// Kirchhoff elements (in DST they work on its shear strains) and the
/// drilling spring none, so for the stresses of u this is K u except on
/// the (fictitious) drilling stiffness.
pub fn internal_forces(
    f: Formulation,
    mode: Mode,
    x: &[[f64; 3]],
    m: &Material,
    sig: &GaussField,
) -> Result<Vec<f64>, FemError> {
    dofs(f, mode)?;
    let fr = if f == Formulation::Dst { shear(f, frame(f, x)?, m, &section(f, m)?)? } else { frame(f, x)? };
    let pts = points(f, &fr)?;
    let e = m.exce.unwrap_or(0.0);
    if sig.values.len() != pts.len() {
        return Err(FemError::WrongPointCount { elem: f.name(), expected: pts.len(), got: sig.values.len() });
    }
    let mut fl = vec![0.0; 6 * x.len()];
    for (k, (p, w)) in pts.iter().enumerate() {
        let s = |c: usize| sig.get(STRESS[c], k).ok_or(FemError::MissingComponent { comp: STRESS[c], elem: f.name() });
        let r = [s(0)?, s(1)?, s(2)?, s(3)?, s(4)?, s(5)?];
        let wd = w * p.det;
        for c in 0..p.bm[0].len() {
            fl[mem(c)] += wd * (0..3).map(|i| p.bm[i][c] * r[i]).sum::<f64>();
        }
        for c in 0..p.bb[0].len() {
            // The offset mid-surface's membrane strain ε + e κ works on N too.
            fl[bend(c)] += wd * (0..3).map(|i| p.bb[i][c] * (r[3 + i] + e * r[i])).sum::<f64>();
        }
        if let Some(d) = &fr.dst {
            let v = [s(6)?, s(7)?];
            for c in 0..9 {
                fl[bend(c)] += wd * (d.gamma[0][c] * v[0] + d.gamma[1][c] * v[1]);
            }
        }
    }
    Ok(to_global(&fr.r, &fl))
}

/// Area of each point of [`rule`] (INTG of a field given at the points).
pub fn point_weights(f: Formulation, x: &[[f64; 3]]) -> Result<Vec<f64>, FemError> {
    let fr = frame(f, x)?;
    Ok(points(f, &fr)?.iter().map(|(p, w)| w * p.det).collect())
}

/// ∫ N_i dA over the element plane, per corner.
pub fn node_weights(f: Formulation, x: &[[f64; 3]]) -> Result<Vec<f64>, FemError> {
    let fr = frame(f, x)?;
    let ty = geometry(f);
    let mut out = vec![0.0; x.len()];
    for ((p, w), (xi, _)) in points(f, &fr)?.iter().zip(rule(ty)) {
        for (o, n) in out.iter_mut().zip(super::shape::eval(ty, xi).n) {
            *o += w * p.det * n;
        }
    }
    Ok(out)
}

/// Mass: ρ t on each translation, ρ t³/12 on each rotation (the same on
/// all three, so the matrix needs no turning), with the corner shape
/// functions: lumped, ∫N_i on the diagonal; consistent, ∫N_i N_j (the
/// rule is exact for these products). Either way the total translational
/// mass is ρ t A.
pub fn mass(f: Formulation, mode: Mode, x: &[[f64; 3]], m: &Material, lumped: bool) -> Result<ElemMatrix, FemError> {
    dofs(f, mode)?;
    let rho = m.density(f.name())?;
    let t = m.positive(m.epai, "EPAI", f.name())?;
    let nn = x.len();
    let nij = if lumped {
        let mut d = vec![0.0; nn * nn];
        for (i, wi) in node_weights(f, x)?.into_iter().enumerate() {
            d[i * nn + i] = wi;
        }
        d
    } else {
        shape_products(f, x)?
    };
    let n = 6 * nn;
    let mut k = vec![0.0; n * n];
    for i in 0..nn {
        for j in 0..nn {
            for c in 0..6 {
                let v = if c < 3 { rho * t } else { rho * t * t * t / 12.0 };
                k[(6 * i + c) * n + 6 * j + c] = v * nij[i * nn + j];
            }
        }
    }
    Ok(ElemMatrix { dofs: dof_list(nn), k })
}

/// ∫ N_i N_j dA over the element plane (`nn × nn`, row-major): the rule
/// is exact for these products.
pub fn shape_products(f: Formulation, x: &[[f64; 3]]) -> Result<Vec<f64>, FemError> {
    let fr = frame(f, x)?;
    let ty = geometry(f);
    let nn = x.len();
    let mut nij = vec![0.0; nn * nn];
    for ((p, w), (xi, _)) in points(f, &fr)?.iter().zip(rule(ty)) {
        let sh = super::shape::eval(ty, xi).n;
        for i in 0..nn {
            for j in 0..nn {
                nij[i * nn + j] += w * p.det * sh[i] * sh[j];
            }
        }
    }
    Ok(nij)
}

/// The element's unit normal (x3 of its frame).
pub fn normal(f: Formulation, x: &[[f64; 3]]) -> Result<[f64; 3], FemError> {
    Ok(frame(f, x)?.r[2])
}

/// Nodal forces of a uniform pressure `p` on a shell element (PRES
/// 'COQU'): p ∫N_i dA along the element normal n (see the frame above),
/// so a positive pressure pushes along n.
pub fn pressure_load(f: Formulation, x: &[[f64; 3]], p: f64) -> Result<Vec<[f64; 3]>, FemError> {
    let fr = frame(f, x)?;
    let n = fr.r[2];
    Ok(node_weights(f, x)?.into_iter().map(|w| [p * w * n[0], p * w * n[1], p * w * n[2]]).collect())
}
