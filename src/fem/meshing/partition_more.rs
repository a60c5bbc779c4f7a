//! PART's separator ('SEPA') and balanced ('OPTI') partitions.
//!
//! * Separators: two elements are neighbours when they share a face of
//!   their own dimension less one (a node for lines, at least two nodes
//!   for surfaces, three for volumes); zones are the classes of
//!   neighbours not cut by a rule. A rule cuts a pair when their common
//!   nodes (the interface) lie on more than two elements (junctions), lie
//!   in one element of a separator mesh, or when their normals (surfaces)
//!   or tangents (lines) make too large an angle.
//! * Balanced: recursive bisection of the element centres across the
//!   widest extent, halves of equal counts; a power of two of zones, each
//!   of whose sizes differ by at most one element per level.

use crate::fem::mesh::{Mesh, Nodes, Part};
use std::collections::{HashMap, HashSet};

/// One rule by which neighbouring elements are put in different zones.
pub enum Separator {
    /// Interfaces shared by more than two elements ('LIGN', 'FACE').
    Junction,
    /// Interfaces contained in an element of this mesh ('MAIL').
    Mesh(Mesh),
    /// Angle in degrees between normals/tangents at or above which the
    /// neighbours are cut; `oriented` keeps a half-turn as a sharp angle
    /// ('TELQ'), else directions are taken up to their sign.
    Angle { degrees: f64, oriented: bool },
}

/// Every element as (part index, nodes), in mesh order.
pub(super) fn elements(mesh: &Mesh) -> Vec<(usize, &[usize])> {
    mesh.parts.iter().enumerate().flat_map(|(i, p)| p.elems().map(move |e| (i, e))).collect()
}

/// Regroup elements by zone label (labels in first-met order).
pub(super) fn zones(mesh: &Mesh, elems: &[(usize, &[usize])], label: &[usize]) -> Vec<Mesh> {
    let mut zone_of: HashMap<usize, usize> = HashMap::new();
    let mut pieces: Vec<Vec<Vec<usize>>> = Vec::new();
    for (k, (i, e)) in elems.iter().enumerate() {
        let z = *zone_of.entry(label[k]).or_insert_with(|| {
            pieces.push(vec![Vec::new(); mesh.parts.len()]);
            pieces.len() - 1
        });
        pieces[z][*i].extend_from_slice(e);
    }
    pieces
        .into_iter()
        .map(|p| Mesh {
            parts: p
                .into_iter()
                .enumerate()
                .filter(|(_, c)| !c.is_empty())
                .map(|(i, conn)| Part { conn, ..mesh.parts[i].clone() })
                .collect(),
        })
        .collect()
}

