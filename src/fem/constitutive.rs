//! Point-wise constitutive operations on element fields: thermal strains
//! (EPTH), Hooke's law applied to a strain field (ELAS), the strain energy
//! density (ENER), stress invariants (INVA) and the Tresca stress (TRES).
//!
//! Fields are [`GaussField`]s at the points of
//! [`super::element::gauss_points`], with the component names of SIGM and
//! EPSI, so that `SIGM mo ma u - ELAS mo ma (EPTH mo ma t)` subtracts
//! point by point.

use super::element::{gauss_points, FemError, Formulation, GaussField, Mode};
use super::material::{elasticity, Material};
use super::mesh::ElemType;
use super::{beam, principal, shape, solid};

/// Thermal strains α(T − TREF) at the element's points, from the nodal
/// temperatures `t` (element node order).
///
/// Massive elements: the temperature is interpolated with the element's
/// shape functions and every direct strain gets α(T − TREF), shears 0.
/// In the plane modes EPZZ is α(T − TREF) too: in plane strain the
/// out-of-plane stiffness then turns it into the σzz = −EαΔT of a slab
/// held in z and the (1 + ν)αΔT in-plane expansion of a free one; in plane
/// stress the elasticity matrix has no zz row, and EPZZ is the free
/// out-of-plane thermal strain. AXIS: EPRR EPZZ EPTT.
///
/// Bars and beams: the axial strain EPSS of the element's mean
/// temperature, the same at both ends (curvatures 0: no gradient across
/// the section). The mean, not the end values, because the bar's nodal
/// forces ±N must balance; for a temperature linear along the element it
/// is the exact work-equivalent load.
pub fn thermal_strain(
    f: Formulation,
    ty: ElemType,
    mode: Mode,
    m: &Material,
    t: &[f64],
) -> Result<GaussField, FemError> {
    if t.len() != ty.nodes() {
        return Err(FemError::WrongNodeCount { elem: ty.name(), expected: ty.nodes(), got: t.len() });
    }
    let elem = match f {
        Formulation::Solid | Formulation::Q4ri | Formulation::Q8ri | Formulation::Incomp => ty.name(),
        _ => f.name(),
    };
    if f.is_shell() {
        return Err(FemError::NotFor { what: "thermal strain (EPTH)", form: f.name() });
    }
    let alpha = m.expansion(elem)?;
    let tref = m.tref.unwrap_or(0.0);
    match f {
        Formulation::Barr | Formulation::Baex | Formulation::Pout | Formulation::Timo => {
            if ty != ElemType::Seg2 {
                return Err(FemError::Unsupported { form: f.name(), elem: ty.name(), mode: mode.name() });
            }
            let e = alpha * (0.5 * (t[0] + t[1]) - tref);
            let comps = match (f, mode) {
                (Formulation::Barr | Formulation::Baex, _) => vec!["EPSS"],
                (_, Mode::Trid) => vec!["EPSS", "GAXY", "GAXZ", "CURX", "CURY", "CURZ"],
                _ => vec!["EPSS", "GAXY", "CURZ"],
            };
            let mut row = vec![0.0; comps.len()];
            row[0] = e;
            Ok(GaussField { comps, values: vec![row; 2] })
        }
        Formulation::Solid | Formulation::Q4ri | Formulation::Q8ri | Formulation::Incomp => {
            check_solid(f, ty, mode)?;
            let comps = solid::strain_comps(mode);
            let values = gauss_points(f, ty)
                .into_iter()
                .map(|(p, _)| {
                    let tp: f64 = shape::eval(ty, p).n.iter().zip(t).map(|(n, ti)| n * ti).sum();
                    let e = alpha * (tp - tref);
                    // Direct strains come first in every mode's order.
                    comps.iter().enumerate().map(|(i, _)| if i < 3 { e } else { 0.0 }).collect()
                })
                .collect();
            Ok(GaussField { comps, values })
        }
        // Shells and joints have no thermal strain here.
        _ => Err(FemError::Unsupported { form: f.name(), elem: ty.name(), mode: mode.name() }),
    }
}

fn check_solid(f: Formulation, ty: ElemType, mode: Mode) -> Result<(), FemError> {
    let ok = !solid::rule(f, ty).is_empty() && (ty.dim() == 3) == (mode == Mode::Trid) && ty.dim() >= 2;
    if ok {
        Ok(())
    } else {
        Err(FemError::Unsupported { form: f.name(), elem: ty.name(), mode: mode.name() })
    }
}

