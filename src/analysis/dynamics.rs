//! Linear dynamics over time steps: Newmark's average acceleration
//! (β = 1/4, γ = 1/2, the trapezoidal rule), the implicit scheme
//! Cast3M's PASAPAS uses with 'DYNAMIQUE' (pasapas.notice: 'VITESSES',
//! 'ACCELERATIONS', 'MASSE', 'AMORTISSEMENT').
//!
//! Over a step h from (u₀, v₀, a₀) the scheme takes
//!   u₁ = u₀ + h v₀ + h²/4 (a₀ + a₁),   v₁ = v₀ + h/2 (a₀ + a₁),
//! and the equation of motion at the end of the step
//!   M a₁ + C v₁ + K u₁ + Cᵀλ = F₁  (the conditions on u₁ as in statics).
//! Eliminating a₁ and v₁ leaves a static problem on u₁ with the effective
//! operator K + 4/h² M + 2/h C and the load
//!   F₁ + M (4/h² u₀ + 4/h v₀) + 2/h C u₀ + r₀,   r₀ = M a₀ + C v₀,
//! so the step goes through the same [`super::stepper::Stepper`] as a
//! static step (one factorisation per step length; unilateral conditions
//! by the same status iteration) and λ is the reaction at the end of the
//! step. The scheme is unconditionally stable and, for a linear system,
//! conserves the energy exactly (its only error is a period elongation).
//!
//! The inertial force r = M a + C v is carried from step to step rather
//! than a: at the start it comes from the equilibrium residual F₀ − K u₀
//! (as in Cast3M), so a run loaded from its first instant starts with the
//! acceleration its load gives even when no 'ACCELERATIONS' is given (the
//! accelerations reported follow the scheme from 'ACCELERATIONS'.0, 0 by
//! default, as Cast3M reports them).

use super::stepper::Stepper;
use crate::solve::{Condition, Load, Matrix, Problem};

/// y = A x for a matrix of triplets (repeated entries add up).
pub fn matvec(a: &Matrix, x: &[f64]) -> Vec<f64> {
    let mut y = vec![0.0; a.n];
    for &(i, j, v) in &a.entries {
        y[i] += v * x[j];
    }
    y
}

/// The state of a dynamic run and its mass and damping.
pub struct Newmark {
    pub mass: Matrix,
    pub damping: Option<Matrix>,
    /// Displacements, velocities, accelerations at the last time.
    pub u: Vec<f64>,
    pub v: Vec<f64>,
    pub a: Vec<f64>,
    /// Inertial and viscous forces at the last time, M a + C v.
    pub r: Vec<f64>,
    /// The step length the effective operator was last built for.
    pub h: Option<f64>,
}

impl Newmark {
    /// A run from (u₀, v₀, a₀), its inertial force at the start `r0`.
    pub fn new(mass: Matrix, damping: Option<Matrix>, u: Vec<f64>, v: Vec<f64>, a: Vec<f64>, r0: Vec<f64>) -> Self {
        Newmark { mass, damping, u, v, a, r: r0, h: None }
    }

    /// The inertial force at the start from the equilibrium residual
    /// F₀ − K u₀: M a₀ + C v₀ with a₀ solving M a₀ = F₀ − K u₀ − C v₀
    /// − Cᵀλ₀ under the bilateral conditions (their reactions at the start
    /// taken out, so the reactions of the steps are those of the motion).
    /// When the mass cannot be solved for (unknowns without mass), the
    /// residual itself.
    pub fn start_from(&mut self, conditions: &[Condition], residual: Vec<f64>) {
        let mut f = residual.clone();
        if let Some(c) = &self.damping {
            for (fi, ci) in f.iter_mut().zip(matvec(c, &self.v)) {
                *fi -= ci;
            }
        }
        let bilateral: Vec<Condition> = conditions.iter().filter(|c| !c.kind.is_unilateral()).cloned().collect();
        let m = bilateral.len();
        let p = Problem { k: self.mass.clone(), conditions: bilateral };
        let a0 = Stepper::new(p)
            .and_then(|mut s| s.solve(&Load { f, d: vec![0.0; m] }, &mut |_| {}))
            .map(|out| out.solution.u)
            .ok()
            .filter(|a| a.iter().all(|x| x.is_finite()));
        self.r = match a0 {
            Some(a0) => {
                let mut r = matvec(&self.mass, &a0);
                if let Some(c) = &self.damping {
                    for (ri, ci) in r.iter_mut().zip(matvec(c, &self.v)) {
                        *ri += ci;
                    }
                }
                r
            }
            None => residual,
        };
    }

