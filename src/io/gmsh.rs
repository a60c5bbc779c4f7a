//! Gmsh `.msh` reader: formats 2.2 and 4.1, ASCII.
//!
//! Hand-written rather than a crate: the one maintained Rust reader
//! (`mshio`) reads 4.1 only, and we want errors that name the line. The
//! format is a sequence of `$Section … $EndSection` blocks of
//! whitespace-separated numbers, so a token cursor that remembers its line
//! is all the machinery needed. Unknown sections are skipped, as Gmsh
//! itself does. Binary files are refused with a hint (`-format msh2`,
//! `Mesh.Binary = 0`): they are rare for meshes small enough to hand-drive.

use super::{err, IoError, Result};
use crate::fem::mesh::{ElemType, Mesh, Part};
use std::collections::{BTreeMap, HashMap};
use std::path::Path;

/// A physical group: dimension, tag and (if `$PhysicalNames` gave one) name.
#[derive(Debug, Clone, PartialEq)]
pub struct PhysicalGroup {
    pub dim: usize,
    pub tag: i64,
    pub name: Option<String>,
}

/// One element: gibi type, nodes as indices into [`GmshMesh::coords`] in
/// gibi's node order, and the physical groups `(dim, tag)` it belongs to.
#[derive(Debug, Clone, PartialEq)]
pub struct Element {
    pub ty: ElemType,
    pub nodes: Vec<usize>,
    pub physicals: Vec<(usize, i64)>,
}

/// A mesh as read: only the nodes some element uses, in node-tag order.
#[derive(Debug, Clone, Default)]
pub struct GmshMesh {
    pub version: String,
    pub coords: Vec<[f64; 3]>,
    /// Gmsh tag of each node of `coords`.
    pub node_tags: Vec<u64>,
    pub elements: Vec<Element>,
    /// Every physical group elements refer to, sorted by (dim, tag).
    pub groups: Vec<PhysicalGroup>,
}

impl GmshMesh {
    /// The elements of one physical group (node numbers index `coords`).
    pub fn group_mesh(&self, dim: usize, tag: i64) -> Mesh {
        to_mesh(self.elements.iter().filter(|e| e.physicals.contains(&(dim, tag))))
    }

    /// Every element of the file.
    pub fn all_mesh(&self) -> Mesh {
        to_mesh(self.elements.iter())
    }
}

/// Parts in order of first appearance of each type, elements in file order.
fn to_mesh<'a>(elems: impl Iterator<Item = &'a Element>) -> Mesh {
    let mut m = Mesh::default();
    for e in elems {
        match m.parts.iter_mut().find(|p| p.ty == e.ty) {
            Some(p) => p.conn.extend_from_slice(&e.nodes),
            None => m.parts.push(Part::with(e.ty, e.nodes.clone())),
        }
    }
    m
}

/// Gmsh element type → gibi type and, for each gibi node, the Gmsh node
/// position. Gmsh lists corners then mid-side nodes; gibi goes round the
/// boundary (SEG3 end-mid-end, TRI6 c1 m12 c2 m23 c3 m31, QUA8 c1 m12 c2
/// m23 c3 m34 c4 m41). Linear types share Gmsh's order.
fn gmsh_type(code: i64) -> std::result::Result<(ElemType, &'static [usize]), String> {
    Ok(match code {
        1 => (ElemType::Seg2, &[0, 1]),
        2 => (ElemType::Tri3, &[0, 1, 2]),
        3 => (ElemType::Qua4, &[0, 1, 2, 3]),
        4 => (ElemType::Tet4, &[0, 1, 2, 3]),
        5 => (ElemType::Cub8, &[0, 1, 2, 3, 4, 5, 6, 7]),
        6 => (ElemType::Pri6, &[0, 1, 2, 3, 4, 5]),
        8 => (ElemType::Seg3, &[0, 2, 1]),
        9 => (ElemType::Tri6, &[0, 3, 1, 4, 2, 5]),
        15 => (ElemType::Poi1, &[0]),
        16 => (ElemType::Qua8, &[0, 4, 1, 5, 2, 6, 3, 7]),
        7 => return Err("Gmsh element type 7 (5-node pyramid) has no gibi equivalent".into()),
        10 => {
            return Err("Gmsh element type 10 (9-node quadrangle) has no gibi equivalent: \
                        mesh with Mesh.SecondOrderIncomplete = 1 to get 8-node quadrangles (QUA8)"
                .into())
        }
        11 => return Err("Gmsh element type 11 (10-node tetrahedron) has no gibi equivalent".into()),
        17 => return Err("Gmsh element type 17 (20-node hexahedron) has no gibi equivalent".into()),
        c => return Err(format!("Gmsh element type {} has no gibi equivalent", c)),
    })
}

