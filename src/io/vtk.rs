//! ParaView output: `.vtu` unstructured grids (VTK XML, arrays stored
//! inline as base64 binary) and `.pvd` collections that give each `.vtu` a
//! real time.
//!
//! Base64 inline rather than raw appended data: the file stays valid XML
//! and UTF-8 (diffable, greppable, parseable by any XML reader) at a 4/3
//! size cost, and ParaView reads it at full speed. Every array is Float64
//! or Int64 so no precision is lost on the way.

use super::{err, write_file, Result};
use crate::fem::mesh::{ElemType, Mesh, Nodes};
use base64::Engine;
use quick_xml::escape::escape;
use std::collections::HashMap;
use std::fmt::Write as _;
use std::path::Path;

/// A named array over points or cells: `values[i * ncomp + c]`.
#[derive(Debug, Clone, PartialEq)]
pub struct DataArray {
    pub name: String,
    /// Component names (one per component; ParaView shows them).
    pub comps: Vec<String>,
    pub values: Vec<f64>,
}

impl DataArray {
    pub fn ncomp(&self) -> usize {
        self.comps.len().max(1)
    }
}

/// VTK cell type and the position, in gibi's node order, of each VTK node.
/// gibi numbers quadratic elements around the boundary (corner, mid,
/// corner, …); VTK lists corners first, then mid-side nodes. VTK's wedge
/// base triangle turns the other way from gibi's (and Gmsh's) PRI6.
pub fn vtk_cell(ty: ElemType) -> (u8, &'static [usize]) {
    match ty {
        ElemType::Poi1 => (1, &[0]),
        ElemType::Seg2 => (3, &[0, 1]),
        ElemType::Seg3 => (21, &[0, 2, 1]),
        ElemType::Tri3 => (5, &[0, 1, 2]),
        ElemType::Tri6 => (22, &[0, 2, 4, 1, 3, 5]),
        ElemType::Qua4 => (9, &[0, 1, 2, 3]),
        ElemType::Qua8 => (23, &[0, 2, 4, 6, 1, 3, 5, 7]),
        ElemType::Cub8 => (12, &[0, 1, 2, 3, 4, 5, 6, 7]),
        ElemType::Tet4 => (10, &[0, 1, 2, 3]),
        ElemType::Pri6 => (13, &[0, 2, 1, 3, 5, 4]),
        ElemType::Pyr5 => (14, &[0, 1, 2, 3, 4]),
        // Quadratic volumes: VTK's corners, the base's edges, the top's,
        // then the vertical ones.
        ElemType::Cu20 => (25, &[0, 2, 4, 6, 12, 14, 16, 18, 1, 3, 5, 7, 13, 15, 17, 19, 8, 9, 10, 11]),
        ElemType::Pr15 => (26, &[0, 4, 2, 9, 13, 11, 5, 3, 1, 14, 12, 10, 6, 8, 7]),
        // Joints: the two sides as one flat cell (polygon, wedge, hexahedron).
        ElemType::Rac2 => (9, &[0, 1, 3, 2]),
        ElemType::Rac3 => (7, &[0, 1, 2, 5, 4, 3]),
        ElemType::Lia3 => (13, &[0, 1, 2, 3, 4, 5]),
        ElemType::Lia4 => (12, &[0, 1, 2, 3, 4, 5, 6, 7]),
        // A relation element is drawn as its hanging node.
        ElemType::Mult3 | ElemType::Mult4 | ElemType::Mult5 => (1, &[0]),
    }
}

/// A mesh with its fields, ready to be written as one `.vtu` piece.
/// Points are the mesh's nodes in order of first appearance; cells are
/// its elements part by part.
#[derive(Debug, Clone)]
pub struct Grid {
    pub nodes: Vec<usize>,
    pub coords: Vec<[f64; 3]>,
    pub cells: Vec<(ElemType, Vec<usize>)>,
    pub point_data: Vec<DataArray>,
    pub cell_data: Vec<DataArray>,
    point_of: HashMap<usize, usize>,
}

impl Grid {
    pub fn new(mesh: &Mesh, nodes: &Nodes) -> Result<Grid> {
        let list = mesh.node_list();
        if let Some(&bad) = list.iter().find(|&&n| n >= nodes.len()) {
            return err(format!("node {} of the mesh is not in the node table", bad + 1));
        }
        let point_of = list.iter().enumerate().map(|(i, &n)| (n, i)).collect();
        let coords = list.iter().map(|&n| nodes.get(n)).collect();
        let cells = mesh.parts.iter().flat_map(|p| p.elems().map(move |e| (p.ty, e.to_vec()))).collect();
        Ok(Grid { nodes: list, coords, cells, point_data: vec![], cell_data: vec![], point_of })
    }

    pub fn n_points(&self) -> usize {
        self.nodes.len()
    }

    pub fn n_cells(&self) -> usize {
        self.cells.len()
    }

    /// The point a node of the node table became, if it is in the mesh.
    pub fn point_index(&self, node: usize) -> Option<usize> {
        self.point_of.get(&node).copied()
    }

