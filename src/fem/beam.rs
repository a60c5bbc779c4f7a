//! Bars (BARR) and beams (POUT Euler–Bernoulli, TIMO Timoshenko) on SEG2.
//!
//! Beams in PLAN CONT/DEFO have dofs UX UY RZ and bend in the xy plane with
//! INRZ; in TRID they have UX UY UZ RX RY RZ, a local frame (x along the
//! element, y from CARA 'VECT', z = x × y), INRY/INRZ about local y/z and
//! torsion G·TORS.
//!
//! TIMO is Cast3M's Timoshenko element: linear deflection and rotation,
//! bending and shear energies integrated at the element's middle (one
//! point, which keeps it free of shear locking). A tip force F on one
//! element of length L therefore deflects it by F·L/(G·As) + F·L³/(4EI)
//! (the exact beam has L³/3). Its stiffness is the "interdependent
//! interpolation" formula with Φ = 12EI/(G·As·L²) − 1: the bending block
//! is the Euler–Bernoulli one with 4 → 4+Φ, 2 → 2−Φ and a 1/(1+Φ) factor
//! (1 + Φ > 0 for any section). SECY is the shear area for deflection
//! along local y (bending with INRZ), SECZ along local z.
//!
//! Stress output (SIGM) is given at the two element ends ("points" 1 and 2):
//! the section resultants EFFX EFFY (EFFZ) (MOMX MOMY) MOMZ in local axes,
//! with the continuum sign convention (the action of the x+ side on the x−
//! side, so tension and sagging moments M = EI·κ are positive at both ends).

use super::element::{ElemMatrix, FemError, GaussField, Mode};
use super::material::Material;
use super::vec3::{cross, dot, sub};

/// Element geometry: length and local axes (rows ex, ey, ez in global).
struct Frame {
    l: f64,
    r: [[f64; 3]; 3],
}

fn frame(elem: &'static str, mode: Mode, x: &[[f64; 3]], m: &Material, need_vect: bool) -> Result<Frame, FemError> {
    if x.len() != 2 {
        return Err(FemError::WrongNodeCount { elem: "SEG2", expected: 2, got: x.len() });
    }
    let mut d = sub(x[1], x[0]);
    if mode != Mode::Trid {
        d[2] = 0.0;
    }
    let l = dot(d, d).sqrt();
    let scale = x.iter().flatten().fold(0.0f64, |a, v| a.max(v.abs()));
    if l <= 1e-12 * scale.max(f64::MIN_POSITIVE) || !l.is_finite() {
        return Err(FemError::Degenerate { elem, why: "zero-length element (both ends coincide)".into() });
    }
    let ex = [d[0] / l, d[1] / l, d[2] / l];
    let (ey, ez) = if mode != Mode::Trid {
        ([-ex[1], ex[0], 0.0], [0.0, 0.0, 1.0])
    } else if need_vect {
        // Without CARA 'VECT', Cast3M's default local y (pouloc.eso): the
        // horizontal normal (−dy, dx, 0) of the axis, or (0, −dz, dy) for an
        // axis along z.
        let v = m.vect.unwrap_or(if ex[0].abs().max(ex[1].abs()) > 1e-12 {
            [-ex[1], ex[0], 0.0]
        } else {
            [0.0, -ex[2], ex[1]]
        });
        let p = dot(v, ex);
        let y = [v[0] - p * ex[0], v[1] - p * ex[1], v[2] - p * ex[2]];
        let ny = dot(y, y).sqrt();
        if ny <= 1e-8 * dot(v, v).sqrt() || !ny.is_finite() {
            return Err(FemError::Degenerate {
                elem,
                why: "CARA VECT is parallel to the element axis (local y undefined)".into(),
            });
        }
        let ey = [y[0] / ny, y[1] / ny, y[2] / ny];
        (ey, cross(ex, ey))
    } else {
        ([0.0; 3], [0.0; 3])
    };
    Ok(Frame { l, r: [ex, ey, ez] })
}

/// Section data a beam needs, read once.
struct Section {
    e: f64,
    g: f64,
    a: f64,
    iy: f64,
    iz: f64,
    j: f64,
    phi_y: f64,
    phi_z: f64,
}

