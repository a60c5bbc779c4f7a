//! Shape functions on reference elements, and the boundary faces of each
//! geometry.
//!
//! Node orders follow Cast3M: linear elements counter-clockwise (CUB8 and
//! PRI6: bottom face, then the top face above it); quadratic elements list
//! their nodes *around the contour*, corner, mid-side, corner, ... (SEG3 is
//! end, middle, end; TRI6 is c1 m12 c2 m23 c3 m31; QUA8 is c1 m12 c2 m23 c3
//! m34 c4 m41).
//!
//! Reference elements: segment ξ ∈ [-1, 1]; triangle (0,0) (1,0) (0,1);
//! square and cube [-1, 1]ⁿ; tetrahedron (0,0,0) (1,0,0) (0,1,0) (0,0,1);
//! prism = triangle × ζ ∈ [-1, 1].

use super::mesh::ElemType;

/// Values and reference derivatives of the shape functions at one point.
#[derive(Debug, Clone)]
pub struct Shape {
    pub n: Vec<f64>,
    pub dn: Vec<[f64; 3]>,
}

/// Reference coordinates of the nodes.
pub fn ref_nodes(ty: ElemType) -> Vec<[f64; 3]> {
    let q8 = [(-1., -1.), (0., -1.), (1., -1.), (1., 0.), (1., 1.), (0., 1.), (-1., 1.), (-1., 0.)];
    match ty {
        ElemType::Poi1 => vec![[0.0; 3]],
        ElemType::Seg2 => vec![[-1., 0., 0.], [1., 0., 0.]],
        ElemType::Seg3 => vec![[-1., 0., 0.], [0., 0., 0.], [1., 0., 0.]],
        ElemType::Tri3 => vec![[0., 0., 0.], [1., 0., 0.], [0., 1., 0.]],
        ElemType::Tri6 => vec![[0., 0., 0.], [0.5, 0., 0.], [1., 0., 0.], [0.5, 0.5, 0.], [0., 1., 0.], [0., 0.5, 0.]],
        ElemType::Qua4 => vec![[-1., -1., 0.], [1., -1., 0.], [1., 1., 0.], [-1., 1., 0.]],
        ElemType::Qua8 => q8.iter().map(|&(x, y)| [x, y, 0.]).collect(),
        ElemType::Cub8 => {
            let mut v = ref_nodes(ElemType::Qua4);
            let top: Vec<_> = v.iter().map(|p| [p[0], p[1], 1.]).collect();
            v.iter_mut().for_each(|p| p[2] = -1.);
            v.extend(top);
            v
        }
        ElemType::Tet4 => vec![[0., 0., 0.], [1., 0., 0.], [0., 1., 0.], [0., 0., 1.]],
        ElemType::Pri6 => {
            let t = ref_nodes(ElemType::Tri3);
            let mut v: Vec<_> = t.iter().map(|p| [p[0], p[1], -1.]).collect();
            v.extend(t.iter().map(|p| [p[0], p[1], 1.]));
            v
        }
        // A joint is its face drawn twice: side 1 at t = -1, side 2 at
        // t = +1, t the coordinate after the face's own (y on a line, z
        // on a surface).
        ElemType::Rac2 | ElemType::Rac3 | ElemType::Lia3 | ElemType::Lia4 => {
            let (face, t) = joint_axes(ty);
            let f = ref_nodes(face);
            let mut v: Vec<_> = f.iter().map(|p| with(*p, t, -1.)).collect();
            v.extend(f.iter().map(|p| with(*p, t, 1.)));
            v
        }
    }
}

/// The face of a joint geometry and the reference coordinate across it.
fn joint_axes(ty: ElemType) -> (ElemType, usize) {
    let face = ty.joint_face().expect("a joint geometry");
    (face, face.dim())
}

fn with(mut p: [f64; 3], c: usize, v: f64) -> [f64; 3] {
    p[c] = v;
    p
}

