//! FOFI: nodal forces of a stress field S through the gradient of a field
//! U, the forces F whose work in any V is ∫ S : (∇V·∇U) = ∫ S_ij V_i,k
//! U_k,j. The notice's ASCII formula pairs S with a product of the two
//! gradients without showing which indices contract; this is the reading
//! the G-theta procedures need: for DJ/DA they load their auxiliary
//! problem with BSIG(D:sym(∇u·∇π) − σ div π) + FOFI(σ, ∇π), which is
//! −(dK/dπ)·u, the derivative of the stiffness when the mesh moves along
//! π, exactly when FOFI has this form (rupt11 checks dJ/da to 0.5 %;
//! the other pairing S_ij U_k,i V_k,j is 77 % off there).

use super::element::{FemError, Formulation, GaussField, Mode};
use super::material::Material;
use super::mesh::ElemType;
use super::solid::{dofs, gradient_comps, points, rule};

/// Stress component of the symmetric tensor entry (i, j), by axis index
/// (r z θ in AXIS), or None where the mode has none (the plane modes'
/// out-of-plane shears).
fn stress_name(mode: Mode, i: usize, j: usize) -> Option<&'static str> {
    let (a, b) = if i <= j { (i, j) } else { (j, i) };
    let axis = mode == Mode::Axis;
    Some(match (a, b) {
        (0, 0) if axis => "SMRR",
        (1, 1) if axis => "SMZZ",
        (2, 2) if axis => "SMTT",
        (0, 1) if axis => "SMRZ",
        (0, 0) => "SMXX",
        (1, 1) => "SMYY",
        (2, 2) => "SMZZ",
        (0, 1) => "SMXY",
        _ if axis || mode != Mode::Trid => return None,
        (0, 2) => "SMXZ",
        _ => "SMYZ",
    })
}

/// `Σ_p w_p S_cj U_k,j ∂N/∂x_k` for each node and component c (V = N e_c),
/// in [`super::element::ElemMatrix`] dof order, over the stress points of
/// the massive element. In AXIS the hoop term S_θθ (V_r/r)(U_r/r) acts on
/// the radial component.
pub fn quadratic_forces(
    f: Formulation,
    ty: ElemType,
    mode: Mode,
    x: &[[f64; 3]],
    m: &Material,
    sig: &GaussField,
    grad: &GaussField,
) -> Result<Vec<f64>, FemError> {
    let t = m.thickness(mode, ty.name())?;
    let pts = points(ty, mode, x, &rule(f, ty), t)?;
    for field in [sig, grad] {
        if field.values.len() != pts.len() {
            return Err(FemError::WrongPointCount { elem: ty.name(), expected: pts.len(), got: field.values.len() });
        }
    }
    let gnames = gradient_comps(mode);
    if let Some(c) = gnames.iter().find(|c| !grad.comps.contains(c)) {
        return Err(FemError::MissingComponent { comp: c, elem: ty.name() });
    }
    let first = stress_name(mode, 0, 0).unwrap_or("SMXX");
    if !sig.comps.contains(&first) {
        return Err(FemError::MissingComponent { comp: first, elem: ty.name() });
    }
    let nc = dofs(mode).len();
    // Derivatives along the element's own axes: 2 in the plane modes.
    let nd = if mode == Mode::Trid { 3 } else { 2 };
    let mut out = vec![0.0; ty.nodes() * nc];
    for (k, p) in pts.iter().enumerate() {
        let s = |i: usize, j: usize| stress_name(mode, i, j).and_then(|n| sig.get(n, k)).unwrap_or(0.0);
        let g = |i: usize, j: usize| grad.get(gnames[3 * i + j], k).unwrap_or(0.0);
        // a[c][k] = Σ_j S_cj U_k,j: the force density against V_c,k.
        let mut a = [[0.0; 3]; 3];
        for (c, row) in a.iter_mut().enumerate() {
            for (k, v) in row.iter_mut().enumerate() {
                *v = (0..3).map(|j| s(c, j) * g(k, j)).sum();
            }
        }
        for (node, dn) in p.dndx.iter().enumerate() {
            for c in 0..nc {
                let mut v: f64 = (0..nd).map(|j| a[c][j] * dn[j]).sum();
                if mode == Mode::Axis && c == 0 {
                    v += a[2][2] * p.n[node] / p.r;
                }
                out[node * nc + c] += v * p.w;
            }
        }
    }
    if out.iter().any(|v| !v.is_finite()) {
        return Err(FemError::Degenerate { elem: ty.name(), why: "the forces are not finite".into() });
    }
    Ok(out)
}