    /// Add a nodal field given by component names and a lookup
    /// `value(node, component)`. Components `<S>X <S>Y (<S>Z)` become one
    /// 3-component vector (UX UY → U with UZ = 0 in 2D, so ParaView's Warp
    /// By Vector works in any dimension); the others become scalars. The
    /// displacement vector (stem U), else the first vector, else a lone
    /// scalar, takes `name`; the rest are `name_<stem>` / `name_<comp>`.
    /// Missing vector components are 0 (a NaN would break Warp By
    /// Vector); missing scalars are NaN (ParaView shows them as holes).
    pub fn add_point_field(&mut self, name: &str, comps: &[String], value: impl Fn(usize, &str) -> Option<f64>) {
        let groups = split_components(comps);
        let bare = groups
            .iter()
            .position(|g| g.stem == "U" && g.vector)
            .or_else(|| groups.iter().position(|g| g.vector).or((groups.len() == 1).then_some(0)));
        for (gi, g) in groups.iter().enumerate() {
            let array_name = if Some(gi) == bare { name.to_string() } else { format!("{}_{}", name, g.stem) };
            let missing = if g.vector { 0.0 } else { f64::NAN };
            let mut values = Vec::with_capacity(self.n_points() * g.members.len());
            for &n in &self.nodes {
                for m in &g.members {
                    values.push(m.as_deref().and_then(|c| value(n, c)).unwrap_or(missing));
                }
            }
            let comp_names = g.members.iter().enumerate().map(|(i, m)| component_label(g, i, m)).collect();
            self.point_data.push(DataArray { name: array_name, comps: comp_names, values });
        }
    }

    /// Contact results of unilateral conditions as three point fields:
    /// `contact_status` (1 closed, 0 open, NaN where no condition acts),
    /// `contact_gap` and `contact_pressure`. The arrays are per node of the
    /// node table (`nodes[i]` has `closed[i]`, `gap[i]`, `pressure[i]`);
    /// nodes outside the mesh are ignored.
    pub fn add_contact(&mut self, nodes: &[usize], closed: &[bool], gap: &[f64], pressure: &[f64]) -> Result<()> {
        if closed.len() != nodes.len() || gap.len() != nodes.len() || pressure.len() != nodes.len() {
            return err(format!(
                "contact arrays have different lengths (nodes {}, status {}, gap {}, pressure {})",
                nodes.len(),
                closed.len(),
                gap.len(),
                pressure.len()
            ));
        }
        let np = self.n_points();
        let (mut st, mut g, mut p) = (vec![f64::NAN; np], vec![f64::NAN; np], vec![f64::NAN; np]);
        for (i, &n) in nodes.iter().enumerate() {
            if let Some(k) = self.point_index(n) {
                st[k] = if closed[i] { 1.0 } else { 0.0 };
                g[k] = gap[i];
                p[k] = pressure[i];
            }
        }
        for (name, values) in [("contact_status", st), ("contact_gap", g), ("contact_pressure", p)] {
            self.point_data.push(DataArray { name: name.into(), comps: vec![], values });
        }
        Ok(())
    }

    /// The cell of an element (same type, same nodes in the same order).
    pub fn cell_lookup(&self) -> HashMap<(ElemType, &[usize]), usize> {
        self.cells.iter().enumerate().map(|(i, (t, c))| ((*t, c.as_slice()), i)).collect()
    }

    pub fn add_cell_array(&mut self, a: DataArray) -> Result<()> {
        if a.values.len() != self.n_cells() * a.ncomp() {
            return err(format!("cell array {} has {} values for {} cells", a.name, a.values.len(), self.n_cells()));
        }
        self.cell_data.push(a);
        Ok(())
    }

