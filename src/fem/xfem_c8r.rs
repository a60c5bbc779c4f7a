//! X-FEM hexahedron XC8R: a CUB8 whose nodes may carry, besides the
//! displacement (UX UY UZ), a Heaviside enrichment (AX AY AZ) and the four
//! crack-tip functions (B1X … B1Z, C1X …, D1X …, E1X … E1Z) of the crack described by two level
//! sets: the *normal* one (PSIP's PHI, signed distance to the crack
//! surface) and the *tangent* one (PSIP's PSI, signed distance to the
//! surface through the front normal to the crack, negative on the crack).
//!
//! The displacement is u = Σᵢ Nᵢ (Uᵢ + H Aᵢ + Σⱼ Fⱼ Bⱼᵢ), enrichments not
//! shifted: the physical displacement of node i is Uᵢ + H(xᵢ) Aᵢ + … (what
//! XFEM 'RECO' rebuilds). H = ±1 is the sign of the normal level set; with
//! (x, y) = (tangent, normal), r and θ the polar coordinates of the point
//! in the front frame, F = √r (sin θ/2, cos θ/2, sin θ/2 sin θ,
//! cos θ/2 sin θ).
//!
//! Integration: an element with no enriched node, or whose Heaviside is
//! constant over it and has no tip node, is a CUB8 (2×2×2). A cut element
//! uses [`sided_rule`] so that the jump of H falls between pieces; an
//! element with tip nodes uses it on finer sub-cells, since √r and its
//! r^-½ derivatives are far from polynomial.

use super::element::{ElemMatrix, FemError, GaussField, Mode};
use super::material::{elasticity, Material};
use super::mesh::ElemType;
use super::quadrature::{hexa, QPoint};
use super::solid::{points, Point};
use super::xfem::q4::{self, XElem};
use super::xfem::NodeKind;
use super::xfem_c8r_cut::{sided_rule, SidedPoint};

pub const NAME: &str = "XC8R";

/// Unknown names: displacement, Heaviside, then the four tip functions.
pub const U: [&str; 3] = ["UX", "UY", "UZ"];
pub const A: [&str; 3] = ["AX", "AY", "AZ"];
pub const B: [[&str; 3]; 4] =
    [["B1X", "B1Y", "B1Z"], ["C1X", "C1Y", "C1Z"], ["D1X", "D1Y", "D1Z"], ["E1X", "E1Y", "E1Z"]];

/// Sub-cells per axis and Gauss points per direction of each piece, for
/// cut elements and for elements touching the front.
const CUT_CELLS: usize = 1;
const CUT_ORDER: usize = 3;
const TIP_CELLS: usize = 2;
const TIP_ORDER: usize = 3;
// (27 points per piece: the conical rule of order n is exact to degree 2n-3.)

/// The crack seen by one element: level sets and enrichment of its 8 nodes.
#[derive(Debug, Clone, PartialEq)]
pub struct Crack {
    pub normal: [f64; 8],
    pub tangent: [f64; 8],
    pub heaviside: [bool; 8],
    pub tip: [bool; 8],
}

impl Crack {
    /// No enrichment: the element is a CUB8.
    pub fn none() -> Crack {
        Crack { normal: [1.0; 8], tangent: [1.0; 8], heaviside: [false; 8], tip: [false; 8] }
    }

    /// The element's unknowns, node-major: U, then A if the node is
    /// Heaviside-enriched, then B1..B4 if it is tip-enriched.
    pub fn dofs(&self) -> Vec<(usize, &'static str)> {
        let mut out = Vec::new();
        for i in 0..8 {
            out.extend(U.iter().map(|&d| (i, d)));
            if self.heaviside[i] {
                out.extend(A.iter().map(|&d| (i, d)));
            }
            if self.tip[i] {
                out.extend(B.iter().flatten().map(|&d| (i, d)));
            }
        }
        out
    }

