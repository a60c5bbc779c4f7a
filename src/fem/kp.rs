//! KP with a pressure gradient: the stiffness of a pressure that varies
//! linearly in space, p(x) = rg·(g·x) + p0, seen by a moving shell. A node
//! displaced by u sees the pressure change rg·(g·u); the pressure pushes
//! along the element normal n, so the force change is
//! δf_i = ∫ N_i n rg (g·Σ_j N_j u_j) dA, and the matrix is
//! K[(i,c),(j,d)] = rg ∫N_i N_j dA · n_c g_d (K u = δf). Without g the
//! direction is the normal itself: K = rg ∫N_i N_j · n nᵀ, a Winkler soil
//! of stiffness rg, symmetric and positive for rg > 0. The change of the
//! normal's direction is not part of this matrix (the pressure field
//! itself is not given here).

use super::element::{ElemMatrix, FemError, Formulation};
use super::shell;

pub fn gradient_stiffness(
    f: Formulation,
    x: &[[f64; 3]],
    rg: f64,
    dir: Option<[f64; 3]>,
) -> Result<ElemMatrix, FemError> {
    if !matches!(f, Formulation::Coq3 | Formulation::Dkt | Formulation::Dst | Formulation::Coq4) {
        return Err(FemError::NotFor { what: "KP with a pressure gradient", form: f.name() });
    }
    let n = shell::normal(f, x)?;
    let g = dir.unwrap_or(n);
    let nij = shell::shape_products(f, x)?;
    let nn = x.len();
    let m = 3 * nn;
    let mut k = vec![0.0; m * m];
    for i in 0..nn {
        for j in 0..nn {
            for c in 0..3 {
                for d in 0..3 {
                    k[(3 * i + c) * m + 3 * j + d] = rg * nij[i * nn + j] * n[c] * g[d];
                }
            }
        }
    }
    let names = ["UX", "UY", "UZ"];
    let dofs = (0..nn).flat_map(|i| names.iter().map(move |&d| (i, d))).collect();
    Ok(ElemMatrix { dofs, k })
}
