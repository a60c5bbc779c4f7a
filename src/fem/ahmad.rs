//! The stiffness and mass of COQ6 (TRI6) and COQ8 (QUA8): degenerated
//! solid shells in the manner of Ahmad, Irons and Zienkiewicz (1970), a
//! Mindlin-type kinematics with transverse shear.
//!
//! Each node carries a unit normal V_i, the normal of the element's
//! mid-surface at that node (computed per element from the quadratic
//! geometry). A point at reference (ξ, η) and height ζ ∈ [−1, 1] is
//!     X = Σ N_i (x_i + h V_i),  h = e + ζ t/2
//! (t = EPAI, e = EXCE: the mid-surface sits at e along the normal from
//! the nodes), and moves with the nodal translations and rotation vectors
//!     u = Σ N_i (u_i + h θ_i × V_i),
//! so any rigid motion is exact (u = a + θ × X) and a fibre stays straight.
//! Strains are read in a frame at each point (e3 normal to the lamina
//! ζ = const, e1 along ∂X/∂ξ), with plane stress (σ33 = 0) and the
//! transverse shears γ13, γ23 carried by k G, k = 5/6.
//!
//! Integration: the in-plane rule of the output points (2×2 on QUA8,
//! 3 points on TRI6: the reduced rules that keep the element from locking
//! in shear when thin) times 2 Gauss points through the thickness, exact
//! for the bending energy of a flat element.
//!
//! Drilling: the rotation θ_i·V_i about a node's own normal has no
//! stiffness in this kinematics, so, as for the flat shells
//! ([`super::shell`]), a small fictitious energy ½ k Σ (θ_i·V_i − ω_i)²
//! ties it to the in-plane rotation ω_i of the mid-surface at the node;
//! rigid motions still cost nothing (θ·V_i = ω_i for them).

use super::element::{ElemMatrix, FemError, Formulation, Mode};
use super::material::Material;
use super::mesh::ElemType;
use super::quadrature::{gauss_1d, quad, tri, QPoint};
use super::shape::{eval, ref_nodes};
use super::vec3::{cross, dot, unit};

/// Shear correction of the transverse shears.
pub const SHEAR_FACTOR: f64 = 5.0 / 6.0;

/// One element's geometry: nodes, nodal normals, thickness, offset.
struct Geom {
    ty: ElemType,
    x: Vec<[f64; 3]>,
    v: Vec<[f64; 3]>,
    t: f64,
    e: f64,
}

fn geom(f: Formulation, x: &[[f64; 3]], m: &Material) -> Result<Geom, FemError> {
    let ty = super::thick_shell::geometry(f);
    if x.len() != ty.nodes() {
        return Err(FemError::WrongNodeCount { elem: ty.name(), expected: ty.nodes(), got: x.len() });
    }
    let t = m.positive(m.epai, "EPAI", f.name())?;
    let size = x.iter().map(|p| dot(sub3(*p, x[0]), sub3(*p, x[0]))).fold(0.0, f64::max).sqrt();
    let mut v = Vec::with_capacity(x.len());
    for p in ref_nodes(ty) {
        let [a1, a2] = tangents(ty, x, None, p);
        let n = cross(a1, a2);
        let nn = dot(n, n).sqrt();
        if nn <= 1e-12 * size * size || !nn.is_finite() {
            return Err(FemError::Degenerate {
                elem: f.name(),
                why: "zero area at a node (aligned or coincident nodes)".into(),
            });
        }
        v.push(n.map(|c| c / nn));
    }
    Ok(Geom { ty, x: x.to_vec(), v, t, e: m.exce.unwrap_or(0.0) })
}

