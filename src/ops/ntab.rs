//! NTABLEAU: curves printed as a table on the output. The first column
//! gathers every abscissa of the curves (equal ones share a row), each
//! curve then gives a column of ordinates, blank where it has no point
//! at that abscissa. Colours, frame, date, page and logo options concern
//! a graphics device; gibi prints text and accepts them without effect.

use super::{Args, OpDef};
use crate::error::Result;
use crate::eval::Interp;
use crate::value::Value;
use crate::value::{fmt_float, Evolution};
use std::collections::HashMap;
use std::rc::Rc;

pub(crate) const OPS: &[OpDef] = &[OpDef {
    name: "NTABLEAU",
    signature: "NTAB EVOL ('TITR' MOT1) ('STITR' MOT2) ('TCOL' I MOT3 …) ('TLIG' J MOT4 …) ('TRILIG' I) ('TRICOL' J) (display options)",
    doc: "Prints the curves of EVOL as a table: column 1 the abscissas of all curves, then one column of ordinates per curve. 'TITR' and 'STITR' give a title and a subtitle, 'TCOL' I and 'TLIG' J the title of column I and of row J (from 1), 'TRILIG' I sorts the rows by the values of column I, 'TRICOL' J the ordinate columns by the values of row J. 'TEXCOU', 'LIGCOU', 'TITCOU', 'LOGCOU', 'COLCOU' (with an integer), 'NODATE', 'NOLIG', 'NOCENTER', 'PAGE', 'NOPAGE' and 'LOGO' are accepted and have no effect on text.",
    example: "ntab (evol 'MANU' (prog 0. 1.) (prog 2. 3.)) 'TITR' 'Table' ;",
    f: ntab,
}];

fn ntab(it: &mut Interp, a: &mut Args) -> Result<Vec<Value>> {
    let evol = a.req::<Rc<Evolution>>()?;
    let (mut title, mut subtitle) = (None, None);
    let mut col_titles: HashMap<usize, String> = HashMap::new();
    let mut row_titles: HashMap<usize, String> = HashMap::new();
    let (mut sort_rows, mut sort_cols) = (None, None);
    // Whole words: 'TITR' and 'TITCOU' share their first letters.
    while let Some(w) = a.word() {
        match w.to_uppercase().as_str() {
            "TITR" | "TITRE" => title = Some(a.req::<String>()?),
            "STITR" | "STITRE" => subtitle = Some(a.req::<String>()?),
            "TCOL" => {
                let i = a.req::<i64>()?;
                col_titles.insert(i.max(0) as usize, a.req::<String>()?);
            }
            "TLIG" => {
                let i = a.req::<i64>()?;
                row_titles.insert(i.max(0) as usize, a.req::<String>()?);
            }
            "TRILIG" => sort_rows = Some(a.req::<i64>()?),
            "TRICOL" => sort_cols = Some(a.req::<i64>()?),
            "TEXCOU" | "LIGCOU" | "TITCOU" | "LOGCOU" | "COLCOU" => {
                a.req::<i64>()?;
            }
            "NODATE" | "NOLIG" | "NOCENTER" | "PAGE" | "NOPAGE" | "LOGO" => {}
            other => return Err(a.err(format!("'{}' is not an option of NTABLEAU", other))),
        }
    }
    let curves = &evol.curves;
    // Rows: the abscissas in the order they first appear.
    let mut xs: Vec<f64> = Vec::new();
    for c in curves {
        for x in &c.x {
            if !xs.contains(x) {
                xs.push(*x);
            }
        }
    }
    let mut rows: Vec<Vec<Option<f64>>> = xs
        .iter()
        .map(|x| {
            let mut row = vec![Some(*x)];
            row.extend(curves.iter().map(|c| c.x.iter().position(|cx| cx == x).map(|k| c.y[k])));
            row
        })
        .collect();
    let ncols = curves.len() + 1;
    let col_name = |j: usize| -> String {
        col_titles.get(&(j + 1)).cloned().unwrap_or_else(|| match j {
            0 => curves.first().map(|c| c.x_name.clone()).unwrap_or_default(),
            _ => {
                let c = &curves[j - 1];
                if c.legend.is_empty() {
                    c.y_name.clone()
                } else {
                    c.legend.clone()
                }
            }
        })
    };
    let mut order: Vec<usize> = (0..ncols).collect();
    if let Some(i) = sort_rows {
        let i = index(a, i, ncols, "column")?;
        rows.sort_by(|p, q| key(p[i]).total_cmp(&key(q[i])));
    }
    if let Some(j) = sort_cols {
        let j = index(a, j, rows.len(), "row")?;
        order[1..].sort_by(|&p, &q| key(rows[j][p]).total_cmp(&key(rows[j][q])));
    }
    let cell = |v: Option<f64>| v.map(fmt_float).unwrap_or_default();
    let label = |r: usize| row_titles.get(&(r + 1)).cloned().unwrap_or_default();
    let mut widths: Vec<usize> = order.iter().map(|&j| col_name(j).chars().count()).collect();
    for row in &rows {
        for (w, &j) in widths.iter_mut().zip(&order) {
            *w = (*w).max(cell(row[j]).len());
        }
    }
    let lw = (0..rows.len()).map(|r| label(r).chars().count()).max().unwrap_or(0);
    let line = |first: String, cells: Vec<String>| {
        // Row titles, when there are any, take a column of their own.
        let mut s = if lw > 0 { format!("{:<lw$}", first) } else { String::new() };
        for (k, (c, w)) in cells.iter().zip(&widths).enumerate() {
            let sep = if k == 0 && lw == 0 { "" } else { " | " };
            s.push_str(&format!("{}{:>w$}", sep, c, w = *w));
        }
        s.trim_end().to_string()
    };
    for t in [title, subtitle].into_iter().flatten() {
        it.println(&t);
    }
    it.println(&line(String::new(), order.iter().map(|&j| col_name(j)).collect()));
    for (r, row) in rows.iter().enumerate() {
        it.println(&line(label(r), order.iter().map(|&j| cell(row[j])).collect()));
    }
    Ok(vec![])
}

/// Blank cells sort last.
fn key(v: Option<f64>) -> f64 {
    v.unwrap_or(f64::INFINITY)
}

fn index(a: &Args, i: i64, n: usize, what: &str) -> Result<usize> {
    if i < 1 || i as usize > n {
        return Err(a.err(format!("{} {} does not exist: the table has {} of them", what, i, n)));
    }
    Ok(i as usize - 1)
}
