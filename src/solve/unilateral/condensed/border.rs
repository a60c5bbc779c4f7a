//! Condensation onto the second multipliers with the tail kept *out* of the
//! sparse factor (unilateral.md §3, solver-notes §3.3).
//!
//! The doubled matrix, the condensed λ2 ordered last, is the bordered
//! system `[A₁₁ B; Bᵀ C]`. One faer LDLᵀ factorises A₁₁ alone; the Schur
//! complement `S = C − Bᵀ A₁₁⁻¹ B` is then formed supernode by supernode as
//! `C − Wᵀ D⁻¹ W` with `W = L⁻¹ B`: column q of W lives only on the
//! supernodes of the elimination-tree path from the unknowns of condition q
//! to the root, so W is stored as one dense block per supernode (the
//! conditions whose path crosses it). This is the interrupted factorisation
//! of the paper done by hand for the border: the same numbers as factorising
//! the whole bordered matrix and reading S from its trailing supernode, but
//!
//! * the trailing m×m block is never factorised and S never rebuilt from
//!   its factor (2 × m³/3 flops saved, 5.3 Gflop at m = 2000);
//! * the sparse factor of A₁₁ has no border rows, so faer runs it with the
//!   kernels and threading that suit the mesh, while the border's dense
//!   blocks, largest near the root, get threads of their own;
//! * the tail need not form one supernode (disjoint contact zones).
//!
//! A₁₁ is the leading principal block of the elimination order, so its
//! pivots are the ones the full factorisation would meet before the tail:
//! a zero pivot there is the same failure, and the caller falls back to the
//! whole-matrix path ([`crate::solve::bilateral::schur`]) for its diagnostics.

use faer::linalg::matmul::matmul;
use faer::linalg::matmul::triangular::{matmul as tri_matmul, BlockStructure};
use faer::linalg::triangular_solve::solve_unit_lower_triangular_in_place;
use faer::prelude::ReborrowMut;
use faer::{Accum, Mat, MatMut, MatRef, Par};

use crate::solve::bilateral::lagrange::Doubled;
use crate::solve::bilateral::linear::{SymFactor, ZeroPivot};
use crate::solve::error::SolveError;

/// Multiply-adds of one supernode's border work above which it uses
/// faer's global parallelism (below, thread hand-offs cost more).
const PAR_WORK: usize = 1 << 22;

const NONE: usize = usize::MAX;

/// Entries of the scratch for one supernode's update of S (32 MB; tiny
/// under test, so that the unit tests go through the chunking).
const T_CHUNK: usize = if cfg!(test) { 64 } else { 1 << 22 };

/// The doubled system with its condensed tail bordered out of the factor.
#[derive(Debug)]
pub(crate) struct Bordered {
    pub sys: Doubled,
    /// A₁₁ natural index → full natural index.
    full_of: Vec<usize>,
    /// Tail position q → full natural index (the λ2 of condition q).
    tail: Vec<usize>,
    col_ptr: Vec<usize>,
    row_idx: Vec<usize>,
    values: Vec<f64>,
    row_scale: Vec<f64>,
    /// Slot in `sys.values` of every value of A₁₁.
    src: Vec<usize>,
    /// B entries: (elimination position in A₁₁, tail position, slot).
    b: Vec<(usize, usize, usize)>,
    /// C entries: (tail position, tail position, slot).
    c: Vec<(usize, usize, usize)>,
    factor: SymFactor,
    /// Elimination position → supernode.
    sup_of: Vec<usize>,
    /// Tail positions whose W column crosses supernode s, increasing:
    /// `j_idx[j_ptr[s]..j_ptr[s + 1]]`.
    j_ptr: Vec<usize>,
    j_idx: Vec<usize>,
    /// Start of supernode s's block of W (width × |J_s|, column-major).
    w_ptr: Vec<usize>,
    w: Vec<f64>,
    /// S over the tail (tail positions), both triangles.
    pub schur: Mat<f64>,
}

