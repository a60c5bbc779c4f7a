//! MatrixMarket dumps of assembled matrices, with a companion `.dofs`
//! file naming each row, so a matrix can be inspected in Python (scipy's
//! `mmread`), Julia or Octave and related back to nodes and components.

use super::{write_file, Result};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// What one row/column of the matrix is.
#[derive(Debug, Clone, PartialEq)]
pub struct Unknown {
    /// Node number as gibi shows it (1-based).
    pub node: usize,
    /// Component (UX, RZ, …; LX for a multiplier).
    pub comp: String,
    /// Extra words (for multipliers: the condition's kind).
    pub note: String,
}

/// Sum repeated (row, col) entries; rows/cols are 0-based. Entries that
/// sum to exactly zero are kept: they are part of the pattern.
pub fn compress(mut triplets: Vec<(usize, usize, f64)>) -> Vec<(usize, usize, f64)> {
    triplets.sort_by_key(|&(i, j, _)| (i, j));
    let mut out: Vec<(usize, usize, f64)> = Vec::with_capacity(triplets.len());
    for (i, j, v) in triplets {
        match out.last_mut() {
            Some(last) if last.0 == i && last.1 == j => last.2 += v,
            _ => out.push((i, j, v)),
        }
    }
    out
}

/// The MatrixMarket text of an n×n matrix (`general`, 1-based, repeated
/// entries summed). `comments` become `%` lines after the banner.
pub fn matrix_market(n: usize, triplets: Vec<(usize, usize, f64)>, comments: &[String]) -> String {
    let entries = compress(triplets);
    let mut s = String::from("%%MatrixMarket matrix coordinate real general\n");
    for c in comments {
        for line in c.lines() {
            let _ = writeln!(s, "% {}", line);
        }
    }
    let _ = writeln!(s, "{} {} {}", n, n, entries.len());
    for (i, j, v) in entries {
        let _ = writeln!(s, "{} {} {:e}", i + 1, j + 1, v);
    }
    s
}

/// The `.dofs` companion: one line `row node component (note)` per row.
pub fn dofs_listing(unknowns: &[Unknown]) -> String {
    let mut s = String::from("% row node component\n");
    for (r, u) in unknowns.iter().enumerate() {
        let _ = write!(s, "{} {} {}", r + 1, u.node, u.comp);
        if !u.note.is_empty() {
            let _ = write!(s, " {}", u.note);
        }
        s.push('\n');
    }
    s
}

/// Write `path` and `path.dofs`.
pub fn write(path: &Path, triplets: Vec<(usize, usize, f64)>, unknowns: &[Unknown], comments: &[String]) -> Result<()> {
    write_file(path, matrix_market(unknowns.len(), triplets, comments).as_bytes())?;
    write_file(&dofs_path(path), dofs_listing(unknowns).as_bytes())
}

/// `file.mtx` → `file.mtx.dofs`.
pub fn dofs_path(path: &Path) -> PathBuf {
    let mut p = path.as_os_str().to_owned();
    p.push(".dofs");
    PathBuf::from(p)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn repeated_entries_are_summed() {
        let s = matrix_market(2, vec![(0, 0, 1.0), (1, 0, 2.0), (0, 0, 3.0)], &["two".into()]);
        assert_eq!(s, "%%MatrixMarket matrix coordinate real general\n% two\n2 2 2\n1 1 4e0\n2 1 2e0\n");
    }
}