fn section(elem: &'static str, mode: Mode, m: &Material, timo: bool, l: f64) -> Result<Section, FemError> {
    let e = m.young(elem)?;
    let a = m.positive(m.sect, "SECT", elem)?;
    let iz = m.positive(m.inrz, "INRZ", elem)?;
    let d3 = mode == Mode::Trid;
    let g = if d3 || timo { m.shear_modulus(elem)? } else { 0.0 };
    let (iy, j) = if d3 { (m.positive(m.inry, "INRY", elem)?, m.positive(m.tors, "TORS", elem)?) } else { (0.0, 0.0) };
    let (mut phi_y, mut phi_z) = (0.0, 0.0);
    if timo {
        // Φ − 1: the reduced-integration element (see the module notes).
        phi_y = 12.0 * e * iz / (g * m.positive(m.secy.or(m.sect), "SECY", elem)? * l * l) - 1.0;
        if d3 {
            phi_z = 12.0 * e * iy / (g * m.positive(m.secz.or(m.sect), "SECZ", elem)? * l * l) - 1.0;
        }
    }
    Ok(Section { e, g, a, iy, iz, j, phi_y, phi_z })
}

/// Per-node local dof layout: index of (u, v, w, θx, θy, θz) in a node
/// block, `None` when absent (2D).
fn layout(d3: bool) -> [Option<usize>; 6] {
    if d3 {
        [Some(0), Some(1), Some(2), Some(3), Some(4), Some(5)]
    } else {
        [Some(0), Some(1), None, None, None, Some(2)]
    }
}

/// Add the 2×2 block `blk` on rows/columns `idx` of the n×n matrix `k`.
fn add2(k: &mut [f64], n: usize, idx: [usize; 2], blk: [[f64; 2]; 2]) {
    for (p, &i) in idx.iter().enumerate() {
        for (q, &j) in idx.iter().enumerate() {
            k[i * n + j] += blk[p][q];
        }
    }
}

fn add4(k: &mut [f64], n: usize, idx: [usize; 4], blk: [[f64; 4]; 4]) {
    for (p, &i) in idx.iter().enumerate() {
        for (q, &j) in idx.iter().enumerate() {
            k[i * n + j] += blk[p][q];
        }
    }
}

/// Bending block for (v1, θ1, v2, θ2), `s` = +1 for the xy plane (θz = v')
/// and −1 for the xz plane (θy = −w').
fn bending(ei: f64, l: f64, phi: f64, s: f64) -> [[f64; 4]; 4] {
    let c = ei / (l * l * l * (1.0 + phi));
    let (a, b, d, e) = (12.0 * c, s * 6.0 * l * c, (4.0 + phi) * l * l * c, (2.0 - phi) * l * l * c);
    [[a, b, -a, b], [b, d, -b, e], [-a, -b, a, -b], [b, e, -b, d]]
}

fn local_stiffness(sec: &Section, l: f64, d3: bool) -> (usize, Vec<f64>) {
    let nb = if d3 { 6 } else { 3 };
    let n = 2 * nb;
    let mut k = vec![0.0; n * n];
    let lay = layout(d3);
    let at = |c: usize| -> [usize; 2] { [lay[c].unwrap(), nb + lay[c].unwrap()] };
    let ea = sec.e * sec.a / l;
    add2(&mut k, n, at(0), [[ea, -ea], [-ea, ea]]);
    let (v, tz) = (at(1), at(5));
    add4(&mut k, n, [v[0], tz[0], v[1], tz[1]], bending(sec.e * sec.iz, l, sec.phi_y, 1.0));
    if d3 {
        let gj = sec.g * sec.j / l;
        add2(&mut k, n, at(3), [[gj, -gj], [-gj, gj]]);
        let (w, ty) = (at(2), at(4));
        add4(&mut k, n, [w[0], ty[0], w[1], ty[1]], bending(sec.e * sec.iy, l, sec.phi_z, -1.0));
    }
    (n, k)
}