    fn level_tol(&self) -> f64 {
        1e-9 * self.normal.iter().fold(0.0f64, |m, v| m.max(v.abs())).max(f64::MIN_POSITIVE)
    }

    /// Is the normal level set of both signs on the element?
    fn is_cut(&self) -> bool {
        let tol = self.level_tol();
        self.normal.iter().any(|&v| v > tol) && self.normal.iter().any(|&v| v < -tol)
    }

    /// The side of an element the crack does not cut: the sign of its
    /// nodes off the crack (+1 when all are on it).
    fn whole_side(&self) -> f64 {
        let tol = self.level_tol();
        if self.normal.iter().any(|&v| v < -tol) {
            -1.0
        } else {
            1.0
        }
    }
}

/// The element's integration points in reference coordinates, with the
/// side of the crack each lies on.
pub fn rule(c: &Crack) -> Vec<SidedPoint> {
    let tip = c.tip.iter().any(|&t| t);
    if !tip && !c.is_cut() {
        let side = c.whole_side();
        return hexa(2).into_iter().map(|(xi, w)| SidedPoint { xi, w, side }).collect();
    }
    let level = |xi: [f64; 3]| {
        let s = super::shape::eval(ElemType::Cub8, xi);
        s.n.iter().zip(&c.normal).map(|(n, v)| n * v).sum::<f64>()
    };
    let (cells, order) = if tip { (TIP_CELLS, TIP_ORDER) } else { (CUT_CELLS, CUT_ORDER) };
    sided_rule(level, cells, order, c.level_tol())
}

/// One enrichment function at a point: its value and physical gradient.
#[derive(Debug, Clone, Copy)]
struct Fun {
    v: f64,
    g: [f64; 3],
}

/// The four tip functions at a point whose front-frame coordinates are
/// (x, y) = (tangent, normal), with their gradients gx, gy. `side` is the
/// piece's side of the crack: where the interpolated normal level set
/// disagrees with it (close to the crack), the point is put on the crack
/// lip of its piece, so that sin θ/2 jumps where the pieces meet.
fn tip_functions(x: f64, y: f64, gx: [f64; 3], gy: [f64; 3], side: f64) -> [Fun; 4] {
    let y = if y * side <= 0.0 { 0.0 * side } else { y };
    let r = (x * x + y * y).sqrt();
    if r == 0.0 {
        return [Fun { v: 0.0, g: [0.0; 3] }; 4];
    }
    let th = y.atan2(x);
    let (s, c) = (th / 2.0).sin_cos();
    let (st, ct) = th.sin_cos();
    let sr = r.sqrt();
    // Angular parts g(θ) and g'(θ); F = √r g.
    let g = [s, c, s * st, c * st];
    let dg = [c / 2.0, -s / 2.0, c / 2.0 * st + s * ct, -s / 2.0 * st + c * ct];
    let mut out = [Fun { v: 0.0, g: [0.0; 3] }; 4];
    for k in 0..4 {
        let dr = g[k] / (2.0 * sr);
        let dth = sr * dg[k];
        let dx = ct * dr - st / r * dth;
        let dy = st * dr + ct / r * dth;
        out[k] = Fun { v: sr * g[k], g: [dx * gx[0] + dy * gy[0], dx * gx[1] + dy * gy[1], dx * gx[2] + dy * gy[2]] };
    }
    out
}

