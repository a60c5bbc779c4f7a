//! The few 3D vector operations the generators need (coordinates are always
//! stored in 3D, unused components being 0).

pub type V3 = [f64; 3];

pub fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

pub fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

pub fn scale(a: V3, s: f64) -> V3 {
    [a[0] * s, a[1] * s, a[2] * s]
}

/// `a + t (b - a)`.
pub fn lerp(a: V3, b: V3, t: f64) -> V3 {
    add(a, scale(sub(b, a), t))
}

pub fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub fn cross(a: V3, b: V3) -> V3 {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

pub fn norm(a: V3) -> f64 {
    dot(a, a).sqrt()
}

pub fn dist(a: V3, b: V3) -> f64 {
    norm(sub(a, b))
}

/// Rotate `p` by `angle` (radians) about the axis through `o` with unit
/// direction `k` (Rodrigues' formula, right-hand rule).
pub fn rotate(p: V3, o: V3, k: V3, angle: f64) -> V3 {
    let v = sub(p, o);
    let (s, c) = angle.sin_cos();
    let kv = cross(k, v);
    let kd = dot(k, v) * (1.0 - c);
    add(o, add(add(scale(v, c), scale(kv, s)), scale(k, kd)))
}
