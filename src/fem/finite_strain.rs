//! Changes of configuration of stress and strain tensors at a point, from
//! the displacement gradient G = ∂u/∂X between the two configurations
//! (PICA and CAPI): F = I + G.
//!
//! * Truesdell kinematics (strains LINEAIRE, QUADRATIQUE, TRUESDELL):
//!   second Piola-Kirchhoff S ↔ Cauchy σ = F S Fᵀ / J, and Green-Lagrange
//!   E ↔ Almansi-Euler e = F⁻ᵀ E F⁻¹ (the push-forward of each);
//! * Jaumann kinematics: only the rotation R of F = R U (polar
//!   decomposition) turns the tensors, σ = R S Rᵀ;
//! * user kinematics: the behaviour gives Cauchy stresses already.

pub type M3 = [[f64; 3]; 3];

/// How the tensors follow the motion.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kinematics {
    Truesdell,
    Jaumann,
    User,
}

/// Stresses are pushed forward with a 1/J factor, strains without.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Measure {
    Stress,
    Strain,
}

#[derive(Debug, Clone, PartialEq)]
pub enum FiniteStrainError {
    /// det F ≤ 0: the displacement turns the matter inside out.
    Inverted(f64),
    NonFinite,
}

impl std::fmt::Display for FiniteStrainError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            FiniteStrainError::Inverted(j) => {
                write!(f, "the displacement inverts the matter (det F = {:.5E} is not positive)", j)
            }
            FiniteStrainError::NonFinite => write!(f, "the deformation gradient is not finite"),
        }
    }
}

fn mul(a: &M3, b: &M3) -> M3 {
    let mut c = [[0.0; 3]; 3];
    for (i, row) in c.iter_mut().enumerate() {
        for (j, v) in row.iter_mut().enumerate() {
            *v = (0..3).map(|k| a[i][k] * b[k][j]).sum();
        }
    }
    c
}

fn transpose(a: &M3) -> M3 {
    let mut t = [[0.0; 3]; 3];
    for (i, row) in t.iter_mut().enumerate() {
        for (j, v) in row.iter_mut().enumerate() {
            *v = a[j][i];
        }
    }
    t
}

fn det(a: &M3) -> f64 {
    a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
        + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0])
}

fn inverse(a: &M3) -> M3 {
    let d = det(a);
    let c = |i: usize, j: usize| {
        let (i1, i2) = ((i + 1) % 3, (i + 2) % 3);
        let (j1, j2) = ((j + 1) % 3, (j + 2) % 3);
        a[i1][j1] * a[i2][j2] - a[i1][j2] * a[i2][j1]
    };
    let mut inv = [[0.0; 3]; 3];
    for (i, row) in inv.iter_mut().enumerate() {
        for (j, v) in row.iter_mut().enumerate() {
            // The cofactor of a[j][i], over det.
            *v = c(j, i) / d;
        }
    }
    inv
}

/// The deformation gradient F = I + G, checked.
pub fn deformation_gradient(g: &M3) -> Result<M3, FiniteStrainError> {
    let mut f = *g;
    for (i, row) in f.iter_mut().enumerate() {
        row[i] += 1.0;
    }
    if f.iter().flatten().any(|v| !v.is_finite()) {
        return Err(FiniteStrainError::NonFinite);
    }
    let j = det(&f);
    if j <= 0.0 {
        return Err(FiniteStrainError::Inverted(j));
    }
    Ok(f)
}

/// The rotation of the polar decomposition F = R U, by Newton's iteration
/// R ← (R + R⁻ᵀ)/2, which converges quadratically for det F > 0.
pub fn rotation(f: &M3) -> M3 {
    let mut r = *f;
    for _ in 0..50 {
        let it = transpose(&inverse(&r));
        let mut next = [[0.0; 3]; 3];
        let mut change: f64 = 0.0;
        for i in 0..3 {
            for j in 0..3 {
                next[i][j] = 0.5 * (r[i][j] + it[i][j]);
                change = change.max((next[i][j] - r[i][j]).abs());
            }
        }
        r = next;
        if change < 1e-15 {
            break;
        }
    }
    r
}

