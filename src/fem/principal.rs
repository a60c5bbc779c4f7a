//! Principal values and directions of a symmetric stress tensor (PRIN).
//!
//! In the plane (PLAN CONT, PLAN DEFO, AXIS) the in-plane 2×2 tensor is
//! diagonalised and the out-of-plane stress (SMZZ, or SMTT in AXIS) is a
//! principal value on its own. In 3D the 3×3 tensor is diagonalised by
//! Jacobi rotations, which keep the directions orthonormal even for
//! repeated values. Principal values come in decreasing order (the
//! in-plane ones in 2D), each direction as a unit vector.

/// Principal values, largest first, and the matching unit directions.
#[derive(Debug, Clone, PartialEq)]
pub struct Principal {
    pub values: [f64; 3],
    pub dirs: [[f64; 3]; 3],
}

/// In-plane tensor [[sxx, sxy], [sxy, syy]] and out-of-plane value szz:
/// values `(s1, s2, szz)` with s1 ≥ s2; directions of s1 and s2 in the
/// plane, szz along the third axis.
pub fn plane(sxx: f64, syy: f64, sxy: f64, szz: f64) -> Principal {
    let c = 0.5 * (sxx + syy);
    let r = (0.25 * (sxx - syy).powi(2) + sxy * sxy).sqrt();
    // Direction of the largest value: angle θ with tan 2θ = 2 sxy / (sxx - syy).
    let theta = 0.5 * (2.0 * sxy).atan2(sxx - syy);
    let (s, co) = theta.sin_cos();
    Principal { values: [c + r, c - r, szz], dirs: [[co, s, 0.0], [-s, co, 0.0], [0.0, 0.0, 1.0]] }
}

/// Full symmetric tensor, components (xx, yy, zz, xy, xz, yz).
pub fn space(s: [f64; 6]) -> Principal {
    let mut a = [[s[0], s[3], s[4]], [s[3], s[1], s[5]], [s[4], s[5], s[2]]];
    let mut v = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let scale = a.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
    for _sweep in 0..50 {
        let off = a[0][1].abs() + a[0][2].abs() + a[1][2].abs();
        if off <= 1e-15 * scale || off == 0.0 {
            break;
        }
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            if a[p][q] == 0.0 {
                continue;
            }
            // Classical Jacobi rotation that zeroes a[p][q].
            let theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
            let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
            let c = 1.0 / (t * t + 1.0).sqrt();
            let sn = t * c;
            // A ← Jᵀ A J and V ← V J: columns p and q of A and V, then
            // rows p and q of A.
            for row in a.iter_mut().chain(v.iter_mut()) {
                let (xp, xq) = (row[p], row[q]);
                row[p] = c * xp - sn * xq;
                row[q] = sn * xp + c * xq;
            }
            let (rp, rq) = (a[p], a[q]);
            for k in 0..3 {
                a[p][k] = c * rp[k] - sn * rq[k];
                a[q][k] = sn * rp[k] + c * rq[k];
            }
        }
    }
    let mut order = [0, 1, 2];
    order.sort_by(|&i, &j| a[j][j].total_cmp(&a[i][i]));
    Principal {
        values: order.map(|i| a[i][i]),
        // Column i of v is the direction of a[i][i].
        dirs: order.map(|i| [v[0][i], v[1][i], v[2][i]]),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plane_values_and_directions() {
        // Pure shear 1: values ±1 at 45 degrees.
        let p = plane(0.0, 0.0, 1.0, 0.5);
        assert!((p.values[0] - 1.0).abs() < 1e-15 && (p.values[1] + 1.0).abs() < 1e-15);
        let h = 0.5f64.sqrt();
        assert!((p.dirs[0][0] - h).abs() < 1e-15 && (p.dirs[0][1] - h).abs() < 1e-15);
        assert_eq!(p.values[2], 0.5);
    }

    #[test]
    fn space_matches_the_tensor() {
        let s = [3.0, 1.0, -2.0, 1.0, 0.5, -0.7];
        let p = space(s);
        let a = [[s[0], s[3], s[4]], [s[3], s[1], s[5]], [s[4], s[5], s[2]]];
        assert!(p.values[0] >= p.values[1] && p.values[1] >= p.values[2]);
        for (l, d) in p.values.iter().zip(&p.dirs) {
            for i in 0..3 {
                let ad: f64 = (0..3).map(|j| a[i][j] * d[j]).sum();
                assert!((ad - l * d[i]).abs() < 1e-12, "{ad} vs {}", l * d[i]);
            }
        }
        let trace: f64 = p.values.iter().sum();
        assert!((trace - 2.0).abs() < 1e-12);
    }
}
