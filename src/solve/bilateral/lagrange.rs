//! The doubled-multiplier system of Verpeaux & Charras (unilateral.md §2).
//!
//! Unknowns are numbered in a fixed *natural* numbering: primal unknowns
//! `0..n`, then the first multipliers `λ1_i = n + i`, then the second ones
//! `λ2_i = n + m + i`. The elimination order is a separate permutation
//! ([`super::ordering`]); keeping the natural numbering here lets the same
//! assembled pattern serve every ordering.
//!
//! For condition i with row c_i, scaling σ_i and block coefficient α_i:
//!
//! ```text
//!   rows (λ1, u, λ2):  [ −α    σc    α ]   rhs (σd, F, σd)
//!                      [ σcᵀ   K   σcᵀ ]
//!                      [  α    σc   −α ]
//! ```
//!
//! and the physical multiplier is λ = σ(λ1 + λ2).
//!
//! The pattern is assembled once, with a map from every source term (K
//! entry, condition coefficient, multiplier-block entry) to its slot in the
//! CSC value array, so that new values of the same structure are scattered
//! without rebuilding anything ([`Doubled::fill`]).

use crate::solve::error::SolveError;
use crate::solve::problem::Problem;

/// Marker for a source term that is not stored (lower-triangle K entry of
/// a symmetric matrix).
const NONE: u32 = u32::MAX;

/// Per-condition scaling of §2.2 (Cast3M's `assem2`): σ_i on the coupling
/// terms, α_i on the multiplier block.
#[derive(Debug, Clone, PartialEq)]
pub struct Scaling {
    pub sigma: Vec<f64>,
    pub alpha: Vec<f64>,
}

/// Computes σ and α from the largest |K| entry of each row (`row_max`,
/// assembled values) as spec §2.2 describes, ĉ_i = max(1, max|c|),
/// κ_i = 1.5 k_i, σ_i = κ_i/ĉ_i, α_i = 2κ_i, except that k_i is the
/// *smallest* row maximum among the condition's unknowns (that carry any
/// stiffness), where Cast3M takes the largest. For one unknown it is the
/// same. For a relation between a stiff and a soft unknown (a beam resting
/// on soil springs through RELA 'MINI'), the soft side is the compliance
/// the condition sees: scaled on the stiff side, releasing the condition
/// changes the condensed operator by k_soft/k_stiff only, which a ratio of
/// 10⁸–10⁹ (a steel beam on a fine mesh) makes indistinguishable from a
/// singular release, and a support in tension from one in compression.
/// Any α > 0 gives the same solution (§2.2). Fallback: the global max,
/// then 1.
pub fn scaling(p: &Problem, row_max: &[f64]) -> Scaling {
    let global = row_max.iter().fold(0.0f64, |a, &b| a.max(b));
    let mut sigma = Vec::with_capacity(p.conditions.len());
    let mut alpha = Vec::with_capacity(p.conditions.len());
    for c in &p.conditions {
        let mut k = c.terms.iter().map(|&(j, _)| row_max[j]).filter(|&r| r > 0.0).fold(f64::INFINITY, f64::min);
        if !k.is_finite() {
            k = 0.0;
        }
        // A condition on unknowns that carry no stiffness still needs a
        // multiplier block of the problem's order of magnitude.
        if k <= 0.0 {
            k = if global > 0.0 { global } else { 1.0 };
        }
        let chat = c.terms.iter().fold(1.0f64, |a, &(_, v)| a.max(v.abs()));
        let kappa = 1.5 * k;
        sigma.push(kappa / chat);
        alpha.push(2.0 * kappa);
    }
    Scaling { sigma, alpha }
}

