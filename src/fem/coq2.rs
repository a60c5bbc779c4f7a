//! COQ2: the thin conical shell on SEG2, in AXIS (a frustum of a cone
//! turning about the y axis, dofs UR UZ RT) and in the plane modes (a
//! cylindrical shell strip, dofs UX UY RZ).
//!
//! Kirchhoff–Love kinematics on a straight generator of length L with
//! direction (c, s) = (cos φ, sin φ) in the (x, y) plane. Local dofs per
//! node: u along the generator, w along the normal n = (−s, c) (the
//! generator turned by +90°), and the rotation β = dw/dσ, σ the arc
//! length. u is linear in σ, w a cubic Hermite, so rigid motions and a
//! uniform stretch are exact.
//!
//! Generalised strains (1 = along the generator, 2 = hoop in AXIS, the
//! out-of-plane direction in the plane modes):
//! EPSS = u', EPTT = (c u − s w)/r, RTSS = −w'', RTTT = −c w'/r, so a
//! fibre at distance ζ along n is stretched by EPSS + ζ RTSS (and
//! EPTT + ζ RTTT). In the plane modes EPTT = RTTT = 0.
//!
//! In the hoop stretch EPTT, w is interpolated linearly between the nodes,
//! like u: with the cubic w there, the radial motion (c u − s w) mixes a
//! linear and a cubic part that u' cannot balance, and a faceted curved
//! shell (a sphere meshed by cones) under a membrane state shows spurious
//! bending (about 10% on the moment near a sphere–cylinder junction at
//! 20 elements). Rigid motions stay exact (w is linear in them).
//!
//! Resultants (SIGM): N11 N22 per unit length, M11 M22 with M = ∫ σ ζ dζ,
//! so a positive M11 stretches the +n face. AXIS and PLAN DEFO use the
//! plane-stress shell law C = E t/(1 − ν²), D = C t²/12 (in PLAN DEFO
//! N22 = ν N11 from EPTT = 0); PLAN CONT is a strip free to contract across
//! (σ22 = 0: N11 = E t EPSS, N22 = 0) whose matrices carry the width DIM3
//! (default 1). AXIS matrices and loads are for the whole ring (∫ … 2πr dσ), see [`RING`].
//!
//! Integration: 3 Gauss points along the element (the hoop terms hold
//! 1/r, so no rule is exact; 3 points keep the error well below the
//! discretisation error and avoid the apex r = 0). Outputs are at the
//! same points.

use super::element::{ElemMatrix, FemError, GaussField, Mode};
use super::material::Material;
use super::quadrature::{seg, QPoint};

pub const STRESS: [&str; 4] = ["N11", "N22", "M11", "M22"];
pub const STRAIN: [&str; 4] = ["EPSS", "EPTT", "RTSS", "RTTT"];
const NAME: &str = "COQ2";
const STIFF: usize = 3;

/// In AXIS, COQ2's matrices and loads are for the whole ring (∫ … 2πr dσ),
/// unlike the massive elements (per radian): Cast3M's COQ2 takes a nodal
/// force as the total over the circumference (a ring load H per unit
/// length on a ring of radius R is the nodal force 2πR·H).
const RING: f64 = 2.0 * std::f64::consts::PI;

pub fn dofs(mode: Mode) -> Result<&'static [&'static str], FemError> {
    match mode {
        Mode::Axis => Ok(&["UR", "UZ", "RT"]),
        Mode::PlanCont | Mode::PlanDefo => Ok(&["UX", "UY", "RZ"]),
        Mode::Trid | Mode::Fourier(_) => Err(FemError::Unsupported { form: NAME, elem: "SEG2", mode: mode.name() }),
    }
}

/// Integration and output points.
pub fn rule() -> Vec<QPoint> {
    seg(STIFF)
}

struct Geom {
    len: f64,
    c: f64,
    s: f64,
    x: [[f64; 2]; 2],
}

