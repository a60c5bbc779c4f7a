//! One-degree-of-freedom oscillators driven by a sampled signal:
//! `x'' + 2 xi w x' + r(x) = f(t)`, with `r = w^2 x` (linear: OSCI, SPO) or
//! a bilinear hysteretic spring (SPON). The signal is piecewise linear
//! between its samples and zero outside them.

/// The forcing: a piecewise-linear signal, zero outside its samples.
pub struct Signal<'a> {
    pub t: &'a [f64],
    pub f: &'a [f64],
}

impl Signal<'_> {
    pub fn at(&self, t: f64) -> f64 {
        let (ts, fs) = (self.t, self.f);
        if ts.is_empty() || t < ts[0] || t > ts[ts.len() - 1] {
            return 0.0;
        }
        let i = ts.partition_point(|&x| x <= t);
        if i == 0 {
            return fs[0];
        }
        if i >= ts.len() {
            return fs[ts.len() - 1];
        }
        let (t0, t1) = (ts[i - 1], ts[i]);
        if t1 <= t0 {
            return fs[i];
        }
        fs[i - 1] + (fs[i] - fs[i - 1]) * (t - t0) / (t1 - t0)
    }
}

/// Free motion over `dt`: (x, v) -> (a11 x + a12 v, a21 x + a22 v).
#[derive(Clone, Copy)]
struct Free {
    a: [f64; 4],
}

impl Free {
    fn new(w: f64, xi: f64, dt: f64) -> Free {
        let e = (-xi * w * dt).exp();
        // sin(wd t)/wd and cos(wd t), continued to the over-damped side.
        let (s, c) = if xi < 1.0 {
            let wd = w * (1.0 - xi * xi).sqrt();
            ((wd * dt).sin() / wd, (wd * dt).cos())
        } else if xi > 1.0 {
            let wd = w * (xi * xi - 1.0).sqrt();
            ((wd * dt).sinh() / wd, (wd * dt).cosh())
        } else {
            (dt, 1.0)
        };
        Free { a: [e * (c + xi * w * s), e * s, -e * w * w * s, e * (c - xi * w * s)] }
    }
}

/// What a run of the linear oscillator gives.
pub struct Response {
    /// Displacement and velocity at the requested times.
    pub x: Vec<f64>,
    pub v: Vec<f64>,
    /// Largest |x|, |x'| and |2 xi w x' + w^2 x| (the absolute
    /// acceleration) over every computed instant.
    pub max_x: f64,
    pub max_v: f64,
    pub max_acc: f64,
}

/// The exact response of the linear oscillator (frequency `w` in rad/s,
/// reduced damping `xi`) to the piecewise-linear signal, at `times`
/// (increasing), starting at `times[0]` from (x0, v0). The signal's own
/// samples inside the interval are stepped over too, so no peak of the
/// forcing is lost between two requested times.
pub fn linear(sig: &Signal, w: f64, xi: f64, times: &[f64], x0: f64, v0: f64) -> Result<Response, String> {
    check(w, xi)?;
    if times.windows(2).any(|p| p[1] < p[0]) {
        return Err("the times must increase".into());
    }
    let mut out = Response { x: Vec::new(), v: Vec::new(), max_x: 0.0, max_v: 0.0, max_acc: 0.0 };
    let Some(&t0) = times.first() else { return Ok(out) };
    let (mut x, mut v, mut t, mut p) = (x0, v0, t0, sig.at(t0));
    let mut free: Option<(f64, Free)> = None;
    let mut k = sig.t.partition_point(|&s| s <= t0);
    let w2 = w * w;
    let note = |x: f64, v: f64, out: &mut Response| {
        out.max_x = out.max_x.max(x.abs());
        out.max_v = out.max_v.max(v.abs());
        out.max_acc = out.max_acc.max((2.0 * xi * w * v + w2 * x).abs());
    };
    note(x, v, &mut out);
    for &target in times {
        loop {
            // The next instant: a sample of the signal before the target, or the target.
            let next = if k < sig.t.len() && sig.t[k] < target { sig.t[k] } else { target };
            if next > t {
                let dt = next - t;
                let p1 = sig.at(next);
                let f = match free {
                    Some((d, f)) if (d - dt).abs() <= 1e-12 * dt => f,
                    _ => {
                        let f = Free::new(w, xi, dt);
                        free = Some((dt, f));
                        f
                    }
                };
                // Linear forcing a + b s: particular solution c0 + c1 s.
                let b = (p1 - p) / dt;
                let c1 = b / w2;
                let c0 = (p - 2.0 * xi * w * c1) / w2;
                let (hx, hv) = (x - c0, v - c1);
                x = f.a[0] * hx + f.a[1] * hv + c0 + c1 * dt;
                v = f.a[2] * hx + f.a[3] * hv + c1;
                t = next;
                p = p1;
                note(x, v, &mut out);
            }
            if next >= target {
                break;
            }
            k += 1;
        }
        out.x.push(x);
        out.v.push(v);
    }
    Ok(out)
}

