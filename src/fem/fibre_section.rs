//! Beam sections described by a mesh (MODE … SECTION TIMO with MATE
//! 'MODS' section_model 'MATS' section_material): the section elements
//! (QUAS on QUA4, TRIS on TRI3) are the fibres, each with its own E, ν,
//! ρ and shear factors ALPY/ALPZ.
//!
//! The section lies in the plane xOy of its mesh; its x axis is the beam's
//! local y and its y axis the local z (MATE's notice). For a linear
//! elastic section the fibres add up to the rigidities of a TIMO section:
//! EA = ΣE·dA, bending EI about the section's elastic (E-weighted)
//! centroid — the beam axis is taken through it, where tension and
//! bending uncouple — torsion G·J with the polar moment about that
//! centroid (exact for circles and rings, an upper bound otherwise), and
//! shear G·ALPY·dA, G·ALPZ·dA. They are handed to the TIMO element as an
//! equivalent homogeneous section: the first fibre's E and ν, and the
//! areas and inertias that give the same rigidities.

use super::element::{Formulation, Mode};
use super::material::Material;
use super::mesh::ElemType;
use super::{element, solid};

/// One fibre: a section element, its nodes and its material (ALPY, ALPZ
/// default to 1, the plain shear area).
pub struct Fibre<'a> {
    pub ty: ElemType,
    pub x: Vec<[f64; 3]>,
    pub mat: &'a Material,
    pub alpy: f64,
    pub alpz: f64,
}

/// The properties (MATE names) of the homogeneous TIMO section with the
/// rigidities of the fibres.
pub fn equivalent(fibres: &[Fibre]) -> Result<Vec<(&'static str, f64)>, String> {
    let (mut ea, mut gay, mut gaz, mut rho_a, mut with_rho) = (0.0, 0.0, 0.0, 0.0, true);
    let (mut sy, mut sz) = (0.0, 0.0);
    // Gauss points: (E dA, G dA, x, y) kept for the moments about the centroid.
    let mut pts: Vec<(f64, f64, f64, f64)> = Vec::new();
    let mut reference: Option<(f64, f64)> = None;
    for (i, f) in fibres.iter().enumerate() {
        if !matches!(f.ty, ElemType::Qua4 | ElemType::Tri3 | ElemType::Qua8 | ElemType::Tri6) {
            return Err(format!("a section is meshed with surface elements, not {}", f.ty.name()));
        }
        let at = |e: element::FemError| format!("section element {}: {}", i + 1, e);
        let e = f.mat.young("QUAS").map_err(at)?;
        let g = f.mat.shear_modulus("QUAS").map_err(at)?;
        reference.get_or_insert((e, f.mat.nu.unwrap_or(0.0)));
        let w =
            solid::point_weights(Formulation::Solid, f.ty, Mode::PlanCont, &f.x, &Material::default()).map_err(at)?;
        let pos = element::gauss_positions(Formulation::Solid, f.ty, &f.x);
        for (wk, p) in w.iter().zip(&pos) {
            ea += e * wk;
            sy += e * wk * p[0];
            sz += e * wk * p[1];
            gay += g * f.alpy * wk;
            gaz += g * f.alpz * wk;
            match f.mat.rho {
                Some(r) => rho_a += r * wk,
                None => with_rho = false,
            }
            pts.push((e * wk, g * wk, p[0], p[1]));
        }
    }
    let Some((e0, nu0)) = reference else {
        return Err("the section model has no element".into());
    };
    if ea <= 0.0 || !ea.is_finite() {
        return Err("the section has no area".into());
    }
    let (yc, zc) = (sy / ea, sz / ea);
    let (mut eiy, mut eiz, mut gj) = (0.0, 0.0, 0.0);
    for (ew, gw, y, z) in &pts {
        let (dy, dz) = (y - yc, z - zc);
        eiy += ew * dz * dz;
        eiz += ew * dy * dy;
        gj += gw * (dy * dy + dz * dz);
    }
    let g0 = e0 / (2.0 * (1.0 + nu0));
    let sect = ea / e0;
    let mut out = vec![
        ("YOUN", e0),
        ("NU", nu0),
        ("SECT", sect),
        ("INRY", eiy / e0),
        ("INRZ", eiz / e0),
        ("TORS", gj / g0),
        ("SECY", gay / g0),
        ("SECZ", gaz / g0),
    ];
    if with_rho {
        out.push(("RHO", rho_a / sect));
    }
    if let Some((k, v)) = out.iter().find(|(_, v)| !v.is_finite()) {
        return Err(format!("the section gives a non-finite {} ({})", k, v));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 2 × 0.5 rectangle offset from the origin, split in two fibres:
    /// inertias about its own centroid, b h³/12 and h b³/12.
    #[test]
    fn rectangle_rigidities() {
        let m = Material { youn: Some(10.0), nu: Some(0.25), ..Default::default() };
        let q = |x0: f64| vec![[x0, 3.0, 0.0], [x0 + 1.0, 3.0, 0.0], [x0 + 1.0, 3.5, 0.0], [x0, 3.5, 0.0]];
        let fib = |x0| Fibre { ty: ElemType::Qua4, x: q(x0), mat: &m, alpy: 1.0, alpz: 0.5 };
        let p = equivalent(&[fib(-1.0), fib(0.0)]).unwrap();
        let get = |k: &str| p.iter().find(|(n, _)| *n == k).unwrap().1;
        assert!((get("SECT") - 1.0).abs() < 1e-14);
        assert!((get("INRY") - 2.0 * 0.125 / 12.0).abs() < 1e-14);
        assert!((get("INRZ") - 0.5 * 8.0 / 12.0).abs() < 1e-14);
        assert!((get("SECZ") - 0.5).abs() < 1e-14);
    }
}
