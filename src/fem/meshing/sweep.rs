//! Sweeps: TRAN (translation), ROTA (rotation) and VOLU (between two
//! surfaces). A sweep turns points into SEG2, SEG2 into QUA4, SEG3 into
//! QUA8, TRI3 into PRI6, QUA4 into CUB8, TRI6 into PR15 and QUA8 into CU20.
//!
//! Common conventions of the three operators:
//!
//! * **Nodes.** The input's nodes are layer 0. New nodes are appended layer
//!   after layer, each layer in the input's node order ([`Mesh::node_list`]);
//!   for QUA8, the middle layer between layers k and k + 1 (made only of the
//!   end nodes of SEG3 elements) comes just before layer k + 1. A node that
//!   does not move (on the axis of ROTA, shared by both surfaces of VOLU) is
//!   not copied: the elements touching it are degenerate (a repeated node).
//!   New nodes keep the density of the node they come from (VOLU
//!   interpolates between the two surfaces).
//! * **Elements** come layer after layer; within a layer, in input order.
//!   A SEG2 `(a, b)` gives the QUA4 `(a_k, b_k, b_k+1, a_k+1)`, so element 1
//!   starts with the input line's first edge and COTE sees the input as side
//!   1, the path of its last point as side 2, the final copy (reversed) as
//!   side 3 and the path of its first point (reversed) as side 4. Surface
//!   orientation follows the input line; volumes are always made positive:
//!   when the base face's normal points against the sweep, the base is
//!   listed reversed (`a d c b` / `a c b`) before the top face above it.

use super::grading::{fractions, Spacing, MAX_COUNT};
use super::vec3::{add, cross, dist, dot, lerp, norm, rotate, scale, sub, V3};
use super::{check_nodes, fail, MeshError};
use crate::fem::mesh::{ElemType, Mesh, Nodes};
use std::collections::HashMap;

/// `GEO TRAN (n) ('DINI' d1) ('DFIN' d2) VEC`: sweep `mesh` along `v`.
/// Layer thicknesses follow [`Spacing`] over the length of `v`; without a
/// count or densities the average density of the swept nodes sets it.
pub fn tran(nodes: &mut Nodes, mesh: &Mesh, spacing: &Spacing, v: V3) -> Result<Mesh, MeshError> {
    const OP: &str = "TRAN";
    check_nodes(OP, nodes, mesh)?;
    let d = mean_density(nodes, mesh);
    let t = fractions(OP, spacing, norm(v), d, d)?;
    let place = |x: V3, _: usize, s: f64| add(x, scale(v, s));
    sweep(OP, nodes, mesh, &t, place, |_| false, false)
}

/// `GEO ROTA (n) angle P1 (P2)`: sweep `mesh` by a rotation of `angle_deg`
/// degrees about the point `centre` (2D: about the z axis, positive
/// counter-clockwise) or, when `axis_end` is given (3D), about the axis from
/// `centre` to `axis_end` (right-hand rule). `|angle| <= 360`; a full turn
/// closes on the input's nodes instead of copying them. The layer count
/// follows [`Spacing`] over the arc length of the node farthest from the
/// axis.
pub fn rota(
    nodes: &mut Nodes,
    mesh: &Mesh,
    spacing: &Spacing,
    angle_deg: f64,
    centre: V3,
    axis_end: Option<V3>,
) -> Result<Mesh, MeshError> {
    const OP: &str = "ROTA";
    check_nodes(OP, nodes, mesh)?;
    if !(angle_deg.is_finite() && angle_deg != 0.0 && angle_deg.abs() <= 360.0 + 1e-9) {
        return fail(OP, format!("the angle must be non-zero and at most 360 degrees (got {angle_deg})"));
    }
    let k = match axis_end {
        None => [0.0, 0.0, 1.0],
        Some(p2) => {
            let a = sub(p2, centre);
            if norm(a) == 0.0 {
                return fail(OP, "the two points of the axis coincide");
            }
            scale(a, 1.0 / norm(a))
        }
    };
    let radius = |x: V3| norm(cross(k, sub(x, centre)));
    let list = mesh.node_list();
    let rmax = list.iter().map(|&n| radius(nodes.get(n))).fold(0.0, f64::max);
    if rmax == 0.0 {
        return fail(OP, "every node lies on the axis of rotation");
    }
    let angle = angle_deg.to_radians();
    let d = mean_density(nodes, mesh);
    let t = fractions(OP, spacing, rmax * angle.abs(), d, d)?;
    let closed = (angle_deg.abs() - 360.0).abs() <= 1e-9;
    let on_axis: std::collections::HashSet<usize> =
        list.iter().copied().filter(|&n| radius(nodes.get(n)) <= 1e-12 * rmax).collect();
    let place = |x: V3, _: usize, s: f64| rotate(x, centre, k, angle * s);
    sweep(OP, nodes, mesh, &t, place, |n| on_axis.contains(&n), closed)
}