impl Bordered {
    /// `fwd` is the elimination order of the whole doubled system with the
    /// `tail` (full natural indices, tail position order irrelevant to it)
    /// last; `sys` holds the values of the problem.
    pub fn new(sys: Doubled, fwd: &[usize], tail: Vec<usize>) -> Result<Result<Self, ZeroPivot>, SolveError> {
        let dim = sys.dim();
        let mt = tail.len();
        let mut q_of = vec![NONE; dim];
        for (q, &t) in tail.iter().enumerate() {
            if t >= dim || q_of[t] != NONE {
                return Err(SolveError::Other("bad condensed tail".into()));
            }
            q_of[t] = q;
        }
        let mut sub_of = vec![NONE; dim];
        let mut full_of = Vec::with_capacity(dim - mt);
        for i in 0..dim {
            if q_of[i] == NONE {
                sub_of[i] = full_of.len();
                full_of.push(i);
            }
        }
        let ns = full_of.len();
        let head: Vec<usize> = fwd.iter().filter(|&&o| q_of[o] == NONE).map(|&o| sub_of[o]).collect();
        if head.len() != ns || fwd.len() != dim {
            return Err(SolveError::Other("elimination order does not cover the system".into()));
        }
        // A₁₁ in its own numbering (the map is increasing, so rows stay
        // sorted), and the border entries.
        let mut col_ptr = vec![0usize; ns + 1];
        let (mut row_idx, mut src, mut b, mut c) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        for col in 0..dim {
            for k in sys.col_ptr[col]..sys.col_ptr[col + 1] {
                let r = sys.row_idx[k];
                match (q_of[r], q_of[col]) {
                    (NONE, NONE) => {
                        row_idx.push(sub_of[r]);
                        src.push(k);
                    }
                    (NONE, q) => b.push((sub_of[r], q, k)),
                    (q, NONE) => b.push((sub_of[col], q, k)),
                    (q1, q2) => c.push((q1, q2, k)),
                }
            }
            if q_of[col] == NONE {
                col_ptr[sub_of[col] + 1] = row_idx.len();
            }
        }
        let factor = SymFactor::analyse(&col_ptr, &row_idx, head)?;
        let inv = factor.inv();
        for e in &mut b {
            e.0 = inv[e.0];
        }
        let (sup_of, j_ptr, j_idx, w_ptr) = border_structure(&factor, &b, mt);
        let w = vec![0.0; *w_ptr.last().unwrap_or(&0)];
        let values = vec![0.0; row_idx.len()];
        let mut me = Bordered {
            sys,
            full_of,
            tail,
            col_ptr,
            row_idx,
            values,
            row_scale: Vec::new(),
            src,
            b,
            c,
            factor,
            sup_of,
            j_ptr,
            j_idx,
            w_ptr,
            w,
            schur: Mat::zeros(0, 0),
        };
        Ok(me.numeric().map(|()| me))
    }

    /// Factorises A₁₁ with the values now in `sys` and forms S.
    pub fn numeric(&mut self) -> Result<(), ZeroPivot> {
        for (v, &k) in self.values.iter_mut().zip(&self.src) {
            *v = self.sys.values[k];
        }
        self.row_scale = self.full_of.iter().map(|&i| self.sys.row_scale[i]).collect();
        let res =
            self.factor.factor(&self.col_ptr, &self.row_idx, &self.values, &self.row_scale, self.full_of.len(), None);
        if let Err(z) = res {
            // Back to the full numbering for the caller's report.
            let index = if z.index < self.full_of.len() { self.full_of[z.index] } else { z.index };
            return Err(ZeroPivot { index });
        }
        self.form_schur();
        Ok(())
    }

