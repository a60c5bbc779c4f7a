//! Post-processing of element fields: equivalent stress (VMIS) and the
//! transfer of Gauss-point values to element nodes (CHAN 'NOEUD').

use super::element::{FemError, Formulation, GaussField, Mode};
use super::material::Material;
use super::mesh::ElemType;
use super::shape::eval;

/// VMIS from a SIGM field of the same element.
///
/// Massive elements: von Mises of the full tensor (σzz included, so plane
/// strain and AXIS hoop stresses count). Bars and beams: Cast3M's
/// `sqrt((EFFX/SECT)² + (MOMX·DX/TORS)² + (MOMY·DZ/INRY)² + (MOMZ·DY/INRZ)²)`;
/// an absent fibre distance DX/DY/DZ drops its term (the stress on the
/// neutral fibre), absent components count as 0. Shells: the larger of the
/// plane-stress von Mises values on the two faces, σ = N/t ± 6M/t².
pub fn von_mises(f: Formulation, mode: Mode, m: &Material, sig: &GaussField) -> Result<GaussField, FemError> {
    let at = |v: &[f64], name: &str| sig.comps.iter().position(|c| *c == name).map_or(0.0, |i| v[i]);
    let values = match f {
        Formulation::Joint | Formulation::Thermal => {
            return Err(FemError::NotFor { what: "a von Mises stress (VMIS)", form: f.name() })
        }
        Formulation::Barr | Formulation::Baex | Formulation::Pout | Formulation::Timo => {
            let elem = f.name();
            let a = m.positive(m.sect, "SECT", elem)?;
            let term = |d: Option<f64>, inertia: Option<f64>, prop: &'static str| -> Result<f64, FemError> {
                match d {
                    Some(d) if d != 0.0 => Ok(d / m.positive(inertia, prop, elem)?),
                    _ => Ok(0.0),
                }
            };
            let (cx, cy, cz) = (term(m.dx, m.tors, "TORS")?, term(m.dz, m.inry, "INRY")?, term(m.dy, m.inrz, "INRZ")?);
            sig.values
                .iter()
                .map(|v| {
                    let s = (at(v, "EFFX") / a).powi(2)
                        + (at(v, "MOMX") * cx).powi(2)
                        + (at(v, "MOMY") * cy).powi(2)
                        + (at(v, "MOMZ") * cz).powi(2);
                    vec![s.sqrt()]
                })
                .collect()
        }
        Formulation::Coq3
        | Formulation::Dkt
        | Formulation::Dst
        | Formulation::Coq4
        | Formulation::Coq6
        | Formulation::Coq8
        | Formulation::Coq2 => {
            let t = m.positive(m.epai, "EPAI", f.name())?;
            let vm = |s: [f64; 3]| (s[0] * s[0] + s[1] * s[1] - s[0] * s[1] + 3.0 * s[2] * s[2]).sqrt();
            sig.values
                .iter()
                .map(|v| {
                    let face = |z: f64| -> [f64; 3] {
                        let c = ["N11", "N22", "N12"].map(|n| at(v, n) / t);
                        let b = ["M11", "M22", "M12"].map(|n| at(v, n) * 6.0 / (t * t));
                        [c[0] + z * b[0], c[1] + z * b[1], c[2] + z * b[2]]
                    };
                    vec![vm(face(1.0)).max(vm(face(-1.0)))]
                })
                .collect()
        }
        Formulation::Solid | Formulation::Q4ri | Formulation::Q8ri | Formulation::Incomp | Formulation::Dpge => {
            let names: [&str; 6] = match mode {
                Mode::Axis => ["SMRR", "SMZZ", "SMTT", "SMRZ", "", ""],
                Mode::Fourier(_) => super::fourier::STRESSES,
                _ => ["SMXX", "SMYY", "SMZZ", "SMXY", "SMXZ", "SMYZ"],
            };
            sig.values
                .iter()
                .map(|v| {
                    let s: Vec<f64> = names.iter().map(|n| at(v, n)).collect();
                    let dev = (s[0] - s[1]).powi(2) + (s[1] - s[2]).powi(2) + (s[2] - s[0]).powi(2);
                    let sh = s[3] * s[3] + s[4] * s[4] + s[5] * s[5];
                    vec![(0.5 * dev + 3.0 * sh).sqrt()]
                })
                .collect()
        }
    };
    Ok(GaussField { comps: vec!["SCAL"], values })
}

