//! One step of the method of moving asymptotes (Svanberg 1987), for
//! EXCELLENCE: from the values and gradients of the objective and of the
//! constraints at x, the minimum of their convex separable approximation
//!   f̃(x) = r + Σ_i p_i / (U_i − x_i) + q_i / (x_i − L_i)
//! under the approximated constraints and the bounds, solved through its
//! concave dual (one multiplier per constraint, each found by bisection).

/// How the asymptotes L < x < U are placed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Asymptotes {
    /// Fixed: L = t x, U = x / t (0 < t < 1; the larger t, the closer the
    /// asymptotes and the more convex the approximation).
    Fixed(f64),
    /// Moving: from the two previous iterates, the asymptotes move away
    /// while x goes one way (by 1/s) and close in when it oscillates (by s).
    Moving(f64),
    /// Far asymptotes: a nearly linear approximation.
    Linear,
}

/// A problem at the current point.
pub struct Step<'a> {
    pub x: &'a [f64],
    pub grad_f: &'a [f64],
    /// Per constraint: its value and gradient at x, and its bound.
    pub cons: &'a [(f64, Vec<f64>, f64)],
    pub xmin: &'a [f64],
    pub xmax: &'a [f64],
}

/// The asymptotes of the previous steps, for the moving method.
#[derive(Debug, Clone, Default)]
pub struct History {
    pub x1: Option<Vec<f64>>,
    pub x2: Option<Vec<f64>>,
    pub low: Option<Vec<f64>>,
    pub upp: Option<Vec<f64>>,
}

/// The asymptotes at x.
pub fn asymptotes(s: &Step, how: Asymptotes, h: &History) -> (Vec<f64>, Vec<f64>) {
    let n = s.x.len();
    let fixed = |t: f64, i: usize| {
        let x = s.x[i];
        let span = (s.xmax[i] - s.xmin[i]).abs().max(1e-12);
        if x > 0.0 {
            (t * x, x / t)
        } else {
            (x - (1.0 - t) * span, x + (1.0 - t) * span)
        }
    };
    let mut low = vec![0.0; n];
    let mut upp = vec![0.0; n];
    for i in 0..n {
        let span = (s.xmax[i] - s.xmin[i]).abs().max(1e-12);
        (low[i], upp[i]) = match how {
            Asymptotes::Fixed(t) => fixed(t, i),
            Asymptotes::Linear => (s.x[i] - 100.0 * span, s.x[i] + 100.0 * span),
            Asymptotes::Moving(sm) => match (&h.x1, &h.x2, &h.low, &h.upp) {
                (Some(x1), Some(x2), Some(l), Some(u)) => {
                    let osc = (s.x[i] - x1[i]) * (x1[i] - x2[i]);
                    let g = if osc < 0.0 {
                        sm
                    } else if osc > 0.0 {
                        1.0 / sm
                    } else {
                        1.0
                    };
                    let lo = s.x[i] - g * (x1[i] - l[i]);
                    let up = s.x[i] + g * (u[i] - x1[i]);
                    // Keep them at a sane distance: not on x, not past 10 spans.
                    let (dmin, dmax) = (1e-2 * span, 10.0 * span);
                    (s.x[i] - (s.x[i] - lo).clamp(dmin, dmax), s.x[i] + (up - s.x[i]).clamp(dmin, dmax))
                }
                _ => fixed(sm, i),
            },
        };
    }
    (low, upp)
}