/// A token cursor over the text that knows the current line number.
struct Cursor<'a> {
    lines: std::iter::Enumerate<std::str::Lines<'a>>,
    line: &'a str,
    pos: usize,
    lineno: usize,
}

impl<'a> Cursor<'a> {
    fn new(text: &'a str) -> Self {
        Cursor { lines: text.lines().enumerate(), line: "", pos: 0, lineno: 0 }
    }

    fn at(&self, msg: impl std::fmt::Display) -> IoError {
        IoError(format!("line {}: {}", self.lineno, msg))
    }

    /// The next token, moving to later lines as needed.
    fn next_opt(&mut self) -> Option<&'a str> {
        loop {
            let rest = &self.line[self.pos..];
            let start = rest.len() - rest.trim_start().len();
            let rest = &rest[start..];
            if !rest.is_empty() {
                let len = rest.find(char::is_whitespace).unwrap_or(rest.len());
                self.pos += start + len;
                return Some(&rest[..len]);
            }
            let (i, l) = self.lines.next()?;
            self.line = l;
            self.pos = 0;
            self.lineno = i + 1;
        }
    }

    fn next(&mut self, what: &str) -> Result<&'a str> {
        self.next_opt().ok_or_else(|| self.at(format!("unexpected end of file, expected {}", what)))
    }

    fn num<T: std::str::FromStr>(&mut self, what: &str) -> Result<T> {
        let t = self.next(what)?;
        t.parse().map_err(|_| self.at(format!("expected {}, found {}", what, other(t))))
    }

    fn count(&mut self, what: &str) -> Result<usize> {
        let n: usize = self.num(what)?;
        // Counts size allocations: refuse absurd ones from corrupt files.
        if n > 100_000_000 {
            return Err(self.at(format!("{} = {} is not plausible", what, n)));
        }
        Ok(n)
    }

    /// The unread rest of the current line.
    fn rest_of_line(&mut self) -> &'a str {
        let r = self.line[self.pos..].trim();
        self.pos = self.line.len();
        r
    }

    fn expect(&mut self, word: &str) -> Result<()> {
        let t = self.next(word)?;
        if t != word {
            return Err(self.at(format!("expected {}, found {}", word, other(t))));
        }
        Ok(())
    }

    /// Skip an unknown section up to its end marker.
    fn skip_section(&mut self, name: &str) -> Result<()> {
        let end = format!("$End{}", &name[1..]);
        while let Some(t) = self.next_opt() {
            if t == end {
                return Ok(());
            }
        }
        Err(self.at(format!("unexpected end of file inside section {}", name)))
    }
}

/// What the sections build up before elements are resolved.
#[derive(Default)]
struct Reader {
    version: String,
    names: HashMap<(usize, i64), String>,
    /// (entity dim, entity tag) → physical tags (format 4.1).
    entity_physicals: HashMap<(usize, i64), Vec<i64>>,
    nodes: BTreeMap<u64, [f64; 3]>,
    /// Elements with node tags (resolved at the end).
    raw: Vec<RawElement>,
}

/// An element as read: node tags, physical groups, line (for errors).
struct RawElement {
    ty: ElemType,
    tags: Vec<u64>,
    physicals: Vec<(usize, i64)>,
    line: usize,
}

/// What was found instead of what a reader expected. Never the text
/// itself: the path may name a file that is not a mesh at all, and an
/// error must not show its content.
fn other(t: &str) -> String {
    match t.chars().count() {
        1 => "other text (1 character)".into(),
        n => format!("other text ({} characters)", n),
    }
}

/// Read a `.msh` file.
pub fn read(path: &Path) -> Result<GmshMesh> {
    let bytes = super::read_file(path)?;
    let text = String::from_utf8_lossy(&bytes);
    parse(&text).map_err(|e| IoError(format!("{}: {}", path.display(), e)))
}

