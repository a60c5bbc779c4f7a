//! The condenser of the CONDENSE method (unilateral.md §3, solver-notes
//! §3.3): the unilateral problem condensed onto the second multipliers of
//! its unilateral conditions by one interrupted factorisation.
//!
//! Its normal path is `border`: the sparse factor holds everything
//! but those multipliers, and the Schur complement S of the tail is formed
//! from the border, supernode by supernode. Its fallback is the
//! whole-matrix path of [`crate::solve::bilateral::schur`] (a zero pivot
//! before the tail is reported from there, with the unknowns involved).
//!
//! The first block of the factor (everything but the tail) is independent
//! of the statuses, so one factorisation serves every status iteration;
//! right-hand sides and the recovery use partial forward and back
//! substitutions through that block only.

use faer::Mat;

use super::border::Bordered;
use super::Condensed;
use crate::solve::bilateral::direct::check_structure;
use crate::solve::bilateral::lagrange::Doubled;
use crate::solve::bilateral::ordering;
use crate::solve::bilateral::schur::Interrupted;
use crate::solve::error::SolveError;
use crate::solve::problem::{Load, Problem, Solution};
use std::rc::Rc;

/// How the condensation onto the λ2 is held: the border kept out of the
/// factor (the normal case, [`Bordered`]), or the whole doubled matrix
/// factorised with its tail (the fallback: it names the unknowns of a zero
/// pivot, and copes with a tail that the border path cannot factor).
#[derive(Debug)]
enum Core {
    Bordered(Box<Bordered>),
    Whole(Box<Interrupted>),
}

/// The unilateral problem condensed onto the second multipliers of its
/// unilateral conditions (`kind != Equal`); bilateral conditions stay
/// doubled inside the factor.
#[derive(Debug)]
pub struct Condenser {
    core: Core,
    /// G = −S/4, shared with every [`Condensed`] without a copy.
    g: Rc<Mat<f64>>,
    /// The forward substitution of the last load's rhs, keyed by the load:
    /// the recovery of that load then skips its forward half.
    forwarded: std::sync::Mutex<Option<(u64, Mat<f64>)>>,
    /// Global numbers of the unilateral conditions, in condensed order.
    uni: Vec<usize>,
    sense: Vec<f64>,
    rows: Vec<Vec<(usize, f64)>>,
}

impl Condenser {
    pub fn new(p: &Problem) -> Result<Self, SolveError> {
        Self::build(p, false)
    }

    /// The whole-matrix path only (tests compare both paths).
    #[cfg(test)]
    pub(crate) fn new_whole(p: &Problem) -> Result<Self, SolveError> {
        Self::build(p, true)
    }

    fn build(p: &Problem, force_whole: bool) -> Result<Self, SolveError> {
        let uni: Vec<usize> = (0..p.conditions.len()).filter(|&i| p.conditions[i].kind.is_unilateral()).collect();
        if uni.is_empty() {
            return Err(SolveError::Other("no unilateral condition".into()));
        }
        // The interrupted LDLᵀ needs a symmetric operator; Cast3M does not
        // condense non-symmetric ones either (unilateral.md §3.6).
        if !p.k.symmetric {
            return Err(SolveError::Other(
                "the condensed method needs a symmetric matrix: use the CREUX method for a non-symmetric one".into(),
            ));
        }
        let (n, m) = (p.k.n, p.conditions.len());
        let tail: Vec<usize> = uni.iter().map(|&i| n + m + i).collect();
        // Doubled::new validates the data.
        let sys = Doubled::new(p, &[])?;
        check_structure(p)?;
        let primal = ordering::primal_best(p, &[], Some((&sys.col_ptr, &sys.row_idx)))?;
        let fwd = ordering::doubled_order(p, &primal, &uni);
        let rows: Vec<Vec<(usize, f64)>> = uni.iter().map(|&i| p.conditions[i].terms.clone()).collect();
        let sense: Vec<f64> = uni.iter().map(|&i| p.conditions[i].kind.sense()).collect();
        let bordered = if force_whole { None } else { Bordered::new(sys, &fwd, tail)?.ok() };
        let core = match bordered {
            Some(b) => Core::Bordered(Box::new(b)),
            None => Core::Whole(Box::new(Self::whole(p, &uni, fwd, &rows, &sense)?)),
        };
        let mut c =
            Condenser { core, g: Rc::new(Mat::zeros(0, 0)), forwarded: std::sync::Mutex::new(None), sense, rows, uni };
        c.take_g();
        Ok(c)
    }

