//! Arrival times of a front spreading from burning points (FRON).
//!
//! The points carry no connectivity (a CHPOINT's support), so the front
//! travels in straight legs between points: a leg from i to j lasts
//! |x_i − x_j| / ((v_i + v_j) / 2), the mean of the end speeds standing for
//! the speed along it (on a chain of short legs this is close to ∫ ds / v).
//! A point burns for its combustion time after the front reaches it and
//! can only light the points its legs reach meanwhile, which keeps the
//! spreading local. The earliest arrival over chains of legs is a
//! shortest path (Dijkstra over all pairs, O(N²) without a heap).

/// For each point, its new arrival time, or `None` to keep the old one.
/// Points with `t ≤ t1` have burnt at `t1` and are the sources; every other
/// point the front reaches by `t2` gets the time it is reached.
pub fn arrival_times(x: &[[f64; 3]], t: &[f64], speed: &[f64], burn: &[f64], t1: f64, t2: f64) -> Vec<Option<f64>> {
    let n = x.len();
    let mut best: Vec<f64> = t.iter().map(|&ti| if ti <= t1 { ti } else { f64::INFINITY }).collect();
    let mut done = vec![false; n];
    loop {
        let mut u = None;
        for i in 0..n {
            if !done[i] && best[i].is_finite() && u.is_none_or(|k: usize| best[i] < best[k]) {
                u = Some(i);
            }
        }
        let Some(u) = u else { break };
        if best[u] > t2 {
            break;
        }
        done[u] = true;
        for j in 0..n {
            if done[j] {
                continue;
            }
            let v = 0.5 * (speed[u] + speed[j]);
            if v <= 0.0 {
                continue;
            }
            let d = (0..3).map(|c| (x[u][c] - x[j][c]).powi(2)).sum::<f64>().sqrt();
            let leg = d / v;
            if leg <= burn[u] && best[u] + leg < best[j] {
                best[j] = best[u] + leg;
            }
        }
    }
    (0..n).map(|i| (t[i] > t1 && best[i] <= t2).then_some(best[i])).collect()
}

#[cfg(test)]
mod tests {
    use super::arrival_times;

    #[test]
    fn a_line_of_points_at_constant_speed() {
        let x: Vec<[f64; 3]> = (0..5).map(|i| [i as f64, 0.0, 0.0]).collect();
        let t = [0.0, 9.0, 9.0, 9.0, 9.0];
        let r = arrival_times(&x, &t, &[2.0; 5], &[10.0; 5], 0.0, 1.6);
        // Reached at 0.5, 1.0, 1.5; the last (2.0) is beyond t2 and kept.
        assert_eq!(r, vec![None, Some(0.5), Some(1.0), Some(1.5), None]);
    }

    #[test]
    fn burning_time_limits_the_legs() {
        let x = [[0.0, 0.0, 0.0], [3.0, 0.0, 0.0]];
        let r = arrival_times(&x, &[0.0, 99.0], &[1.0, 1.0], &[2.0, 2.0], 0.0, 50.0);
        assert_eq!(r, vec![None, None]);
    }
}