/// Parse the text of a `.msh` file.
pub fn parse(text: &str) -> Result<GmshMesh> {
    let mut c = Cursor::new(text);
    let mut r = Reader::default();
    while let Some(tok) = c.next_opt() {
        match tok {
            "$MeshFormat" => mesh_format(&mut c, &mut r)?,
            _ if r.version.is_empty() => {
                return Err(c.at(format!("expected $MeshFormat, found {}: not a Gmsh mesh", other(tok))))
            }
            "$PhysicalNames" => physical_names(&mut c, &mut r)?,
            "$Entities" => entities(&mut c, &mut r)?,
            "$Nodes" if r.version.starts_with('4') => nodes_v4(&mut c, &mut r)?,
            "$Nodes" => nodes_v2(&mut c, &mut r)?,
            "$Elements" if r.version.starts_with('4') => elements_v4(&mut c, &mut r)?,
            "$Elements" => elements_v2(&mut c, &mut r)?,
            t if t.starts_with('$') && !t.starts_with("$End") => c.skip_section(t)?,
            t => return Err(c.at(format!("expected a section such as $Nodes or $Elements, found {}", other(t)))),
        }
    }
    if r.version.is_empty() {
        return err("not a Gmsh mesh: no $MeshFormat section");
    }
    finish(r)
}

fn mesh_format(c: &mut Cursor, r: &mut Reader) -> Result<()> {
    let v = c.next("the format version")?;
    let file_type: i64 = c.num("the file type (0 ASCII, 1 binary)")?;
    let _data_size: i64 = c.num("the data size")?;
    if file_type != 0 {
        return Err(c.at("binary .msh files are not supported: save as ASCII (gmsh -format msh41, Mesh.Binary = 0)"));
    }
    if !(v.starts_with("2.") || v == "4.1") {
        return Err(c.at("this Gmsh format version is not supported: save as 4.1 or 2.2"));
    }
    r.version = v.to_string();
    c.expect("$EndMeshFormat")
}

fn physical_names(c: &mut Cursor, r: &mut Reader) -> Result<()> {
    let n = c.count("the number of physical names")?;
    for _ in 0..n {
        let dim: usize = c.num("a physical dimension")?;
        let tag: i64 = c.num("a physical tag")?;
        let name = c.rest_of_line().trim_matches('"').to_string();
        r.names.insert((dim, tag), name);
    }
    c.expect("$EndPhysicalNames")
}

fn entities(c: &mut Cursor, r: &mut Reader) -> Result<()> {
    let mut counts = [0usize; 4];
    for (d, k) in counts.iter_mut().enumerate() {
        *k = c.count(
            ["the number of points", "the number of curves", "the number of surfaces", "the number of volumes"][d],
        )?;
    }
    for (dim, &n) in counts.iter().enumerate() {
        for _ in 0..n {
            let tag: i64 = c.num("an entity tag")?;
            // A point has its coordinates, other entities a bounding box.
            for _ in 0..if dim == 0 { 3 } else { 6 } {
                let _: f64 = c.num("a coordinate")?;
            }
            let np = c.count("the number of physical tags")?;
            let mut phys = Vec::with_capacity(np.min(64));
            for _ in 0..np {
                phys.push(c.num::<i64>("a physical tag")?.abs());
            }
            if dim > 0 {
                let nb = c.count("the number of bounding entities")?;
                for _ in 0..nb {
                    let _: i64 = c.num("a bounding entity tag")?;
                }
            }
            r.entity_physicals.insert((dim, tag), phys);
        }
    }
    c.expect("$EndEntities")
}

fn coords(c: &mut Cursor) -> Result<[f64; 3]> {
    Ok([c.num("a coordinate")?, c.num("a coordinate")?, c.num("a coordinate")?])
}

fn nodes_v2(c: &mut Cursor, r: &mut Reader) -> Result<()> {
    let n = c.count("the number of nodes")?;
    for _ in 0..n {
        let tag: u64 = c.num("a node tag")?;
        r.nodes.insert(tag, coords(c)?);
    }
    c.expect("$EndNodes")
}

