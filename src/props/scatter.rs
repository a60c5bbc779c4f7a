//! Functions of several variables known at sample points (IPOL on a
//! NUAGE): multilinear interpolation on a grid, inverse distance
//! weighting, and a weighted least-squares fit of a first-order polynomial
//! around the point (the diffuse approximation, exact for linear data).

/// Multilinear interpolation on a grid. `axes[d]` are the increasing
/// coordinates along dimension d; `values` run fastest along the first
/// axis. Outside the grid the value at its border holds, as IPOL's
/// interpolation of a curve does. The caller checks the sizes.
pub fn grid(axes: &[Vec<f64>], values: &[f64], x: &[f64]) -> f64 {
    // Per dimension: the lower index of the cell and the weight of the
    // upper one.
    let cells: Vec<(usize, f64)> = axes
        .iter()
        .zip(x)
        .map(|(ax, &t)| {
            let n = ax.len();
            if n == 1 || t <= ax[0] {
                return (0, 0.0);
            }
            if t >= ax[n - 1] {
                return (n - 1, 0.0);
            }
            let j = ax.partition_point(|a| *a <= t).clamp(1, n - 1);
            (j - 1, (t - ax[j - 1]) / (ax[j] - ax[j - 1]))
        })
        .collect();
    let mut total = 0.0;
    for corner in 0..(1usize << axes.len()) {
        let (mut w, mut index, mut stride) = (1.0, 0, 1);
        for (d, (&(i, t), ax)) in cells.iter().zip(axes).enumerate() {
            let upper = corner >> d & 1 == 1;
            w *= if upper { t } else { 1.0 - t };
            index += (i + usize::from(upper && t > 0.0)) * stride;
            stride *= ax.len();
        }
        if w != 0.0 {
            total += w * values[index];
        }
    }
    total
}

fn distance(p: &[f64], x: &[f64]) -> f64 {
    p.iter().zip(x).map(|(a, b)| (a - b) * (a - b)).sum::<f64>().sqrt()
}

/// Inverse distance weighting (Shepard): weights 1/d^power; exact at a
/// sample point.
pub fn idw(points: &[Vec<f64>], values: &[Vec<f64>], x: &[f64], power: f64) -> Vec<f64> {
    let p = values.first().map_or(0, Vec::len);
    let mut sum = vec![0.0; p];
    let mut wsum = 0.0;
    for (pt, v) in points.iter().zip(values) {
        let d = distance(pt, x);
        if d == 0.0 {
            return v.clone();
        }
        let w = d.powf(-power);
        wsum += w;
        for (s, f) in sum.iter_mut().zip(v) {
            *s += w * f;
        }
    }
    sum.iter().map(|s| s / wsum).collect()
}

/// The weight function of the diffuse approximation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Weight {
    /// exp(-r²)
    Gauss,
    /// 1 / (1 + r²)
    Ratio,
}

/// Weighted least-squares fit of a first-order polynomial around `x`,
/// evaluated at `x`. The distances are scaled by the distance to the
/// (n+1)-th nearest sample, the fewest that fix a plane in n variables;
/// the scale doubles while the weighted system stays singular. None when
/// the samples do not fix a plane at all (all on a line in 2D…).
pub fn diffuse(points: &[Vec<f64>], values: &[Vec<f64>], x: &[f64], weight: Weight) -> Option<Vec<f64>> {
    let n = x.len();
    let p = values.first().map_or(0, Vec::len);
    let ds: Vec<f64> = points.iter().map(|pt| distance(pt, x)).collect();
    let mut sorted = ds.clone();
    sorted.sort_by(f64::total_cmp);
    let mut h = sorted.get(n).or(sorted.last()).copied().unwrap_or(1.0);
    if h == 0.0 {
        h = sorted.iter().copied().find(|d| *d > 0.0).unwrap_or(1.0);
    }
    for _ in 0..8 {
        let m = n + 1;
        let (mut a, mut b) = (vec![0.0; m * m], vec![0.0; m * p]);
        for ((pt, v), d) in points.iter().zip(values).zip(&ds) {
            let r2 = (*d / h) * (*d / h);
            let w = match weight {
                Weight::Gauss => (-r2).exp(),
                Weight::Ratio => 1.0 / (1.0 + r2),
            };
            // Basis centred on x: the fit's value at x is its constant term.
            let basis: Vec<f64> = std::iter::once(1.0).chain(pt.iter().zip(x).map(|(c, t)| c - t)).collect();
            for i in 0..m {
                for j in 0..m {
                    a[i * m + j] += w * basis[i] * basis[j];
                }
                for k in 0..p {
                    b[i * p + k] += w * basis[i] * v[k];
                }
            }
        }
        if let Some(c) = solve(m, &mut a, &mut b, p) {
            return Some(c[..p].to_vec());
        }
        h *= 2.0;
    }
    None
}

