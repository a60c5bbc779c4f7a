//! Classes of events for HIST: each event is a tuple of reals, each
//! coordinate sorted into the intervals of its own list of bounds; the
//! classes of the coordinates combine into one global number, the first
//! coordinate varying fastest.

/// The global class (from 1) of each event, 0 when a coordinate lies
/// outside its bounds, and the number of events in each class.
/// `values[d][e]` is coordinate `d` of event `e`; `bounds[d]` are the
/// strictly increasing bounds of coordinate `d`. Intervals are closed
/// below and open above, except the last, which keeps its upper bound.
pub fn classify(values: &[&[f64]], bounds: &[&[f64]]) -> (Vec<i64>, Vec<i64>) {
    let events = values.first().map_or(0, |v| v.len());
    let total: usize = bounds.iter().map(|b| b.len().saturating_sub(1)).product();
    let mut occurrences = vec![0i64; total];
    let classes = (0..events)
        .map(|e| {
            let mut global = 0;
            let mut stride = 1;
            for (v, b) in values.iter().zip(bounds) {
                match interval(v[e], b) {
                    Some(k) => global += k * stride,
                    None => return 0,
                }
                stride *= b.len() - 1;
            }
            occurrences[global] += 1;
            global as i64 + 1
        })
        .collect();
    (classes, occurrences)
}

/// The interval (from 0) of `bounds` holding `x`.
fn interval(x: f64, bounds: &[f64]) -> Option<usize> {
    let n = bounds.len().checked_sub(1)?;
    if n == 0 || x < bounds[0] || x > bounds[n] {
        return None;
    }
    // The number of bounds ≤ x, less one, is the interval; x on the
    // top bound goes in the last one.
    Some((bounds.partition_point(|b| *b <= x) - 1).min(n - 1))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_coordinates() {
        let x1 = [0.2, 0.1, 1.1, 0.5, 0.4];
        let x2 = [4.0, 14.0, 9.0, 10.0, 1.0];
        let (c, o) = classify(&[&x1, &x2], &[&[0.0, 0.5, 1.0], &[0.0, 5.0, 10.0, 15.0, 20.0]]);
        assert_eq!(c, vec![1, 5, 0, 6, 1]);
        assert_eq!(o, vec![2, 0, 0, 0, 1, 1, 0, 0]);
    }
}

/// The density of `values` over the intervals of `bounds` (strictly
/// increasing): the share of the values in each interval divided by its
/// width, so that it sums (times the widths) to the share inside the
/// bounds. One value per bound, the last repeating the last interval's,
/// as a step curve drawn on the bounds ends.
pub fn density(values: &[f64], bounds: &[f64]) -> Vec<f64> {
    let n = bounds.len() - 1;
    let mut counts = vec![0usize; n];
    for &x in values {
        if let Some(k) = interval(x, bounds) {
            counts[k] += 1;
        }
    }
    let total = values.len().max(1) as f64;
    let mut d: Vec<f64> =
        counts.iter().zip(bounds.windows(2)).map(|(c, w)| *c as f64 / total / (w[1] - w[0])).collect();
    d.push(d[n - 1]);
    d
}

#[cfg(test)]
mod density_tests {
    #[test]
    fn shares_over_widths() {
        // 4 values: 1 in [0,1), 3 in [1,3]: 0.25/1 and 0.75/2.
        let d = super::density(&[0.5, 1.0, 2.0, 3.0], &[0.0, 1.0, 3.0]);
        assert_eq!(d, vec![0.25, 0.375, 0.375]);
    }
}
