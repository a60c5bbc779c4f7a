//! Finding where a point lies in an element: the reference coordinates
//! whose image by the element's geometric map is the point (PROI's
//! projection of a field onto other points).

use super::mesh::ElemType;
use super::shape;

/// Relative tolerance on the reference coordinates (a point on a side is
/// in both elements that share it) and on the distance to a line or
/// surface element in a space of higher dimension.
const TOL: f64 = 1e-6;

/// The reference coordinates of `x` in the element of type `ty` whose
/// nodes are at `xs`, if `x` lies in it (within a tolerance). A line in
/// the plane or a surface in space is matched in the least-squares sense
/// and the point must lie on it.
pub fn locate(ty: ElemType, xs: &[[f64; 3]], x: [f64; 3]) -> Option<[f64; 3]> {
    let d = ty.dim();
    if d == 0 || xs.len() != ty.nodes() {
        return None;
    }
    let size = diameter(xs);
    // A bounding-box test first: most elements are far from the point.
    for c in 0..3 {
        let lo = xs.iter().map(|p| p[c]).fold(f64::INFINITY, f64::min);
        let hi = xs.iter().map(|p| p[c]).fold(f64::NEG_INFINITY, f64::max);
        if x[c] < lo - TOL * size || x[c] > hi + TOL * size {
            return None;
        }
    }
    let refs = shape::ref_nodes(ty);
    let mut xi = [0.0; 3];
    for r in &refs {
        (0..3).for_each(|k| xi[k] += r[k] / refs.len() as f64);
    }
    for _ in 0..30 {
        let s = shape::eval(ty, xi);
        let (img, jac) = image(&s, xs);
        let res = [x[0] - img[0], x[1] - img[1], x[2] - img[2]];
        // Normal equations (JᵀJ) δ = Jᵀ r over the element's d directions.
        let mut a = [[0.0; 3]; 3];
        let mut b = [0.0; 3];
        for i in 0..d {
            for j in 0..d {
                a[i][j] = (0..3).map(|c| jac[c][i] * jac[c][j]).sum();
            }
            b[i] = (0..3).map(|c| jac[c][i] * res[c]).sum();
        }
        let delta = solve(&a, &b, d)?;
        (0..d).for_each(|i| xi[i] += delta[i]);
        if delta.iter().all(|v| v.abs() < 1e-12) {
            break;
        }
    }
    let (img, _) = image(&shape::eval(ty, xi), xs);
    let dist = ((0..3).map(|c| (img[c] - x[c]).powi(2)).sum::<f64>()).sqrt();
    (dist <= TOL * size.max(f64::MIN_POSITIVE) && inside(ty, xi)).then_some(xi)
}

/// The point of reference coordinates `xi` and the Jacobian ∂x/∂ξ.
fn image(s: &shape::Shape, xs: &[[f64; 3]]) -> ([f64; 3], [[f64; 3]; 3]) {
    let mut img = [0.0; 3];
    let mut jac = [[0.0; 3]; 3];
    for (k, p) in xs.iter().enumerate() {
        for c in 0..3 {
            img[c] += s.n[k] * p[c];
            for (j, d) in jac[c].iter_mut().zip(&s.dn[k]) {
                *j += d * p[c];
            }
        }
    }
    (img, jac)
}

fn diameter(xs: &[[f64; 3]]) -> f64 {
    let mut m: f64 = 0.0;
    for p in xs {
        for q in xs {
            m = m.max(((0..3).map(|c| (p[c] - q[c]).powi(2)).sum::<f64>()).sqrt());
        }
    }
    m
}

/// Gaussian elimination with partial pivoting on the leading n × n block.
fn solve(a: &[[f64; 3]; 3], b: &[f64; 3], n: usize) -> Option<[f64; 3]> {
    let mut m = *a;
    let mut r = *b;
    let scale = (0..n).map(|i| m[i][i].abs()).fold(0.0, f64::max);
    for c in 0..n {
        let p = (c..n).max_by(|&i, &j| m[i][c].abs().total_cmp(&m[j][c].abs()))?;
        if m[p][c].abs() <= 1e-14 * scale || scale == 0.0 {
            return None;
        }
        m.swap(c, p);
        r.swap(c, p);
        for i in c + 1..n {
            let f = m[i][c] / m[c][c];
            let pivot = m[c];
            for (x, y) in m[i][c..n].iter_mut().zip(&pivot[c..n]) {
                *x -= f * y;
            }
            r[i] -= f * r[c];
        }
    }
    let mut x = [0.0; 3];
    for i in (0..n).rev() {
        x[i] = (r[i] - (i + 1..n).map(|j| m[i][j] * x[j]).sum::<f64>()) / m[i][i];
    }
    Some(x)
}

/// Whether reference coordinates lie in the reference element.
fn inside(ty: ElemType, xi: [f64; 3]) -> bool {
    let lo = -TOL;
    let hi = 1.0 + TOL;
    let box1 = |v: f64| v.abs() <= hi;
    let simplex = |n: usize| xi[..n].iter().all(|v| *v >= lo) && xi[..n].iter().sum::<f64>() <= hi;
    match ty {
        ElemType::Seg2 | ElemType::Seg3 => box1(xi[0]),
        ElemType::Qua4 | ElemType::Qua8 => box1(xi[0]) && box1(xi[1]),
        ElemType::Cub8 | ElemType::Cu20 | ElemType::Pyr5 => xi.iter().all(|v| box1(*v)),
        ElemType::Tri3 | ElemType::Tri6 => simplex(2),
        ElemType::Tet4 => simplex(3),
        ElemType::Pri6 | ElemType::Pr15 => simplex(2) && box1(xi[2]),
        _ => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_point_in_a_distorted_quadrangle() {
        let xs = [[0., 0., 0.], [2., 0., 0.], [3., 2., 0.], [0., 1., 0.]];
        let xi = locate(ElemType::Qua4, &xs, [1.25, 0.75, 0.]).expect("inside");
        let (img, _) = image(&shape::eval(ElemType::Qua4, xi), &xs);
        assert!((img[0] - 1.25).abs() < 1e-10 && (img[1] - 0.75).abs() < 1e-10);
        assert!(locate(ElemType::Qua4, &xs, [2.5, 0.2, 0.]).is_none());
    }

    #[test]
    fn a_point_on_a_segment_in_the_plane() {
        let xs = [[0., 0., 0.], [2., 2., 0.]];
        assert!(locate(ElemType::Seg2, &xs, [0.5, 0.5, 0.]).is_some());
        assert!(locate(ElemType::Seg2, &xs, [0.5, 0.6, 0.]).is_none());
    }
}
