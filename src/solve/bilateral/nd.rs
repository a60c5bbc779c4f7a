//! Nested-dissection ordering through METIS (`METIS_NodeND`).
//!
//! faer only has AMD. On 3D meshes, and above all when the unknowns of a
//! contact face must be condensed (their second multipliers are eliminated
//! last, so every column whose subtree touches the face carries them), a
//! nested dissection gives much less fill: the separators are planes, not
//! the greedy cliques AMD ends with.

use crate::solve::error::SolveError;

/// Nested-dissection order of a symmetric graph given by its sorted upper
/// (or lower) pattern in CSC form, diagonal allowed: `perm[new] = old`.
pub fn order(n: usize, col_ptr: &[usize], row_idx: &[usize]) -> Result<Vec<usize>, SolveError> {
    if n == 0 {
        return Ok(Vec::new());
    }
    let too_big = || SolveError::Other("graph too large for METIS (32-bit indices)".into());
    // Full adjacency without the diagonal, as METIS wants it.
    let mut deg = vec![0usize; n];
    for c in 0..n {
        for &r in &row_idx[col_ptr[c]..col_ptr[c + 1]] {
            if r != c {
                deg[r] += 1;
                deg[c] += 1;
            }
        }
    }
    let mut xadj = Vec::with_capacity(n + 1);
    xadj.push(0usize);
    for &d in &deg {
        xadj.push(xadj.last().copied().unwrap_or(0) + d);
    }
    let mut next: Vec<usize> = xadj[..n].to_vec();
    let mut adj = vec![0usize; xadj[n]];
    for c in 0..n {
        for &r in &row_idx[col_ptr[c]..col_ptr[c + 1]] {
            if r != c {
                adj[next[r]] = c;
                next[r] += 1;
                adj[next[c]] = r;
                next[c] += 1;
            }
        }
    }
    let conv = |v: usize| metis_sys::idx_t::try_from(v).map_err(|_| too_big());
    let mut xadj: Vec<metis_sys::idx_t> = xadj.into_iter().map(conv).collect::<Result<_, _>>()?;
    let mut adjncy: Vec<metis_sys::idx_t> = adj.into_iter().map(conv).collect::<Result<_, _>>()?;
    let mut nv = conv(n)?;
    let mut perm = vec![0 as metis_sys::idx_t; n];
    let mut iperm = vec![0 as metis_sys::idx_t; n];
    let mut options = [0 as metis_sys::idx_t; metis_sys::METIS_NOPTIONS as usize];
    // SAFETY: METIS_SetDefaultOptions writes METIS_NOPTIONS entries.
    unsafe { metis_sys::METIS_SetDefaultOptions(options.as_mut_ptr()) };
    options[metis_sys::moptions_et_METIS_OPTION_NUMBERING as usize] = 0;
    // SAFETY: xadj has n + 1 entries, adjncy xadj[n] entries (a symmetric
    // graph without self loops), perm/iperm n entries, options
    // METIS_NOPTIONS; vwgt may be null. METIS reads only these.
    let rc = unsafe {
        metis_sys::METIS_NodeND(
            &mut nv,
            xadj.as_mut_ptr(),
            adjncy.as_mut_ptr(),
            std::ptr::null_mut(),
            options.as_mut_ptr(),
            perm.as_mut_ptr(),
            iperm.as_mut_ptr(),
        )
    };
    if rc != metis_sys::rstatus_et_METIS_OK {
        return Err(SolveError::Other(format!("METIS_NodeND failed (status {rc})")));
    }
    // METIS's perm is ours: perm[new] = old.
    Ok(perm.into_iter().map(|v| v as usize).collect())
}
