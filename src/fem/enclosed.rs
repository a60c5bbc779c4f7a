//! What a closed boundary encloses: the area inside a closed line and the
//! volume inside a closed surface (MESU 'SURF' / 'VOLU' of a boundary).
//! Both are sums over the boundary's pieces, so the orientation of every
//! piece must agree (as a mesh built by walking the contour gives).

use super::vec3::{cross, dot};

/// Area inside a closed polyline given as segments (each a node chain in
/// order): half the norm of Σ pᵢ × pᵢ₊₁ (Newell's vector area). In 3D this
/// is the area of the contour projected onto its mean plane.
pub fn area_inside(segments: &[Vec<[f64; 3]>]) -> f64 {
    let mut s = [0.0; 3];
    for seg in segments {
        for w in seg.windows(2) {
            let c = cross(w[0], w[1]);
            for i in 0..3 {
                s[i] += c[i];
            }
        }
    }
    0.5 * dot(s, s).sqrt()
}

/// Volume inside a closed surface given as faces (each a node loop in
/// order): Σ of the signed volumes of the tetrahedra from the origin to a
/// fan of triangles of each face.
pub fn volume_inside(faces: &[Vec<[f64; 3]>]) -> f64 {
    let mut v = 0.0;
    for f in faces {
        for k in 1..f.len().saturating_sub(1) {
            v += dot(f[0], cross(f[k], f[k + 1])) / 6.0;
        }
    }
    v.abs()
}