fn geom(x: &[[f64; 3]]) -> Result<Geom, FemError> {
    if x.len() != 2 {
        return Err(FemError::WrongNodeCount { elem: "SEG2", expected: 2, got: x.len() });
    }
    let (dx, dy) = (x[1][0] - x[0][0], x[1][1] - x[0][1]);
    let len = (dx * dx + dy * dy).sqrt();
    if len <= 0.0 || !len.is_finite() {
        return Err(FemError::Degenerate { elem: NAME, why: "zero length".into() });
    }
    Ok(Geom { len, c: dx / len, s: dy / len, x: [[x[0][0], x[0][1]], [x[1][0], x[1][1]]] })
}

/// One point: the weight of ∫ … dσ (times r in AXIS, DIM3 in PLAN CONT)
/// and the 4 strain rows over the 6 global dofs.
struct Point {
    w: f64,
    b: [[f64; 6]; 4],
}

fn points(mode: Mode, g: &Geom, width: f64) -> Result<Vec<Point>, FemError> {
    points_on(mode, g, width, rule())
}

fn points_on(mode: Mode, g: &Geom, width: f64, rule: Vec<QPoint>) -> Result<Vec<Point>, FemError> {
    let axis = mode == Mode::Axis;
    rule.into_iter()
        .map(|(p, wq)| {
            let xi = p[0];
            let r = radius(g, xi);
            let bl = local_rows(g, xi, axis)?;
            let w = wq * g.len / 2.0 * if axis { RING * r } else { width };
            Ok(Point { w, b: bl.map(|row| to_global_row(g, &row)) })
        })
        .collect()
}

fn radius(g: &Geom, xi: f64) -> f64 {
    0.5 * (1.0 - xi) * g.x[0][0] + 0.5 * (1.0 + xi) * g.x[1][0]
}

/// The 4 strain rows at ξ over the local dofs (u1 w1 β1 u2 w2 β2).
fn local_rows(g: &Geom, xi: f64, axis: bool) -> Result<[[f64; 6]; 4], FemError> {
    let l = g.len;
    let r = radius(g, xi);
    if axis && (r <= 0.0 || !r.is_finite()) {
        return Err(FemError::Degenerate {
            elem: NAME,
            why: "in AXIS the element must lie at radius r >= 0, off the axis".into(),
        });
    }
    let n = [0.5 * (1.0 - xi), 0.5 * (1.0 + xi)];
    let dn = [-1.0 / l, 1.0 / l];
    let (_, dh, d2h) = hermite(l, xi);
    let mut bl = [[0.0; 6]; 4];
    for a in 0..2 {
        bl[0][3 * a] = dn[a];
        bl[2][3 * a + 1] = -d2h[2 * a];
        bl[2][3 * a + 2] = -d2h[2 * a + 1];
        if axis {
            bl[1][3 * a] = g.c * n[a] / r;
            // Hoop stretch with w interpolated linearly, like u: see the
            // module doc.
            bl[1][3 * a + 1] = -g.s * n[a] / r;
            bl[3][3 * a + 1] = -g.c * dh[2 * a] / r;
            bl[3][3 * a + 2] = -g.c * dh[2 * a + 1] / r;
        }
    }
    Ok(bl)
}

/// Hermite functions of w over (w1 β1 w2 β2) at ξ, with their first and
/// second σ-derivatives (KSIGMA's beams use the first ones too).
pub(crate) fn hermite(l: f64, xi: f64) -> ([f64; 4], [f64; 4], [f64; 4]) {
    let h = [
        0.25 * (1.0 - xi).powi(2) * (2.0 + xi),
        l / 8.0 * (1.0 - xi).powi(2) * (1.0 + xi),
        0.25 * (1.0 + xi).powi(2) * (2.0 - xi),
        -l / 8.0 * (1.0 + xi).powi(2) * (1.0 - xi),
    ];
    let j = 2.0 / l;
    let dh = [
        0.75 * (xi * xi - 1.0) * j,
        l / 8.0 * (3.0 * xi * xi - 2.0 * xi - 1.0) * j,
        0.75 * (1.0 - xi * xi) * j,
        l / 8.0 * (3.0 * xi * xi + 2.0 * xi - 1.0) * j,
    ];
    let d2h =
        [1.5 * xi * j * j, l / 8.0 * (6.0 * xi - 2.0) * j * j, -1.5 * xi * j * j, l / 8.0 * (6.0 * xi + 2.0) * j * j];
    (h, dh, d2h)
}