fn check(w: f64, xi: f64) -> Result<(), String> {
    if !(w > 0.0 && w.is_finite()) {
        return Err(format!(
            "the frequency of an oscillator must be positive, found {}",
            w / (2.0 * std::f64::consts::PI)
        ));
    }
    if !(xi >= 0.0 && xi.is_finite()) {
        return Err(format!("the damping of an oscillator must be positive or zero, found {}", xi));
    }
    Ok(())
}

/// The default times of a spectrum: the signal's own, followed by half a
/// period of free motion at the signal's mean step (the peak may come
/// after the excitation ends).
pub fn spectrum_times(t: &[f64], w: f64) -> Vec<f64> {
    let mut out = t.to_vec();
    if t.len() < 2 {
        return out;
    }
    let dt = (t[t.len() - 1] - t[0]) / (t.len() - 1) as f64;
    let end = t[t.len() - 1] + std::f64::consts::PI / w;
    let mut s = t[t.len() - 1];
    while dt > 0.0 && s < end {
        s += dt;
        out.push(s);
    }
    out
}

/// The default frequencies of a spectrum (spo.notice): from 1/T by steps
/// of 1/T up to 1/(xi T), then steps df = xi f, up to 1/(2 dt).
pub fn spectrum_frequencies(t: &[f64], xi: f64) -> Vec<f64> {
    if t.len() < 2 {
        return Vec::new();
    }
    let dur = t[t.len() - 1] - t[0];
    let dt = dur / (t.len() - 1) as f64;
    if dur <= 0.0 {
        return Vec::new();
    }
    let (first, top) = (1.0 / dur, 0.5 / dt);
    let xi = if xi > 0.0 { xi } else { 0.05 };
    let mut f = first;
    let mut out = Vec::new();
    while f <= top * (1.0 + 1e-9) && out.len() < 100_000 {
        out.push(f);
        f += if f < 1.0 / (xi * dur) { first } else { xi * f };
    }
    out
}

/// A bilinear hysteretic spring: initial stiffness w^2, stiffness
/// `theta w^2` past the yield displacement `uy`.
#[derive(Clone, Copy)]
pub enum Spring {
    /// Kinematic hardening: the force stays between the two lines
    /// `theta w^2 x +- (1 - theta) w^2 uy`.
    Kinematic,
    /// Isotropic hardening: the elastic range grows with the largest force reached.
    Isotropic,
    /// Non-linear elastic: loading and unloading on the same bilinear curve.
    Elastic,
}

