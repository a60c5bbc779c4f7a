//! Tensors and vectors seen in another orthonormal frame (RTENS).

/// An orthonormal direct frame from a first direction and a second one
/// in the plane of the first two axes (3D), or the first direction turned
/// by +90 degrees (2D, `v2` None and `v1[2]` ignored).
pub fn frame(v1: [f64; 3], v2: Option<[f64; 3]>) -> Result<[[f64; 3]; 3], String> {
    let e1 = unit(v1).ok_or("the first direction of the frame is zero")?;
    let Some(v2) = v2 else {
        let e1 = unit([v1[0], v1[1], 0.0]).ok_or("the direction of the frame is zero in the plane")?;
        return Ok([e1, [-e1[1], e1[0], 0.0], [0.0, 0.0, 1.0]]);
    };
    let d = dot(v2, e1);
    let e2 = unit([v2[0] - d * e1[0], v2[1] - d * e1[1], v2[2] - d * e1[2]])
        .ok_or("the two directions of the frame are parallel")?;
    Ok([e1, e2, cross(e1, e2)])
}

pub fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

pub fn unit(a: [f64; 3]) -> Option<[f64; 3]> {
    let n = dot(a, a).sqrt();
    (n > 0.0 && n.is_finite()).then(|| [a[0] / n, a[1] / n, a[2] / n])
}

/// The symmetric tensor `s` (xx yy zz xy xz yz) in the frame `e`:
/// `s'_ij = e_i . s . e_j`.
pub fn rotate_sym(s: [f64; 6], e: &[[f64; 3]; 3]) -> [f64; 6] {
    let m = [[s[0], s[3], s[4]], [s[3], s[1], s[5]], [s[4], s[5], s[2]]];
    let c = |i: usize, j: usize| {
        let mut t = 0.0;
        for (p, row) in m.iter().enumerate() {
            for (q, v) in row.iter().enumerate() {
                t += e[i][p] * v * e[j][q];
            }
        }
        t
    };
    [c(0, 0), c(1, 1), c(2, 2), c(0, 1), c(0, 2), c(1, 2)]
}

/// A plane symmetric tensor (11 22 12) turned into axes at angle
/// (cos c, sin s) from the old ones.
pub fn rotate_plane(t: [f64; 3], c: f64, s: f64) -> [f64; 3] {
    [
        c * c * t[0] + s * s * t[1] + 2.0 * c * s * t[2],
        s * s * t[0] + c * c * t[1] - 2.0 * c * s * t[2],
        -c * s * t[0] + c * s * t[1] + (c * c - s * s) * t[2],
    ]
}

/// The local frame of a shell element (first axis along its first side,
/// third along its normal) and the angle (cos, sin) from that first axis
/// to the projection of `v1` on the element's plane.
pub fn shell_angle(nodes: &[[f64; 3]], v1: [f64; 3]) -> Result<(f64, f64), String> {
    if nodes.len() < 3 {
        return Err("a shell element needs at least 3 nodes".into());
    }
    let sub = |a: [f64; 3], b: [f64; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
    let e1 = unit(sub(nodes[1], nodes[0])).ok_or("a shell element has a side of zero length")?;
    let last = nodes[nodes.len() - 1];
    let e3 = unit(cross(e1, sub(last, nodes[0]))).ok_or("a shell element is flat to a line")?;
    let e2 = cross(e3, e1);
    let (c, s) = (dot(v1, e1), dot(v1, e2));
    let n = (c * c + s * s).sqrt();
    if n.is_nan() || n <= 0.0 {
        return Err("the direction of the frame is normal to a shell element".into());
    }
    Ok((c / n, s / n))
}