/// The shape functions of every element unknown at one mapped point, as
/// (value, gradient), in the order of [`Crack::dofs`] divided by 3 (one
/// scalar per node and enrichment; the three components share it).
fn scalars(c: &Crack, p: &Point, side: f64) -> Vec<Fun> {
    let tip = c.tip.iter().any(|&t| t);
    let funs = if tip {
        let (mut x, mut y, mut gx, mut gy) = (0.0, 0.0, [0.0; 3], [0.0; 3]);
        for i in 0..8 {
            x += p.n[i] * c.tangent[i];
            y += p.n[i] * c.normal[i];
            for d in 0..3 {
                gx[d] += p.dndx[i][d] * c.tangent[i];
                gy[d] += p.dndx[i][d] * c.normal[i];
            }
        }
        tip_functions(x, y, gx, gy, side)
    } else {
        [Fun { v: 0.0, g: [0.0; 3] }; 4]
    };
    let mut out = Vec::with_capacity(8 * 6);
    for i in 0..8 {
        let (n, dn) = (p.n[i], p.dndx[i]);
        out.push(Fun { v: n, g: dn });
        if c.heaviside[i] {
            // H is constant on the piece: its gradient vanishes there.
            out.push(Fun { v: n * side, g: [dn[0] * side, dn[1] * side, dn[2] * side] });
        }
        if c.tip[i] {
            for f in funs {
                let g = [dn[0] * f.v + n * f.g[0], dn[1] * f.v + n * f.g[1], dn[2] * f.v + n * f.g[2]];
                out.push(Fun { v: n * f.v, g });
            }
        }
    }
    out
}

/// Mapped points of the rule, with their sides.
fn mapped(x: &[[f64; 3]], c: &Crack) -> Result<Vec<(Point, f64)>, FemError> {
    let r = rule(c);
    let q: Vec<QPoint> = r.iter().map(|p| (p.xi, p.w)).collect();
    let pts = points(ElemType::Cub8, Mode::Trid, x, &q, 1.0)?;
    Ok(pts.into_iter().zip(r.iter().map(|p| p.side)).collect())
}

/// Strains (EPXX EPYY EPZZ GAXY GAXZ GAYZ) of the element unknowns `u`
/// (ordered as [`Crack::dofs`]) at a point.
fn strain(f: &[Fun], u: &[f64]) -> [f64; 6] {
    let mut e = [0.0; 6];
    for (k, s) in f.iter().enumerate() {
        let (ux, uy, uz) = (u[3 * k], u[3 * k + 1], u[3 * k + 2]);
        let g = s.g;
        e[0] += g[0] * ux;
        e[1] += g[1] * uy;
        e[2] += g[2] * uz;
        e[3] += g[1] * ux + g[0] * uy;
        e[4] += g[2] * ux + g[0] * uz;
        e[5] += g[2] * uy + g[1] * uz;
    }
    e
}

fn check(x: &[[f64; 3]]) -> Result<(), FemError> {
    if x.len() != 8 {
        return Err(FemError::WrongNodeCount { elem: NAME, expected: 8, got: x.len() });
    }
    Ok(())
}

/// Stiffness ∫ Bᵀ D B over the element's sided rule.
pub fn stiffness(x: &[[f64; 3]], c: &Crack, m: &Material) -> Result<ElemMatrix, FemError> {
    check(x)?;
    let d = elasticity(Mode::Trid, m, NAME)?;
    let dofs = c.dofs();
    let nd = dofs.len();
    let mut k = vec![0.0; nd * nd];
    let mut b = vec![[0.0; 6]; nd];
    let mut db = vec![[0.0; 6]; nd];
    for (p, side) in mapped(x, c)? {
        // Column j of B: the strain of unit unknown j.
        for (s, f) in scalars(c, &p, side).iter().enumerate() {
            let g = f.g;
            b[3 * s] = [g[0], 0.0, 0.0, g[1], g[2], 0.0];
            b[3 * s + 1] = [0.0, g[1], 0.0, g[0], 0.0, g[2]];
            b[3 * s + 2] = [0.0, 0.0, g[2], 0.0, g[0], g[1]];
        }
        for j in 0..nd {
            for q in 0..6 {
                db[j][q] = p.w * (0..6).map(|s| d[q][s] * b[j][s]).sum::<f64>();
            }
        }
        for i in 0..nd {
            for j in i..nd {
                k[i * nd + j] += (0..6).map(|q| b[i][q] * db[j][q]).sum::<f64>();
            }
        }
    }
    for i in 0..nd {
        for j in 0..i {
            k[i * nd + j] = k[j * nd + i];
        }
    }
    Ok(ElemMatrix { dofs, k })
}