    /// The whole-matrix condensation (see [`Core`]).
    fn whole(
        p: &Problem,
        uni: &[usize],
        fwd: Vec<usize>,
        rows: &[Vec<(usize, f64)>],
        sense: &[f64],
    ) -> Result<Interrupted, SolveError> {
        let (n, m) = (p.k.n, p.conditions.len());
        let tail: Vec<usize> = uni.iter().map(|&i| n + m + i).collect();
        let cut = fwd.len() - uni.len();
        // Without proportional rows (duplicates, a gap on both sides of a
        // dof) G is usually regular: the tail is then factorised unshifted
        // and its factor is the status loop's first one (all active).
        let plain = crate::solve::unilateral::status::groups::analyse(rows, sense, &vec![0.0; uni.len()])
            .is_ok_and(|g| g.partner.iter().all(Option::is_none) && !g.fixed_inactive.iter().any(|&f| f));
        // Without the m² explicit tail pairs first: one mesh connects the
        // tail anyway; disconnected contact zones need them.
        let sys = Doubled::with_tail(p, &tail, false)?;
        Ok(match Interrupted::try_new(p, fwd.clone(), cut, Some(sys), plain)? {
            Some(core) => core,
            None => Interrupted::new(p, fwd, cut, Some(Doubled::new(p, &tail)?), plain)?,
        })
    }

    /// Moves S out of the core as G = −S/4 (no copy).
    fn take_g(&mut self) {
        let s = match &mut self.core {
            Core::Bordered(b) => &mut b.schur,
            Core::Whole(w) => &mut w.schur,
        };
        let mut g = std::mem::replace(s, Mat::zeros(0, 0));
        g *= faer::Scale(-0.25);
        self.g = Rc::new(g);
    }

    fn sys(&self) -> &Doubled {
        match &self.core {
            Core::Bordered(b) => &b.sys,
            Core::Whole(w) => &w.sys,
        }
    }

    /// Global numbers of the unilateral conditions (position q ↦ condition).
    pub fn unilateral(&self) -> &[usize] {
        &self.uni
    }

    pub fn same_pattern(&self, p: &Problem) -> bool {
        self.sys().same_pattern(p)
    }

    /// New values on the same structure: numeric factorisation only.
    pub fn refactor(&mut self, p: &Problem) -> Result<(), SolveError> {
        if let Ok(mut slot) = self.forwarded.lock() {
            *slot = None;
        }
        self.rows = self.uni.iter().map(|&i| p.conditions[i].terms.clone()).collect();
        match &mut self.core {
            Core::Bordered(b) => {
                b.sys.fill(p, 0.0)?;
                if b.numeric().is_err() {
                    // The whole-matrix path names the failure.
                    let fwd = b.elimination_order();
                    self.core = Core::Whole(Box::new(Self::whole(p, &self.uni, fwd, &self.rows, &self.sense)?));
                }
            }
            Core::Whole(w) => w.numeric(p, true)?,
        }
        self.take_g();
        Ok(())
    }

    fn check_load(&self, load: &Load) -> Result<(), SolveError> {
        let (n, m) = (self.sys().n, self.sys().m);
        if load.f.len() != n || load.d.len() != m {
            return Err(SolveError::Other(format!(
                "load sizes ({}, {}) do not match ({n}, {m})",
                load.f.len(),
                load.d.len()
            )));
        }
        Ok(())
    }

    /// The condensed problem `T x = h` for one load (§3.2).
    pub fn condensed(&self, load: &Load) -> Result<Condensed, SolveError> {
        let fw = self.forward_load(load)?;
        if let Ok(mut slot) = self.forwarded.lock() {
            *slot = Some((load_key(load), fw.y.subcols(0, 1).to_owned()));
        }
        Ok(self.condensed_from(&fw, &load.d))
    }

    /// The forward substitution of a load through the first block of the
    /// factor: the right-hand side of the load and of its forces alone, and
    /// their reduced tail. It is linear in the load, so a caller whose
    /// loads combine a few fixed ones forwards each once
    /// ([`Forwarded::add`]) and goes on with [`Condenser::condensed_from`]
    /// and [`Condenser::recover_from`] (PASAPAS's steps).
    pub fn forward_load(&self, load: &Load) -> Result<Forwarded, SolveError> {
        self.check_load(load)?;
        let sys = self.sys();
        let (n, dim) = (sys.n, sys.dim());
        let mut full = vec![0.0; dim];
        sys.rhs(&load.f, &load.d, &mut full);
        let mut f_only = vec![0.0; dim];
        f_only[..n].copy_from_slice(&load.f);
        let (y, r) = match &self.core {
            Core::Bordered(b) => b.forward(&[full, f_only]),
            Core::Whole(w) => {
                let x = w.forward(&[full, f_only]);
                let r = x.subrows(w.cut, dim - w.cut).to_owned();
                (x, r)
            }
        };
        Ok(Forwarded { y, r })
    }