/// The next point.
pub fn step(s: &Step, low: &[f64], upp: &[f64]) -> Vec<f64> {
    let n = s.x.len();
    let m = s.cons.len();
    let alpha: Vec<f64> = (0..n).map(|i| s.xmin[i].max(0.9 * low[i] + 0.1 * s.x[i])).collect();
    let beta: Vec<f64> = (0..n).map(|i| s.xmax[i].min(0.9 * upp[i] + 0.1 * s.x[i])).collect();
    let pq = |g: f64, i: usize, reg: bool| {
        let (u2, l2) = ((upp[i] - s.x[i]).powi(2), (s.x[i] - low[i]).powi(2));
        let (gp, gm) = (g.max(0.0), (-g).max(0.0));
        if reg {
            // A little curvature both ways keeps the objective strictly convex.
            let e = 1e-5 / (s.xmax[i] - s.xmin[i]).abs().max(1e-12);
            (u2 * (1.001 * gp + 0.001 * gm + e), l2 * (0.001 * gp + 1.001 * gm + e))
        } else {
            (u2 * gp, l2 * gm)
        }
    };
    let p0: Vec<(f64, f64)> = (0..n).map(|i| pq(s.grad_f[i], i, true)).collect();
    let pc: Vec<Vec<(f64, f64)>> =
        s.cons.iter().map(|(_, g, _)| (0..n).map(|i| pq(g[i], i, false)).collect()).collect();
    // r_j − bound_j: the constant of each approximated constraint.
    let rc: Vec<f64> = s
        .cons
        .iter()
        .zip(&pc)
        .map(|((v, _, b), pj)| {
            v - b - (0..n).map(|i| pj[i].0 / (upp[i] - s.x[i]) + pj[i].1 / (s.x[i] - low[i])).sum::<f64>()
        })
        .collect();
    let x_of = |lam: &[f64]| -> Vec<f64> {
        (0..n)
            .map(|i| {
                let p = p0[i].0 + (0..m).map(|j| lam[j] * pc[j][i].0).sum::<f64>();
                let q = p0[i].1 + (0..m).map(|j| lam[j] * pc[j][i].1).sum::<f64>();
                let (sp, sq) = (p.sqrt(), q.sqrt());
                let x = if sp + sq > 0.0 { (low[i] * sp + upp[i] * sq) / (sp + sq) } else { s.x[i] };
                x.clamp(alpha[i], beta[i])
            })
            .collect()
    };
    let slack = |j: usize, x: &[f64]| {
        rc[j] + (0..n).map(|i| pc[j][i].0 / (upp[i] - x[i]) + pc[j][i].1 / (x[i] - low[i])).sum::<f64>()
    };
    let mut lam = vec![0.0; m];
    for _sweep in 0..if m > 1 { 50 } else { 1 } {
        let mut moved = 0.0f64;
        for j in 0..m {
            let old = lam[j];
            let mut at = |v: f64| {
                lam[j] = v;
                slack(j, &x_of(&lam))
            };
            let new = if at(0.0) <= 0.0 {
                0.0
            } else {
                let mut hi = 1.0;
                while at(hi) > 0.0 && hi < 1e15 {
                    hi *= 4.0;
                }
                let mut lo = 0.0;
                for _ in 0..200 {
                    let mid = 0.5 * (lo + hi);
                    if at(mid) > 0.0 {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                    if hi - lo <= 1e-15 * hi {
                        break;
                    }
                }
                hi
            };
            lam[j] = new;
            moved = moved.max((new - old).abs() / (1.0 + new.abs()));
        }
        if moved < 1e-12 {
            break;
        }
    }
    x_of(&lam)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reaches_the_constrained_minimum() {
        // min (x1-3)² + (x2-3)² with x1 + x2 <= 2: the minimum is (1, 1).
        let mut x = vec![0.5, 0.2];
        let mut h = History::default();
        for _ in 0..60 {
            let g = [2.0 * (x[0] - 3.0), 2.0 * (x[1] - 3.0)];
            let cons = [(x[0] + x[1], vec![1.0, 1.0], 2.0)];
            let s = Step { x: &x, grad_f: &g, cons: &cons, xmin: &[0.01, 0.01], xmax: &[10.0, 10.0] };
            let (l, u) = asymptotes(&s, Asymptotes::Moving(0.7), &h);
            let nx = step(&s, &l, &u);
            h = History { x2: h.x1.take(), x1: Some(x.clone()), low: Some(l), upp: Some(u) };
            x = nx;
        }
        assert!((x[0] - 1.0).abs() < 1e-4 && (x[1] - 1.0).abs() < 1e-4, "{x:?}");
    }
}
