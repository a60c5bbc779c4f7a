//! Columns of numbers from a delimited text file (CSV), through the `csv`
//! crate: quoting and line endings are its job, not a hand-written split.

use super::{err, read_file, IoError, Result};
use std::path::Path;

/// Read the numeric columns of `path`, from line `first` (1-based) on,
/// fields separated by `sep`. Every row must have the same number of
/// fields; empty lines are skipped. Errors give the line and column and
/// never quote the file; they do not name the path either (the caller
/// names the file as its user wrote it).
pub fn read_columns(path: &Path, first: usize, sep: u8) -> Result<Vec<Vec<f64>>> {
    parse_columns(&read_file(path)?, first, sep)
}

pub fn parse_columns(bytes: &[u8], first: usize, sep: u8) -> Result<Vec<Vec<f64>>> {
    let mut rd = csv::ReaderBuilder::new()
        .has_headers(false)
        .delimiter(sep)
        .flexible(true)
        .trim(csv::Trim::All)
        .from_reader(bytes);
    let mut cols: Vec<Vec<f64>> = Vec::new();
    let mut rec = csv::ByteRecord::new();
    loop {
        let more = rd.read_byte_record(&mut rec).map_err(|e| {
            let line = e.position().map_or(String::new(), |p| format!("line {}: ", p.line()));
            IoError(format!("{}malformed CSV", line))
        })?;
        if !more {
            break;
        }
        let line = rec.position().map_or(0, |p| p.line() as usize);
        if line < first {
            continue;
        }
        // A trailing separator leaves an empty last field: not a column.
        let n = if rec.len() > 1 && rec.get(rec.len() - 1) == Some(b"") { rec.len() - 1 } else { rec.len() };
        if cols.is_empty() {
            cols = vec![Vec::new(); n];
        } else if n != cols.len() {
            return err(format!("line {}: {} fields where the first row read has {}", line, n, cols.len()));
        }
        for (k, field) in rec.iter().take(n).enumerate() {
            let x = std::str::from_utf8(field)
                .ok()
                .and_then(|f| number(f, sep))
                .ok_or_else(|| IoError(format!("line {}, column {}: not a number", line, k + 1)))?;
            if !x.is_finite() {
                return err(format!("line {}, column {}: not a finite number", line, k + 1));
            }
            cols[k].push(x);
        }
    }
    Ok(cols)
}

/// A number as Fortran-minded files write it (1.5D+03 too), or with a
/// decimal comma (French spreadsheets) when ',' is not the separator.
fn number(s: &str, sep: u8) -> Option<f64> {
    let s = if sep != b',' && !s.contains('.') { s.replacen(',', ".", 1) } else { s.to_string() };
    s.parse::<f64>().ok().or_else(|| s.replace(['D', 'd'], "E").parse().ok())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn columns_from_a_line_on() {
        let c = parse_columns(b"t;u\n0;1.5\n\n1;2.5D0;\n2;-0,25\n", 2, b';').unwrap();
        assert_eq!(c, vec![vec![0.0, 1.0, 2.0], vec![1.5, 2.5, -0.25]]);
        let e = parse_columns(b"0;1\n1;x9\n", 1, b';').unwrap_err().0;
        assert_eq!(e, "line 2, column 2: not a number");
        let e = parse_columns(b"0;1\n1\n", 1, b';').unwrap_err().0;
        assert!(e.starts_with("line 2: 1 fields"), "{}", e);
    }
}