/// Hooke's law point by point (ELAS): the stresses of a strain field with
/// SIGM's components. Massive elements: σ = D ε with the mode's elasticity
/// matrix (engineering shears; in plane stress D already has σzz = 0, so
/// EPZZ is ignored). Bars: EFFX = E·SECT·EPSS. Beams: see
/// [`beam::hooke`]. A strain component the field lacks counts as 0, but a
/// field with none of them is not a strain field of this element.
pub fn hooke(f: Formulation, ty: ElemType, mode: Mode, m: &Material, eps: &GaussField) -> Result<GaussField, FemError> {
    let wanted: Vec<&'static str> = match f {
        Formulation::Barr | Formulation::Baex => vec!["EPSS"],
        Formulation::Pout | Formulation::Timo => vec!["EPSS", "GAXY", "GAXZ", "CURX", "CURY", "CURZ"],
        Formulation::Solid | Formulation::Q4ri | Formulation::Q8ri | Formulation::Incomp => solid::strain_comps(mode),
        Formulation::Joint => return super::joint::hooke(mode, m, eps),
        Formulation::Coq2 => return super::coq2::hooke(mode, m, eps),
        // The shells: their forces come from SIGM, not from a strain field.
        _ => return Err(FemError::NotFor { what: "Hooke's law on a strain field (ELAS)", form: f.name() }),
    };
    if !wanted.iter().any(|w| eps.comps.contains(w)) {
        return Err(FemError::MissingComponent { comp: wanted[0], elem: ty.name() });
    }
    match f {
        Formulation::Barr | Formulation::Baex => {
            let ea = m.young("BARR")? * m.positive(m.sect, "SECT", "BARR")?;
            let values = eps.values.iter().map(|v| vec![ea * get(eps, v, "EPSS")]).collect();
            Ok(GaussField { comps: vec!["EFFX"], values })
        }
        Formulation::Pout | Formulation::Timo => beam::hooke(f == Formulation::Timo, mode, m, eps),
        Formulation::Solid | Formulation::Q4ri | Formulation::Q8ri | Formulation::Incomp => {
            check_solid(f, ty, mode)?;
            let d = elasticity(mode, m, ty.name())?;
            let values = eps
                .values
                .iter()
                .map(|v| {
                    let e: Vec<f64> = wanted.iter().map(|c| get(eps, v, c)).collect();
                    d.iter().map(|row| row.iter().zip(&e).map(|(a, b)| a * b).sum()).collect()
                })
                .collect();
            Ok(GaussField { comps: solid::stress_comps(mode), values })
        }
        // Shells and joints returned above.
        _ => Err(FemError::Unsupported { form: f.name(), elem: ty.name(), mode: mode.name() }),
    }
}

fn get(g: &GaussField, v: &[f64], comp: &str) -> f64 {
    g.comps.iter().position(|c| *c == comp).map_or(0.0, |i| v[i])
}

/// Stress/strain pairs whose product is work: massive elements
/// (engineering shears, so σxy·γxy counts the shear once in each
/// direction as it should), then bar and beam resultants with their
/// generalised strains.
const WORK_PAIRS: &[(&str, &str)] = &[
    ("SMXX", "EPXX"),
    ("SMYY", "EPYY"),
    ("SMZZ", "EPZZ"),
    ("SMXY", "GAXY"),
    ("SMXZ", "GAXZ"),
    ("SMYZ", "GAYZ"),
    ("SMRR", "EPRR"),
    ("SMTT", "EPTT"),
    ("SMRZ", "GARZ"),
    ("EFFX", "EPSS"),
    ("EFFY", "GAXY"),
    ("EFFZ", "GAXZ"),
    ("MOMX", "CURX"),
    ("MOMY", "CURY"),
    ("MOMZ", "CURZ"),
    // Thin shells: membrane forces and moments per unit length with the
    // membrane strains and curvatures (engineering shear and twist).
    ("N11", "EPSS"),
    ("N22", "EPTT"),
    ("N12", "GAST"),
    ("M11", "RTSS"),
    ("M22", "RTTT"),
    ("M12", "RTST"),
];