/// A·T·Bᵀ.
fn sandwich(a: &M3, t: &M3, b: &M3) -> M3 {
    mul(&mul(a, t), &transpose(b))
}

/// From the reference configuration to the current one (PICA): Cauchy
/// stresses from second Piola-Kirchhoff ones, Almansi-Euler strains from
/// Green-Lagrange ones (tensor components, shears not doubled).
pub fn push_forward(k: Kinematics, m: Measure, f: &M3, t: &M3) -> M3 {
    match (k, m) {
        (Kinematics::User, _) => *t,
        (Kinematics::Jaumann, _) => {
            let r = rotation(f);
            sandwich(&r, t, &r)
        }
        (Kinematics::Truesdell, Measure::Stress) => {
            let j = det(f);
            let s = sandwich(f, t, f);
            s.map(|row| row.map(|v| v / j))
        }
        (Kinematics::Truesdell, Measure::Strain) => {
            let fi = inverse(f);
            let fit = transpose(&fi);
            sandwich(&fit, t, &fit)
        }
    }
}

/// The reverse change (CAPI): second Piola-Kirchhoff from Cauchy,
/// Green-Lagrange from Almansi-Euler.
pub fn pull_back(k: Kinematics, m: Measure, f: &M3, t: &M3) -> M3 {
    match (k, m) {
        (Kinematics::User, _) => *t,
        (Kinematics::Jaumann, _) => {
            let rt = transpose(&rotation(f));
            sandwich(&rt, t, &rt)
        }
        (Kinematics::Truesdell, Measure::Stress) => {
            let j = det(f);
            let fi = inverse(f);
            let s = sandwich(&fi, t, &fi);
            s.map(|row| row.map(|v| v * j))
        }
        (Kinematics::Truesdell, Measure::Strain) => {
            let ft = transpose(f);
            sandwich(&ft, t, &ft)
        }
    }
}

/// The gradient from a reference configuration to the current one when
/// both displacements are known on a third, undeformed one (PICA's second
/// field, X-FEM): x = X₀ + u₂ + u₁ and X = X₀ + u₂ give
/// F = ∂x/∂X = I + G₁ (I + G₂)⁻¹, Gₖ = ∂uₖ/∂X₀; checked.
pub fn relative_gradient(g1: &M3, g2: &M3) -> Result<M3, FiniteStrainError> {
    let f2 = deformation_gradient(g2)?;
    deformation_gradient(&mul(g1, &inverse(&f2)))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: &M3, b: &M3) -> bool {
        (0..3).all(|i| (0..3).all(|j| (a[i][j] - b[i][j]).abs() < 1e-12))
    }

    #[test]
    fn round_trip_and_rotation() {
        let g = [[0.1, 0.3, 0.0], [-0.2, 0.05, 0.1], [0.0, 0.02, -0.1]];
        let f = deformation_gradient(&g).unwrap();
        let s = [[1.0, 0.5, 0.2], [0.5, -2.0, 0.3], [0.2, 0.3, 0.7]];
        for k in [Kinematics::Truesdell, Kinematics::Jaumann, Kinematics::User] {
            for m in [Measure::Stress, Measure::Strain] {
                let back = pull_back(k, m, &f, &push_forward(k, m, &f, &s));
                assert!(close(&back, &s));
            }
        }
        // A rigid rotation of 90° about z: F is its own rotation.
        let g = [[-1.0, -1.0, 0.0], [1.0, -1.0, 0.0], [0.0, 0.0, 0.0]];
        let f = deformation_gradient(&g).unwrap();
        assert!(close(&rotation(&f), &f));
        let sxx = [[1.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]];
        let syy = [[0.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 0.0]];
        assert!(close(&push_forward(Kinematics::Truesdell, Measure::Stress, &f, &sxx), &syy));
        assert!(deformation_gradient(&[[-2.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]]).is_err());
    }
}