/// Checks indices and finiteness of the data; everything downstream may
/// then index freely.
pub fn validate(p: &Problem) -> Result<(), SolveError> {
    let n = p.k.n;
    for &(i, j, v) in &p.k.entries {
        if i >= n || j >= n {
            return Err(SolveError::Other(format!("matrix entry ({i}, {j}) outside the {n} unknowns")));
        }
        if !v.is_finite() {
            return Err(SolveError::Other(format!("matrix entry ({i}, {j}) is not finite")));
        }
    }
    for (ci, c) in p.conditions.iter().enumerate() {
        if c.terms.is_empty() {
            // A row without unknowns makes the multiplier block singular.
            return Err(SolveError::DependentConditions { conditions: vec![ci] });
        }
        for &(j, v) in c.terms.iter().chain(c.dual.iter().flatten()) {
            if j >= n || !v.is_finite() {
                return Err(SolveError::Other(format!("condition {ci}: bad term on unknown {j}")));
            }
        }
        if let Some(dual) = &c.dual {
            if p.k.symmetric {
                return Err(SolveError::Other(format!(
                    "condition {ci} is non-associated: the problem must be given as non-symmetric"
                )));
            }
            if dual.is_empty() {
                return Err(SolveError::DependentConditions { conditions: vec![ci] });
            }
        }
    }
    Ok(())
}

/// How the entries of a symmetric K are read: elementary blocks give both
/// triangles, but a caller may give only one; we use the upper one when any
/// strictly-upper entry exists, else the (transposed) lower one. Taking both
/// would count off-diagonal terms twice.
fn upper_mode(p: &Problem) -> bool {
    p.k.entries.iter().any(|&(i, j, _)| i < j) || p.k.entries.is_empty()
}

/// The doubled matrix: CSC pattern in the natural numbering (upper triangle
/// when symmetric, full otherwise), its values, and the scatter map.
#[derive(Debug, Clone)]
pub struct Doubled {
    pub n: usize,
    pub m: usize,
    pub symmetric: bool,
    pub col_ptr: Vec<usize>,
    pub row_idx: Vec<usize>,
    pub values: Vec<f64>,
    pub scaling: Scaling,
    /// Largest |entry| of each row of the whole doubled matrix (both
    /// triangles), the reference for the tiny-pivot test.
    pub row_scale: Vec<f64>,
    /// Slot of every source term, in the order of [`Doubled::fill`]
    /// (32-bit: the pattern build is memory-bound).
    pos: Vec<u32>,
    upper: bool,
    n_terms: usize,
    structure: u64,
}

impl Doubled {
    pub fn dim(&self) -> usize {
        self.n + 2 * self.m
    }

    /// Assembles the pattern and the values. `dense_tail` lists unknowns
    /// (natural numbering) that get explicit (zero) couplings with each
    /// other, so that they form one dense trailing supernode (condensation).
    pub fn new(p: &Problem, dense_tail: &[usize]) -> Result<Self, SolveError> {
        Self::with_tail(p, dense_tail, true)
    }