fn sub3(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// ∂X/∂ξ and ∂X/∂η of the surface through the nodes (offset by h along
/// the normals when given).
fn tangents(ty: ElemType, x: &[[f64; 3]], off: Option<(&[[f64; 3]], f64)>, p: [f64; 3]) -> [[f64; 3]; 2] {
    let s = eval(ty, p);
    std::array::from_fn(|a| {
        std::array::from_fn(|c| {
            s.dn.iter().enumerate().map(|(i, d)| d[a] * (x[i][c] + off.map_or(0.0, |(v, h)| h * v[i][c]))).sum::<f64>()
        })
    })
}

fn inv3(j: &[[f64; 3]; 3]) -> Option<([[f64; 3]; 3], f64)> {
    let det = dot(j[0], cross(j[1], j[2]));
    if det <= 0.0 || !det.is_finite() {
        return None;
    }
    // Columns of the inverse are the reciprocal basis: inv[l][a] with
    // Σ_l J[a][l] inv[l][b] = δ_ab.
    let r = [cross(j[1], j[2]), cross(j[2], j[0]), cross(j[0], j[1])];
    Some((std::array::from_fn(|l| std::array::from_fn(|a| r[a][l] / det)), det))
}

/// Strain rows at one point: (ε11, ε22, γ12, γ13, γ23) in the point's
/// frame over the 6n element dofs, and the volume weight det J.
struct Point {
    b: [Vec<f64>; 5],
    det: f64,
}

/// The per-dof displacement fields at a point, u = w φ: for each element
/// dof its direction w and the physical gradient of its scalar φ; the
/// point's frame (e1, e2, e3) and det J.
struct Fields {
    cols: Vec<([f64; 3], [f64; 3])>,
    frame: [[f64; 3]; 3],
    det: f64,
}

fn fields(g: &Geom, p: [f64; 3], zeta: f64) -> Option<Fields> {
    let h = g.e + zeta * g.t / 2.0;
    let s = eval(g.ty, p);
    let [a1, a2] = tangents(g.ty, &g.x, Some((&g.v, h)), p);
    let a3: [f64; 3] = std::array::from_fn(|c| s.n.iter().zip(&g.v).map(|(n, v)| n * v[c] * g.t / 2.0).sum::<f64>());
    let (jinv, det) = inv3(&[a1, a2, a3])?;
    let phys = |d: [f64; 3]| -> [f64; 3] { std::array::from_fn(|l| (0..3).map(|a| jinv[l][a] * d[a]).sum()) };
    let e3 = unit(cross(a1, a2));
    let e1 = unit(a1);
    let e2 = cross(e3, e1);
    let mut out = Vec::with_capacity(6 * g.x.len());
    for (i, v) in g.v.iter().enumerate() {
        let pt = phys([s.dn[i][0], s.dn[i][1], 0.0]);
        let pr = phys([s.dn[i][0] * h, s.dn[i][1] * h, s.n[i] * g.t / 2.0]);
        for d in 0..3 {
            let mut w = [0.0; 3];
            w[d] = 1.0;
            out.push((w, pt));
        }
        for d in 0..3 {
            let mut ed = [0.0; 3];
            ed[d] = 1.0;
            out.push((cross(ed, *v), pr));
        }
    }
    Some(Fields { cols: out, frame: [e1, e2, e3], det })
}

fn folded(f: Formulation) -> FemError {
    FemError::Degenerate { elem: f.name(), why: "the element is folded, or thicker than its curvature allows".into() }
}

fn point(g: &Geom, f: Formulation, p: [f64; 3], zeta: f64) -> Result<Point, FemError> {
    let Fields { cols, frame: e, det } = fields(g, p, zeta).ok_or_else(|| folded(f))?;
    let n = cols.len();
    let mut b = [vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]];
    // e_a · G e_b with G = w ⊗ P: (e_a·w)(P·e_b).
    for (c, (w, pg)) in cols.iter().enumerate() {
        let ew: [f64; 3] = std::array::from_fn(|a| dot(e[a], *w));
        let pe: [f64; 3] = std::array::from_fn(|a| dot(*pg, e[a]));
        b[0][c] = ew[0] * pe[0];
        b[1][c] = ew[1] * pe[1];
        b[2][c] = ew[0] * pe[1] + ew[1] * pe[0];
        b[3][c] = ew[0] * pe[2] + ew[2] * pe[0];
        b[4][c] = ew[1] * pe[2] + ew[2] * pe[1];
    }
    Ok(Point { b, det })
}

