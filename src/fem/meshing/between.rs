//! `LIGNE ELEM 'COMPRIS' P1 P2`: the part of a line between two of its
//! points, described from P1 to P2 (from P1 to itself: once around a
//! closed line).

use super::query::line_chain;
use super::{fail, inve, orie, MeshError};
use crate::fem::mesh::{ElemType, Mesh, Nodes, Part};

const OP: &str = "ELEM";

/// The elements of `line` from node `p1` to node `p2`, walking the line in
/// its own direction (around a closed line, past its end if need be);
/// when `p2` comes before `p1` on an open line, the part between them is
/// returned run backwards, so it always starts at `p1`.
pub fn elem_compris(nodes: &Nodes, line: &Mesh, p1: usize, p2: usize) -> Result<Mesh, MeshError> {
    let parts: Vec<&Part> = line.parts.iter().filter(|p| !p.is_empty()).collect();
    let ty = match parts.first() {
        Some(p) if p.ty.dim() == 1 && parts.iter().all(|q| q.ty == p.ty) => p.ty,
        _ => return fail(OP, "'COMPRIS' takes the part of a line (SEG2 or SEG3 elements only)"),
    };
    // The line in order, head to tail (as ORIE puts it when it is not).
    let chain = match line_chain(OP, line) {
        Ok(c) => c,
        Err(_) => line_chain(OP, &orie(nodes, line, 3)?)?,
    };
    let step = if ty == ElemType::Seg3 { 2 } else { 1 };
    let corners: Vec<usize> = chain.iter().copied().step_by(step).collect();
    let n_el = corners.len() - 1;
    let closed = corners.first() == corners.last();
    let find = |p: usize| corners.iter().position(|&c| c == p);
    let (Some(i1), Some(i2)) = (find(p1), find(p2)) else {
        return fail(OP, "'COMPRIS': both points must be nodes of the line (ends of its elements)");
    };
    let elem = |k: usize| -> Vec<usize> { chain[k * step..=(k + 1) * step].to_vec() };
    // From a point to itself: once around a closed line, from that point.
    if p1 == p2 {
        if !closed {
            return fail(OP, "'COMPRIS': the two points are the same point and the line is open");
        }
        let conn = (0..n_el).flat_map(|j| elem((i1 + j) % n_el)).collect();
        return Ok(Mesh { parts: vec![Part::with(ty, conn)] });
    }
    let mut conn = Vec::new();
    let mut backwards = false;
    // Around a closed line both arcs join p1 to p2: take the shorter one
    // (forward on a tie), described from p1 to p2. A lip of a crack cut
    // out of the contour of a mirrored half (`CONT half ELEM 'COMPRIS'
    // tip end`) is the short arc whichever way that contour turns.
    let forward_len = (i2 + n_el - i1 % n_el) % n_el;
    if closed && forward_len > n_el - forward_len {
        // The arc from p2 to p1 in the line's direction, then run backwards.
        let mut k = i2 % n_el;
        loop {
            conn.extend(elem(k));
            if corners[k + 1] == p1 {
                break;
            }
            k = (k + 1) % n_el;
        }
        return inve(&Mesh { parts: vec![Part::with(ty, conn)] });
    }
    if i1 < i2 || closed {
        // Forward from p1 to p2, around the end of a closed line.
        let mut k = i1 % n_el;
        loop {
            conn.extend(elem(k));
            let end = corners[k + 1];
            if end == p2 {
                break;
            }
            k = (k + 1) % n_el;
        }
    } else {
        for k in i2..i1 {
            conn.extend(elem(k));
        }
        backwards = true;
    }
    let part = Mesh { parts: vec![Part::with(ty, conn)] };
    if backwards {
        inve(&part)
    } else {
        Ok(part)
    }
}