    /// [`Condenser::condensed`] from a forwarded load; `d` are the limits of
    /// every condition (the load's).
    pub fn condensed_from(&self, fw: &Forwarded, d: &[f64]) -> Condensed {
        let sys = self.sys();
        let r = &fw.r;
        let mu = self.uni.len();
        let alpha: Vec<f64> = self.uni.iter().map(|&i| sys.scaling.alpha[i]).collect();
        let g_factor = match &self.core {
            Core::Whole(w) => w.tail_factor.clone(),
            Core::Bordered(_) => None,
        };
        // The Schur system reads −4T x = r, so h = −r/4; with d = 0
        // (F only), r = −2ΣCH⁻¹F.
        Condensed {
            g: self.g.clone(),
            g_factor,
            h: (0..mu).map(|q| -r[(q, 0)] / 4.0).collect(),
            alpha,
            sigma: self.uni.iter().map(|&i| sys.scaling.sigma[i]).collect(),
            sense: self.sense.clone(),
            xtf: (0..mu).map(|q| -r[(q, 1)] / 2.0).collect(),
            rows: self.rows.clone(),
            d: self.uni.iter().map(|&i| d.get(i).copied().unwrap_or(0.0)).collect(),
        }
    }

    /// [`Condenser::recover`] from a forwarded load: the partial back
    /// substitution only.
    pub fn recover_from(&self, fw: &Forwarded, x: &[f64], active: &[bool]) -> Result<Solution, SolveError> {
        self.finish(fw.y.subcols(0, 1).to_owned(), x, active)
    }

    /// Displacements and multipliers for the condensed solution `x` (the
    /// λ2 of the unilateral conditions) and their statuses.
    pub fn recover(&self, load: &Load, x: &[f64], active: &[bool]) -> Result<Solution, SolveError> {
        self.check_load(load)?;
        let sys = self.sys();
        let dim = sys.dim();
        let saved = self.forwarded.lock().ok().and_then(|mut s| s.take());
        let fx = match saved {
            Some((key, fx)) if key == load_key(load) => fx,
            _ => {
                let mut rhs = vec![0.0; dim];
                sys.rhs(&load.f, &load.d, &mut rhs);
                match &self.core {
                    Core::Bordered(b) => b.forward(&[rhs]).0,
                    Core::Whole(w) => w.forward(&[rhs]),
                }
            }
        };
        self.finish(fx, x, active)
    }

    /// The back substitution from a forwarded right-hand side `fx` (one
    /// column) and the tail values `x`.
    fn finish(&self, fx: Mat<f64>, x: &[f64], active: &[bool]) -> Result<Solution, SolveError> {
        let mu = self.uni.len();
        if x.len() != mu || active.len() != mu {
            return Err(SolveError::Other("status vector size mismatch".into()));
        }
        let sys = self.sys();
        let (n, m) = (sys.n, sys.m);
        let z = match &self.core {
            Core::Bordered(b) => b.finish(fx, x),
            Core::Whole(w) => w.finish_with_tail(fx, x),
        };
        let sg = &sys.scaling.sigma;
        let mut lambda: Vec<f64> = (0..m).map(|i| sg[i] * (z[n + i] + z[n + m + i])).collect();
        let mut act = vec![true; m];
        for (q, &i) in self.uni.iter().enumerate() {
            act[i] = active[q];
            lambda[i] = if active[q] { 2.0 * sg[i] * x[q] } else { 0.0 };
        }
        Ok(Solution { u: z[..n].to_vec(), lambda, active: act })
    }
}

/// A load forwarded through the first block of a [`Condenser`]'s factor
/// (see [`Condenser::forward_load`]).
#[derive(Debug, Clone)]
pub struct Forwarded {
    /// The forwarded right-hand sides (the load, its forces alone).
    y: Mat<f64>,
    /// Their reduced tail.
    r: Mat<f64>,
}

impl Forwarded {
    /// `self += a · other` (the forward substitution is linear).
    pub fn add(&mut self, a: f64, other: &Forwarded) {
        self.y += faer::Scale(a) * &other.y;
        self.r += faer::Scale(a) * &other.r;
    }
}

/// Fingerprint of a load's numbers.
fn load_key(load: &Load) -> u64 {
    let mut h: u64 = 0x2545_f491_4f6c_dd1d;
    for &v in load.f.iter().chain(&load.d) {
        h ^= v.to_bits();
        h = h.wrapping_mul(0x0000_0100_0000_01b3).rotate_left(29);
    }
    h
}

#[cfg(test)]
#[path = "../tests/condenser.rs"]
mod tests;