/// Global ← local: K = Tᵀ K_loc T with T = diag(R, R, ...) on the
/// translation and rotation triples (2D: the 2×2 rotation, RZ unchanged).
fn to_global(kl: &[f64], n: usize, f: &Frame, d3: bool) -> Vec<f64> {
    let t = transform(n, f, d3);
    let mut tmp = vec![0.0; n * n];
    for i in 0..n {
        for j in 0..n {
            tmp[i * n + j] = (0..n).map(|q| kl[i * n + q] * t[q * n + j]).sum();
        }
    }
    let mut k = vec![0.0; n * n];
    for i in 0..n {
        for j in 0..n {
            k[i * n + j] = (0..n).map(|q| t[q * n + i] * tmp[q * n + j]).sum();
        }
    }
    k
}

fn transform(n: usize, f: &Frame, d3: bool) -> Vec<f64> {
    let mut t = vec![0.0; n * n];
    let (bs, nbl) = if d3 { (3, n / 3) } else { (2, 0) };
    if d3 {
        for b in 0..nbl {
            for i in 0..3 {
                for j in 0..3 {
                    t[(b * bs + i) * n + b * bs + j] = f.r[i][j];
                }
            }
        }
    } else {
        for node in 0..2 {
            let o = 3 * node;
            for i in 0..2 {
                for j in 0..2 {
                    t[(o + i) * n + o + j] = f.r[i][j];
                }
            }
            t[(o + 2) * n + o + 2] = 1.0;
        }
    }
    t
}

pub fn dofs(mode: Mode) -> Result<&'static [&'static str], FemError> {
    match mode {
        Mode::PlanCont | Mode::PlanDefo => Ok(&["UX", "UY", "RZ"]),
        Mode::Trid => Ok(&["UX", "UY", "UZ", "RX", "RY", "RZ"]),
        Mode::Axis | Mode::Fourier(_) => {
            Err(FemError::Unsupported { form: "POUT/TIMO", elem: "SEG2", mode: mode.name() })
        }
    }
}

fn dof_list(names: &'static [&'static str]) -> Vec<(usize, &'static str)> {
    (0..2).flat_map(|i| names.iter().map(move |&d| (i, d))).collect()
}

fn elem_name(timo: bool) -> &'static str {
    if timo {
        "TIMO"
    } else {
        "POUT"
    }
}

pub fn stiffness(timo: bool, mode: Mode, x: &[[f64; 3]], m: &Material) -> Result<ElemMatrix, FemError> {
    let names = dofs(mode)?;
    let elem = elem_name(timo);
    let d3 = mode == Mode::Trid;
    let f = frame(elem, mode, x, m, d3)?;
    let sec = section(elem, mode, m, timo, f.l)?;
    let (n, kl) = local_stiffness(&sec, f.l, d3);
    Ok(ElemMatrix { dofs: dof_list(names), k: to_global(&kl, n, &f, d3) })
}

/// Consistent (cubic Hermite, Euler–Bernoulli, also used for TIMO) or
/// lumped (ρAL/2 per translation, ρAL³/78 per bending rotation — the HRZ
/// values — and ρ(INRY+INRZ)L/2 in torsion) mass.
pub fn mass(timo: bool, mode: Mode, x: &[[f64; 3]], m: &Material, lumped: bool) -> Result<ElemMatrix, FemError> {
    let names = dofs(mode)?;
    let elem = elem_name(timo);
    let d3 = mode == Mode::Trid;
    let f = frame(elem, mode, x, m, d3)?;
    let rho = m.density(elem)?;
    let a = m.positive(m.sect, "SECT", elem)?;
    let ip = if d3 { m.positive(m.inry, "INRY", elem)? + m.positive(m.inrz, "INRZ", elem)? } else { 0.0 };
    let l = f.l;
    let nb = names.len();
    let n = 2 * nb;
    let lay = layout(d3);
    let at = |c: usize| -> [usize; 2] { [lay[c].unwrap(), nb + lay[c].unwrap()] };
    let mut kl = vec![0.0; n * n];
    let (mt, mr) = (rho * a * l, rho * ip * l);
    let bar = |t: f64| {
        if lumped {
            [[t / 2.0, 0.0], [0.0, t / 2.0]]
        } else {
            [[t / 3.0, t / 6.0], [t / 6.0, t / 3.0]]
        }
    };
    let bend = |s: f64| -> [[f64; 4]; 4] {
        if lumped {
            let (p, q) = (mt / 2.0, mt * l * l / 78.0);
            [[p, 0., 0., 0.], [0., q, 0., 0.], [0., 0., p, 0.], [0., 0., 0., q]]
        } else {
            let c = mt / 420.0;
            let (a, b, d, e, g, h) =
                (156.0 * c, s * 22.0 * l * c, 4.0 * l * l * c, 54.0 * c, s * 13.0 * l * c, -3.0 * l * l * c);
            [[a, b, e, -g], [b, d, g, h], [e, g, a, -b], [-g, h, -b, d]]
        }
    };
    add2(&mut kl, n, at(0), bar(mt));
    let (v, tz) = (at(1), at(5));
    add4(&mut kl, n, [v[0], tz[0], v[1], tz[1]], bend(1.0));
    if d3 {
        add2(&mut kl, n, at(3), bar(mr));
        let (w, ty) = (at(2), at(4));
        add4(&mut kl, n, [w[0], ty[0], w[1], ty[1]], bend(-1.0));
    }
    Ok(ElemMatrix { dofs: dof_list(names), k: to_global(&kl, n, &f, d3) })
}

