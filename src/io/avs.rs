//! AVS UCD (Unstructured Cell Data) ASCII files: nodes, cells, node data,
//! cell data and model data (global values such as the time). Several
//! structures may follow one another in a file (one per time step); each
//! is read on its own, from a byte offset the caller keeps.
//!
//! Cells are linear (pt, line, tri, quad, tet, prism, hex): the corner
//! nodes of quadratic elements are written. Node order is gibi's, which
//! for these types is the one AVS documents. Numbers are written in the
//! shortest form that reads back to the same f64.

use super::{append_file, err, read_file, write_file, IoError, Result};
use crate::fem::mesh::ElemType;
use std::collections::HashMap;
use std::fmt::Write;
use std::path::Path;

/// One UCD structure. Node and cell numbers are 0-based indices.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Ucd {
    pub coords: Vec<[f64; 3]>,
    pub cells: Vec<Cell>,
    /// (label, one value per node).
    pub node_data: Vec<(String, Vec<f64>)>,
    /// (label, one value per cell).
    pub cell_data: Vec<(String, Vec<f64>)>,
    /// (label, value), e.g. ("time", t).
    pub model_data: Vec<(String, f64)>,
}

#[derive(Debug, Clone, PartialEq)]
pub struct Cell {
    pub material: i64,
    pub ty: ElemType,
    pub nodes: Vec<usize>,
}

const TYPES: [(ElemType, &str); 7] = [
    (ElemType::Poi1, "pt"),
    (ElemType::Seg2, "line"),
    (ElemType::Tri3, "tri"),
    (ElemType::Qua4, "quad"),
    (ElemType::Tet4, "tet"),
    (ElemType::Pri6, "prism"),
    (ElemType::Cub8, "hex"),
];

/// The linear type a cell is written as (quadratic ones by their corners).
pub fn linear(ty: ElemType) -> ElemType {
    match ty {
        ElemType::Seg3 => ElemType::Seg2,
        ElemType::Tri6 => ElemType::Tri3,
        ElemType::Qua8 => ElemType::Qua4,
        t => t,
    }
}

fn type_word(ty: ElemType) -> &'static str {
    TYPES.iter().find(|(t, _)| *t == linear(ty)).map_or("pt", |(_, w)| w)
}

/// The text of one structure.
pub fn to_text(u: &Ucd) -> String {
    let mut s = String::from("# AVS UCD written by gibi\n");
    let (nd, cd, md) = (u.node_data.len(), u.cell_data.len(), u.model_data.len());
    let _ = writeln!(s, "{} {} {} {} {}", u.coords.len(), u.cells.len(), nd, cd, md);
    for (i, x) in u.coords.iter().enumerate() {
        let _ = writeln!(s, "{} {:e} {:e} {:e}", i + 1, x[0], x[1], x[2]);
    }
    for (i, c) in u.cells.iter().enumerate() {
        let _ = write!(s, "{} {} {}", i + 1, c.material, type_word(c.ty));
        for n in c.nodes.iter().take(linear(c.ty).nodes()) {
            let _ = write!(s, " {}", n + 1);
        }
        s.push('\n');
    }
    let block = |s: &mut String, data: &[(String, Vec<f64>)], n: usize| {
        if data.is_empty() {
            return;
        }
        let _ = writeln!(s, "{}{}", data.len(), " 1".repeat(data.len()));
        for (label, _) in data {
            let _ = writeln!(s, "{}, none", label);
        }
        for i in 0..n {
            let _ = write!(s, "{}", i + 1);
            for (_, v) in data {
                let _ = write!(s, " {:e}", v[i]);
            }
            s.push('\n');
        }
    };
    block(&mut s, &u.node_data, u.coords.len());
    block(&mut s, &u.cell_data, u.cells.len());
    let model: Vec<(String, Vec<f64>)> = u.model_data.iter().map(|(l, v)| (l.clone(), vec![*v])).collect();
    block(&mut s, &model, 1);
    s
}

/// Write one structure, after those already in the file when `append`.
pub fn write(path: &Path, u: &Ucd, append: bool) -> Result<()> {
    let text = to_text(u);
    if append {
        append_file(path, text.as_bytes())
    } else {
        write_file(path, text.as_bytes())
    }
}