pub(super) fn root(parent: &mut [usize], mut x: usize) -> usize {
    while parent[x] != x {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    x
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// The unit normal (surface) or tangent (line) of an element, if any.
/// Surface normals use Newell's sum over the boundary nodes, which holds
/// for quadratic elements too (their nodes go round the boundary).
fn direction(nodes: &Nodes, dim: usize, e: &[usize]) -> Option<[f64; 3]> {
    let v = match dim {
        1 => sub(nodes.get(e[e.len() - 1]), nodes.get(e[0])),
        2 => {
            let mut n = [0.0; 3];
            for k in 0..e.len() {
                let (a, b) = (nodes.get(e[k]), nodes.get(e[(k + 1) % e.len()]));
                n[0] += (a[1] - b[1]) * (a[2] + b[2]);
                n[1] += (a[2] - b[2]) * (a[0] + b[0]);
                n[2] += (a[0] - b[0]) * (a[1] + b[1]);
            }
            n
        }
        _ => return None,
    };
    let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    (l > 0.0).then(|| [v[0] / l, v[1] / l, v[2] / l])
}

/// Split `mesh` into zones along the separators (see the module notes).
pub fn separated(mesh: &Mesh, nodes: &Nodes, rules: &[Separator]) -> Vec<Mesh> {
    let elems = elements(mesh);
    let dims: Vec<usize> = elems.iter().map(|(i, _)| mesh.parts[*i].ty.dim()).collect();
    let mut at: HashMap<usize, Vec<usize>> = HashMap::new();
    for (k, (_, e)) in elems.iter().enumerate() {
        let mut seen = HashSet::new();
        for &n in e.iter() {
            if seen.insert(n) {
                at.entry(n).or_default().push(k);
            }
        }
    }
    let sep_sets: Vec<Vec<HashSet<usize>>> = rules
        .iter()
        .map(|r| match r {
            Separator::Mesh(m) => m.parts.iter().flat_map(|p| p.elems().map(|e| e.iter().copied().collect())).collect(),
            _ => Vec::new(),
        })
        .collect();
    let mut parent: Vec<usize> = (0..elems.len()).collect();
    let mut done: HashSet<(usize, usize)> = HashSet::new();
    let mut node_ids: Vec<&usize> = at.keys().collect();
    node_ids.sort();
    for n in node_ids {
        let here = &at[n];
        for (x, &a) in here.iter().enumerate() {
            for &b in &here[x + 1..] {
                if !done.insert((a, b)) {
                    continue;
                }
                let sa: HashSet<usize> = elems[a].1.iter().copied().collect();
                let shared: Vec<usize> = {
                    let mut s: Vec<usize> = elems[b].1.iter().copied().filter(|v| sa.contains(v)).collect();
                    s.sort_unstable();
                    s.dedup();
                    s
                };
                if shared.len() < dims[a].max(dims[b]).max(1) {
                    continue;
                }
                let cut = rules.iter().zip(&sep_sets).any(|(r, sets)| match r {
                    Separator::Junction => {
                        let on_all =
                            at[&shared[0]].iter().filter(|&&k| shared.iter().all(|v| elems[k].1.contains(v))).count();
                        on_all > 2
                    }
                    Separator::Mesh(_) => sets.iter().any(|s| shared.iter().all(|v| s.contains(v))),
                    Separator::Angle { degrees, oriented } => {
                        match (direction(nodes, dims[a], elems[a].1), direction(nodes, dims[b], elems[b].1)) {
                            (Some(u), Some(v)) => {
                                let c = (u[0] * v[0] + u[1] * v[1] + u[2] * v[2]).clamp(-1.0, 1.0);
                                let c = if *oriented { c } else { c.abs() };
                                c.acos().to_degrees() >= *degrees
                            }
                            _ => false,
                        }
                    }
                });
                if !cut {
                    let (ra, rb) = (root(&mut parent, a), root(&mut parent, b));
                    if ra != rb {
                        parent[ra.max(rb)] = ra.min(rb);
                    }
                }
            }
        }
    }
    let label: Vec<usize> = (0..elems.len()).map(|k| root(&mut parent, k)).collect();
    zones(mesh, &elems, &label)
}

/// Split `mesh` into (up to) `n` zones, `n` a power of two, by recursive
/// bisection of the element centres; fewer zones when there are fewer
/// elements, never an empty one.
pub fn bisected(mesh: &Mesh, nodes: &Nodes, n: usize) -> Vec<Mesh> {
    let elems = elements(mesh);
    let centres: Vec<[f64; 3]> = elems
        .iter()
        .map(|(_, e)| {
            let mut c = [0.0; 3];
            for &v in e.iter() {
                let x = nodes.get(v);
                (0..3).for_each(|d| c[d] += x[d] / e.len() as f64);
            }
            c
        })
        .collect();
    let mut label = vec![0; elems.len()];
    let mut next = 0;
    fn split(ids: Vec<usize>, n: usize, c: &[[f64; 3]], label: &mut [usize], next: &mut usize) {
        if n <= 1 || ids.len() <= 1 {
            ids.iter().for_each(|&k| label[k] = *next);
            *next += 1;
            return;
        }
        let axis = (0..3)
            .max_by(|&a, &b| {
                let ext = |d: usize| {
                    let (lo, hi) = ids.iter().fold((f64::MAX, f64::MIN), |(l, h), &k| (l.min(c[k][d]), h.max(c[k][d])));
                    hi - lo
                };
                ext(a).total_cmp(&ext(b))
            })
            .unwrap_or(0);
        let mut ids = ids;
        ids.sort_by(|&a, &b| c[a][axis].total_cmp(&c[b][axis]).then(a.cmp(&b)));
        let right = ids.split_off(ids.len() / 2);
        split(ids, n / 2, c, label, next);
        split(right, n / 2, c, label, next);
    }
    split((0..elems.len()).collect(), n.max(1), &centres, &mut label, &mut next);
    zones(mesh, &elems, &label)
}