    /// The `.vtu` document.
    pub fn to_xml(&self) -> String {
        let mut s = String::new();
        s.push_str("<?xml version=\"1.0\"?>\n");
        s.push_str(
            "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n",
        );
        s.push_str("<UnstructuredGrid>\n");
        let _ = writeln!(s, "<Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">", self.n_points(), self.n_cells());
        s.push_str("<PointData>\n");
        for a in &self.point_data {
            data_array(&mut s, a);
        }
        s.push_str("</PointData>\n<CellData>\n");
        for a in &self.cell_data {
            data_array(&mut s, a);
        }
        s.push_str("</CellData>\n<Points>\n");
        let xyz: Vec<f64> = self.coords.iter().flatten().copied().collect();
        s.push_str("<DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" format=\"binary\">");
        s.push_str(&b64(xyz.iter().flat_map(|v| v.to_le_bytes())));
        s.push_str("</DataArray>\n</Points>\n<Cells>\n");
        let (mut conn, mut offsets, mut types) = (Vec::<i64>::new(), Vec::<i64>::new(), Vec::<u8>::new());
        for (ty, nodes) in &self.cells {
            let (code, order) = vtk_cell(*ty);
            conn.extend(order.iter().map(|&k| self.point_of[&nodes[k]] as i64));
            offsets.push(conn.len() as i64);
            types.push(code);
        }
        for (name, v) in [("connectivity", &conn), ("offsets", &offsets)] {
            let _ = write!(s, "<DataArray type=\"Int64\" Name=\"{}\" format=\"binary\">", name);
            s.push_str(&b64(v.iter().flat_map(|x| x.to_le_bytes())));
            s.push_str("</DataArray>\n");
        }
        s.push_str("<DataArray type=\"UInt8\" Name=\"types\" format=\"binary\">");
        s.push_str(&b64(types.iter().copied()));
        s.push_str("</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
        s
    }

    pub fn write(&self, path: &Path) -> Result<()> {
        write_file(path, self.to_xml().as_bytes())
    }
}

/// One vector group or scalar of a nodal field.
#[derive(Debug, Clone, PartialEq)]
struct Group {
    stem: String,
    vector: bool,
    /// Component names, X Y Z for a vector (None where absent).
    members: Vec<Option<String>>,
}

fn component_label(g: &Group, i: usize, m: &Option<String>) -> String {
    match m {
        Some(c) => c.clone(),
        None => format!("{}{}", g.stem, ["X", "Y", "Z"][i.min(2)]),
    }
}

/// Group `<S>X <S>Y <S>Z` components into vectors (at least two present),
/// in the order the first member appears; everything else is a scalar.
fn split_components(comps: &[String]) -> Vec<Group> {
    let mut out: Vec<Group> = Vec::new();
    for c in comps {
        let stem = c.strip_suffix(['X', 'Y', 'Z']).filter(|s| !s.is_empty());
        let siblings = stem.map(|s| ["X", "Y", "Z"].iter().filter(|x| comps.contains(&format!("{}{}", s, x))).count());
        match (stem, siblings) {
            (Some(s), Some(k)) if k >= 2 => {
                if !out.iter().any(|g| g.vector && g.stem == s) {
                    let members = ["X", "Y", "Z"]
                        .iter()
                        .map(|x| Some(format!("{}{}", s, x)).filter(|n| comps.contains(n)))
                        .collect();
                    out.push(Group { stem: s.to_string(), vector: true, members });
                }
            }
            _ => out.push(Group { stem: c.clone(), vector: false, members: vec![Some(c.clone())] }),
        }
    }
    out
}

fn data_array(s: &mut String, a: &DataArray) {
    let _ = write!(s, "<DataArray type=\"Float64\" Name=\"{}\" NumberOfComponents=\"{}\"", escape(&a.name), a.ncomp());
    if a.comps.len() > 1 {
        for (i, c) in a.comps.iter().enumerate() {
            let _ = write!(s, " ComponentName{}=\"{}\"", i, escape(c));
        }
    }
    s.push_str(" format=\"binary\">");
    s.push_str(&b64(a.values.iter().flat_map(|v| v.to_le_bytes())));
    s.push_str("</DataArray>\n");
}

/// VTK's inline binary: base64 of (byte count as UInt64, then the data),
/// encoded as one stream.
fn b64(bytes: impl Iterator<Item = u8>) -> String {
    let data: Vec<u8> = bytes.collect();
    let mut all = (data.len() as u64).to_le_bytes().to_vec();
    all.extend_from_slice(&data);
    base64::engine::general_purpose::STANDARD.encode(all)
}

/// A `.pvd` collection: (time, file) pairs, files relative to the `.pvd`.
pub fn pvd_xml(steps: &[(f64, String)]) -> String {
    let mut s = String::from("<?xml version=\"1.0\"?>\n");
    s.push_str("<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n<Collection>\n");
    for (t, f) in steps {
        let _ = writeln!(s, "<DataSet timestep=\"{:e}\" group=\"\" part=\"0\" file=\"{}\"/>", t, escape(f.as_str()));
    }
    s.push_str("</Collection>\n</VTKFile>\n");
    s
}

pub fn write_pvd(path: &Path, steps: &[(f64, String)]) -> Result<()> {
    write_file(path, pvd_xml(steps).as_bytes())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn s(v: &[&str]) -> Vec<String> {
        v.iter().map(|x| x.to_string()).collect()
    }

    #[test]
    fn displacements_become_one_vector_and_rotations_stay_scalars() {
        let g = split_components(&s(&["UX", "UY", "RZ"]));
        assert_eq!(g.len(), 2);
        assert!(g[0].vector && g[0].stem == "U" && g[0].members[2].is_none());
        assert!(!g[1].vector && g[1].stem == "RZ");
        assert_eq!(split_components(&s(&["T"]))[0].stem, "T");
    }

    #[test]
    fn base64_carries_the_byte_count_first() {
        let out = base64::engine::general_purpose::STANDARD.decode(b64([1u8, 2, 3].into_iter())).unwrap();
        assert_eq!(out, vec![3, 0, 0, 0, 0, 0, 0, 0, 1, 2, 3]);
    }
}
