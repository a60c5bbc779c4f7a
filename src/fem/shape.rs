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
        // A relation element is its hanging node: every node at the origin.
        ElemType::Mult3 | ElemType::Mult4 | ElemType::Mult5 => vec![[0.0; 3]; ty.nodes()],
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
        ElemType::Pyr5 => {
            let mut v = ref_nodes(ElemType::Cub8);
            v.truncate(4);
            v.push([0., 0., 1.]);
            v
        }
        ElemType::Cu20 => layered(&ref_nodes(ElemType::Qua8), &[0, 2, 4, 6]),
        ElemType::Pr15 => layered(&ref_nodes(ElemType::Tri6), &[0, 2, 4]),
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

/// A quadratic volume's reference nodes: its base face at ζ = -1, the
/// mid-height nodes above the base's corners at ζ = 0, the top face at 1.
fn layered(face: &[[f64; 3]], corners: &[usize]) -> Vec<[f64; 3]> {
    let mut v: Vec<_> = face.iter().map(|p| [p[0], p[1], -1.]).collect();
    v.extend(corners.iter().map(|&k| [face[k][0], face[k][1], 0.]));
    v.extend(face.iter().map(|p| [p[0], p[1], 1.]));
    v
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
        ElemType::Mult3 | ElemType::Mult4 | ElemType::Mult5 => {
            let mut n = vec![0.0; ty.nodes()];
            n[0] = 1.0;
            Shape { n, dn: vec![[0.0; 3]; ty.nodes()] }
        }
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
        // The cube's functions with its four top nodes at the apex (a
        // degenerate CUB8): polynomial, exact for the volume.
        ElemType::Pyr5 => {
            let mut n = Vec::with_capacity(5);
            let mut dn = Vec::with_capacity(5);
            for [a, b, _] in ref_nodes(ElemType::Qua4) {
                let (fa, fb, fc) = (1. + a * x, 1. + b * y, 1. - z);
                n.push(0.125 * fa * fb * fc);
                dn.push([0.125 * a * fb * fc, 0.125 * b * fa * fc, -0.125 * fa * fb]);
            }
            n.push(0.5 * (1. + z));
            dn.push([0., 0., 0.5]);
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
        ElemType::Cu20 => {
            // Serendipity: corners (1+aξ)(1+bη)(1+cζ)(aξ+bη+cζ-2)/8, an
            // edge node (1-ξ_d²)·Π(1+a_e ξ_e)/4 over the two other axes.
            let mut n = Vec::with_capacity(20);
            let mut dn = Vec::with_capacity(20);
            for a in ref_nodes(ty) {
                let f: [f64; 3] = std::array::from_fn(|d| 1. + a[d] * p[d]);
                match (0..3).find(|&d| a[d] == 0.) {
                    None => {
                        let s = a[0] * x + a[1] * y + a[2] * z - 2.;
                        n.push(0.125 * f[0] * f[1] * f[2] * s);
                        dn.push(std::array::from_fn(|d| {
                            let (e, g) = ((d + 1) % 3, (d + 2) % 3);
                            0.125 * a[d] * f[e] * f[g] * (s + f[d])
                        }));
                    }
                    Some(d) => {
                        let (e, g) = ((d + 1) % 3, (d + 2) % 3);
                        let q = 1. - p[d] * p[d];
                        n.push(0.25 * q * f[e] * f[g]);
                        let mut di = [0.; 3];
                        di[d] = -0.5 * p[d] * f[e] * f[g];
                        di[e] = 0.25 * q * a[e] * f[g];
                        di[g] = 0.25 * q * f[e] * a[g];
                        dn.push(di);
                    }
                }
            }
            Shape { n, dn }
        }
        ElemType::Pr15 => {
            let l = [1. - x - y, x, y];
            let dl = [[-1., -1.], [1., 0.], [0., 1.]];
            let (mut n, mut dn) = (vec![0.; 15], vec![[0.; 3]; 15]);
            for c in [-1., 1.] {
                let base = if c < 0. { 0 } else { 9 };
                let fz = 1. + c * z;
                for i in 0..3 {
                    let j = (i + 1) % 3;
                    // Corner: L(2L-1)(1+cζ)/2 - L(1-ζ²)/2.
                    let g = (2. * l[i] - 1.) * fz - (1. - z * z);
                    n[base + 2 * i] = 0.5 * l[i] * g;
                    let dg_dl = 2. * fz;
                    let dlg = 0.5 * (g + l[i] * dg_dl);
                    dn[base + 2 * i] = [dlg * dl[i][0], dlg * dl[i][1], 0.5 * l[i] * ((2. * l[i] - 1.) * c + 2. * z)];
                    // Mid-side of the triangle: 2 Li Lj (1+cζ).
                    n[base + 2 * i + 1] = 2. * l[i] * l[j] * fz;
                    dn[base + 2 * i + 1] = [
                        2. * fz * (dl[i][0] * l[j] + l[i] * dl[j][0]),
                        2. * fz * (dl[i][1] * l[j] + l[i] * dl[j][1]),
                        2. * l[i] * l[j] * c,
                    ];
                }
            }
            for i in 0..3 {
                let q = 1. - z * z;
                n[6 + i] = l[i] * q;
                dn[6 + i] = [dl[i][0] * q, dl[i][1] * q, -2. * z * l[i]];
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
        Poi1 | Mult3 | Mult4 | Mult5 => vec![],
        Seg2 => f(Poi1, &[&[0], &[1]]),
        Seg3 => f(Poi1, &[&[0], &[2]]),
        Tri3 => f(Seg2, &[&[0, 1], &[1, 2], &[2, 0]]),
        Tri6 => f(Seg3, &[&[0, 1, 2], &[2, 3, 4], &[4, 5, 0]]),
        Qua4 => f(Seg2, &[&[0, 1], &[1, 2], &[2, 3], &[3, 0]]),
        Qua8 => f(Seg3, &[&[0, 1, 2], &[2, 3, 4], &[4, 5, 6], &[6, 7, 0]]),
        Cub8 => f(Qua4, &[&[0, 3, 2, 1], &[4, 5, 6, 7], &[0, 1, 5, 4], &[1, 2, 6, 5], &[2, 3, 7, 6], &[3, 0, 4, 7]]),
        Tet4 => f(Tri3, &[&[0, 2, 1], &[0, 1, 3], &[1, 2, 3], &[2, 0, 3]]),
        Pyr5 => {
            let mut v = f(Qua4, &[&[0, 3, 2, 1]]);
            v.extend(f(Tri3, &[&[0, 1, 4], &[1, 2, 4], &[2, 3, 4], &[3, 0, 4]]));
            v
        }
        Pri6 => {
            let mut v = f(Tri3, &[&[0, 2, 1], &[3, 4, 5]]);
            v.extend(f(Qua4, &[&[0, 1, 4, 3], &[1, 2, 5, 4], &[2, 0, 3, 5]]));
            v
        }
        Cu20 => {
            let mut v = f(Qua8, &[&[0, 7, 6, 5, 4, 3, 2, 1], &[12, 13, 14, 15, 16, 17, 18, 19]]);
            v.extend((0..4).map(|k| (Qua8, side(k, 4))));
            v
        }
        Pr15 => {
            let mut v = f(Tri6, &[&[0, 5, 4, 3, 2, 1], &[9, 10, 11, 12, 13, 14]]);
            v.extend((0..3).map(|k| (Qua8, side(k, 3))));
            v
        }
        // A joint has no boundary of its own: it lies between two.
        Rac2 | Rac3 | Lia3 | Lia4 => vec![],
    }
}

/// Side face k (between base corners k and k + 1) of a quadratic volume
/// whose base has `nc` corners: a QUA8 turning outward.
fn side(k: usize, nc: usize) -> Vec<usize> {
    let k1 = (k + 1) % nc;
    let top = 2 * nc + nc;
    vec![2 * k, 2 * k + 1, 2 * k1, 2 * nc + k1, top + 2 * k1, top + 2 * k + 1, top + 2 * k, 2 * nc + k]
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