/// Read the structure of `path` that starts at byte `pos` (see
/// [`parse_at`]). Format errors do not name the path: the caller names the
/// file as its user wrote it.
pub fn read_at(path: &Path, pos: usize, line: usize) -> Result<Option<(Ucd, usize, usize)>> {
    let bytes = read_file(path)?;
    let text = String::from_utf8_lossy(&bytes);
    if pos > text.len() || !text.is_char_boundary(pos) {
        return Ok(None);
    }
    parse_at(&text, pos, line)
}

/// The significant lines of a text from a byte offset: comments ('#')
/// and blank lines are passed over; positions are kept for errors and for
/// the next structure.
struct Lines<'a> {
    text: &'a str,
    pos: usize,
    line: usize,
}

impl<'a> Lines<'a> {
    /// The next significant line, split in words, with its number.
    fn next(&mut self, what: &str) -> Result<(usize, Vec<&'a str>)> {
        loop {
            if self.pos >= self.text.len() {
                return err(format!("the file ends after line {} where {} was expected", self.line, what));
            }
            let rest = &self.text[self.pos..];
            let end = rest.find('\n').map_or(rest.len(), |i| i + 1);
            let l = &rest[..end];
            self.pos += end;
            self.line += 1;
            let t = l.trim();
            if !t.is_empty() && !t.starts_with('#') {
                return Ok((
                    self.line,
                    t.split(|c: char| c.is_whitespace() || c == ',').filter(|w| !w.is_empty()).collect(),
                ));
            }
        }
    }

    /// Whether only comments and blank lines are left.
    fn at_end(&self) -> bool {
        self.text[self.pos..].lines().all(|l| l.trim().is_empty() || l.trim().starts_with('#'))
    }
}

fn num<T: std::str::FromStr>(w: Option<&&str>, line: usize, what: &str) -> Result<T> {
    w.and_then(|w| w.parse().ok()).ok_or_else(|| IoError(format!("line {}: expected {}", line, what)))
}

fn real(w: Option<&&str>, line: usize, what: &str) -> Result<f64> {
    let x: f64 = num(w, line, what)?;
    if !x.is_finite() {
        return err(format!("line {}: {} is not finite", line, what));
    }
    Ok(x)
}

/// Parse the structure that starts at byte `pos` (line `line` before it).
/// Returns it with the byte offset and line number where the next one
/// starts, or None when only comments are left.
pub fn parse_at(text: &str, pos: usize, line: usize) -> Result<Option<(Ucd, usize, usize)>> {
    let mut ls = Lines { text, pos, line };
    if ls.at_end() {
        return Ok(None);
    }
    let (l, w) = ls.next("the counts line")?;
    let count = |k: usize, what: &str| num::<usize>(w.get(k), l, what);
    let (nn, nc) = (count(0, "the number of nodes")?, count(1, "the number of cells")?);
    let (nd, cd, md) =
        (count(2, "the node data count")?, count(3, "the cell data count")?, count(4, "the model data count")?);
    let mut u = Ucd::default();
    let mut ids: HashMap<i64, usize> = HashMap::new();
    for _ in 0..nn {
        let (l, w) = ls.next("a node")?;
        let id: i64 = num(w.first(), l, "a node number")?;
        let x = [real(w.get(1), l, "x")?, real(w.get(2), l, "y")?, real(w.get(3), l, "z")?];
        if ids.insert(id, u.coords.len()).is_some() {
            return err(format!("line {}: node {} is defined twice", l, id));
        }
        u.coords.push(x);
    }
    for _ in 0..nc {
        let (l, w) = ls.next("a cell")?;
        let _: i64 = num(w.first(), l, "a cell number")?;
        let material: i64 = num(w.get(1), l, "a material number")?;
        let word = w.get(2).map(|s| s.to_ascii_lowercase()).unwrap_or_default();
        let ty = TYPES
            .iter()
            .find(|(_, n)| *n == word)
            .map(|(t, _)| *t)
            .ok_or_else(|| IoError(format!("line {}: expected a cell type (pt line tri quad tet prism hex)", l)))?;
        if w.len() != 3 + ty.nodes() {
            return err(format!(
                "line {}: a {} cell has {} nodes, found {}",
                l,
                TYPES.iter().find(|t| t.0 == ty).map_or("", |t| t.1),
                ty.nodes(),
                w.len().saturating_sub(3)
            ));
        }
        let mut nodes = Vec::with_capacity(ty.nodes());
        for k in 3..w.len() {
            let id: i64 = num(w.get(k), l, "a node number")?;
            nodes.push(*ids.get(&id).ok_or_else(|| IoError(format!("line {}: node {} is not defined", l, id)))?);
        }
        u.cells.push(Cell { material, ty, nodes });
    }
    u.node_data = data_block(&mut ls, nd, nn, "node")?;
    u.cell_data = data_block(&mut ls, cd, nc, "cell")?;
    u.model_data = data_block(&mut ls, md, 1, "model")?.into_iter().map(|(l, v)| (l, v[0])).collect();
    Ok(Some((u, ls.pos, ls.line)))
}