/// Local end forces K_loc·T·u, turned into section resultants at both ends.
fn end_resultants(
    timo: bool,
    mode: Mode,
    x: &[[f64; 3]],
    m: &Material,
    u: &[f64],
) -> Result<(Section, [[f64; 6]; 2]), FemError> {
    let names = dofs(mode)?;
    let elem = elem_name(timo);
    if u.len() != 2 * names.len() {
        return Err(FemError::WrongDofCount { elem, expected: 2 * names.len(), got: u.len() });
    }
    let d3 = mode == Mode::Trid;
    let f = frame(elem, mode, x, m, d3)?;
    let sec = section(elem, mode, m, timo, f.l)?;
    let (n, kl) = local_stiffness(&sec, f.l, d3);
    let t = transform(n, &f, d3);
    let ul: Vec<f64> = (0..n).map(|i| (0..n).map(|j| t[i * n + j] * u[j]).sum()).collect();
    let fl: Vec<f64> = (0..n).map(|i| (0..n).map(|j| kl[i * n + j] * ul[j]).sum()).collect();
    let nb = names.len();
    let mut out = [[0.0; 6]; 2];
    for (c, slot) in layout(d3).iter().enumerate() {
        if let Some(s) = slot {
            out[0][c] = -fl[*s];
            out[1][c] = fl[nb + *s];
        }
    }
    Ok((sec, out))
}

pub fn stress(timo: bool, mode: Mode, x: &[[f64; 3]], m: &Material, u: &[f64]) -> Result<GaussField, FemError> {
    let (_, r) = end_resultants(timo, mode, x, m, u)?;
    Ok(if mode == Mode::Trid {
        GaussField {
            comps: vec!["EFFX", "EFFY", "EFFZ", "MOMX", "MOMY", "MOMZ"],
            values: r.iter().map(|v| v.to_vec()).collect(),
        }
    } else {
        GaussField { comps: vec!["EFFX", "EFFY", "MOMZ"], values: r.iter().map(|v| vec![v[0], v[1], v[5]]).collect() }
    })
}

/// Generalised strains: axial EPSS = N/EA, shears GAXY GAXZ = V/(G·As)
/// (0 for POUT, which has no shear strain), twist CURX = Mx/GJ and
/// curvatures CURY CURZ = M/EI, at the two ends.
pub fn strain(timo: bool, mode: Mode, x: &[[f64; 3]], m: &Material, u: &[f64]) -> Result<GaussField, FemError> {
    let (s, r) = end_resultants(timo, mode, x, m, u)?;
    let elem = elem_name(timo);
    let (gy, gz) = if timo {
        let gz = if mode == Mode::Trid { s.g * m.positive(m.secz.or(m.sect), "SECZ", elem)? } else { 1.0 };
        (s.g * m.positive(m.secy.or(m.sect), "SECY", elem)?, gz)
    } else {
        (f64::INFINITY, f64::INFINITY)
    };
    let e = |v: &[f64; 6]| -> [f64; 6] {
        let tw = if s.j > 0.0 { v[3] / (s.g * s.j) } else { 0.0 };
        let cy = if s.iy > 0.0 { v[4] / (s.e * s.iy) } else { 0.0 };
        [v[0] / (s.e * s.a), v[1] / gy, v[2] / gz, tw, cy, v[5] / (s.e * s.iz)]
    };
    let vals: Vec<[f64; 6]> = r.iter().map(e).collect();
    Ok(if mode == Mode::Trid {
        GaussField {
            comps: vec!["EPSS", "GAXY", "GAXZ", "CURX", "CURY", "CURZ"],
            values: vals.iter().map(|v| v.to_vec()).collect(),
        }
    } else {
        GaussField {
            comps: vec!["EPSS", "GAXY", "CURZ"],
            values: vals.iter().map(|v| vec![v[0], v[1], v[5]]).collect(),
        }
    })
}