    /// [`Doubled::new`]; with `pairs == false` the tail gets only the
    /// couplings to its first unknown (and a chain), not the m² explicit
    /// pairs. That is already one trailing supernode: every tail unknown
    /// fills into the head's column, and eliminating the head makes the
    /// rest dense. It is much cheaper to build and analyse at m ~ 10³; the
    /// pairs stay as the caller's fallback.
    pub fn with_tail(p: &Problem, dense_tail: &[usize], pairs: bool) -> Result<Self, SolveError> {
        validate(p)?;
        let n = p.k.n;
        let m = p.conditions.len();
        let dim = n + 2 * m;
        let symmetric = p.k.symmetric;
        let upper = upper_mode(p);
        let n_terms: usize = p.conditions.iter().map(|c| c.terms.len() + c.reaction_terms().len()).sum();
        let n_src = p.k.entries.len() + 4 * n_terms + 4 * m;
        if dim >= NONE as usize
            || n_src.saturating_add(2 * dim).saturating_add(dense_tail.len().saturating_mul(dense_tail.len()))
                >= NONE as usize
        {
            return Err(SolveError::Other("system too large for 32-bit pattern indices".into()));
        }
        // The source terms as (row, col), in the fixed order fill() follows,
        // generated twice (count, then place) instead of stored: the build
        // is memory-bound.
        let key = |r: usize, c: usize| -> (u32, u32) {
            if symmetric && r > c {
                (c as u32, r as u32)
            } else {
                (r as u32, c as u32)
            }
        };
        let sources = |emit: &mut dyn FnMut(u32, u32)| {
            for &(i, j, _) in &p.k.entries {
                if !symmetric || if upper { i <= j } else { i >= j } {
                    let (r, c) = key(i, j);
                    emit(r, c);
                } else {
                    emit(NONE, NONE);
                }
            }
            for (ci, c) in p.conditions.iter().enumerate() {
                for &(j, _) in &c.terms {
                    let (r, c) = key(n + ci, j);
                    emit(r, c);
                    let (r, c) = key(n + m + ci, j);
                    emit(r, c);
                }
                // The columns of the multipliers: the reaction direction
                // (the row itself unless the condition is non-associated).
                if !symmetric {
                    for &(j, _) in c.reaction_terms() {
                        emit(j as u32, (n + ci) as u32);
                        emit(j as u32, (n + m + ci) as u32);
                    }
                }
            }
            for ci in 0..m {
                let (a, b) = ((n + ci) as u32, (n + m + ci) as u32);
                emit(a, a);
                emit(b, b);
                emit(a, b);
                if !symmetric {
                    emit(b, a);
                }
            }
        };
        let mut count = vec![0usize; dim + 1];
        let mut n_fill = 0usize;
        let mut in_tail = vec![false; if dense_tail.is_empty() { 0 } else { dim }];
        for &t in dense_tail {
            in_tail[t] = true;
        }
        let mut extra = vec![false; in_tail.len()];
        sources(&mut |r, c| {
            n_fill += 1;
            if r != NONE {
                count[c as usize + 1] += 1;
                let (r, c) = (r as usize, c as usize);
                if !in_tail.is_empty() && in_tail[r] != in_tail[c] {
                    extra[if in_tail[r] { c } else { r }] = true;
                }
            }
        });
        // Every unknown coupled to the tail also gets an explicit entry in
        // the row of the tail's first unknown. Fill then carries that row up
        // the elimination tree, so no column outside the tail has a parent
        // inside it other than the first one: the tail stays one chain, hence
        // one supernode, whatever the couplings (e.g. independent contact
        // zones).
        let mut more: Vec<(u32, u32)> = Vec::new();
        let both = |r: usize, c: usize, more: &mut Vec<(u32, u32)>| {
            more.push(key(r, c));
            if !symmetric {
                more.push((c as u32, r as u32));
            }
        };
        if let Some(&head) = dense_tail.first() {
            for (k, _) in extra.iter().enumerate().filter(|e| *e.1) {
                both(k, head, &mut more);
            }
            for w in dense_tail.windows(2) {
                both(w[1], w[0], &mut more);
            }
        }
        if pairs {
            for (a, &ca) in dense_tail.iter().enumerate() {
                for &cb in &dense_tail[..a] {
                    both(ca, cb, &mut more);
                }
            }
        }
        for &(_, c) in &more {
            count[c as usize + 1] += 1;
        }
        for c in 0..dim {
            count[c + 1] += count[c];
        }
        // (row << 32 | source index): one integer sort key per column.
        let mut next = count.clone();
        let mut bucket = vec![0u64; count[dim]];
        let mut s = 0u64;
        let mut place = |r: u32, c: u32| {
            if r != NONE {
                bucket[next[c as usize]] = (u64::from(r) << 32) | s;
                next[c as usize] += 1;
            }
            s += 1;
        };
        sources(&mut place);
        for &(r, c) in &more {
            place(r, c);
        }
        drop(next);
        let (col_ptr, row_idx, pos) = compress(dim, &count, &mut bucket, n_fill + more.len());
        let mut pos = pos;
        pos.truncate(n_fill);
        let structure = structure_hash(p);
        let mut d = Doubled {
            n,
            m,
            symmetric,
            values: vec![0.0; row_idx.len()],
            col_ptr,
            row_idx,
            scaling: Scaling { sigma: vec![], alpha: vec![] },
            row_scale: vec![],
            pos,
            upper,
            n_terms,
            structure,
        };
        d.scatter(p, 0.0);
        Ok(d)
    }

