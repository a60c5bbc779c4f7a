//! Eccentric flat shells (MATE … 'EXCE' e): the mid-surface lies at e
//! along the element normal from the nodes' plane. The mid-surface moves
//! with the nodes as a rigid offset, u_mid = u + θ × (e n): in the element
//! axes (n = z) u_mid = u + e θy and v_mid = v − e θx, the other dofs
//! unchanged. That map T (6 dofs per node, local axes) turns the
//! mid-surface stiffness into the nodes' one, Tᵀ K T, and mid-surface
//! nodal forces into the nodes' ones, Tᵀ f.

/// u_mid = T u_ref on local displacements.
pub fn to_mid(e: f64, u: &mut [f64]) {
    for d in u.chunks_mut(6) {
        d[0] += e * d[4];
        d[1] -= e * d[3];
    }
}

/// f_ref = Tᵀ f_mid on local nodal forces.
pub fn forces_to_ref(e: f64, f: &mut [f64]) {
    for d in f.chunks_mut(6) {
        d[4] += e * d[0];
        d[3] -= e * d[1];
    }
}

/// K_ref = Tᵀ K_mid T on a dense n×n local matrix (row-major).
pub fn stiffness_to_ref(e: f64, k: &mut [f64], n: usize) {
    if e == 0.0 {
        return;
    }
    // K T: column 6i+4 gains e·column 6i, column 6i+3 loses e·column 6i+1.
    for r in 0..n {
        forces_to_ref(e, &mut k[r * n..(r + 1) * n]);
    }
    // Tᵀ (K T): the same on the rows.
    for i in 0..n / 6 {
        for c in 0..n {
            let (r0, r1) = (k[(6 * i) * n + c], k[(6 * i + 1) * n + c]);
            k[(6 * i + 4) * n + c] += e * r0;
            k[(6 * i + 3) * n + c] -= e * r1;
        }
    }
}