fn nodes_v4(c: &mut Cursor, r: &mut Reader) -> Result<()> {
    let blocks = c.count("the number of node blocks")?;
    let _total = c.count("the number of nodes")?;
    let _min: u64 = c.num("the smallest node tag")?;
    let _max: u64 = c.num("the largest node tag")?;
    for _ in 0..blocks {
        let dim: usize = c.num("an entity dimension")?;
        let _tag: i64 = c.num("an entity tag")?;
        let parametric: i64 = c.num("the parametric flag")?;
        let n = c.count("the number of nodes in the block")?;
        let mut tags = Vec::with_capacity(n.min(4096));
        for _ in 0..n {
            tags.push(c.num::<u64>("a node tag")?);
        }
        for t in tags {
            r.nodes.insert(t, coords(c)?);
            if parametric == 1 {
                for _ in 0..dim.min(3) {
                    let _: f64 = c.num("a parametric coordinate")?;
                }
            }
        }
    }
    c.expect("$EndNodes")
}

fn element_nodes(c: &mut Cursor, code: i64) -> Result<(ElemType, Vec<u64>)> {
    let (ty, order) = gmsh_type(code).map_err(|m| c.at(m))?;
    let mut tags = Vec::with_capacity(order.len());
    for _ in 0..order.len() {
        tags.push(c.num::<u64>("a node tag")?);
    }
    Ok((ty, order.iter().map(|&k| tags[k]).collect()))
}

fn elements_v2(c: &mut Cursor, r: &mut Reader) -> Result<()> {
    let n = c.count("the number of elements")?;
    for _ in 0..n {
        let _tag: u64 = c.num("an element tag")?;
        let code: i64 = c.num("an element type")?;
        let ntags = c.count("the number of element tags")?;
        let mut tags = Vec::with_capacity(ntags.min(64));
        for _ in 0..ntags {
            tags.push(c.num::<i64>("an element tag")?);
        }
        let line = c.lineno;
        let (ty, nodes) = element_nodes(c, code)?;
        // The first tag is the physical group (0: none), of the element's
        // own dimension.
        let phys = tags.first().filter(|&&p| p != 0).map(|&p| vec![(ty.dim(), p)]).unwrap_or_default();
        r.raw.push(RawElement { ty, tags: nodes, physicals: phys, line });
    }
    c.expect("$EndElements")
}

fn elements_v4(c: &mut Cursor, r: &mut Reader) -> Result<()> {
    let blocks = c.count("the number of element blocks")?;
    let _total = c.count("the number of elements")?;
    let _min: u64 = c.num("the smallest element tag")?;
    let _max: u64 = c.num("the largest element tag")?;
    for _ in 0..blocks {
        let dim: usize = c.num("an entity dimension")?;
        let etag: i64 = c.num("an entity tag")?;
        let code: i64 = c.num("an element type")?;
        let n = c.count("the number of elements in the block")?;
        let phys: Vec<(usize, i64)> =
            r.entity_physicals.get(&(dim, etag)).map(|v| v.iter().map(|&p| (dim, p)).collect()).unwrap_or_default();
        for _ in 0..n {
            let _tag: u64 = c.num("an element tag")?;
            let line = c.lineno;
            let (ty, nodes) = element_nodes(c, code)?;
            r.raw.push(RawElement { ty, tags: nodes, physicals: phys.clone(), line });
        }
    }
    c.expect("$EndElements")
}

/// Keep the nodes elements use, number them, resolve group names.
fn finish(r: Reader) -> Result<GmshMesh> {
    let mut used: BTreeMap<u64, usize> = BTreeMap::new();
    for e in &r.raw {
        for t in &e.tags {
            if !r.nodes.contains_key(t) {
                return err(format!("line {}: element uses node {}, which $Nodes does not define", e.line, t));
            }
            used.insert(*t, 0);
        }
    }
    let mut m = GmshMesh { version: r.version, ..Default::default() };
    for (i, (t, idx)) in used.iter_mut().enumerate() {
        *idx = i;
        m.node_tags.push(*t);
        m.coords.push(r.nodes[t]);
    }
    let mut groups = std::collections::BTreeSet::new();
    for e in r.raw {
        groups.extend(e.physicals.iter().copied());
        m.elements.push(Element { ty: e.ty, nodes: e.tags.iter().map(|t| used[t]).collect(), physicals: e.physicals });
    }
    m.groups = groups
        .into_iter()
        .map(|(dim, tag)| PhysicalGroup { dim, tag, name: r.names.get(&(dim, tag)).cloned() })
        .collect();
    Ok(m)
}
