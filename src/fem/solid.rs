//! Isoparametric massive elements: TRI3, TRI6, QUA4 (and Q4RI), QUA8 in the
//! 2D modes; CUB8, TET4, PRI6 in TRID.
//!
//! Integration (stiffness and stress points):
//! * TRI3, TET4: 1 point (B is constant, so this is exact).
//! * TRI6: 3 points (degree 2: exact for straight-sided elements).
//! * QUA4: 2×2. Q4RI: 1 point, see [`rule`] for its hourglass modes.
//! * Q8RI: QUA8 at 2×2 (reduced): exact for linear strain fields, less
//!   stiff in bending; a lone element has one zero-energy mode.
//! * QUA8: 3×3, full integration. 2×2 would leave a zero-energy mode in a
//!   lone element (and locks less only for thin bending); we prefer a matrix
//!   that is never spuriously singular and exact on rectangles, as Cast3M
//!   does for QUA8.
//! * CUB8: 2×2×2; PRI6: 3-point triangle × 2 Gauss points along ζ.
//! * CU20: 3×3×3 (full, as QUA8); PR15: 7-point triangle × 3 along ζ.
//!
//! Mass uses richer rules so that the consistent mass is exact for
//! undistorted shapes (its integrand is of higher degree than B'DB).

use super::element::{ElemMatrix, FemError, Formulation, GaussField, Mode};
use super::material::{elasticity, Material};
use super::mesh::ElemType;
use super::quadrature::{hexa, prism, quad, seg, tet, tri, QPoint};
use super::shape::eval;

/// Stiffness/stress integration rule.
///
/// Q4RI integrates the QUA4 at its centre only. That matrix has rank 3
/// instead of 5: besides the 3 rigid modes it has 2 *hourglass* modes,
/// u = ξη·(a, b) (the "keystone" patterns), with zero energy. No
/// stabilisation is added; they are controlled only by the neighbours
/// and the boundary conditions, so a Q4RI mesh can be singular where the
/// QUA4 one is not.
pub fn rule(f: Formulation, ty: ElemType) -> Vec<QPoint> {
    match (f, ty) {
        (Formulation::Q4ri, _) => quad(1),
        (Formulation::Q8ri, _) => quad(2),
        (_, ElemType::Tri3) => tri(1),
        (_, ElemType::Tri6) => tri(3),
        (_, ElemType::Qua4) => quad(2),
        (_, ElemType::Qua8) => quad(3),
        (_, ElemType::Cub8) => hexa(2),
        (_, ElemType::Tet4) => tet(1),
        (_, ElemType::Pri6) => prism(3, 2),
        (_, ElemType::Cu20) => hexa(3),
        (_, ElemType::Pr15) => prism(7, 3),
        // The edges of a pressure model (MODE 'CHARGEMENT') in the plane
        // modes carry their values at Gauss points of their own.
        (_, ElemType::Seg2) => seg(2),
        (_, ElemType::Seg3) => seg(3),
        _ => vec![],
    }
}

pub(super) fn mass_rule(ty: ElemType) -> Vec<QPoint> {
    match ty {
        ElemType::Tri3 => tri(3),
        ElemType::Tri6 => tri(7),
        ElemType::Qua4 | ElemType::Qua8 => quad(3),
        ElemType::Cub8 => hexa(3),
        ElemType::Tet4 => tet(4),
        ElemType::Pri6 => prism(7, 3),
        ElemType::Cu20 => hexa(3),
        ElemType::Pr15 => prism(7, 3),
        _ => vec![],
    }
}

/// Names of the displacement components of a massive element.
pub fn dofs(mode: Mode) -> &'static [&'static str] {
    match mode {
        Mode::PlanCont | Mode::PlanDefo => &["UX", "UY"],
        Mode::Axis => &["UR", "UZ"],
        Mode::Trid => &["UX", "UY", "UZ"],
        Mode::Fourier(_) => super::fourier::DOFS,
    }
}

pub fn stress_comps(mode: Mode) -> Vec<&'static str> {
    match mode {
        Mode::PlanCont | Mode::PlanDefo => vec!["SMXX", "SMYY", "SMZZ", "SMXY"],
        Mode::Axis => vec!["SMRR", "SMZZ", "SMTT", "SMRZ"],
        Mode::Trid => vec!["SMXX", "SMYY", "SMZZ", "SMXY", "SMXZ", "SMYZ"],
        Mode::Fourier(_) => super::fourier::STRESSES.to_vec(),
    }
}