/// Consistent mass ρ ∫ Ñᵢ Ñⱼ over the sided rule (per component).
pub fn mass(x: &[[f64; 3]], c: &Crack, m: &Material) -> Result<ElemMatrix, FemError> {
    check(x)?;
    let rho = m.density(NAME)?;
    let dofs = c.dofs();
    let nd = dofs.len();
    let mut k = vec![0.0; nd * nd];
    for (p, side) in mapped(x, c)? {
        let f = scalars(c, &p, side);
        for (a, fa) in f.iter().enumerate() {
            for (b, fb) in f.iter().enumerate() {
                let v = rho * p.w * fa.v * fb.v;
                for d in 0..3 {
                    k[(3 * a + d) * nd + 3 * b + d] += v;
                }
            }
        }
    }
    Ok(ElemMatrix { dofs, k })
}

/// What [`field`] gives at the points.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Field {
    Strain,
    Stress,
    Gradient,
}

fn normal_at(c: &Crack, p: &Point) -> f64 {
    p.n.iter().zip(&c.normal).map(|(a, b)| a * b).sum()
}

fn side_of(f: f64) -> f64 {
    if f < 0.0 {
        -1.0
    } else {
        1.0
    }
}

/// The 2×2×2 Gauss points of the CUB8, each with its side of the crack
/// (the sign of the interpolated normal level set): strains and stresses
/// are given there for every element, so that the fields of an X-FEM zone
/// have the layout of a CUB8 zone.
fn gauss(x: &[[f64; 3]], c: &Crack) -> Result<Vec<(Point, f64)>, FemError> {
    let pts = points(ElemType::Cub8, Mode::Trid, x, &hexa(2), 1.0)?;
    Ok(pts.into_iter().map(|p| (side_of(normal_at(c, &p)), p)).map(|(s, p)| (p, s)).collect())
}

fn check_u(c: &Crack, u: &[f64]) -> Result<(), FemError> {
    let nd = c.dofs().len();
    if u.len() != nd {
        return Err(FemError::WrongDofCount { elem: NAME, expected: nd, got: u.len() });
    }
    Ok(())
}

/// Strains, stresses or displacement gradients at the 2×2×2 Gauss points,
/// from the element unknowns `u` ordered as [`Crack::dofs`].
pub fn field(x: &[[f64; 3]], c: &Crack, m: &Material, u: &[f64], what: Field) -> Result<GaussField, FemError> {
    check(x)?;
    check_u(c, u)?;
    let d = if what == Field::Stress { Some(elasticity(Mode::Trid, m, NAME)?) } else { None };
    let mut values = Vec::with_capacity(8);
    for (p, side) in gauss(x, c)? {
        let f = scalars(c, &p, side);
        if what == Field::Gradient {
            // ∂u_i/∂x_j row by row.
            let mut g = vec![0.0; 9];
            for (k, s) in f.iter().enumerate() {
                for i in 0..3 {
                    for j in 0..3 {
                        g[3 * i + j] += s.g[j] * u[3 * k + i];
                    }
                }
            }
            values.push(g);
            continue;
        }
        let e = strain(&f, u);
        values.push(match &d {
            Some(d) => d.iter().map(|row| row.iter().zip(&e).map(|(a, b)| a * b).sum()).collect(),
            None => e.to_vec(),
        });
    }
    let comps = match what {
        Field::Stress => super::solid::stress_comps(Mode::Trid),
        Field::Strain => super::solid::strain_comps(Mode::Trid),
        Field::Gradient => super::solid::gradient_comps(Mode::Trid),
    };
    Ok(GaussField { comps, values })
}