/// The contracted product σ:ε (ENER), component SCAL (a SCALAIRE field,
/// as Cast3M names it), point by point: the notice's "produit tensoriel
/// contracté", twice the strain energy density (Cast3M's procedures halve
/// it themselves: G_THETA's 0.5*ENER). For bars and beams it is
/// N ε + M κ … per unit length.
pub fn energy(sig: &GaussField, eps: &GaussField, elem: &'static str) -> Result<GaussField, FemError> {
    if sig.values.len() != eps.values.len() {
        return Err(FemError::WrongPointCount { elem, expected: sig.values.len(), got: eps.values.len() });
    }
    let pairs: Vec<(usize, usize)> = WORK_PAIRS
        .iter()
        .filter_map(|(s, e)| Some((sig.comps.iter().position(|c| c == s)?, eps.comps.iter().position(|c| c == e)?)))
        .collect();
    if pairs.is_empty() {
        let comp = sig.comps.first().copied().unwrap_or("SMXX");
        return Err(FemError::MissingComponent { comp, elem });
    }
    let values = sig
        .values
        .iter()
        .zip(&eps.values)
        .map(|(s, e)| vec![pairs.iter().map(|(i, j)| s[*i] * e[*j]).sum::<f64>()])
        .collect();
    Ok(GaussField { comps: vec!["SCAL"], values })
}

/// The full symmetric tensor (xx, yy, zz, xy, xz, yz) of a stress point of
/// a massive element; AXIS maps r → x, z → y, θ → z.
fn tensor(mode: Mode, sig: &GaussField, v: &[f64]) -> [f64; 6] {
    let names: [&str; 6] = match mode {
        Mode::Axis => ["SMRR", "SMZZ", "SMTT", "SMRZ", "", ""],
        Mode::Fourier(_) => super::fourier::STRESSES,
        _ => ["SMXX", "SMYY", "SMZZ", "SMXY", "SMXZ", "SMYZ"],
    };
    names.map(|n| get(sig, v, n))
}

fn check_stress(f: Formulation, mode: Mode, sig: &GaussField, what: &'static str) -> Result<(), FemError> {
    if !matches!(f, Formulation::Solid | Formulation::Q4ri | Formulation::Q8ri | Formulation::Incomp) {
        return Err(FemError::Unsupported { form: f.name(), elem: what, mode: mode.name() });
    }
    let first = if mode.is_axisymmetric() { "SMRR" } else { "SMXX" };
    if !sig.comps.contains(&first) {
        return Err(FemError::MissingComponent { comp: first, elem: what });
    }
    Ok(())
}

/// Stress invariants (INVA): I1 = tr σ, J2 = ½ s:s and J3 = det s of the
/// deviator s = σ − (I1/3)·1, the full 3D tensor (σzz or σθθ included).
/// √(3 J2) is the von Mises stress.
pub fn invariants(f: Formulation, mode: Mode, sig: &GaussField) -> Result<GaussField, FemError> {
    check_stress(f, mode, sig, "INVA")?;
    let values = sig
        .values
        .iter()
        .map(|v| {
            let [xx, yy, zz, xy, xz, yz] = tensor(mode, sig, v);
            let i1 = xx + yy + zz;
            let m = i1 / 3.0;
            let (a, b, c) = (xx - m, yy - m, zz - m);
            let j2 = 0.5 * (a * a + b * b + c * c) + xy * xy + xz * xz + yz * yz;
            let j3 = a * (b * c - yz * yz) - xy * (xy * c - yz * xz) + xz * (xy * yz - b * xz);
            vec![i1, j2, j3]
        })
        .collect();
    Ok(GaussField { comps: vec!["I1", "J2", "J3"], values })
}

/// Tresca equivalent stress (TRES): the largest minus the smallest
/// principal stress of the full 3D tensor (so σzz counts in plane strain
/// and σθθ in AXIS), twice the largest shear stress.
pub fn tresca(f: Formulation, mode: Mode, sig: &GaussField) -> Result<GaussField, FemError> {
    check_stress(f, mode, sig, "TRES")?;
    let values = sig
        .values
        .iter()
        .map(|v| {
            let p = principal::space(tensor(mode, sig, v));
            vec![p.values[0] - p.values[2]]
        })
        .collect();
    Ok(GaussField { comps: vec!["TRES"], values })
}