/// Largest |x| and the cumulated plastic displacement of the bilinear
/// oscillator under the signal, over `times` (steps cut to a fiftieth of
/// the period at most: explicit central differences).
pub fn bilinear(
    sig: &Signal,
    w: f64,
    xi: f64,
    spring: Spring,
    theta: f64,
    uy: f64,
    times: &[f64],
) -> Result<(f64, f64), String> {
    check(w, xi)?;
    if !(uy > 0.0 && uy.is_finite()) {
        return Err(format!("the yield displacement must be positive, found {}", uy));
    }
    let (Some(&t0), Some(&t1)) = (times.first(), times.last()) else { return Ok((0.0, 0.0)) };
    let k1 = w * w;
    let k2 = theta * k1;
    let period = 2.0 * std::f64::consts::PI / w;
    let mut h = period / 50.0;
    if times.len() > 1 {
        h = h.min((t1 - t0) / (times.len() - 1) as f64);
    }
    let n = ((t1 - t0) / h).ceil().max(1.0) as usize;
    let h = (t1 - t0) / n as f64;
    let fy = k1 * uy;
    let (mut x, mut r, mut plastic, mut maxr, mut max_x) = (0.0f64, 0.0f64, 0.0f64, fy, 0.0f64);
    // x_{-1} from x0 = 0, v0 = 0 and a0 = f(t0).
    let mut prev = 0.5 * h * h * sig.at(t0);
    let (c_next, c_prev) = (1.0 / (h * h) + xi * w / h, 1.0 / (h * h) - xi * w / h);
    for i in 0..n {
        let t = t0 + i as f64 * h;
        let next = (sig.at(t) - r + 2.0 * x / (h * h) - c_prev * prev) / c_next;
        let dx = next - x;
        let trial = r + k1 * dx;
        let new_r = match spring {
            Spring::Kinematic => {
                let up = k2 * next + (k1 - k2) * uy;
                let lo = k2 * next - (k1 - k2) * uy;
                trial.clamp(lo, up)
            }
            Spring::Isotropic => {
                let limit = maxr;
                if trial.abs() > limit {
                    // Past the current elastic range: harden along theta w^2.
                    let s = trial.signum();
                    let over = (trial.abs() - limit) / k1;
                    let nr = s * (limit + k2 * over);
                    maxr = nr.abs();
                    nr
                } else {
                    trial
                }
            }
            Spring::Elastic => {
                if next.abs() <= uy {
                    k1 * next
                } else {
                    next.signum() * (fy + k2 * (next.abs() - uy))
                }
            }
        };
        if k1 > 0.0 {
            plastic += ((trial - new_r) / k1).abs();
        }
        r = new_r;
        prev = x;
        x = next;
        if !x.is_finite() {
            return Err("the oscillator's response is not finite".into());
        }
        max_x = max_x.max(x.abs());
    }
    Ok((max_x, plastic))
}

/// The yield displacement for which the bilinear oscillator's ductility
/// (largest |x| over the yield displacement) is `mu`, searched below the
/// linear peak `linear_max` (mu = 1 is the linear oscillator itself).
#[allow(clippy::too_many_arguments)]
pub fn yield_for_ductility(
    sig: &Signal,
    w: f64,
    xi: f64,
    spring: Spring,
    theta: f64,
    mu: f64,
    linear_max: f64,
    times: &[f64],
) -> Result<(f64, f64), String> {
    if !(mu >= 1.0 && mu.is_finite()) {
        return Err(format!("the ductility must be at least 1, found {}", mu));
    }
    if linear_max <= 0.0 || mu == 1.0 {
        return Ok((linear_max, 0.0));
    }
    let ductility = |uy: f64| bilinear(sig, w, xi, spring, theta, uy, times).map(|(m, p)| (m / uy, p));
    // Bisection on log(uy) between a yield small enough to exceed mu and the linear peak.
    let (mut lo, mut hi) = (linear_max / mu, linear_max);
    let mut k = 0;
    while ductility(lo)?.0 < mu && k < 60 {
        lo /= 2.0;
        k += 1;
    }
    for _ in 0..50 {
        let mid = (lo * hi).sqrt();
        if ductility(mid)?.0 > mu {
            lo = mid;
        } else {
            hi = mid;
        }
        if hi / lo < 1.0 + 1e-7 {
            break;
        }
    }
    let uy = (lo * hi).sqrt();
    Ok((uy, ductility(uy)?.1))
}