pub fn strain_comps(mode: Mode) -> Vec<&'static str> {
    match mode {
        Mode::PlanCont | Mode::PlanDefo => vec!["EPXX", "EPYY", "EPZZ", "GAXY"],
        Mode::Axis => vec!["EPRR", "EPZZ", "EPTT", "GARZ"],
        Mode::Trid => vec!["EPXX", "EPYY", "EPZZ", "GAXY", "GAXZ", "GAYZ"],
        Mode::Fourier(_) => super::fourier::STRAINS.to_vec(),
    }
}

/// One integration point mapped to the element: shape values, physical
/// derivatives and the full weight (w·|J|·thickness, or ·2πr in AXIS).
pub(super) struct Point {
    pub(super) n: Vec<f64>,
    pub(super) dndx: Vec<[f64; 3]>,
    pub(super) w: f64,
    pub(super) r: f64,
}

/// The geometries of massive (continuum) elements: surfaces in the 2D
/// modes, volumes in TRID. Mechanics and heat conduction share them.
pub fn is_massive(ty: ElemType) -> bool {
    matches!(
        ty,
        ElemType::Tri3
            | ElemType::Tri6
            | ElemType::Qua4
            | ElemType::Qua8
            | ElemType::Cub8
            | ElemType::Tet4
            | ElemType::Pri6
            | ElemType::Cu20
            | ElemType::Pr15
    )
}

fn check(ty: ElemType, mode: Mode, x: &[[f64; 3]]) -> Result<usize, FemError> {
    let dim = ty.dim();
    let ok = match dim {
        2 => mode != Mode::Trid,
        3 => mode == Mode::Trid,
        _ => false,
    };
    if !ok || !is_massive(ty) {
        return Err(FemError::Unsupported { form: "massive", elem: ty.name(), mode: mode.name() });
    }
    if x.len() != ty.nodes() {
        return Err(FemError::WrongNodeCount { elem: ty.name(), expected: ty.nodes(), got: x.len() });
    }
    Ok(dim)
}

/// Map every point of `rule` to the element. Elements whose node order is
/// uniformly reversed (clockwise in 2D, left-handed in 3D) are accepted
/// with |J|; a Jacobian that vanishes or changes sign inside the element is
/// an error, since the mapping then folds over itself.
pub(super) fn points(
    ty: ElemType,
    mode: Mode,
    x: &[[f64; 3]],
    rule: &[QPoint],
    t: f64,
) -> Result<Vec<Point>, FemError> {
    let dim = check(ty, mode, x)?;
    let mut size: f64 = 0.0;
    for a in x {
        for b in x {
            size = size.max((0..dim).map(|k| (a[k] - b[k]).powi(2)).sum::<f64>().sqrt());
        }
    }
    let tol = 1e-12 * size.powi(dim as i32);
    let mut out = Vec::with_capacity(rule.len());
    let mut sign = 0.0;
    for &(p, w) in rule {
        let s = eval(ty, p);
        let mut j = [[0.0; 3]; 3];
        for (i, d) in s.dn.iter().enumerate() {
            for a in 0..dim {
                for b in 0..dim {
                    j[a][b] += d[a] * x[i][b];
                }
            }
        }
        let (det, inv) = invert(&j, dim);
        if det.abs() <= tol || !det.is_finite() || (sign != 0.0 && det * sign < 0.0) {
            return Err(FemError::Degenerate {
                elem: ty.name(),
                why: format!("Jacobian {det:e} vanishes or changes sign (flat, folded or badly distorted element)"),
            });
        }
        sign = det.signum();
        let dndx =
            s.dn.iter()
                .map(|d| {
                    let mut g = [0.0; 3];
                    for (b, gb) in g.iter_mut().enumerate().take(dim) {
                        *gb = (0..dim).map(|a| inv[b][a] * d[a]).sum();
                    }
                    g
                })
                .collect();
        let r: f64 = s.n.iter().zip(x).map(|(n, p)| n * p[0]).sum();
        let mut wt = w * det.abs() * t;
        if mode.is_axisymmetric() {
            if r <= 0.0 {
                return Err(FemError::Degenerate {
                    elem: ty.name(),
                    why: format!(
                        "{} element reaches r = {r:e} <= 0 (radius must be the first coordinate, positive)",
                        mode.name()
                    ),
                });
            }
            // Cast3M integrates AXIS over the whole ring: the reactions
            // of a pressure p on a disc of radius a sum to p·π·a².
            wt *= r * mode.turn().unwrap_or(1.0);
        }
        out.push(Point { n: s.n, dndx, w: wt, r });
    }
    Ok(out)
}