/// A row over local (u w β) per node as a row over global (X Y θ):
/// u = c X + s Y, w = −s X + c Y.
fn to_global_row(g: &Geom, row: &[f64; 6]) -> [f64; 6] {
    let mut out = [0.0; 6];
    for a in 0..2 {
        let (bu, bw) = (row[3 * a], row[3 * a + 1]);
        out[3 * a] = g.c * bu - g.s * bw;
        out[3 * a + 1] = g.s * bu + g.c * bw;
        out[3 * a + 2] = row[3 * a + 2];
    }
    out
}

/// Section law: (membrane, bending) 2×2 matrices, and the width factor
/// of the plane-stress strip.
struct Section {
    dm: [[f64; 2]; 2],
    db: [[f64; 2]; 2],
    width: f64,
}

fn section(mode: Mode, m: &Material) -> Result<Section, FemError> {
    let e = m.young(NAME)?;
    let nu = m.poisson_plane_stress(NAME)?;
    let t = m.positive(m.epai, "EPAI", NAME)?;
    let (c, nu, width) = match mode {
        Mode::PlanCont => (e * t, 0.0, m.dim3.map_or(Ok(1.0), |_| m.positive(m.dim3, "DIM3", NAME))?),
        _ => (e * t / (1.0 - nu * nu), nu, 1.0),
    };
    let law = |k: f64| {
        if mode == Mode::PlanCont {
            [[k, 0.0], [0.0, 0.0]]
        } else {
            [[k, k * nu], [k * nu, k]]
        }
    };
    Ok(Section { dm: law(c), db: law(c * t * t / 12.0), width })
}

fn dof_list(mode: Mode) -> Result<Vec<(usize, &'static str)>, FemError> {
    let d = dofs(mode)?;
    Ok((0..2).flat_map(|i| d.iter().map(move |&n| (i, n))).collect())
}

/// The 4×4 law over (EPSS EPTT RTSS RTTT).
fn law(sec: &Section) -> [[f64; 4]; 4] {
    let mut d = [[0.0; 4]; 4];
    for i in 0..2 {
        for j in 0..2 {
            d[i][j] = sec.dm[i][j];
            d[2 + i][2 + j] = sec.db[i][j];
        }
    }
    d
}

pub fn stiffness(mode: Mode, x: &[[f64; 3]], m: &Material) -> Result<ElemMatrix, FemError> {
    let dofs = dof_list(mode)?;
    let g = geom(x)?;
    let sec = section(mode, m)?;
    let d = law(&sec);
    let mut k = vec![0.0; 36];
    for p in points_on(mode, &g, sec.width, seg(STIFF))? {
        for i in 0..6 {
            for j in 0..6 {
                let v: f64 = d
                    .iter()
                    .enumerate()
                    .map(|(a, row)| (0..4).map(|b| p.b[a][i] * row[b] * p.b[b][j]).sum::<f64>())
                    .sum();
                k[i * 6 + j] += p.w * v;
            }
        }
    }
    Ok(ElemMatrix { dofs, k })
}

fn check_u(u: &[f64]) -> Result<(), FemError> {
    if u.len() != 6 {
        return Err(FemError::WrongDofCount { elem: NAME, expected: 6, got: u.len() });
    }
    Ok(())
}

fn strains_at(p: &Point, u: &[f64]) -> [f64; 4] {
    std::array::from_fn(|a| (0..6).map(|i| p.b[a][i] * u[i]).sum())
}

pub fn strain(mode: Mode, x: &[[f64; 3]], u: &[f64]) -> Result<GaussField, FemError> {
    dofs(mode)?;
    check_u(u)?;
    let g = geom(x)?;
    let values = points(mode, &g, 1.0)?.iter().map(|p| strains_at(p, u).to_vec()).collect();
    Ok(GaussField { comps: STRAIN.to_vec(), values })
}