    /// Whether `p` has exactly the structure this matrix was built from.
    pub fn same_pattern(&self, p: &Problem) -> bool {
        p.k.n == self.n
            && p.conditions.len() == self.m
            && p.k.symmetric == self.symmetric
            && upper_mode(p) == self.upper
            && p.conditions.iter().map(|c| c.terms.len() + c.reaction_terms().len()).sum::<usize>() == self.n_terms
            && structure_hash(p) == self.structure
    }

    /// Scatters the values of `p` (same structure) and recomputes the
    /// scaling. `stab` > 0 adds `stab × (row max)` to every primal diagonal
    /// ('STAB').
    pub fn fill(&mut self, p: &Problem, stab: f64) -> Result<(), SolveError> {
        if !self.same_pattern(p) {
            return Err(SolveError::Other("the matrix structure changed since the analysis".into()));
        }
        validate(p)?;
        self.scatter(p, stab);
        Ok(())
    }

    /// [`Doubled::fill`] without the checks (`p` known to match).
    fn scatter(&mut self, p: &Problem, stab: f64) {
        let (n, m) = (self.n, self.m);
        self.values.iter_mut().for_each(|v| *v = 0.0);
        let mut s = 0;
        for &(_, _, v) in &p.k.entries {
            let slot = self.pos[s];
            if slot != NONE {
                self.values[slot as usize] += v;
            }
            s += 1;
        }
        // Row maxima of the assembled K, before any condition term lands.
        let mut row_max = vec![0.0f64; n];
        for col in 0..n {
            for k in self.col_ptr[col]..self.col_ptr[col + 1] {
                let r = self.row_idx[k];
                if r < n {
                    let a = self.values[k].abs();
                    row_max[r] = row_max[r].max(a);
                    row_max[col] = row_max[col].max(a);
                }
            }
        }
        if stab > 0.0 {
            for (j, &rm) in row_max.iter().enumerate() {
                if let Some(k) = self.find(j, j) {
                    self.values[k] += stab * rm;
                }
            }
        }
        self.scaling = scaling(p, &row_max);
        for (ci, c) in p.conditions.iter().enumerate() {
            let sg = self.scaling.sigma[ci];
            let columns: &[(usize, f64)] = if self.symmetric { &[] } else { c.reaction_terms() };
            for &(_, v) in c.terms.iter().flat_map(|t| [t, t]).chain(columns.iter().flat_map(|t| [t, t])) {
                self.values[self.pos[s] as usize] += sg * v;
                s += 1;
            }
        }
        for ci in 0..m {
            let a = self.scaling.alpha[ci];
            self.values[self.pos[s] as usize] += -a;
            self.values[self.pos[s + 1] as usize] += -a;
            self.values[self.pos[s + 2] as usize] += a;
            s += 3;
            if !self.symmetric {
                self.values[self.pos[s] as usize] += a;
                s += 1;
            }
        }
        self.row_scale = vec![0.0; self.dim()];
        for col in 0..self.dim() {
            for k in self.col_ptr[col]..self.col_ptr[col + 1] {
                let a = self.values[k].abs();
                let r = self.row_idx[k];
                self.row_scale[r] = self.row_scale[r].max(a);
                self.row_scale[col] = self.row_scale[col].max(a);
            }
        }
    }

