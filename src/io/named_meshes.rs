//! gibi's own text file for SORT MAILLAGE / LIRE (the directive forms):
//! named meshes over shared nodes, so that LIRE gives back the meshes
//! SORT wrote, under their names, with their nodes shared as they were.
//!
//! ```text
//! GIBI-MESHES 1
//! NODES n
//! x y z density            (n lines)
//! MESH NAME parts          (then per part:)
//! PART TYPE elements
//! i j k …                  (one line per element, 1-based node numbers of this file)
//! ```

use super::IoError;
use crate::fem::mesh::{ElemType, Mesh, Part};
use std::fmt::Write as _;

const MAGIC: &str = "GIBI-MESHES 1";

/// Nodes (coordinates and density) and named meshes whose connectivity
/// numbers those nodes from 0.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct NamedMeshes {
    pub nodes: Vec<([f64; 3], f64)>,
    pub meshes: Vec<(String, Mesh)>,
}

pub fn write(data: &NamedMeshes) -> String {
    let mut s = format!("{MAGIC}\nNODES {}\n", data.nodes.len());
    for (x, d) in &data.nodes {
        // {:e} writes the shortest form that reads back exactly.
        let _ = writeln!(s, "{:e} {:e} {:e} {:e}", x[0], x[1], x[2], d);
    }
    for (name, m) in &data.meshes {
        let parts: Vec<&Part> = m.parts.iter().filter(|p| !p.is_empty()).collect();
        let _ = writeln!(s, "MESH {} {}", name, parts.len());
        for p in parts {
            let _ = writeln!(s, "PART {} {}", p.ty.name(), p.len());
            for e in p.elems() {
                let line: Vec<String> = e.iter().map(|n| (n + 1).to_string()).collect();
                let _ = writeln!(s, "{}", line.join(" "));
            }
        }
    }
    s
}

pub fn read(text: &str) -> Result<NamedMeshes, IoError> {
    let mut lines = text.lines().enumerate().map(|(i, l)| (i + 1, l.trim())).filter(|(_, l)| !l.is_empty());
    let bad = |n: usize, what: &str| IoError(format!("line {n}: {what}"));
    match lines.next() {
        Some((_, l)) if l == MAGIC => {}
        _ => return Err(IoError(format!("not a mesh file written by SORT (it does not start with '{MAGIC}')"))),
    }
    let mut next = |what: &str| lines.next().ok_or_else(|| IoError(format!("the file ends before {what}")));
    let (n, l) = next("the node count")?;
    let count: usize =
        l.strip_prefix("NODES ").and_then(|c| c.trim().parse().ok()).ok_or_else(|| bad(n, "expected NODES count"))?;
    let mut out = NamedMeshes::default();
    for _ in 0..count {
        let (n, l) = next("the last node")?;
        let v: Vec<f64> = l
            .split_whitespace()
            .map(str::parse)
            .collect::<Result<_, _>>()
            .map_err(|_| bad(n, "a node is four numbers"))?;
        match v.as_slice() {
            [x, y, z, d] if v.iter().all(|c| c.is_finite()) => out.nodes.push(([*x, *y, *z], *d)),
            _ => return Err(bad(n, "a node is four finite numbers (x y z density)")),
        }
    }
    while let Some((n, l)) = lines.next() {
        let w: Vec<&str> = l.split_whitespace().collect();
        let (name, nparts) = match w.as_slice() {
            ["MESH", name, k] => {
                (name.to_string(), k.parse::<usize>().map_err(|_| bad(n, "expected MESH name parts"))?)
            }
            _ => return Err(bad(n, "expected MESH name parts")),
        };
        let mut mesh = Mesh::default();
        for _ in 0..nparts {
            let (n, l) = lines.next().ok_or_else(|| IoError(format!("the file ends inside mesh {name}")))?;
            let w: Vec<&str> = l.split_whitespace().collect();
            let (ty, ne) = match w.as_slice() {
                ["PART", t, k] => (
                    ElemType::from_name(t).ok_or_else(|| bad(n, &format!("unknown element type {t}")))?,
                    k.parse::<usize>().map_err(|_| bad(n, "expected PART type elements"))?,
                ),
                _ => return Err(bad(n, "expected PART type elements")),
            };
            let mut conn = Vec::with_capacity(ne * ty.nodes());
            for _ in 0..ne {
                let (n, l) = lines.next().ok_or_else(|| IoError(format!("the file ends inside mesh {name}")))?;
                let e: Vec<usize> = l
                    .split_whitespace()
                    .map(|k| k.parse::<usize>().ok().filter(|&k| (1..=count).contains(&k)).map(|k| k - 1))
                    .collect::<Option<_>>()
                    .ok_or_else(|| bad(n, &format!("node numbers are 1 to {count}")))?;
                if e.len() != ty.nodes() {
                    return Err(bad(n, &format!("a {} has {} nodes", ty.name(), ty.nodes())));
                }
                conn.extend(e);
            }
            mesh.parts.push(Part::with(ty, conn));
        }
        out.meshes.push((name, mesh));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn meshes_come_back_as_written() {
        let data = NamedMeshes {
            nodes: vec![([0.0, 0.0, 0.0], 1.0), ([1.0, 0.1, 0.0], 0.5), ([0.0, 1.0, 2.0 / 3.0], 1.0)],
            meshes: vec![
                ("A".into(), Mesh::single(Part::with(ElemType::Tri3, vec![0, 1, 2]))),
                ("B".into(), Mesh::single(Part::with(ElemType::Seg2, vec![0, 1]))),
            ],
        };
        assert_eq!(read(&write(&data)).unwrap(), data);
        assert!(read("nothing").is_err());
    }
}
