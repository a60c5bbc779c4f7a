//! The sides of a surface whose elements form a quadrangular grid, found
//! from connectivity alone (COTE).
//!
//! However the surface was built (DALL, TRAN, ROTA, a line taken from a
//! contour in any element order, pieces joined and merged), its
//! quadrilaterals are placed on an (i, j) grid by walking from element 1
//! across shared edges: element 1's first edge is the bottom (global
//! direction 0), its second edge the right (1), and so on turning like the
//! element. A neighbour across an edge of global direction `g` meets it on
//! one of its own local edges `k`, which therefore has direction `g + 2`;
//! that fixes the neighbour's turn. The cells must fill a rectangle once
//! each. Side 1 is the bottom row (element 1's first edge lies on it: the
//! initial line of a sweep), side 2 the right column, side 3 the top row
//! and side 4 the left column, each running in the contour's direction.
//! Degenerate edges (one node repeated, as a ROTA about an end of the line
//! leaves) are neither neighbours nor side elements, so such a surface has
//! three sides.

use super::extract::edges;
use super::{fail, MeshError};
use crate::fem::mesh::{ElemType, Part};
use std::collections::{HashMap, VecDeque};

const OP: &str = "COTE";

/// The four sides of a grid of QUA4 or QUA8 elements, each a list of
/// edges `(end, end)` or `(end, middle, end)` in contour order.
pub(crate) fn grid_sides(parts: &[&Part]) -> Result<[Vec<Vec<usize>>; 4], MeshError> {
    let ty = parts[0].ty;
    let elems: Vec<&[usize]> = parts.iter().flat_map(|p| p.elems()).collect();
    let local = edges(ty);
    let edge_of = |e: usize, k: usize| -> Vec<usize> { local[k].iter().map(|&i| elems[e][i]).collect() };
    let degenerate = |ed: &[usize]| ed[0] == ed[ed.len() - 1];
    let key = |ed: &[usize]| {
        let mut k = ed.to_vec();
        k.sort_unstable();
        k
    };
    let mut by_edge: HashMap<Vec<usize>, Vec<(usize, usize)>> = HashMap::new();
    for e in 0..elems.len() {
        for k in 0..4 {
            let ed = edge_of(e, k);
            if !degenerate(&ed) {
                by_edge.entry(key(&ed)).or_default().push((e, k));
            }
        }
    }
    // Per element: its turn (global direction of local edge 0), whether it
    // turns as element 1 does, and its cell.
    let mut place: Vec<Option<(usize, bool, i64, i64)>> = vec![None; elems.len()];
    let mut cells: HashMap<(i64, i64), usize> = HashMap::new();
    place[0] = Some((0, true, 0, 0));
    cells.insert((0, 0), 0);
    let mut queue = VecDeque::from([0usize]);
    let not_grid = |why: &str| fail(OP, format!("the surface is not a quadrangular grid ({why})"));
    while let Some(e) = queue.pop_front() {
        let (r, same, i, j) = place[e].expect("queued elements are placed");
        for k in 0..4 {
            let ed = edge_of(e, k);
            if degenerate(&ed) {
                continue;
            }
            let users = &by_edge[&key(&ed)];
            if users.len() > 2 {
                return not_grid("an edge is shared by more than two elements");
            }
            let Some(&(f, kf)) = users.iter().find(|&&(f, _)| f != e) else { continue };
            // A neighbour that runs along the shared edge the same way
            // turns the other way round (a mesh joined from pieces of
            // both orientations).
            let same_f = same == (edge_of(f, kf)[0] == ed[ed.len() - 1]);
            let g = global(r, same, k);
            let (di, dj) = [(0, -1), (1, 0), (0, 1), (-1, 0)][g];
            let rf = if same_f { (g + 2 + 4 - kf) % 4 } else { (g + 2 + kf) % 4 };
            let cell = (i + di, j + dj);
            match place[f] {
                Some(p0) if p0 != (rf, same_f, cell.0, cell.1) => {
                    return not_grid("its elements do not fit on rows and columns")
                }
                Some(_) => {}
                None => {
                    if cells.insert(cell, f).is_some() {
                        return not_grid("two elements fall on the same cell");
                    }
                    place[f] = Some((rf, same_f, cell.0, cell.1));
                    queue.push_back(f);
                }
            }
        }
    }
    if place.iter().any(Option::is_none) {
        return not_grid("its elements are not all connected by edges");
    }
    let (imin, imax) = (cells.keys().map(|c| c.0).min().unwrap_or(0), cells.keys().map(|c| c.0).max().unwrap_or(0));
    let (jmin, jmax) = (cells.keys().map(|c| c.1).min().unwrap_or(0), cells.keys().map(|c| c.1).max().unwrap_or(0));
    if ((imax - imin + 1) * (jmax - jmin + 1)) as usize != cells.len() {
        return not_grid("its elements do not fill a rectangle of rows and columns");
    }
    // The edge of global direction `g` of the element in `cell`, running
    // as element 1 turns.
    let side_edge = |cell: (i64, i64), g: usize| -> Option<Vec<usize>> {
        let e = cells[&cell];
        let (r, same, _, _) = place[e].expect("all placed");
        let k = (0..4).find(|&k| global(r, same, k) == g).expect("four directions");
        let mut ed = edge_of(e, k);
        if !same {
            ed.reverse();
        }
        (!degenerate(&ed)).then_some(ed)
    };
    let row = |j: i64, g: usize, up: bool| -> Vec<Vec<usize>> {
        let is: Vec<i64> = if up { (imin..=imax).collect() } else { (imin..=imax).rev().collect() };
        is.into_iter().filter_map(|i| side_edge((i, j), g)).collect()
    };
    let col = |i: i64, g: usize, up: bool| -> Vec<Vec<usize>> {
        let js: Vec<i64> = if up { (jmin..=jmax).collect() } else { (jmin..=jmax).rev().collect() };
        js.into_iter().filter_map(|j| side_edge((i, j), g)).collect()
    };
    Ok([row(jmin, 0, true), col(imax, 1, true), row(jmax, 2, false), col(imin, 3, false)])
}

/// Global direction of local edge `k` of an element of turn `r` that turns
/// as element 1 (`same`) or the other way.
fn global(r: usize, same: bool, k: usize) -> usize {
    if same {
        (r + k) % 4
    } else {
        (r + 4 - k) % 4
    }
}

/// Whether COTE reads this surface as a grid of quadrilaterals.
pub(crate) fn is_quad(ty: ElemType) -> bool {
    matches!(ty, ElemType::Qua4 | ElemType::Qua8)
}