    /// Slot of entry (r, c) (upper triangle when symmetric), if stored.
    pub fn find(&self, r: usize, c: usize) -> Option<usize> {
        let (r, c) = if self.symmetric && r > c { (c, r) } else { (r, c) };
        let rows = &self.row_idx[self.col_ptr[c]..self.col_ptr[c + 1]];
        rows.binary_search(&r).ok().map(|k| k + self.col_ptr[c])
    }

    /// Adds `v` to the diagonal entry of unknown `i` (natural numbering).
    pub fn add_diag(&mut self, i: usize, v: f64) {
        if let Some(k) = self.find(i, i) {
            self.values[k] += v;
        }
    }

    /// The doubled right-hand side (σd, F, σd) in the natural numbering,
    /// written into `out` (length `dim`).
    pub fn rhs(&self, f: &[f64], d: &[f64], out: &mut [f64]) {
        let (n, m) = (self.n, self.m);
        out[..n].copy_from_slice(f);
        for i in 0..m {
            let v = self.scaling.sigma[i] * d[i];
            out[n + i] = v;
            out[n + m + i] = v;
        }
    }

    /// y = M x (natural numbering), and t = |M| |x| for backward errors.
    pub fn apply(&self, x: &[f64], y: &mut [f64], t: &mut [f64]) {
        y.iter_mut().for_each(|v| *v = 0.0);
        t.iter_mut().for_each(|v| *v = 0.0);
        for col in 0..self.dim() {
            for k in self.col_ptr[col]..self.col_ptr[col + 1] {
                let r = self.row_idx[k];
                let a = self.values[k];
                y[r] += a * x[col];
                t[r] += (a * x[col]).abs();
                if self.symmetric && r != col {
                    y[col] += a * x[r];
                    t[col] += (a * x[r]).abs();
                }
            }
        }
    }
}

/// CSC `(col_ptr, row_idx)` plus the slot of each source pair.
type Compressed = (Vec<usize>, Vec<usize>, Vec<u32>);

/// Builds a CSC pattern (sorted rows, duplicates merged) from the
/// column-bucketed keys `row << 32 | source` of a counting sort on columns
/// (`count` = column starts), and returns the slot of each source. O(nnz)
/// plus tiny per-column sorts: a global sort would cost a sizeable
/// fraction of the factorisation at 10⁶ entries.
fn compress(dim: usize, count: &[usize], bucket: &mut [u64], n_src: usize) -> Compressed {
    let mut pos = vec![NONE; n_src];
    let mut col_ptr = vec![0usize; dim + 1];
    let mut row_idx = Vec::with_capacity(bucket.len());
    for c in 0..dim {
        let b = &mut bucket[count[c]..count[c + 1]];
        b.sort_unstable();
        let mut last = u64::MAX;
        for &key in b.iter() {
            let r = key >> 32;
            if r != last {
                row_idx.push(r as usize);
                last = r;
            }
            pos[(key & 0xffff_ffff) as usize] = (row_idx.len() - 1) as u32;
        }
        col_ptr[c + 1] = row_idx.len();
    }
    (col_ptr, row_idx, pos)
}

/// A fast structural fingerprint (indices and kinds, not values) for the
/// "same pattern" test: reading it costs one pass over the entries, far
/// less than a factorisation.
pub fn structure_hash(p: &Problem) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    let mut mix = |x: u64| {
        h ^= x;
        h = h.wrapping_mul(0x0000_0100_0000_01b3).rotate_left(17);
    };
    mix(p.k.entries.len() as u64);
    for &(i, j, _) in &p.k.entries {
        mix(((i as u64) << 32) ^ j as u64);
    }
    for c in &p.conditions {
        mix(c.terms.len() as u64 ^ ((c.kind as u64) << 40));
        for &(j, _) in &c.terms {
            mix(j as u64);
        }
        if let Some(dual) = &c.dual {
            mix(dual.len() as u64 ^ (1 << 48));
            for &(j, _) in dual {
                mix(j as u64);
            }
        }
    }
    h
}

#[cfg(test)]
#[path = "tests/lagrange.rs"]
mod tests;