/// Determinant and inverse of the leading dim×dim block.
fn invert(j: &[[f64; 3]; 3], dim: usize) -> (f64, [[f64; 3]; 3]) {
    let mut inv = [[0.0; 3]; 3];
    if dim == 2 {
        let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
        if det != 0.0 {
            inv[0] = [j[1][1] / det, -j[0][1] / det, 0.0];
            inv[1] = [-j[1][0] / det, j[0][0] / det, 0.0];
        }
        return (det, inv);
    }
    let c = |r: usize, s: usize| {
        let (r1, r2, s1, s2) = ((r + 1) % 3, (r + 2) % 3, (s + 1) % 3, (s + 2) % 3);
        j[r1][s1] * j[r2][s2] - j[r1][s2] * j[r2][s1]
    };
    let det = (0..3).map(|k| j[0][k] * c(0, k)).sum::<f64>();
    if det != 0.0 {
        for (a, row) in inv.iter_mut().enumerate() {
            for (b, v) in row.iter_mut().enumerate() {
                *v = c(b, a) / det;
            }
        }
    }
    (det, inv)
}

/// Strain-displacement matrix (rows: strains of the mode; columns: element
/// dofs, node-major).
pub(super) fn bmat(mode: Mode, p: &Point) -> Vec<Vec<f64>> {
    let nn = p.n.len();
    if mode == Mode::Trid {
        let mut b = vec![vec![0.0; 3 * nn]; 6];
        for (i, g) in p.dndx.iter().enumerate() {
            let c = 3 * i;
            b[0][c] = g[0];
            b[1][c + 1] = g[1];
            b[2][c + 2] = g[2];
            b[3][c] = g[1];
            b[3][c + 1] = g[0];
            b[4][c] = g[2];
            b[4][c + 2] = g[0];
            b[5][c + 1] = g[2];
            b[5][c + 2] = g[1];
        }
        return b;
    }
    if let Mode::Fourier(n) = mode {
        return super::fourier::bmat(n, &p.n, &p.dndx, p.r);
    }
    let mut b = vec![vec![0.0; 2 * nn]; 4];
    for (i, g) in p.dndx.iter().enumerate() {
        let c = 2 * i;
        b[0][c] = g[0];
        b[1][c + 1] = g[1];
        if mode == Mode::Axis {
            // Hoop strain u_r / r.
            b[2][c] = p.n[i] / p.r;
        }
        b[3][c] = g[1];
        b[3][c + 1] = g[0];
    }
    b
}

pub(super) fn dof_list(ty: ElemType, mode: Mode) -> Vec<(usize, &'static str)> {
    (0..ty.nodes()).flat_map(|i| dofs(mode).iter().map(move |&d| (i, d))).collect()
}

pub fn stiffness(
    f: Formulation,
    ty: ElemType,
    mode: Mode,
    x: &[[f64; 3]],
    m: &Material,
) -> Result<ElemMatrix, FemError> {
    let d = elasticity(mode, m, ty.name())?;
    let t = m.thickness(mode, ty.name())?;
    let pts = points(ty, mode, x, &rule(f, ty), t)?;
    let dofs = dof_list(ty, mode);
    let nd = dofs.len();
    let ns = d.len();
    let mut k = vec![0.0; nd * nd];
    // Flat, reused buffers: RIGI calls this once per element, so the
    // per-point allocations of a Vec-of-rows version dominated its time.
    let mut b = vec![0.0; ns * nd];
    let mut db = vec![0.0; ns * nd];
    for p in &pts {
        for (q, row) in bmat(mode, p).into_iter().enumerate() {
            b[q * nd..(q + 1) * nd].copy_from_slice(&row);
        }
        // (D B) w, then K += Bᵀ (D B w) on the upper triangle.
        for (q, drow) in d.iter().enumerate() {
            let out = &mut db[q * nd..(q + 1) * nd];
            out.fill(0.0);
            for (s, dv) in drow.iter().enumerate() {
                if *dv != 0.0 {
                    let f = dv * p.w;
                    for (o, bv) in out.iter_mut().zip(&b[s * nd..(s + 1) * nd]) {
                        *o += f * bv;
                    }
                }
            }
        }
        for q in 0..ns {
            let (bq, dbq) = (&b[q * nd..(q + 1) * nd], &db[q * nd..(q + 1) * nd]);
            for r in 0..nd {
                let br = bq[r];
                if br != 0.0 {
                    for (kv, dv) in k[r * nd + r..(r + 1) * nd].iter_mut().zip(&dbq[r..]) {
                        *kv += br * dv;
                    }
                }
            }
        }
    }
    // Mirror the upper triangle (K is symmetric).
    for r in 0..nd {
        for c in 0..r {
            k[r * nd + c] = k[c * nd + r];
        }
    }
    Ok(ElemMatrix { dofs, k })
}