/// `VOLU (n) S1 S2`: the volume between two surfaces of identical structure
/// (same element types and counts, element e of `s2` above element e of
/// `s1`, node by node). Intermediate layers interpolate linearly; a node
/// shared by both surfaces stays put. Layers follow [`Spacing`] over the
/// mean distance between corresponding nodes.
pub fn volu(nodes: &mut Nodes, s1: &Mesh, s2: &Mesh, spacing: &Spacing) -> Result<Mesh, MeshError> {
    between("VOLU", nodes, s1, s2, spacing)
}

/// The sweep from `s1` to `s2` of VOLU (two surfaces) and REGLER (two
/// lines), see [`volu`]; `op` names the operator in errors. Without a
/// count, the layers are graded from the mean density of `s1` to that of
/// `s2`.
pub fn between(
    op: &'static str,
    nodes: &mut Nodes,
    s1: &Mesh,
    s2: &Mesh,
    spacing: &Spacing,
) -> Result<Mesh, MeshError> {
    check_nodes(op, nodes, s1)?;
    check_nodes(op, nodes, s2)?;
    // Element types in order, consecutive parts of one type (colours)
    // counted together: elements face each other one by one.
    let types = |m: &Mesh| {
        let mut v: Vec<(ElemType, usize)> = Vec::new();
        for p in m.parts.iter().filter(|p| !p.is_empty()) {
            match v.last_mut() {
                Some((t, n)) if *t == p.ty => *n += p.len(),
                _ => v.push((p.ty, p.len())),
            }
        }
        v
    };
    if types(s1) != types(s2) {
        let show = |m: &Mesh| types(m).iter().map(|(t, n)| format!("{n} {}", t.name())).collect::<Vec<_>>().join(" + ");
        return fail(
            op,
            format!(
                "the two meshes must have the same elements, in number and type: the first has {}, the second {}",
                show(s1),
                show(s2)
            ),
        );
    }
    // Node k of element e of s1 faces node k of element e of s2; failing
    // that, every element of s1 turned over (the face 2 of a volume whose
    // sweep listed its base reversed, see `sweep_to`).
    let pairing = |turned: bool| -> Result<HashMap<usize, usize>, usize> {
        let mut map: HashMap<usize, usize> = HashMap::new();
        let e1 = s1.parts.iter().flat_map(|p| p.elems().map(move |e| (p.ty, e)));
        let e2 = s2.parts.iter().flat_map(|p| p.elems());
        for ((ty, a), b) in e1.zip(e2) {
            let perm = super::symmetry::turn_over(ty);
            for k in 0..a.len() {
                let ak = if turned { a[perm[k]] } else { a[k] };
                if *map.entry(ak).or_insert(b[k]) != b[k] {
                    return Err(ak);
                }
            }
        }
        Ok(map)
    };
    let map = match pairing(false).or_else(|_| pairing(true)) {
        Ok(m) => m,
        Err(a) => return fail(op, format!("node {} of the first mesh faces two different nodes of the second", a + 1)),
    };
    let targets: Vec<(usize, V3, f64)> = map.iter().map(|(&a, &b)| (a, nodes.get(b), nodes.density[b])).collect();
    let gap = targets.iter().map(|(a, x, _)| dist(nodes.get(*a), *x)).sum::<f64>() / targets.len().max(1) as f64;
    let t = fractions(op, spacing, gap, mean_density(nodes, s1), mean_density(nodes, s2))?;
    let far: HashMap<usize, V3> = targets.iter().map(|(a, x, _)| (*a, *x)).collect();
    let place = |x: V3, n: usize, s: f64| lerp(x, far[&n], s);
    // The last layer is the second surface itself.
    let last = |n: usize| map[&n];
    let same = |n: usize| map[&n] == n;
    sweep_to(op, nodes, s1, &t, place, same, Some(&last))
}