/// Generalised Hooke's law (ELAS): resultants from generalised strains,
/// EFFX = EA·EPSS, MOMX = GJ·CURX, MOMY = EI_y·CURY, MOMZ = EI_z·CURZ, and
/// for TIMO the shear forces G·A_s·GAXY (GAXZ). A POUT is rigid in shear:
/// its shear forces come from equilibrium, not from a strain, so they are
/// 0 here. Absent strain components count as 0.
pub fn hooke(timo: bool, mode: Mode, m: &Material, eps: &GaussField) -> Result<GaussField, FemError> {
    let elem = elem_name(timo);
    let s = section(elem, mode, m, timo, 1.0)?;
    let d3 = mode == Mode::Trid;
    let (gy, gz) = if timo {
        let gz = if d3 { s.g * m.positive(m.secz.or(m.sect), "SECZ", elem)? } else { 0.0 };
        (s.g * m.positive(m.secy.or(m.sect), "SECY", elem)?, gz)
    } else {
        (0.0, 0.0)
    };
    let at = |v: &[f64], c: &str| eps.comps.iter().position(|n| *n == c).map_or(0.0, |i| v[i]);
    let values = eps
        .values
        .iter()
        .map(|v| {
            let r = [
                s.e * s.a * at(v, "EPSS"),
                gy * at(v, "GAXY"),
                gz * at(v, "GAXZ"),
                s.g * s.j * at(v, "CURX"),
                s.e * s.iy * at(v, "CURY"),
                s.e * s.iz * at(v, "CURZ"),
            ];
            if d3 {
                r.to_vec()
            } else {
                vec![r[0], r[1], r[5]]
            }
        })
        .collect();
    let comps = if d3 { vec!["EFFX", "EFFY", "EFFZ", "MOMX", "MOMY", "MOMZ"] } else { vec!["EFFX", "EFFY", "MOMZ"] };
    Ok(GaussField { comps, values })
}

/// Nodal forces of the section resultants at both ends (the inverse of
/// [`stress`]): in local axes −R at node 1 and +R at node 2, then turned
/// to global axes.
pub fn internal_forces(
    timo: bool,
    mode: Mode,
    x: &[[f64; 3]],
    m: &Material,
    sig: &GaussField,
) -> Result<Vec<f64>, FemError> {
    let names = dofs(mode)?;
    let elem = elem_name(timo);
    let d3 = mode == Mode::Trid;
    if sig.values.len() != 2 {
        return Err(FemError::WrongPointCount { elem, expected: 2, got: sig.values.len() });
    }
    let f = frame(elem, mode, x, m, d3)?;
    const COMPS: [&str; 6] = ["EFFX", "EFFY", "EFFZ", "MOMX", "MOMY", "MOMZ"];
    let nb = names.len();
    let n = 2 * nb;
    let mut fl = vec![0.0; n];
    for (c, slot) in layout(d3).iter().enumerate() {
        if let Some(s) = slot {
            let r = |k: usize| sig.get(COMPS[c], k).ok_or(FemError::MissingComponent { comp: COMPS[c], elem });
            fl[*s] = -r(0)?;
            fl[nb + *s] = r(1)?;
        }
    }
    let t = transform(n, &f, d3);
    Ok((0..n).map(|j| (0..n).map(|i| t[i * n + j] * fl[i]).sum()).collect())
}