/// Consistent mass ρ∫NᵢNⱼ, or its HRZ lumping (diagonal scaled to keep the
/// total mass, which stays positive for quadratic elements where row sums
/// would give zero or negative corner masses).
pub fn mass(ty: ElemType, mode: Mode, x: &[[f64; 3]], m: &Material, lumped: bool) -> Result<ElemMatrix, FemError> {
    let rho = m.density(ty.name())?;
    let t = m.thickness(mode, ty.name())?;
    let pts = points(ty, mode, x, &mass_rule(ty), t)?;
    let nn = ty.nodes();
    let mut mn = vec![0.0; nn * nn];
    for p in &pts {
        for i in 0..nn {
            for j in 0..nn {
                mn[i * nn + j] += rho * p.n[i] * p.n[j] * p.w;
            }
        }
    }
    if lumped {
        let total: f64 = mn.iter().sum();
        let diag: f64 = (0..nn).map(|i| mn[i * nn + i]).sum();
        for i in 0..nn {
            for j in 0..nn {
                mn[i * nn + j] = if i == j { mn[i * nn + i] * total / diag } else { 0.0 };
            }
        }
    }
    let nc = dofs(mode).len();
    let list = dof_list(ty, mode);
    let nd = list.len();
    let mut k = vec![0.0; nd * nd];
    for i in 0..nn {
        for j in 0..nn {
            for c in 0..nc {
                k[(i * nc + c) * nd + j * nc + c] = mn[i * nn + j];
            }
        }
    }
    Ok(ElemMatrix { dofs: list, k })
}

/// Strains (`stress = false`) or stresses at the integration points.
pub fn field(
    f: Formulation,
    ty: ElemType,
    mode: Mode,
    x: &[[f64; 3]],
    m: &Material,
    u: &[f64],
    stress: bool,
) -> Result<GaussField, FemError> {
    let nd = ty.nodes() * dofs(mode).len();
    if u.len() != nd {
        return Err(FemError::WrongDofCount { elem: ty.name(), expected: nd, got: u.len() });
    }
    let pts = points(ty, mode, x, &rule(f, ty), 1.0)?;
    // Strains need no elastic constants, except Poisson's ratio for the
    // plane-stress EPZZ below: do not ask for YOUN when it is not used.
    let d = if stress { Some(elasticity(mode, m, ty.name())?) } else { None };
    let mut values = Vec::with_capacity(pts.len());
    for p in &pts {
        let b = bmat(mode, p);
        let mut eps: Vec<f64> = b.iter().map(|row| row.iter().zip(u).map(|(a, b)| a * b).sum()).collect();
        if mode == Mode::PlanCont && !stress {
            // Plane stress: the out-of-plane strain follows from σzz = 0.
            // Without a material (EPSI mo u, as Cast3M decks write it to
            // compare with ELAS) it stays 0: the in-plane strains need no
            // constant, and Hooke's law in plane stress ignores EPZZ.
            if m.nu.is_some() {
                let nu = m.poisson_plane_stress(ty.name())?;
                eps[2] = -nu / (1.0 - nu) * (eps[0] + eps[1]);
            }
        }
        values.push(match (&d, stress) {
            (Some(d), true) => d.iter().map(|row| row.iter().zip(&eps).map(|(a, b)| a * b).sum()).collect(),
            _ => eps,
        });
    }
    let comps = if stress { stress_comps(mode) } else { strain_comps(mode) };
    Ok(GaussField { comps, values })
}