/// Shape functions and their derivatives at reference point `p`.
pub fn eval(ty: ElemType, p: [f64; 3]) -> Shape {
    let [x, y, z] = p;
    match ty {
        ElemType::Poi1 => Shape { n: vec![1.0], dn: vec![[0.0; 3]] },
        ElemType::Seg2 => Shape { n: vec![0.5 * (1. - x), 0.5 * (1. + x)], dn: vec![[-0.5, 0., 0.], [0.5, 0., 0.]] },
        ElemType::Seg3 => Shape {
            n: vec![0.5 * x * (x - 1.), 1. - x * x, 0.5 * x * (x + 1.)],
            dn: vec![[x - 0.5, 0., 0.], [-2. * x, 0., 0.], [x + 0.5, 0., 0.]],
        },
        ElemType::Tri3 => Shape { n: vec![1. - x - y, x, y], dn: vec![[-1., -1., 0.], [1., 0., 0.], [0., 1., 0.]] },
        ElemType::Tri6 => {
            let l = [1. - x - y, x, y];
            // d(L_i)/d(ξ, η)
            let dl = [[-1., -1.], [1., 0.], [0., 1.]];
            let mut n = Vec::with_capacity(6);
            let mut dn = Vec::with_capacity(6);
            for i in 0..3 {
                let j = (i + 1) % 3;
                n.push(l[i] * (2. * l[i] - 1.));
                let c = 4. * l[i] - 1.;
                dn.push([c * dl[i][0], c * dl[i][1], 0.]);
                n.push(4. * l[i] * l[j]);
                dn.push([4. * (dl[i][0] * l[j] + l[i] * dl[j][0]), 4. * (dl[i][1] * l[j] + l[i] * dl[j][1]), 0.]);
            }
            Shape { n, dn }
        }
        ElemType::Qua4 => {
            let mut n = Vec::with_capacity(4);
            let mut dn = Vec::with_capacity(4);
            for [a, b, _] in ref_nodes(ty) {
                n.push(0.25 * (1. + a * x) * (1. + b * y));
                dn.push([0.25 * a * (1. + b * y), 0.25 * b * (1. + a * x), 0.]);
            }
            Shape { n, dn }
        }
        ElemType::Qua8 => {
            let mut n = Vec::with_capacity(8);
            let mut dn = Vec::with_capacity(8);
            for [a, b, _] in ref_nodes(ty) {
                if a != 0. && b != 0. {
                    let s = a * x + b * y - 1.;
                    let (fa, fb) = (1. + a * x, 1. + b * y);
                    n.push(0.25 * fa * fb * s);
                    dn.push([0.25 * a * fb * (s + fa), 0.25 * b * fa * (s + fb), 0.]);
                } else if a == 0. {
                    n.push(0.5 * (1. - x * x) * (1. + b * y));
                    dn.push([-x * (1. + b * y), 0.5 * b * (1. - x * x), 0.]);
                } else {
                    n.push(0.5 * (1. + a * x) * (1. - y * y));
                    dn.push([0.5 * a * (1. - y * y), -y * (1. + a * x), 0.]);
                }
            }
            Shape { n, dn }
        }
        ElemType::Cub8 => {
            let mut n = Vec::with_capacity(8);
            let mut dn = Vec::with_capacity(8);
            for [a, b, c] in ref_nodes(ty) {
                let (fa, fb, fc) = (1. + a * x, 1. + b * y, 1. + c * z);
                n.push(0.125 * fa * fb * fc);
                dn.push([0.125 * a * fb * fc, 0.125 * b * fa * fc, 0.125 * c * fa * fb]);
            }
            Shape { n, dn }
        }
        ElemType::Tet4 => Shape {
            n: vec![1. - x - y - z, x, y, z],
            dn: vec![[-1., -1., -1.], [1., 0., 0.], [0., 1., 0.], [0., 0., 1.]],
        },
        ElemType::Pri6 => {
            let t = [1. - x - y, x, y];
            let dt = [[-1., -1.], [1., 0.], [0., 1.]];
            let mut n = Vec::with_capacity(6);
            let mut dn = Vec::with_capacity(6);
            for c in [-1., 1.] {
                let fz = 0.5 * (1. + c * z);
                for i in 0..3 {
                    n.push(t[i] * fz);
                    dn.push([dt[i][0] * fz, dt[i][1] * fz, 0.5 * c * t[i]]);
                }
            }
            Shape { n, dn }
        }
        ElemType::Rac2 | ElemType::Rac3 | ElemType::Lia3 | ElemType::Lia4 => {
            let (face, t) = joint_axes(ty);
            let s = eval(face, with(p, t, 0.));
            let mut n = Vec::with_capacity(2 * s.n.len());
            let mut dn = Vec::with_capacity(2 * s.n.len());
            for c in [-1., 1.] {
                let ft = 0.5 * (1. + c * p[t]);
                for (ni, di) in s.n.iter().zip(&s.dn) {
                    n.push(ni * ft);
                    dn.push(with([di[0] * ft, di[1] * ft, di[2] * ft], t, 0.5 * c * ni));
                }
            }
            Shape { n, dn }
        }
    }
}

