//! Nastran bulk data: GRID points, elements by property, single-point
//! constraints, nodal forces, moments and temperatures, RBE2 rigid
//! elements; written as GRID and element cards.
//!
//! The three field layouts are read: small (8-character fields), large
//! (16-character fields, card name ending in '*') and free (commas), with
//! continuation lines. Reals may use Nastran's short exponent (1.5-3 for
//! 1.5E-3). Written files use large fields for GRID coordinates (ten
//! significant digits) and small fields for elements. Coordinate systems
//! (CORD2R…) are not read: coordinates are taken as given.

use super::{err, read_file, write_file, IoError, Result};
use crate::fem::mesh::ElemType;
use std::collections::BTreeMap;
use std::fmt::Write;
use std::path::Path;

/// A bulk data deck as read. Node references are GRID ids.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Bulk {
    /// GRID id -> coordinates, in file order.
    pub grids: Vec<(i64, [f64; 3])>,
    /// (property id, type, GRID ids in gibi's node order).
    pub elements: Vec<(i64, ElemType, Vec<i64>)>,
    /// SPC/SPC1 set id -> constrained GRID ids.
    pub spcs: BTreeMap<i64, Vec<i64>>,
    /// FORCE / MOMENT set id -> (GRID id, vector).
    pub forces: BTreeMap<i64, Vec<(i64, [f64; 3])>>,
    pub moments: BTreeMap<i64, Vec<(i64, [f64; 3])>>,
    /// TEMP set id -> (GRID id, temperature).
    pub temperatures: BTreeMap<i64, Vec<(i64, f64)>>,
    /// RBE2 element id -> independent GRID then dependent ones.
    pub rbe2: BTreeMap<i64, Vec<i64>>,
}

/// One card: its name, data fields (field 2 on, continuation markers
/// removed) and the line it starts on.
struct Card {
    name: String,
    fields: Vec<String>,
    line: usize,
}

/// Element cards: name, type, number of grids read, gibi's order of them.
const ELEMENTS: [(&str, ElemType, &[usize]); 13] = [
    ("CBAR", ElemType::Seg2, &[0, 1]),
    ("CBEAM", ElemType::Seg2, &[0, 1]),
    ("CROD", ElemType::Seg2, &[0, 1]),
    ("CTRIA3", ElemType::Tri3, &[0, 1, 2]),
    ("CTRIA6", ElemType::Tri6, &[0, 3, 1, 4, 2, 5]),
    ("CQUAD4", ElemType::Qua4, &[0, 1, 2, 3]),
    ("CQUAD8", ElemType::Qua8, &[0, 4, 1, 5, 2, 6, 3, 7]),
    ("CTETRA", ElemType::Tet4, &[0, 1, 2, 3]),
    ("CPENTA", ElemType::Pri6, &[0, 1, 2, 3, 4, 5]),
    ("CHEXA", ElemType::Cub8, &[0, 1, 2, 3, 4, 5, 6, 7]),
    ("CTRIAR", ElemType::Tri3, &[0, 1, 2]),
    ("CQUADR", ElemType::Qua4, &[0, 1, 2, 3]),
    ("CSHEAR", ElemType::Qua4, &[0, 1, 2, 3]),
];

/// Read a bulk data file. Format errors do not name the path: the caller
/// names the file as its user wrote it.
pub fn read(path: &Path) -> Result<Bulk> {
    parse(&String::from_utf8_lossy(&read_file(path)?))
}

pub fn parse(text: &str) -> Result<Bulk> {
    let mut b = Bulk::default();
    for c in cards(text)? {
        let at = |e: IoError| IoError(format!("line {} ({} card): {}", c.line, c.name, e.0));
        read_card(&mut b, &c).map_err(at)?;
    }
    Ok(b)
}