    /// W = L⁻¹B by supernodes, and S = C − Wᵀ D⁻¹ W.
    fn form_schur(&mut self) {
        let mt = self.tail.len();
        let mut s_mat = Mat::<f64>::zeros(mt, mt);
        for &(q1, q2, k) in &self.c {
            let v = self.sys.values[k];
            s_mat[(q1.max(q2), q1.min(q2))] += v;
        }
        self.w.iter_mut().for_each(|v| *v = 0.0);
        let f = self.factor.ldlt_ref();
        for &(pos, q, k) in &self.b {
            let s = self.sup_of[pos];
            let start = f.supernode(s).start();
            let width = f.supernode(s).val().ncols();
            let c = self.j_of(s).binary_search(&q).expect("q crosses its own supernode");
            self.w[self.w_ptr[s] + c * width + pos - start] += self.sys.values[k];
        }
        // Scratch at the largest sizes met, allocated once.
        let ns = self.j_ptr.len() - 1;
        let (mut ymax, mut tmax, mut umax) = (0, 0, 0);
        for s in 0..ns {
            let k = self.j_ptr[s + 1] - self.j_ptr[s];
            if k == 0 {
                continue;
            }
            let v = f.supernode(s).val();
            ymax = ymax.max(v.ncols() * k);
            let js = self.j_of(s);
            if js[k - 1] - js[0] != k - 1 {
                tmax = tmax.max((k * k).min(T_CHUNK.max(k)));
            }
            umax = umax.max((v.nrows() - v.ncols()) * k);
        }
        let mut ybuf = vec![0.0; ymax];
        let mut tbuf = vec![0.0; tmax];
        let mut ubuf = vec![0.0; umax];
        let mut colmap: Vec<usize> = Vec::new();
        for s in 0..ns {
            let (j0, j1) = (self.j_ptr[s], self.j_ptr[s + 1]);
            let k = j1 - j0;
            if k == 0 {
                continue;
            }
            let sn = f.supernode(s);
            let v = sn.val();
            let (width, below) = (v.ncols(), v.nrows() - v.ncols());
            let par =
                if width * k * (k + width + 2 * below) >= PAR_WORK { faer::get_global_parallelism() } else { Par::Seq };
            let (head, rest) = self.w.split_at_mut(self.w_ptr[s + 1]);
            let xs = MatMut::from_column_major_slice_mut(&mut head[self.w_ptr[s]..], width, k);
            let top = v.submatrix(0, 0, width, width);
            let mut xs = xs;
            solve_unit_lower_triangular_in_place(top, xs.rb_mut(), par);
            let xs = xs.as_ref();
            // S[J, J] −= Xᵀ D⁻¹ X (lower triangle; J increasing keeps it
            // lower in S too).
            let mut y = MatMut::from_column_major_slice_mut(&mut ybuf[..width * k], width, k);
            for c in 0..k {
                for r in 0..width {
                    y[(r, c)] = xs[(r, c)] / top[(r, r)];
                }
            }
            let y = y.as_ref();
            let js = &self.j_idx[j0..j1];
            if js[k - 1] - js[0] == k - 1 {
                // Contiguous conditions (always so near the root): in place.
                let dst = s_mat.as_mut().submatrix_mut(js[0], js[0], k, k);
                sym_update(dst, xs, y, par);
            } else {
                // By column chunks: the scratch stays bounded (k may be in
                // the thousands); each chunk is a rectangle from its
                // diagonal down, its few upper entries computed and unused.
                let bk = (T_CHUNK / k).clamp(1, k);
                for c0 in (0..k).step_by(bk) {
                    let c1 = (c0 + bk).min(k);
                    let rows = k - c0;
                    let mut t = MatMut::from_column_major_slice_mut(&mut tbuf[..rows * (c1 - c0)], rows, c1 - c0);
                    matmul(
                        t.rb_mut(),
                        Accum::Replace,
                        xs.subcols(c0, rows).transpose(),
                        y.subcols(c0, c1 - c0),
                        1.0,
                        par,
                    );
                    for c in c0..c1 {
                        let col = s_mat.col_as_slice_mut(js[c]);
                        for r in c..k {
                            col[js[r]] -= t[(r - c0, c - c0)];
                        }
                    }
                }
            }
            if below == 0 {
                continue;
            }
            // The ancestors' rows: W[P, J] −= L[P, s] X.
            let mut u = MatMut::from_column_major_slice_mut(&mut ubuf[..below * k], below, k);
            matmul(u.rb_mut(), Accum::Replace, v.submatrix(width, 0, below, width), xs, 1.0, par);
            let u = u.as_ref();
            let pattern = sn.pattern();
            let mut i = 0;
            while i < below {
                let t = self.sup_of[pattern[i]];
                let tstart = f.supernode(t).start();
                let twidth = f.supernode(t).val().ncols();
                let mut e = i;
                while e < below && pattern[e] < tstart + twidth {
                    e += 1;
                }
                let jt = &self.j_idx[self.j_ptr[t]..self.j_ptr[t + 1]];
                colmap.clear();
                let mut at = 0;
                for &q in js {
                    at += jt[at..].partition_point(|&x| x < q);
                    colmap.push(at);
                }
                let base = self.w_ptr[t] - self.w_ptr[s + 1];
                for (c, &tc) in colmap.iter().enumerate() {
                    let dst = &mut rest[base + tc * twidth..base + (tc + 1) * twidth];
                    for r in i..e {
                        dst[pattern[r] - tstart] -= u[(r, c)];
                    }
                }
                i = e;
            }
        }
        crate::solve::bilateral::schur::mirror_lower(&mut s_mat);
        self.schur = s_mat;
    }

    fn j_of(&self, s: usize) -> &[usize] {
        &self.j_idx[self.j_ptr[s]..self.j_ptr[s + 1]]
    }

    /// Forward substitution of full natural right-hand sides through A₁₁
    /// (`y = L⁻¹ b₁`, elimination order) and the Schur right-hand sides
    /// `r = b_t − Wᵀ D⁻¹ y` (tail positions).
    pub fn forward(&self, cols: &[Vec<f64>]) -> (Mat<f64>, Mat<f64>) {
        let fwd = self.factor.fwd();
        let nsub = fwd.len();
        let mut y = Mat::from_fn(nsub, cols.len(), |k, j| cols[j][self.full_of[fwd[k]]]);
        self.factor.forward_partial(y.as_mut(), nsub);
        let mut r = Mat::from_fn(self.tail.len(), cols.len(), |q, j| cols[j][self.tail[q]]);
        let d = self.factor.pivots();
        let yd = Mat::from_fn(nsub, cols.len(), |k, j| y[(k, j)] / d[k]);
        self.each_block(|start, width, js, xs| {
            for (c, &q) in js.iter().enumerate() {
                let x = xs.col(c);
                for j in 0..cols.len() {
                    r[(q, j)] -= (0..width).map(|rr| x[rr] * yd[(start + rr, j)]).sum::<f64>();
                }
            }
        });
        (y, r)
    }