pub fn stress(mode: Mode, x: &[[f64; 3]], m: &Material, u: &[f64]) -> Result<GaussField, FemError> {
    dofs(mode)?;
    check_u(u)?;
    let g = geom(x)?;
    let sec = section(mode, m)?;
    let d = law(&sec);
    let pts = points(mode, &g, 1.0)?;
    let values: Vec<Vec<f64>> = pts
        .iter()
        .map(|p| {
            let e = strains_at(p, u);
            (0..4).map(|a| (0..4).map(|b| d[a][b] * e[b]).sum()).collect()
        })
        .collect();
    Ok(GaussField { comps: STRESS.to_vec(), values })
}

/// ELAS: the section's law on a strain field (EPSS EPTT RTSS RTTT, a
/// missing one read as 0), as [`stress`] applies it to the strains of a
/// displacement.
pub fn hooke(mode: Mode, m: &Material, eps: &GaussField) -> Result<GaussField, FemError> {
    dofs(mode)?;
    if STRAIN.iter().all(|c| !eps.comps.contains(c)) {
        return Err(FemError::MissingComponent { comp: STRAIN[0], elem: NAME });
    }
    let d = law(&section(mode, m)?);
    let at = |v: &[f64], c: &str| eps.comps.iter().position(|k| *k == c).map_or(0.0, |i| v[i]);
    let values = eps
        .values
        .iter()
        .map(|v| {
            let e: [f64; 4] = std::array::from_fn(|a| at(v, STRAIN[a]));
            (0..4).map(|a| (0..4).map(|b| d[a][b] * e[b]).sum()).collect()
        })
        .collect();
    Ok(GaussField { comps: STRESS.to_vec(), values })
}

/// BSIG: Σ w Bᵀ (N11 N22 M11 M22).
pub fn internal_forces(mode: Mode, x: &[[f64; 3]], m: &Material, sig: &GaussField) -> Result<Vec<f64>, FemError> {
    dofs(mode)?;
    let g = geom(x)?;
    let width = if mode == Mode::PlanCont { section(mode, m).map_or(1.0, |s| s.width) } else { 1.0 };
    let pts = points(mode, &g, width)?;
    if sig.values.len() != pts.len() {
        return Err(FemError::WrongPointCount { elem: NAME, expected: pts.len(), got: sig.values.len() });
    }
    let mut f = vec![0.0; 6];
    for (k, p) in pts.iter().enumerate() {
        let s: [f64; 4] = std::array::from_fn(|a| sig.get(STRESS[a], k).unwrap_or(0.0));
        if STRESS.iter().all(|c| sig.get(c, k).is_none()) {
            return Err(FemError::MissingComponent { comp: STRESS[0], elem: NAME });
        }
        for (i, fi) in f.iter_mut().enumerate() {
            *fi += p.w * (0..4).map(|a| p.b[a][i] * s[a]).sum::<f64>();
        }
    }
    Ok(f)
}

/// Measure of each output point (∫ dσ, times 2πr in AXIS): INTG weights.
pub fn point_weights(mode: Mode, x: &[[f64; 3]]) -> Result<Vec<f64>, FemError> {
    let g = geom(x)?;
    Ok(points(mode, &g, 1.0)?.iter().map(|p| p.w).collect())
}

/// ∫ N_i dσ (times 2πr in AXIS) per node, N linear.
pub fn node_weights(mode: Mode, x: &[[f64; 3]]) -> Result<Vec<f64>, FemError> {
    let g = geom(x)?;
    let mut out = vec![0.0; 2];
    for ((p, _), q) in rule().into_iter().zip(points(mode, &g, 1.0)?) {
        out[0] += q.w * 0.5 * (1.0 - p[0]);
        out[1] += q.w * 0.5 * (1.0 + p[0]);
    }
    Ok(out)
}