fn read_card(b: &mut Bulk, c: &Card) -> Result<()> {
    let f = &c.fields;
    match c.name.as_str() {
        "GRID" => b.grids.push((int(f, 0, "the GRID id")?, [real(f, 2)?, real(f, 3)?, real(f, 4)?])),
        "SPC1" => {
            let sid = int(f, 0, "the set id")?;
            let ids = id_list(&f[2.min(f.len())..])?;
            b.spcs.entry(sid).or_default().extend(ids);
        }
        "SPC" => {
            let sid = int(f, 0, "the set id")?;
            // Up to two (grid, components, value) triplets.
            for k in [1, 4] {
                if f.get(k).is_some_and(|s| !s.is_empty()) {
                    b.spcs.entry(sid).or_default().push(int(f, k, "a GRID id")?);
                }
            }
        }
        "FORCE" | "MOMENT" => {
            let (sid, g) = (int(f, 0, "the set id")?, int(f, 1, "a GRID id")?);
            let s = real(f, 3)?;
            let v = [s * real(f, 4)?, s * real(f, 5)?, s * real(f, 6)?];
            let map = if c.name == "FORCE" { &mut b.forces } else { &mut b.moments };
            map.entry(sid).or_default().push((g, v));
        }
        "TEMP" => {
            let sid = int(f, 0, "the set id")?;
            for k in [1, 3, 5] {
                if f.get(k).is_some_and(|s| !s.is_empty()) {
                    let t = real(f, k + 1)?;
                    b.temperatures.entry(sid).or_default().push((int(f, k, "a GRID id")?, t));
                }
            }
        }
        "RBE2" => {
            let eid = int(f, 0, "the element id")?;
            let mut ids = vec![int(f, 1, "the independent GRID id")?];
            // GM1 … follow the components; a real at the end is ALPHA.
            for s in f.iter().skip(3).filter(|s| !s.is_empty()) {
                match s.parse::<i64>() {
                    Ok(g) => ids.push(g),
                    Err(_) if real_str(s).is_some() => {}
                    Err(_) => return err("expected a GRID id among the dependent points"),
                }
            }
            b.rbe2.insert(eid, ids);
        }
        name => {
            if let Some((_, ty, order)) = ELEMENTS.iter().find(|(n, _, _)| *n == name) {
                let pid = int(f, 1, "the property id")?;
                let mut g = Vec::with_capacity(order.len());
                for k in 0..order.len() {
                    g.push(int(f, 2 + k, "a GRID id")?);
                }
                b.elements.push((pid, *ty, order.iter().map(|&k| g[k]).collect()));
            }
            // Other cards (properties, materials, coordinate systems…)
            // carry nothing gibi reads.
        }
    }
    Ok(())
}

/// Ids of an SPC1 list: ids, or "id1 THRU id2".
fn id_list(f: &[String]) -> Result<Vec<i64>> {
    let f: Vec<&String> = f.iter().filter(|s| !s.is_empty()).collect();
    if f.len() == 3 && f[1].eq_ignore_ascii_case("THRU") {
        let (a, b) = (idv(f[0])?, idv(f[2])?);
        if b < a || b - a > 10_000_000 {
            return err("a THRU range must go up, by at most 10000000 ids");
        }
        return Ok((a..=b).collect());
    }
    f.iter().map(|s| idv(s)).collect()
}

fn idv(s: &str) -> Result<i64> {
    s.parse().map_err(|_| IoError("expected a GRID id".into()))
}

fn int(f: &[String], k: usize, what: &str) -> Result<i64> {
    f.get(k).and_then(|s| s.parse().ok()).ok_or_else(|| IoError(format!("field {}: expected {}", k + 2, what)))
}

/// A real field (blank is zero, as Nastran reads it).
fn real(f: &[String], k: usize) -> Result<f64> {
    let s = f.get(k).map_or("", String::as_str);
    if s.is_empty() {
        return Ok(0.0);
    }
    real_str(s).ok_or_else(|| IoError(format!("field {}: expected a real number", k + 2)))
}

/// A Nastran real: 1.5, 1.5E-3, 1.5D-3, or 1.5-3 (exponent without E).
fn real_str(s: &str) -> Option<f64> {
    let t = s.replace(['D', 'd'], "E");
    let x = t.parse::<f64>().ok().or_else(|| {
        let k = t.char_indices().skip(1).find(|&(i, ch)| (ch == '+' || ch == '-') && !t[..i].ends_with(['E', 'e']))?.0;
        format!("{}E{}", &t[..k], &t[k..]).parse().ok()
    })?;
    x.is_finite().then_some(x)
}

/// The bulk data cards of a file, continuation lines joined.
fn cards(text: &str) -> Result<Vec<Card>> {
    let bulk_start = text.lines().position(|l| l.trim_start().to_ascii_uppercase().starts_with("BEGIN BULK"));
    let mut out: Vec<Card> = Vec::new();
    for (i, raw) in text.lines().enumerate().skip(bulk_start.map_or(0, |k| k + 1)) {
        let line = expand_tabs(raw);
        let t = line.trim_end();
        if t.trim().is_empty() || t.starts_with('$') {
            continue;
        }
        if t.trim().to_ascii_uppercase().starts_with("ENDDATA") {
            break;
        }
        let (head, data) = split_fields(t);
        let cont = head.is_empty() || head.starts_with('+') || head.starts_with('*');
        if cont {
            match out.last_mut() {
                Some(c) => c.fields.extend(data),
                None => return err(format!("line {}: a continuation line with no card before it", i + 1)),
            }
        } else {
            let name = head.trim_end_matches('*').to_ascii_uppercase();
            if name.is_empty() || !name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
                return err(format!("line {}: expected a card name in the first field", i + 1));
            }
            out.push(Card { name, fields: data, line: i + 1 });
        }
    }
    Ok(out)
}