/// Hooke's law inverted for massive isotropic elements (ELAS on a stress
/// field): ε_ii = (σ_ii − ν Σ_{j≠i} σ_jj)/E and engineering shears σ/G.
/// The three direct stresses are always there (SMZZ included in the
/// plane modes), so one formula serves every mode: in plane stress
/// SMZZ = 0 gives EPZZ = −ν(σxx + σyy)/E.
pub fn inverse_hooke(
    f: Formulation,
    ty: ElemType,
    mode: Mode,
    m: &Material,
    sig: &GaussField,
) -> Result<GaussField, FemError> {
    if !matches!(f, Formulation::Solid | Formulation::Q4ri | Formulation::Q8ri) {
        return Err(FemError::NotFor { what: "Hooke's law on a stress field (ELAS)", form: f.name() });
    }
    check_solid(f, ty, mode)?;
    let (e, nu) = (m.young(ty.name())?, m.poisson(ty.name())?);
    let g = e / (2.0 * (1.0 + nu));
    let names = solid::stress_comps(mode);
    let values = sig
        .values
        .iter()
        .map(|v| {
            let s: Vec<f64> = names.iter().map(|c| get(sig, v, c)).collect();
            let trace: f64 = s[..3].iter().sum();
            s.iter()
                .enumerate()
                .map(|(i, si)| if i < 3 { ((1.0 + nu) * si - nu * trace) / e } else { si / g })
                .collect()
        })
        .collect();
    Ok(GaussField { comps: solid::strain_comps(mode), values })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn steel() -> Material {
        Material { youn: Some(200e9), nu: Some(0.3), alph: Some(1e-5), ..Default::default() }
    }

    #[test]
    fn plane_strain_clamped_stress_has_the_nu_factor() {
        // Fully held (ε = 0) in plane strain: σ = −EαΔT/(1−2ν) in-plane and
        // out of plane alike.
        let m = steel();
        let eps = thermal_strain(Formulation::Solid, ElemType::Tri3, Mode::PlanDefo, &m, &[100.0; 3]).unwrap();
        let mut mech = eps.clone();
        mech.values[0].iter_mut().for_each(|x| *x = -*x);
        let s = hooke(Formulation::Solid, ElemType::Tri3, Mode::PlanDefo, &m, &mech).unwrap();
        let want = -200e9 * 1e-5 * 100.0 / (1.0 - 0.6);
        for c in ["SMXX", "SMYY", "SMZZ"] {
            assert!((s.get(c, 0).unwrap() - want).abs() < 1e-6 * want.abs(), "{c}");
        }
        assert_eq!(s.get("SMXY", 0), Some(0.0));
    }

    #[test]
    fn reference_temperature_and_mean_on_bars() {
        let m = Material { tref: Some(20.0), ..steel() };
        let e = thermal_strain(Formulation::Barr, ElemType::Seg2, Mode::PlanCont, &m, &[20.0, 120.0]).unwrap();
        assert_eq!(e.values, vec![vec![1e-5 * 50.0]; 2]);
        let none = Material { alph: None, ..steel() };
        assert!(matches!(
            thermal_strain(Formulation::Barr, ElemType::Seg2, Mode::PlanCont, &none, &[0.0; 2]),
            Err(FemError::MissingProperty { prop: "ALPH", .. })
        ));
    }

    #[test]
    fn invariants_and_tresca_of_a_known_tensor() {
        let sig = GaussField {
            comps: vec!["SMXX", "SMYY", "SMZZ", "SMXY", "SMXZ", "SMYZ"],
            values: vec![vec![3.0, 1.0, -2.0, 1.0, 0.5, -0.7]],
        };
        let inv = invariants(Formulation::Solid, Mode::Trid, &sig).unwrap();
        let vm = super::super::stress::von_mises(Formulation::Solid, Mode::Trid, &steel(), &sig).unwrap();
        assert!((inv.get("I1", 0).unwrap() - 2.0).abs() < 1e-14);
        assert!(((3.0 * inv.get("J2", 0).unwrap()).sqrt() - vm.values[0][0]).abs() < 1e-12);
        // J3 = s1 s2 s3 from the principal values.
        let p = principal::space([3.0, 1.0, -2.0, 1.0, 0.5, -0.7]).values;
        let m = 2.0 / 3.0;
        let j3 = (p[0] - m) * (p[1] - m) * (p[2] - m);
        assert!((inv.get("J3", 0).unwrap() - j3).abs() < 1e-12);
        let t = tresca(Formulation::Solid, Mode::Trid, &sig).unwrap();
        assert!((t.values[0][0] - (p[0] - p[2])).abs() < 1e-12);
    }

    #[test]
    fn energy_pairs_stresses_with_strains() {
        let sig = GaussField { comps: vec!["SMXX", "SMYY", "SMZZ", "SMXY"], values: vec![vec![2.0, 4.0, 1.0, 3.0]] };
        let eps = GaussField { comps: vec!["EPXX", "EPYY", "EPZZ", "GAXY"], values: vec![vec![1.0, 1.0, 0.0, 2.0]] };
        // 2·1 + 4·1 + 3·2, engineering shear: no half.
        assert_eq!(energy(&sig, &eps, "QUA4").unwrap().values, vec![vec![12.0]]);
        let wrong = GaussField { comps: vec!["UX"], values: vec![vec![1.0]] };
        assert!(energy(&sig, &wrong, "QUA4").is_err());
    }
}