/// Mass: ρ t over the surface. Consistent: the element's own
/// interpolation (u linear, w Hermite) for the translations, plus the
/// rotary inertia ρ t³/12 on β; lumped: ρ t ∫N_i on each translation and
/// ρ t³/12 ∫N_i on the rotation.
pub fn mass(mode: Mode, x: &[[f64; 3]], m: &Material, lumped: bool) -> Result<ElemMatrix, FemError> {
    let dofs = dof_list(mode)?;
    let g = geom(x)?;
    let rho = m.density(NAME)?;
    let t = m.positive(m.epai, "EPAI", NAME)?;
    let width = if mode == Mode::PlanCont { section(mode, m)?.width } else { 1.0 };
    let mut k = vec![0.0; 36];
    if lumped {
        for (i, wi) in node_weights(mode, x)?.into_iter().enumerate() {
            let wi = wi * width;
            k[(3 * i) * 6 + 3 * i] = rho * t * wi;
            k[(3 * i + 1) * 6 + 3 * i + 1] = rho * t * wi;
            k[(3 * i + 2) * 6 + 3 * i + 2] = rho * t * t * t / 12.0 * wi;
        }
        return Ok(ElemMatrix { dofs, k });
    }
    // The mass integrand r·(cubic)² is of degree 7: 4 Gauss points.
    let pts =
        [(-0.861_136_311_594_052_6, 0.347_854_845_137_453_9), (-0.339_981_043_584_856_3, 0.652_145_154_862_546_1)];
    let l = g.len;
    for (xi, wq) in pts.iter().flat_map(|&(a, w)| [(a, w), (-a, w)]) {
        let r = 0.5 * (1.0 - xi) * g.x[0][0] + 0.5 * (1.0 + xi) * g.x[1][0];
        let wr = wq * l / 2.0 * if mode == Mode::Axis { RING * r } else { width };
        let n = [0.5 * (1.0 - xi), 0.5 * (1.0 + xi)];
        let (h, dh, _) = hermite(l, xi);
        let mut ru = [0.0; 6];
        let mut rw = [0.0; 6];
        let mut rb = [0.0; 6];
        for a in 0..2 {
            ru[3 * a] = n[a];
            rw[3 * a + 1] = h[2 * a];
            rw[3 * a + 2] = h[2 * a + 1];
            rb[3 * a + 1] = dh[2 * a];
            rb[3 * a + 2] = dh[2 * a + 1];
        }
        let (ru, rw, rb) = (to_global_row(&g, &ru), to_global_row(&g, &rw), to_global_row(&g, &rb));
        for i in 0..6 {
            for jj in 0..6 {
                k[i * 6 + jj] +=
                    wr * (rho * t * (ru[i] * ru[jj] + rw[i] * rw[jj]) + rho * t * t * t / 12.0 * rb[i] * rb[jj]);
            }
        }
    }
    Ok(ElemMatrix { dofs, k })
}

/// Nodal forces of a pressure p (linear between the nodes): ∫ p N_i n dσ (times 2πr in AXIS,
/// DIM3 in PLAN CONT) with n = (−s, c), the generator turned by +90°; a
/// positive pressure pushes along n. Linear N: the force stays on the
/// translations.
/// `ring` false gives the per-radian forces of a massive element's edge.
pub fn pressure_load(mode: Mode, x: &[[f64; 3]], p: [f64; 2], width: f64, ring: bool) -> Result<Vec<f64>, FemError> {
    dofs(mode)?;
    let around = if ring { RING } else { 1.0 };
    let g = geom(x)?;
    let mut f = vec![0.0; 6];
    for (pt, w) in super::quadrature::seg(3) {
        let xi = pt[0];
        let n = [0.5 * (1.0 - xi), 0.5 * (1.0 + xi)];
        let r = n[0] * g.x[0][0] + n[1] * g.x[1][0];
        let pv = n[0] * p[0] + n[1] * p[1];
        let wr = w * g.len / 2.0 * if mode == Mode::Axis { around * r } else { width };
        for a in 0..2 {
            f[3 * a] += wr * pv * n[a] * -g.s;
            f[3 * a + 1] += wr * pv * n[a] * g.c;
        }
    }
    Ok(f)
}

/// Thickness of the section (for CALP-like skin stresses).
pub fn thickness(m: &Material) -> Result<f64, FemError> {
    m.positive(m.epai, "EPAI", NAME)
}