/// Field 1 and the data fields (2 to 9) of one line.
fn split_fields(t: &str) -> (String, Vec<String>) {
    if t.contains(',') {
        let mut f: Vec<String> = t.split(',').map(|s| s.trim().to_string()).collect();
        let head = f.remove(0);
        f.truncate(8);
        return (head, f);
    }
    let col = |a: usize, b: usize| t.get(a.min(t.len())..b.min(t.len())).unwrap_or("").trim().to_string();
    let head = col(0, 8);
    let large = head.ends_with('*');
    let (w, n) = if large { (16, 4) } else { (8, 8) };
    let data = (0..n).map(|k| col(8 + k * w, 8 + (k + 1) * w)).collect();
    (head, data)
}

fn expand_tabs(s: &str) -> String {
    if !s.contains('\t') {
        return s.to_string();
    }
    let mut out = String::new();
    for ch in s.chars() {
        if ch == '\t' {
            out.push(' ');
            while !out.len().is_multiple_of(8) {
                out.push(' ');
            }
        } else {
            out.push(ch);
        }
    }
    out
}

/// The card written for a type, with the order of its grids from gibi's.
fn card_for(ty: ElemType) -> Option<(&'static str, &'static [usize])> {
    let name = match ty {
        ElemType::Seg2 => "CROD",
        ElemType::Tri3 => "CTRIA3",
        ElemType::Tri6 => "CTRIA6",
        ElemType::Qua4 => "CQUAD4",
        ElemType::Qua8 => "CQUAD8",
        ElemType::Tet4 => "CTETRA",
        ElemType::Pri6 => "CPENTA",
        ElemType::Cub8 => "CHEXA",
        _ => return None,
    };
    let (_, _, order) = ELEMENTS.iter().find(|(n, _, _)| *n == name)?;
    Some((name, order))
}

/// Whether a type can be written.
pub fn writable(ty: ElemType) -> bool {
    card_for(ty).is_some()
}

/// A real in 16 characters, ten significant digits.
fn large_real(x: f64) -> String {
    format!("{:16.9E}", x)
}

/// Write GRIDs (ids 1..n) and elements (ids 1..m, property = the given
/// number). Element nodes are 0-based indices into `coords`.
pub fn write(path: &Path, coords: &[[f64; 3]], elements: &[(i64, ElemType, Vec<usize>)]) -> Result<()> {
    let mut s = String::from("$ Nastran bulk data written by gibi\nBEGIN BULK\n");
    for (i, x) in coords.iter().enumerate() {
        let _ = writeln!(s, "GRID*   {:>16}{:>16}{}{}*", i + 1, "", large_real(x[0]), large_real(x[1]));
        let _ = writeln!(s, "*       {}", large_real(x[2]));
    }
    for (e, (pid, ty, nodes)) in elements.iter().enumerate() {
        let Some((name, order)) = card_for(*ty) else {
            return err(format!("no Nastran card for {} elements", ty.name()));
        };
        // gibi's order -> Nastran's: the inverse of the read permutation.
        let mut grids = vec![0; order.len()];
        for (k, &src) in order.iter().enumerate() {
            grids[src] = nodes[k] + 1;
        }
        let mut fields: Vec<String> = vec![(e + 1).to_string(), pid.to_string()];
        fields.extend(grids.iter().map(|g| g.to_string()));
        let _ = write!(s, "{:<8}", name);
        for (k, f) in fields.iter().enumerate() {
            if k > 0 && k % 8 == 0 {
                s.push_str("+\n+       ");
            }
            let _ = write!(s, "{:>8}", f);
        }
        s.push('\n');
    }
    s.push_str("ENDDATA\n");
    write_file(path, s.as_bytes())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn three_layouts_and_short_exponents() {
        let text = "$ c\nBEGIN BULK\nGRID           1       0      1.      2.    3.-1\n\
GRID*                  2               0           1.5E0          -2.0D0*\n*              4.\n\
GRID,3,,0.,1.,0.\nCTRIA3         7       5       1       2       3\nSPC1           9  123456       1    THRU       3\n\
FORCE          4       2       0      2.      1.      0.      0.\nENDDATA\n";
        let b = parse(text).unwrap();
        assert_eq!(b.grids, vec![(1, [1.0, 2.0, 0.3]), (2, [1.5, -2.0, 4.0]), (3, [0.0, 1.0, 0.0])]);
        assert_eq!(b.elements, vec![(5, ElemType::Tri3, vec![1, 2, 3])]);
        assert_eq!(b.spcs[&9], vec![1, 2, 3]);
        assert_eq!(b.forces[&4], vec![(2, [2.0, 0.0, 0.0])]);
    }

    #[test]
    fn errors_name_the_line_and_field() {
        let e = parse("GRID           1       0      1.  SECRET      3.\n").unwrap_err().0;
        assert_eq!(e, "line 1 (GRID card): field 5: expected a real number");
        assert!(parse("+       1\n").is_err());
    }
}