/// Boundary sub-elements (edges of a surface element, faces of a volume
/// element) as (geometry, local node numbers). They are oriented so that
/// for a positively oriented parent the outward normal follows the
/// right-hand rule (2D: the solid lies to the left of each edge).
pub fn faces(ty: ElemType) -> Vec<(ElemType, Vec<usize>)> {
    use ElemType::*;
    let f = |t: ElemType, lists: &[&[usize]]| -> Vec<(ElemType, Vec<usize>)> {
        lists.iter().map(|l| (t, l.to_vec())).collect()
    };
    match ty {
        Poi1 => vec![],
        Seg2 => f(Poi1, &[&[0], &[1]]),
        Seg3 => f(Poi1, &[&[0], &[2]]),
        Tri3 => f(Seg2, &[&[0, 1], &[1, 2], &[2, 0]]),
        Tri6 => f(Seg3, &[&[0, 1, 2], &[2, 3, 4], &[4, 5, 0]]),
        Qua4 => f(Seg2, &[&[0, 1], &[1, 2], &[2, 3], &[3, 0]]),
        Qua8 => f(Seg3, &[&[0, 1, 2], &[2, 3, 4], &[4, 5, 6], &[6, 7, 0]]),
        Cub8 => f(Qua4, &[&[0, 3, 2, 1], &[4, 5, 6, 7], &[0, 1, 5, 4], &[1, 2, 6, 5], &[2, 3, 7, 6], &[3, 0, 4, 7]]),
        Tet4 => f(Tri3, &[&[0, 2, 1], &[0, 1, 3], &[1, 2, 3], &[2, 0, 3]]),
        Pri6 => {
            let mut v = f(Tri3, &[&[0, 2, 1], &[3, 4, 5]]);
            v.extend(f(Qua4, &[&[0, 1, 4, 3], &[1, 2, 5, 4], &[2, 0, 3, 5]]));
            v
        }
        // A joint has no boundary of its own: it lies between two.
        Rac2 | Rac3 | Lia3 | Lia4 => vec![],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shape_functions_are_nodal_and_sum_to_one() {
        for ty in ElemType::ALL {
            let nodes = ref_nodes(ty);
            assert_eq!(nodes.len(), ty.nodes());
            for (j, &pj) in nodes.iter().enumerate() {
                let s = eval(ty, pj);
                for (i, &ni) in s.n.iter().enumerate() {
                    let want = if i == j { 1.0 } else { 0.0 };
                    assert!((ni - want).abs() < 1e-14, "{} N{i}({j}) = {ni}", ty.name());
                }
            }
            let p = [0.21, 0.17, 0.13];
            let s = eval(ty, p);
            assert!((s.n.iter().sum::<f64>() - 1.0).abs() < 1e-14);
            // Derivatives against central differences.
            let h = 1e-6;
            for d in 0..3 {
                let (mut pp, mut pm) = (p, p);
                pp[d] += h;
                pm[d] -= h;
                let (sp, sm) = (eval(ty, pp), eval(ty, pm));
                for i in 0..ty.nodes() {
                    let fd = (sp.n[i] - sm.n[i]) / (2. * h);
                    assert!((fd - s.dn[i][d]).abs() < 1e-8, "{} dN{i}/d{d}", ty.name());
                }
            }
        }
    }
}