/// Nodal forces Σ Bᵀ σ w of stresses given at the 2×2×2 Gauss points
/// (BSIG), on the element unknowns.
pub fn internal_forces(x: &[[f64; 3]], c: &Crack, sig: &GaussField) -> Result<Vec<f64>, FemError> {
    check(x)?;
    let pts = gauss(x, c)?;
    if sig.values.len() != pts.len() {
        return Err(FemError::WrongPointCount { elem: NAME, expected: pts.len(), got: sig.values.len() });
    }
    let comps = super::solid::stress_comps(Mode::Trid);
    let idx: Vec<usize> = comps
        .iter()
        .map(|n| sig.comps.iter().position(|s| s == n).ok_or(FemError::MissingComponent { comp: n, elem: NAME }))
        .collect::<Result<_, _>>()?;
    let mut out = vec![0.0; c.dofs().len()];
    for ((p, side), s) in pts.iter().zip(&sig.values) {
        let t: Vec<f64> = idx.iter().map(|&i| s[i] * p.w).collect();
        for (k, f) in scalars(c, p, *side).iter().enumerate() {
            let g = f.g;
            out[3 * k] += g[0] * t[0] + g[1] * t[3] + g[2] * t[4];
            out[3 * k + 1] += g[1] * t[1] + g[0] * t[3] + g[2] * t[5];
            out[3 * k + 2] += g[2] * t[2] + g[0] * t[4] + g[1] * t[5];
        }
    }
    Ok(out)
}

/// Physical displacement at reference point `xi` on side `side` of the
/// crack (the lip it belongs to when it lies on the crack; by the sign of
/// the normal level set there when None).
pub fn displacement_at(
    x: &[[f64; 3]],
    c: &Crack,
    u: &[f64],
    xi: [f64; 3],
    side: Option<f64>,
) -> Result<[f64; 3], FemError> {
    check(x)?;
    check_u(c, u)?;
    let p = points(ElemType::Cub8, Mode::Trid, x, &[(xi, 1.0)], 1.0)?.remove(0);
    let side = side.unwrap_or_else(|| side_of(normal_at(c, &p)));
    let mut out = [0.0; 3];
    for (k, f) in scalars(c, &p, side).iter().enumerate() {
        for (d, o) in out.iter_mut().enumerate() {
            *o += f.v * u[3 * k + d];
        }
    }
    Ok(out)
}

/// The element as an X-FEM zone describes it ([`super::xfem`]): PSI is the
/// tangent level set, PHI the normal one; a node has at most one kind.
pub fn crack_of(e: &XElem) -> Result<Crack, FemError> {
    for n in [e.x.len(), e.psi.len(), e.phi.len(), e.kinds.len()] {
        if n != 8 {
            return Err(FemError::WrongNodeCount { elem: NAME, expected: 8, got: n });
        }
    }
    let mut c = Crack::none();
    for i in 0..8 {
        c.tangent[i] = e.psi[i];
        c.normal[i] = e.phi[i];
        c.heaviside[i] = e.kinds[i] == Some(NodeKind::Jump);
        c.tip[i] = e.kinds[i] == Some(NodeKind::Tip);
    }
    Ok(c)
}

/// The unknowns of an element whose nodes have these enrichments.
pub fn dofs(kinds: &[Option<NodeKind>]) -> Vec<(usize, &'static str)> {
    let mut c = Crack::none();
    for (i, k) in kinds.iter().enumerate().take(8) {
        c.heaviside[i] = *k == Some(NodeKind::Jump);
        c.tip[i] = *k == Some(NodeKind::Tip);
    }
    c.dofs()
}

/// What the zone asks of a field, in this element's terms.
pub fn field_of(e: &XElem, m: &Material, u: &[f64], what: q4::Field) -> Result<GaussField, FemError> {
    let w = match what {
        q4::Field::Strain => Field::Strain,
        q4::Field::Stress => Field::Stress,
        q4::Field::Gradient => Field::Gradient,
    };
    field(e.x, &crack_of(e)?, m, u, w)
}