fn mean_density(nodes: &Nodes, mesh: &Mesh) -> f64 {
    let list = mesh.node_list();
    list.iter().map(|&n| nodes.density[n]).sum::<f64>() / list.len().max(1) as f64
}

fn sweep(
    op: &'static str,
    nodes: &mut Nodes,
    mesh: &Mesh,
    t: &[f64],
    place: impl Fn(V3, usize, f64) -> V3,
    fixed: impl Fn(usize) -> bool,
    closed: bool,
) -> Result<Mesh, MeshError> {
    let first = |n: usize| n;
    sweep_to(op, nodes, mesh, t, place, fixed, closed.then_some(&first as &dyn Fn(usize) -> usize))
}

/// The sweep engine. `place(x, node, s)` is where `node` (at `x`) goes at
/// fraction `s`; `fixed` nodes are never copied; `last`, when given, names
/// the existing node that ends each trajectory (closed turns, VOLU).
fn sweep_to(
    op: &'static str,
    nodes: &mut Nodes,
    mesh: &Mesh,
    t: &[f64],
    place: impl Fn(V3, usize, f64) -> V3,
    fixed: impl Fn(usize) -> bool,
    last: Option<&dyn Fn(usize) -> usize>,
) -> Result<Mesh, MeshError> {
    let mut halves_needed = std::collections::HashSet::new();
    for p in mesh.parts.iter().filter(|p| !p.is_empty()) {
        match p.ty {
            ElemType::Poi1 | ElemType::Seg2 | ElemType::Tri3 | ElemType::Qua4 => {}
            ElemType::Seg3 => halves_needed.extend(p.elems().flat_map(|e| [e[0], e[2]])),
            // Quadratic volumes have mid-height nodes above the corners only.
            ElemType::Tri6 | ElemType::Qua8 => {
                let nc = p.ty.nodes() / 2;
                halves_needed.extend(p.elems().flat_map(|e| (0..nc).map(move |k| e[2 * k])))
            }
            other => return fail(op, format!("cannot sweep {} elements (no matching element type)", other.name())),
        }
    }
    let list = mesh.node_list();
    if list.is_empty() {
        return fail(op, "the mesh to sweep is empty");
    }
    let n = t.len() - 1;
    // The layer count is capped alone; the result is layers times the input.
    let total = n.saturating_mul(mesh.n_elements());
    if total > MAX_COUNT {
        return fail(op, format!("{total} elements is more than the {MAX_COUNT} allowed"));
    }
    let origin: Vec<(V3, f64)> = list.iter().map(|&a| (nodes.get(a), nodes.density[a])).collect();
    let copy = |nodes: &mut Nodes, k: usize, s: f64| -> usize {
        let (a, (x, d)) = (list[k], origin[k]);
        if fixed(a) {
            a
        } else {
            nodes.push(place(x, a, s), d)
        }
    };
    // layers[l][k]: node k of the input on layer l; halves[l][k]: between
    // layers l and l + 1 (only for SEG3 end nodes).
    let mut layers: Vec<Vec<usize>> = vec![list.clone()];
    let mut halves: Vec<Vec<usize>> = Vec::with_capacity(n);
    for l in 1..=n {
        let s = 0.5 * (t[l - 1] + t[l]);
        let half = (0..list.len())
            .map(|k| if halves_needed.contains(&list[k]) { copy(nodes, k, s) } else { usize::MAX })
            .collect();
        halves.push(half);
        let layer = match (l == n, last) {
            (true, Some(f)) => list.iter().map(|&a| f(a)).collect(),
            _ => (0..list.len()).map(|k| copy(nodes, k, t[l])).collect(),
        };
        layers.push(layer);
    }
    let index: HashMap<usize, usize> = list.iter().enumerate().map(|(k, &a)| (a, k)).collect();
    let mut out: Vec<(ElemType, Vec<usize>)> = Vec::new();
    for p in mesh.parts.iter().filter(|p| !p.is_empty()) {
        let ty = match p.ty {
            ElemType::Poi1 => ElemType::Seg2,
            ElemType::Seg2 => ElemType::Qua4,
            ElemType::Seg3 => ElemType::Qua8,
            ElemType::Tri3 => ElemType::Pri6,
            ElemType::Tri6 => ElemType::Pr15,
            ElemType::Qua8 => ElemType::Cu20,
            _ => ElemType::Cub8,
        };
        let pos = match out.iter().position(|(t, _)| *t == ty) {
            Some(pos) => pos,
            None => {
                out.push((ty, Vec::new()));
                out.len() - 1
            }
        };
        let mut conn = std::mem::take(&mut out[pos].1);
        for l in 0..n {
            for e in p.elems() {
                let lo: Vec<usize> = e.iter().map(|a| layers[l][index[a]]).collect();
                let hi: Vec<usize> = e.iter().map(|a| layers[l + 1][index[a]]).collect();
                match p.ty {
                    ElemType::Poi1 => conn.extend([lo[0], hi[0]]),
                    ElemType::Seg2 => conn.extend([lo[0], lo[1], hi[1], hi[0]]),
                    ElemType::Seg3 => {
                        let h = |a: usize| halves[l][index[&a]];
                        conn.extend([lo[0], lo[1], lo[2], h(e[2]), hi[2], hi[1], hi[0], h(e[0])]);
                    }
                    ElemType::Tri6 | ElemType::Qua8 => {
                        // The base face around its contour, the mid-height
                        // nodes above its corners, the top face.
                        let nc = e.len() / 2;
                        let cl: Vec<usize> = (0..nc).map(|k| lo[2 * k]).collect();
                        let ch: Vec<usize> = (0..nc).map(|k| hi[2 * k]).collect();
                        let perm: &[usize] = if positive_order(nodes, &cl, &ch)[1] == 1 {
                            &[0, 1, 2, 3, 4, 5, 6, 7][..e.len()]
                        } else if nc == 3 {
                            &[0, 5, 4, 3, 2, 1]
                        } else {
                            &[0, 7, 6, 5, 4, 3, 2, 1]
                        };
                        conn.extend(perm.iter().map(|&i| lo[i]));
                        conn.extend(perm.iter().step_by(2).map(|&i| halves[l][index[&e[i]]]));
                        conn.extend(perm.iter().map(|&i| hi[i]));
                    }
                    _ => {
                        let order = positive_order(nodes, &lo, &hi);
                        conn.extend(order.iter().map(|&i| lo[i]));
                        conn.extend(order.iter().map(|&i| hi[i]));
                    }
                }
            }
        }
        out[pos].1 = conn;
    }
    Ok(super::mesh_of(out))
}

/// Local order of a base face (TRI3 or QUA4) whose normal points along the
/// sweep from `lo` to `hi`: as given, or reversed.
fn positive_order(nodes: &Nodes, lo: &[usize], hi: &[usize]) -> Vec<usize> {
    let x = |n: usize| nodes.get(n);
    let normal = if lo.len() == 3 {
        cross(sub(x(lo[1]), x(lo[0])), sub(x(lo[2]), x(lo[0])))
    } else {
        cross(sub(x(lo[2]), x(lo[0])), sub(x(lo[3]), x(lo[1])))
    };
    let mut dir = [0.0; 3];
    for (&a, &b) in lo.iter().zip(hi) {
        dir = add(dir, sub(x(b), x(a)));
    }
    let ahead = dot(normal, dir) >= 0.0;
    match (lo.len(), ahead) {
        (3, true) => vec![0, 1, 2],
        (3, false) => vec![0, 2, 1],
        (_, true) => vec![0, 1, 2, 3],
        (_, false) => vec![0, 3, 2, 1],
    }
}