/// A data block: "ncomp size…", one "label, unit" per component, then one
/// line per item (its number, then the values; model data may omit it).
/// A component of size s > 1 gives labels label_1 … label_s.
fn data_block(ls: &mut Lines, declared: usize, items: usize, kind: &str) -> Result<Vec<(String, Vec<f64>)>> {
    if declared == 0 {
        return Ok(vec![]);
    }
    let (l, w) = ls.next(&format!("the {} data header", kind))?;
    let ncomp: usize = num(w.first(), l, "a number of components")?;
    if ncomp == 0 || w.len() != 1 + ncomp {
        return err(format!("line {}: expected the number of {} components then the size of each", l, kind));
    }
    let mut sizes = Vec::new();
    for k in 1..=ncomp {
        let s: usize = num(w.get(k), l, "a component size")?;
        if s == 0 || s > 9 {
            return err(format!("line {}: a component size must be from 1 to 9", l));
        }
        sizes.push(s);
    }
    let mut labels = Vec::new();
    for s in &sizes {
        let (l, w) = ls.next("a component label")?;
        let name = w.first().ok_or_else(|| IoError(format!("line {}: expected a label", l)))?;
        let name: String = name.chars().filter(|c| c.is_ascii_alphanumeric() || *c == '_').collect();
        if name.is_empty() {
            return err(format!("line {}: a label must have letters or digits", l));
        }
        // Field components are Gibiane component names (upper case);
        // global values keep their label as written ('time').
        let name = if kind == "model" { name } else { name.to_uppercase() };
        if *s == 1 {
            labels.push(name);
        } else {
            labels.extend((1..=*s).map(|k| format!("{}_{}", name, k)));
        }
    }
    let width = labels.len();
    let mut cols = vec![Vec::new(); width];
    for _ in 0..items {
        let (l, w) = ls.next(&format!("{} data values", kind))?;
        let skip = match w.len() {
            n if n == width + 1 => 1,
            n if n == width && kind == "model" => 0,
            n => return err(format!("line {}: expected a number and {} values, found {} words", l, width, n)),
        };
        if skip == 1 {
            let _: i64 = num(w.first(), l, "an item number")?;
        }
        for (k, c) in cols.iter_mut().enumerate() {
            c.push(real(w.get(skip + k), l, "a value")?);
        }
    }
    Ok(labels.into_iter().zip(cols).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample() -> Ucd {
        Ucd {
            coords: vec![[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0 / 3.0, 0.0]],
            cells: vec![Cell { material: 1, ty: ElemType::Tri3, nodes: vec![0, 1, 2] }],
            node_data: vec![("UX".into(), vec![0.1, -2e-17, 3.0])],
            cell_data: vec![("SMXX".into(), vec![1.5e8])],
            model_data: vec![("time".into(), 1.23456789)],
        }
    }

    #[test]
    fn two_structures_round_trip() {
        let text = to_text(&sample()) + &to_text(&sample());
        let (a, pos, line) = parse_at(&text, 0, 0).unwrap().unwrap();
        assert_eq!(a, sample());
        let (b, pos, line) = parse_at(&text, pos, line).unwrap().unwrap();
        assert_eq!(b, sample());
        assert!(parse_at(&text, pos, line).unwrap().is_none());
    }

    #[test]
    fn errors_give_the_line() {
        let text = to_text(&sample()).replace("1 1 tri 1 2 3", "1 1 tri 1 2 SECRET");
        let e = parse_at(&text, 0, 0).unwrap_err().0;
        assert_eq!(e, "line 6: expected a node number");
        let e = parse_at("2 0 0 0 0\n1 0 0 0\n", 0, 0).unwrap_err().0;
        assert!(e.starts_with("the file ends after line 2"), "{}", e);
    }
}