/// Values at the element nodes from values at the points of
/// [`super::element::gauss_points`] (CHAN 'NOEUD').
///
/// The field is fitted by least squares with the element's own shape
/// functions when there are at least as many points as nodes (QUA4 2×2,
/// QUA8 3×3, CUB8, PRI6: exact extrapolation of what the points can
/// represent), with the corner (linear) functions otherwise (TRI6: 3
/// points, mid-side nodes get the average of their corners), and as the
/// mean when there is a single point (TRI3, TET4, Q4RI). Bars and beams
/// already output at their nodes.
pub fn to_nodes(f: Formulation, ty: ElemType, g: &GaussField) -> Result<GaussField, FemError> {
    let pts = super::element::gauss_points(f, ty);
    if g.values.len() != pts.len() {
        return Err(FemError::WrongDofCount { elem: ty.name(), expected: pts.len(), got: g.values.len() });
    }
    let nn = ty.nodes();
    let nc = g.comps.len();
    if matches!(f, Formulation::Barr | Formulation::Baex | Formulation::Pout | Formulation::Timo) {
        return Ok(g.clone());
    }
    if pts.len() == 1 {
        return Ok(GaussField { comps: g.comps.clone(), values: vec![g.values[0].clone(); nn] });
    }
    let (basis, corners) = if pts.len() >= nn {
        (ty, nn)
    } else {
        match ty {
            ElemType::Tri6 => (ElemType::Tri3, 3),
            ElemType::Qua8 => (ElemType::Qua4, 4),
            _ => (ty, nn),
        }
    };
    // Normal equations AᵀA c = Aᵀv with A[p][i] = N_i(point p).
    let a: Vec<Vec<f64>> = pts.iter().map(|(p, _)| eval(basis, *p).n).collect();
    let mut ata = vec![vec![0.0; corners]; corners];
    for row in &a {
        for i in 0..corners {
            for j in 0..corners {
                ata[i][j] += row[i] * row[j];
            }
        }
    }
    let mut out = vec![vec![0.0; nc]; nn];
    for c in 0..nc {
        let mut rhs: Vec<f64> = (0..corners).map(|i| a.iter().zip(&g.values).map(|(r, v)| r[i] * v[c]).sum()).collect();
        let sol = solve(ata.clone(), &mut rhs).ok_or(FemError::Degenerate {
            elem: ty.name(),
            why: "Gauss points cannot determine nodal values".into(),
        })?;
        // Evaluate the fitted basis at every node of the element.
        for (k, xn) in super::shape::ref_nodes(ty).into_iter().enumerate() {
            out[k][c] = eval(basis, xn).n.iter().zip(&sol).map(|(n, s)| n * s).sum();
        }
    }
    Ok(GaussField { comps: g.comps.clone(), values: out })
}

/// Small dense solve by Gaussian elimination with partial pivoting.
// Index loops read best for elimination on rows k and i of one matrix.
#[allow(clippy::needless_range_loop)]
fn solve(mut a: Vec<Vec<f64>>, b: &mut [f64]) -> Option<Vec<f64>> {
    let n = b.len();
    for k in 0..n {
        let p = (k..n).max_by(|&i, &j| a[i][k].abs().total_cmp(&a[j][k].abs()))?;
        if a[p][k].abs() < 1e-14 {
            return None;
        }
        a.swap(k, p);
        b.swap(k, p);
        for i in k + 1..n {
            let r = a[i][k] / a[k][k];
            for j in k..n {
                a[i][j] -= r * a[k][j];
            }
            b[i] -= r * b[k];
        }
    }
    let mut x = vec![0.0; n];
    for k in (0..n).rev() {
        x[k] = (b[k] - (k + 1..n).map(|j| a[k][j] * x[j]).sum::<f64>()) / a[k][k];
    }
    Some(x)
}