/// In-plane rule for the stiffness (reduced) or the mass (exact for N_i N_j).
fn plane_rule(ty: ElemType, mass: bool) -> Vec<QPoint> {
    match (ty == ElemType::Tri6, mass) {
        (true, false) => tri(3),
        (true, true) => tri(7),
        (false, false) => quad(2),
        (false, true) => quad(3),
    }
}

/// Plane-stress and shear moduli: (E/(1−ν²), ν, k G).
fn moduli(f: Formulation, m: &Material) -> Result<(f64, f64, f64), FemError> {
    let e = m.young(f.name())?;
    let nu = m.poisson_plane_stress(f.name())?;
    Ok((e / (1.0 - nu * nu), nu, SHEAR_FACTOR * m.shear_modulus(f.name())?))
}

fn dof_list(nodes: usize) -> Vec<(usize, &'static str)> {
    let names = ["UX", "UY", "UZ", "RX", "RY", "RZ"];
    (0..nodes).flat_map(|i| names.iter().map(move |&d| (i, d))).collect()
}

pub fn stiffness(f: Formulation, mode: Mode, x: &[[f64; 3]], m: &Material) -> Result<ElemMatrix, FemError> {
    super::thick_shell::dofs(f, mode)?;
    let g = geom(f, x, m)?;
    let (c, nu, ks) = moduli(f, m)?;
    let d = [
        [c, c * nu, 0.0, 0.0, 0.0],
        [c * nu, c, 0.0, 0.0, 0.0],
        [0.0, 0.0, c * (1.0 - nu) / 2.0, 0.0, 0.0],
        [0.0, 0.0, 0.0, ks, 0.0],
        [0.0, 0.0, 0.0, 0.0, ks],
    ];
    let n = 6 * x.len();
    let mut k = vec![0.0; n * n];
    for (p, w) in plane_rule(g.ty, false) {
        for (z, wz) in gauss_1d(2) {
            let pt = point(&g, f, p, z)?;
            let wd = w * wz * pt.det;
            let db: Vec<[f64; 5]> =
                (0..n).map(|j| std::array::from_fn(|r| (0..5).map(|s| d[r][s] * pt.b[s][j]).sum())).collect();
            for i in 0..n {
                let bi: [f64; 5] = std::array::from_fn(|r| pt.b[r][i]);
                if bi.iter().all(|v| *v == 0.0) {
                    continue;
                }
                for j in 0..n {
                    k[i * n + j] += wd * (0..5).map(|r| bi[r] * db[j][r]).sum::<f64>();
                }
            }
        }
    }
    add_drilling(&g, &mut k, n);
    Ok(ElemMatrix { dofs: dof_list(x.len()), k })
}