    /// Whether the operator built for the last step serves a step `h`
    /// (the same length within 1e-4, as Cast3M refactorises beyond it).
    pub fn same_step(&self, h: f64) -> bool {
        self.h.is_some_and(|h0| (h - h0).abs() <= 1e-4 * h0.abs())
    }

    /// The problem of a step `h`: the static operator plus 4/h² M + 2/h C,
    /// the same conditions. Remembers `h` as the current step.
    pub fn effective(&mut self, statics: &Problem, h: f64) -> Problem {
        let mut p = statics.clone();
        let cm = 4.0 / (h * h);
        p.k.entries.extend(self.mass.entries.iter().map(|&(i, j, v)| (i, j, cm * v)));
        if let Some(c) = &self.damping {
            let cc = 2.0 / h;
            p.k.entries.extend(c.entries.iter().map(|&(i, j, v)| (i, j, cc * v)));
            p.k.symmetric &= c.symmetric;
        }
        p.k.symmetric &= self.mass.symmetric;
        self.h = Some(h);
        p
    }

    /// What the past adds to the load of a step `h` (no condition value):
    /// M (4/h² u₀ + 4/h v₀) + 2/h C u₀ + r₀.
    pub fn inertia_load(&self, h: f64, conditions: usize) -> Load {
        let w: Vec<f64> = self.u.iter().zip(&self.v).map(|(u, v)| 4.0 / (h * h) * u + 4.0 / h * v).collect();
        let mut f = matvec(&self.mass, &w);
        if let Some(c) = &self.damping {
            for (fi, ci) in f.iter_mut().zip(matvec(c, &self.u)) {
                *fi += 2.0 / h * ci;
            }
        }
        for (fi, ri) in f.iter_mut().zip(&self.r) {
            *fi += ri;
        }
        Load { f, d: vec![0.0; conditions] }
    }

    /// Moves the state to the end of a step `h` whose displacements are
    /// `u1`: v₁ = 2/h Δu − v₀, a₁ = 4/h² Δu − 4/h v₀ − a₀, and
    /// r₁ = (4/h² M + 2/h C) Δu − 4/h M v₀ − r₀ (= M a₁ + C v₁).
    pub fn advance(&mut self, h: f64, u1: &[f64]) {
        let du: Vec<f64> = u1.iter().zip(&self.u).map(|(a, b)| a - b).collect();
        let w: Vec<f64> = du.iter().zip(&self.v).map(|(d, v)| 4.0 / (h * h) * d - 4.0 / h * v).collect();
        let mut r = matvec(&self.mass, &w);
        if let Some(c) = &self.damping {
            for (ri, ci) in r.iter_mut().zip(matvec(c, &du)) {
                *ri += 2.0 / h * ci;
            }
        }
        for (ri, r0) in r.iter_mut().zip(&self.r) {
            *ri -= r0;
        }
        for ((&d, v), a) in du.iter().zip(self.v.iter_mut()).zip(self.a.iter_mut()) {
            let v1 = 2.0 / h * d - *v;
            *a = 4.0 / (h * h) * d - 4.0 / h * *v - *a;
            *v = v1;
        }
        self.u = u1.to_vec();
        self.r = r;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One mass on a spring, released from u₀ = 1: the average
    /// acceleration scheme gives the exact discrete solution
    /// u_n = cos(n θ), θ = 2 atan(ω h / 2), and keeps the energy.
    #[test]
    fn oscillator_follows_the_discrete_solution() {
        let (k, m, h) = (4.0, 1.0, 0.1);
        let statics = Problem { k: Matrix { n: 1, entries: vec![(0, 0, k)], symmetric: true }, conditions: vec![] };
        let mass = Matrix { n: 1, entries: vec![(0, 0, m)], symmetric: true };
        let mut nm = Newmark::new(mass, None, vec![1.0], vec![0.0], vec![-k], vec![-k]);
        let mut s = Stepper::new(nm.effective(&statics, h)).unwrap();
        let theta = 2.0 * ((k / m).sqrt() * h / 2.0).atan();
        for n in 1..=200 {
            let load = nm.inertia_load(h, 0);
            let u1 = s.solve(&load, &mut |_| {}).unwrap().solution.u;
            nm.advance(h, &u1);
            let exact = (n as f64 * theta).cos();
            assert!((nm.u[0] - exact).abs() < 1e-12, "step {n}: {} vs {exact}", nm.u[0]);
            let e = 0.5 * k * nm.u[0] * nm.u[0] + 0.5 * m * nm.v[0] * nm.v[0];
            assert!((e - 2.0).abs() < 1e-12, "energy {e}");
            assert!((nm.r[0] - m * nm.a[0]).abs() < 1e-9);
        }
    }
}