/// Solve A X = B (A m×m, B m×p, row-major) by Gaussian elimination with
/// partial pivoting; None when A is singular to working precision.
fn solve(m: usize, a: &mut [f64], b: &mut [f64], p: usize) -> Option<Vec<f64>> {
    let scale = a.iter().fold(0.0f64, |s, v| s.max(v.abs()));
    for col in 0..m {
        let piv = (col..m).max_by(|&i, &j| a[i * m + col].abs().total_cmp(&a[j * m + col].abs()))?;
        if a[piv * m + col].abs() <= 1e-12 * scale {
            return None;
        }
        for k in 0..m {
            a.swap(col * m + k, piv * m + k);
        }
        for k in 0..p {
            b.swap(col * p + k, piv * p + k);
        }
        for row in col + 1..m {
            let f = a[row * m + col] / a[col * m + col];
            for k in col..m {
                a[row * m + k] -= f * a[col * m + k];
            }
            for k in 0..p {
                b[row * p + k] -= f * b[col * p + k];
            }
        }
    }
    for col in (0..m).rev() {
        for k in 0..p {
            let mut s = b[col * p + k];
            for j in col + 1..m {
                s -= a[col * m + j] * b[j * p + k];
            }
            b[col * p + k] = s / a[col * m + col];
        }
    }
    Some(b.to_vec())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grid_is_bilinear_and_held_outside() {
        // f = x + 10 y on x in {0, 1, 3}, y in {0, 2}
        let axes = vec![vec![0.0, 1.0, 3.0], vec![0.0, 2.0]];
        let values = [0.0, 1.0, 3.0, 20.0, 21.0, 23.0];
        assert!((grid(&axes, &values, &[2.0, 1.0]) - 12.0).abs() < 1e-12);
        assert!((grid(&axes, &values, &[3.0, 2.0]) - 23.0).abs() < 1e-12);
        assert!((grid(&axes, &values, &[-5.0, 9.0]) - 20.0).abs() < 1e-12);
    }

    #[test]
    fn idw_is_exact_at_samples_and_averages_between() {
        let pts = vec![vec![0.0], vec![2.0]];
        let vals = vec![vec![1.0], vec![3.0]];
        assert_eq!(idw(&pts, &vals, &[2.0], 1.0), vec![3.0]);
        assert!((idw(&pts, &vals, &[1.0], 2.0)[0] - 2.0).abs() < 1e-12);
    }

    #[test]
    fn diffuse_reproduces_a_plane() {
        let pts = vec![vec![0.0, 0.0], vec![1.0, 0.0], vec![1.0, 1.0], vec![0.0, 1.0], vec![1000.0, 0.0]];
        let vals: Vec<Vec<f64>> = pts.iter().map(|p| vec![p[0] + p[1] + 1.0]).collect();
        for w in [Weight::Gauss, Weight::Ratio] {
            let v = diffuse(&pts, &vals, &[0.26, 0.3], w).unwrap();
            assert!((v[0] - 1.56).abs() < 1e-9, "{:?}", v);
        }
    }
}
