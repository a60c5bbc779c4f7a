//! The noses of a rigid projectile (IMPO 'IMPA', impo.notice form f): is
//! a point of the target inside the nose, and along which unit normal its
//! gap grows. The projectile is its tip point P: the nose lies behind P
//! along the axis, which points from the projectile's body to its tip.

/// A nose in the plane; `axis` is a unit vector.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Nose {
    /// A half disc of this radius whose foremost point is the tip.
    Hemisphere { radius: f64, axis: [f64; 2] },
    /// A flat face of this width, centred on the tip, across the axis.
    Flat { width: f64, axis: [f64; 2] },
    /// A cone with its apex at the tip, of this half angle (radians) to
    /// the axis, as wide as `width` at its base.
    Cone { width: f64, half_angle: f64, axis: [f64; 2] },
}

fn dot(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}

/// For a target point at `d` from the tip: the outward unit normal of the
/// nose's surface nearest to it when it is inside the nose, else `None`.
pub fn inside(nose: &Nose, d: [f64; 2]) -> Result<Option<[f64; 2]>, String> {
    if !(d[0].is_finite() && d[1].is_finite()) {
        return Err("a point of the links is not finite".into());
    }
    Ok(match *nose {
        Nose::Hemisphere { radius, axis } => {
            // Centre one radius behind the tip.
            let c = [d[0] + radius * axis[0], d[1] + radius * axis[1]];
            let r = dot(c, c).sqrt();
            if r >= radius || dot(c, axis) < 0.0 || r == 0.0 {
                None
            } else {
                Some([c[0] / r, c[1] / r])
            }
        }
        Nose::Flat { width, axis } => {
            let along = dot(d, axis);
            let lateral = (d[0] * axis[1] - d[1] * axis[0]).abs();
            if along >= 0.0 || lateral > 0.5 * width || -along > width {
                None
            } else {
                Some(axis)
            }
        }
        Nose::Cone { width, half_angle, axis } => {
            let along = dot(d, axis);
            let l = [d[0] - along * axis[0], d[1] - along * axis[1]];
            let r = dot(l, l).sqrt();
            let (s, c) = half_angle.sin_cos();
            // Signed distance to the side on the point's side.
            let g = r * c + along * s;
            if along > 0.0 || g >= 0.0 || r > 0.5 * width {
                None
            } else {
                // On the axis either side will do: take the left one.
                let e = if r > 0.0 { [l[0] / r, l[1] / r] } else { [-axis[1], axis[0]] };
                Some([c * e[0] + s * axis[0], c * e[1] + s * axis[1]])
            }
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn noses() {
        let axis = [0.0, -1.0];
        // A point 0.1 inside the half disc of radius 1 below the tip at 0.
        let n = inside(&Nose::Hemisphere { radius: 1.0, axis }, [0.0, 0.1]).unwrap().unwrap();
        assert!((n[0]).abs() < 1e-12 && (n[1] + 1.0).abs() < 1e-12);
        assert_eq!(inside(&Nose::Hemisphere { radius: 1.0, axis }, [0.0, -0.1]).unwrap(), None);
        assert_eq!(inside(&Nose::Flat { width: 2.0, axis }, [0.5, 0.2]).unwrap(), Some(axis));
        assert_eq!(inside(&Nose::Flat { width: 2.0, axis }, [1.5, 0.2]).unwrap(), None);
        let cone = Nose::Cone { width: 2.0, half_angle: 45f64.to_radians(), axis };
        assert!(inside(&cone, [0.1, 0.5]).unwrap().is_some());
        assert_eq!(inside(&cone, [0.6, 0.5]).unwrap(), None);
    }
}