/// The fictitious drilling energy of the module comment, its stiffness
/// [`super::shell::DRILL`] times the mean rotational stiffness of a node.
fn add_drilling(g: &Geom, k: &mut [f64], n: usize) {
    let nn = g.x.len();
    let rot: f64 = (0..nn).flat_map(|i| (3..6).map(move |d| 6 * i + d)).map(|r| k[r * n + r]).sum();
    let kd = super::shell::DRILL * rot / (2 * nn) as f64;
    for (i, p) in ref_nodes(g.ty).into_iter().enumerate() {
        let s = eval(g.ty, p);
        let vi = g.v[i];
        let [a1, a2] = tangents(g.ty, &g.x, Some((&g.v, g.e)), p);
        let e1 = unit(sub3(a1, vi.map(|c| c * dot(a1, vi))));
        let e2 = cross(vi, e1);
        // ∂/∂x_b = Σ_a inv[b][a] ∂/∂ξ_a on the tangent plane.
        let jl = [[dot(a1, e1), dot(a1, e2)], [dot(a2, e1), dot(a2, e2)]];
        let det = jl[0][0] * jl[1][1] - jl[0][1] * jl[1][0];
        let inv = [[jl[1][1] / det, -jl[0][1] / det], [-jl[1][0] / det, jl[0][0] / det]];
        let mut b = vec![0.0; n];
        for (j, vj) in g.v.iter().enumerate() {
            let dx = [0, 1].map(|bb| inv[bb][0] * s.dn[j][0] + inv[bb][1] * s.dn[j][1]);
            // ω = ½(e2·∂u/∂x1 − e1·∂u/∂x2); u = N_j (u_j + e θ_j × V_j).
            for d in 0..3 {
                let mut ed = [0.0; 3];
                ed[d] = 1.0;
                b[6 * j + d] -= 0.5 * (e2[d] * dx[0] - e1[d] * dx[1]);
                let w = cross(ed, *vj);
                b[6 * j + 3 + d] -= 0.5 * g.e * (dot(e2, w) * dx[0] - dot(e1, w) * dx[1]);
            }
        }
        for d in 0..3 {
            b[6 * i + 3 + d] += vi[d];
        }
        for r in 0..n {
            if b[r] != 0.0 {
                for q in 0..n {
                    k[r * n + q] += kd * b[r] * b[q];
                }
            }
        }
    }
}

/// Consistent mass ∫ ρ uᵀu dV with the shell kinematics (rotary inertia
/// included), or lumped: its diagonal scaled so that each direction keeps
/// the element's total (the diagonal scaling of Hinton, Rock and
/// Zienkiewicz, which keeps the corner masses of QUA8 and TRI6 positive).
pub fn mass(f: Formulation, mode: Mode, x: &[[f64; 3]], m: &Material, lumped: bool) -> Result<ElemMatrix, FemError> {
    super::thick_shell::dofs(f, mode)?;
    let g = geom(f, x, m)?;
    let rho = m.density(f.name())?;
    let nn = x.len();
    let n = 6 * nn;
    let mut k = vec![0.0; n * n];
    for (p, w) in plane_rule(g.ty, true) {
        for (z, wz) in gauss_1d(2) {
            let det = fields(&g, p, z).ok_or_else(|| folded(f))?.det;
            let h = g.e + z * g.t / 2.0;
            let s = eval(g.ty, p);
            // Each dof's displacement vector at the point.
            let u: Vec<[f64; 3]> = (0..n)
                .map(|c| {
                    let (i, d) = (c / 6, c % 6);
                    let mut ed = [0.0; 3];
                    ed[d % 3] = 1.0;
                    let v = if d < 3 { ed } else { cross(ed, g.v[i]).map(|q| q * h) };
                    v.map(|q| q * s.n[i])
                })
                .collect();
            let wd = rho * w * wz * det;
            for i in 0..n {
                for j in 0..n {
                    k[i * n + j] += wd * dot(u[i], u[j]);
                }
            }
        }
    }
    if lumped {
        let mut diag = vec![0.0; n * n];
        for d in 0..6 {
            let idx: Vec<usize> = (0..nn).map(|i| 6 * i + d).collect();
            let total: f64 =
                idx.iter().flat_map(|&r| idx.iter().map(move |&q| (r, q))).map(|(r, q)| k[r * n + q]).sum();
            let trace: f64 = idx.iter().map(|&r| k[r * n + r]).sum();
            // Translations keep the element's mass; rotations their own trace.
            let scale = if d < 3 && trace > 0.0 { total / trace } else { 1.0 };
            for &r in &idx {
                diag[r * n + r] = k[r * n + r] * scale;
            }
        }
        k = diag;
    }
    Ok(ElemMatrix { dofs: dof_list(nn), k })
}