    /// The full natural solution from the forwarded `y` (one column) and the
    /// tail values: `z₁ = L⁻ᵀ D⁻¹ (y − W x_t)`.
    pub fn finish(&self, mut y: Mat<f64>, tail_values: &[f64]) -> Vec<f64> {
        let nsub = y.nrows();
        self.each_block(|start, width, js, xs| {
            for (c, &q) in js.iter().enumerate() {
                let x = tail_values[q];
                if x != 0.0 {
                    for rr in 0..width {
                        y[(start + rr, 0)] -= xs[(rr, c)] * x;
                    }
                }
            }
        });
        self.factor.diagonal_partial(y.as_mut(), nsub);
        self.factor.backward_partial(y.as_mut(), nsub);
        let mut out = vec![0.0; self.sys.dim()];
        for (k, &o) in self.factor.fwd().iter().enumerate() {
            out[self.full_of[o]] = y[(k, 0)];
        }
        for (q, &t) in self.tail.iter().enumerate() {
            out[t] = tail_values[q];
        }
        out
    }

    /// Calls `f(start, width, J_s, X_s)` for every supernode crossed by W.
    fn each_block(&self, mut f: impl FnMut(usize, usize, &[usize], MatRef<'_, f64>)) {
        let fr = self.factor.ldlt_ref();
        for s in 0..self.j_ptr.len() - 1 {
            let js = self.j_of(s);
            if js.is_empty() {
                continue;
            }
            let sn = fr.supernode(s);
            let width = sn.val().ncols();
            let xs = MatRef::from_column_major_slice(&self.w[self.w_ptr[s]..self.w_ptr[s + 1]], width, js.len());
            f(sn.start(), width, js, xs);
        }
    }

    /// The elimination order of the whole doubled system (tail last).
    pub fn elimination_order(&self) -> Vec<usize> {
        let mut fwd: Vec<usize> = self.factor.fwd().iter().map(|&o| self.full_of[o]).collect();
        fwd.extend_from_slice(&self.tail);
        fwd
    }
}

/// `dst −= xᵀ y` on the lower triangle (dst square, k×k).
fn sym_update(dst: MatMut<'_, f64>, x: MatRef<'_, f64>, y: MatRef<'_, f64>, par: Par) {
    tri_matmul(
        dst,
        BlockStructure::TriangularLower,
        Accum::Add,
        x.transpose(),
        BlockStructure::Rectangular,
        y,
        BlockStructure::Rectangular,
        -1.0,
        par,
    );
}

/// The supernode of every elimination position, the sets J_s (conditions
/// whose W column crosses supernode s: the paths from their entries to the
/// root of the supernodal tree) and the offsets of the blocks of W.
fn border_structure(
    factor: &SymFactor,
    b: &[(usize, usize, usize)],
    mt: usize,
) -> (Vec<usize>, Vec<usize>, Vec<usize>, Vec<usize>) {
    let sym = factor.supernodal();
    let ns = sym.n_supernodes();
    let (begin, end) = (sym.supernode_begin(), sym.supernode_end());
    let mut sup_of = vec![0usize; factor.dim()];
    for s in 0..ns {
        sup_of[begin[s]..end[s]].iter_mut().for_each(|x| *x = s);
    }
    // A supernode's parent holds the first row of its pattern.
    let parent: Vec<usize> = (0..ns).map(|s| sym.supernode(s).pattern().first().map_or(NONE, |&r| sup_of[r])).collect();
    let mut by_q: Vec<Vec<usize>> = vec![Vec::new(); mt];
    for &(pos, q, _) in b {
        by_q[q].push(sup_of[pos]);
    }
    let mut mark = vec![NONE; ns];
    let mut lists: Vec<Vec<usize>> = vec![Vec::new(); ns];
    for (q, starts) in by_q.iter().enumerate() {
        for &s0 in starts {
            let mut s = s0;
            while s != NONE && mark[s] != q {
                mark[s] = q;
                lists[s].push(q);
                s = parent[s];
            }
        }
    }
    let mut j_ptr = vec![0usize; ns + 1];
    let mut w_ptr = vec![0usize; ns + 1];
    let mut j_idx = Vec::new();
    for s in 0..ns {
        j_idx.extend_from_slice(&lists[s]);
        j_ptr[s + 1] = j_idx.len();
        w_ptr[s + 1] = w_ptr[s] + (end[s] - begin[s]) * lists[s].len();
    }
    (sup_of, j_ptr, j_idx, w_ptr)
}