/// Displacement gradient (GRAD) at the points of [`rule`]: ∂u_i/∂x_j,
/// row by row, always the nine terms of the 3×3 tensor as Cast3M names
/// them ([`gradient_comps`]): in the plane the terms along Z are zero; in
/// AXIS the only term along θ is the hoop one, UT,T = UR/R.
pub fn gradient(f: Formulation, ty: ElemType, mode: Mode, x: &[[f64; 3]], u: &[f64]) -> Result<GaussField, FemError> {
    if let Mode::Fourier(_) = mode {
        return Err(FemError::NotFor { what: "GRAD in mode FOUR", form: "massive" });
    }
    let names = dofs(mode);
    let nc = names.len();
    let nd = ty.nodes() * nc;
    if u.len() != nd {
        return Err(FemError::WrongDofCount { elem: ty.name(), expected: nd, got: u.len() });
    }
    let pts = points(ty, mode, x, &rule(f, ty), 1.0)?;
    let values = pts
        .iter()
        .map(|p| {
            let d =
                |i: usize, j: usize| -> f64 { p.dndx.iter().enumerate().map(|(a, dn)| dn[j] * u[a * nc + i]).sum() };
            match mode {
                Mode::Trid => (0..3).flat_map(|i| (0..3).map(move |j| (i, j))).map(|(i, j)| d(i, j)).collect(),
                Mode::PlanCont | Mode::PlanDefo => vec![d(0, 0), d(0, 1), 0.0, d(1, 0), d(1, 1), 0.0, 0.0, 0.0, 0.0],
                Mode::Fourier(_) => unreachable!("refused above"),
                Mode::Axis => {
                    let hoop = p.n.iter().enumerate().map(|(a, n)| n * u[a * nc]).sum::<f64>() / p.r;
                    vec![d(0, 0), d(0, 1), 0.0, d(1, 0), d(1, 1), 0.0, 0.0, 0.0, hoop]
                }
            }
        })
        .collect();
    Ok(GaussField { comps: gradient_comps(mode), values })
}

/// Names of the GRAD terms: UX,X … UZ,Z, or UR,R UR,Z UR,T UZ,R … UT,T in
/// AXIS.
pub fn gradient_comps(mode: Mode) -> Vec<&'static str> {
    match mode {
        Mode::Axis => vec!["UR,R", "UR,Z", "UR,T", "UZ,R", "UZ,Z", "UZ,T", "UT,R", "UT,Z", "UT,T"],
        _ => vec!["UX,X", "UX,Y", "UX,Z", "UY,X", "UY,Y", "UY,Z", "UZ,X", "UZ,Y", "UZ,Z"],
    }
}

/// Integration weights (w·|J|·thickness, ·2πr in AXIS) of the points of
/// [`rule`], where [`field`] gives stresses and strains.
pub fn point_weights(
    f: Formulation,
    ty: ElemType,
    mode: Mode,
    x: &[[f64; 3]],
    m: &Material,
) -> Result<Vec<f64>, FemError> {
    let t = m.thickness(mode, ty.name())?;
    Ok(points(ty, mode, x, &rule(f, ty), t)?.into_iter().map(|p| p.w).collect())
}

/// `∫ N_i` over the element for each node (with thickness, ·2πr in AXIS).
pub fn node_weights(ty: ElemType, mode: Mode, x: &[[f64; 3]], m: &Material) -> Result<Vec<f64>, FemError> {
    let t = m.thickness(mode, ty.name())?;
    let mut w = vec![0.0; ty.nodes()];
    for p in points(ty, mode, x, &mass_rule(ty), t)? {
        for (wi, ni) in w.iter_mut().zip(&p.n) {
            *wi += ni * p.w;
        }
    }
    Ok(w)
}

/// Nodal forces of a stress field (BSIG): `Σ_k B_kᵀ σ_k w_k` over the
/// points of [`rule`], in [`ElemMatrix`] dof order. For the stresses of a
/// displacement u this is K u.
pub fn internal_forces(
    f: Formulation,
    ty: ElemType,
    mode: Mode,
    x: &[[f64; 3]],
    m: &Material,
    sig: &GaussField,
) -> Result<Vec<f64>, FemError> {
    let t = m.thickness(mode, ty.name())?;
    let pts = points(ty, mode, x, &rule(f, ty), t)?;
    if sig.values.len() != pts.len() {
        return Err(FemError::WrongPointCount { elem: ty.name(), expected: pts.len(), got: sig.values.len() });
    }
    let comps = stress_comps(mode);
    if let Some(c) = comps.iter().find(|c| !sig.comps.contains(c)) {
        return Err(FemError::MissingComponent { comp: c, elem: ty.name() });
    }
    let mut out = vec![0.0; ty.nodes() * dofs(mode).len()];
    for (k, p) in pts.iter().enumerate() {
        let s: Vec<f64> = comps.iter().map(|c| sig.get(c, k).unwrap_or(0.0)).collect();
        for (row, sv) in bmat(mode, p).iter().zip(&s) {
            for (o, b) in out.iter_mut().zip(row) {
                *o += b * sv * p.w;
            }
        }
    }
    Ok(out)
}
