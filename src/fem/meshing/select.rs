//! `GEO POIN 'SPHE'|'CYLI'|'CONE'|'TORE' ... (crit)`: the nodes of a mesh
//! lying on a surface of revolution, within a distance criterion, as a POI1
//! mesh in node order; and `GEO POIN 'JONC'`, the junction nodes.

use super::query::select;
use super::vec3::{cross, dist, dot, norm, scale, sub, V3};
use super::{check_nodes, fail, MeshError};
use crate::fem::mesh::{ElemType, Mesh, Nodes};
use std::collections::HashMap;

/// A surface given by points, as POIN reads it.
#[derive(Debug, Clone, Copy)]
pub enum Surface {
    /// Centre, and a point of the sphere.
    Sphere(V3, V3),
    /// Two points of the axis, and a point of the cylinder.
    Cylinder(V3, V3, V3),
    /// The apex, a point of the axis, and a point of the cone.
    Cone(V3, V3, V3),
    /// The centre, a point of the axis, the centre of a small circle (its
    /// distance to the centre is the large radius), and a point of the torus.
    Torus(V3, V3, V3, V3),
}

/// Unit vector along `b - a`, or an error naming what is degenerate.
fn unit(a: V3, b: V3, what: &str) -> Result<V3, MeshError> {
    let d = sub(b, a);
    let l = norm(d);
    if !(l > 0.0 && l.is_finite()) {
        return fail("POIN", format!("{what}: the two points coincide"));
    }
    Ok(scale(d, 1.0 / l))
}

/// Distance from `x` to the axis through `o` of unit direction `k`.
fn off_axis(x: V3, o: V3, k: V3) -> f64 {
    norm(cross(k, sub(x, o)))
}

/// The nodes of `mesh` within `tol` of `surface`.
pub fn poin_on(nodes: &Nodes, mesh: &Mesh, surface: Surface, tol: f64) -> Result<Mesh, MeshError> {
    check_nodes("POIN", nodes, mesh)?;
    if !(tol.is_finite() && tol >= 0.0) {
        return fail("POIN", format!("the distance criterion must be positive (got {tol})"));
    }
    Ok(match surface {
        Surface::Sphere(c, p) => {
            let r = dist(p, c);
            select(nodes, mesh, |x| (dist(x, c) - r).abs() <= tol)
        }
        Surface::Cylinder(a, b, p) => {
            let k = unit(a, b, "'CYLI' axis")?;
            let r = off_axis(p, a, k);
            select(nodes, mesh, |x| (off_axis(x, a, k) - r).abs() <= tol)
        }
        Surface::Cone(s, a, p) => {
            let k = unit(s, a, "'CONE' axis")?;
            let lp = dist(p, s);
            if lp == 0.0 {
                return fail("POIN", "'CONE': the point of the cone is its apex");
            }
            // The sine of the half angle: the distance to the axis grows as
            // sin(alpha) times the distance to the apex.
            let sin = off_axis(p, s, k) / lp;
            select(nodes, mesh, |x| (off_axis(x, s, k) - sin * dist(x, s)).abs() <= tol)
        }
        Surface::Torus(c, a, c2, p) => {
            let k = unit(c, a, "'TORE' axis")?;
            let big = dist(c2, c);
            if big == 0.0 {
                return fail("POIN", "'TORE': the small circle's centre is the torus centre");
            }
            // Distance from x to the circle of radius `big` about the axis.
            let to_ring = |x: V3| {
                let v = sub(x, c);
                let h = dot(v, k);
                let rho = norm(sub(v, scale(k, h)));
                ((rho - big).powi(2) + h * h).sqrt()
            };
            let small = to_ring(p);
            select(nodes, mesh, |x| (to_ring(x) - small).abs() <= tol)
        }
    })
}

/// `GEO POIN 'JONC'`: the nodes joining more than two elements
/// (counting each element once per node), in node order.
pub fn poin_jonc(mesh: &Mesh) -> Mesh {
    let mut count: HashMap<usize, usize> = HashMap::new();
    for p in &mesh.parts {
        for e in p.elems() {
            let mut seen: Vec<usize> = e.to_vec();
            seen.sort_unstable();
            seen.dedup();
            for n in seen {
                *count.entry(n).or_default() += 1;
            }
        }
    }
    let picked: Vec<usize> = mesh.node_list().into_iter().filter(|n| count[n] > 2).collect();
    super::mesh_of(vec![(ElemType::Poi1, picked)])
}
